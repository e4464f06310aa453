//! Merging regions: those smaller than a minimum area into a neighbour,
//! and given pairs into one.

use std::cmp::Reverse;
use std::collections::{BTreeMap, BinaryHeap};

use crate::imaging::{Labels, region_adjacency};

/// Merges every region under `min_px` pixels into the neighbour it shares
/// the longest border with (ties: the larger neighbour), smallest first,
/// until none is left; then renumbers. A merged region that is still small
/// goes on merging. Small regions with no neighbour are removed. The region
/// adjacency is computed once and updated as regions merge.
pub(crate) fn merge_small(labels: &mut Labels, min_px: usize) {
    let mut area = labels.areas();
    if !area.iter().any(|&a| a > 0 && a < min_px) {
        labels.compact();
        return;
    }
    let n = area.len();
    let mut nbrs: Vec<BTreeMap<u32, usize>> = vec![BTreeMap::new(); n];
    for (&(a, b), &len) in &region_adjacency(labels) {
        nbrs[a as usize].insert(b, len);
        nbrs[b as usize].insert(a, len);
    }
    let mut parent: Vec<u32> = (0..n as u32).collect();
    let mut heap: BinaryHeap<Reverse<(usize, u32)>> = (1..n as u32)
        .filter(|&l| area[l as usize] > 0 && area[l as usize] < min_px)
        .map(|l| Reverse((area[l as usize], l)))
        .collect();
    while let Some(Reverse((a, l))) = heap.pop() {
        let li = l as usize;
        if parent[li] != l || area[li] != a {
            continue; // merged away, or grown since it was queued
        }
        let best = nbrs[li]
            .iter()
            .max_by_key(|&(&o, &len)| (len, area[o as usize]))
            .map(|(&o, _)| o);
        let Some(o) = best else {
            parent[li] = 0;
            area[li] = 0;
            continue;
        };
        let oi = o as usize;
        parent[li] = o;
        area[oi] += area[li];
        area[li] = 0;
        for (k, len) in std::mem::take(&mut nbrs[li]) {
            let ki = k as usize;
            nbrs[ki].remove(&l);
            if k != o {
                *nbrs[ki].entry(o).or_insert(0) += len;
                *nbrs[oi].entry(k).or_insert(0) += len;
            }
        }
        if area[oi] < min_px {
            heap.push(Reverse((area[oi], o)));
        }
    }
    let root = |mut l: u32| {
        while parent[l as usize] != l {
            l = parent[l as usize];
        }
        l
    };
    let final_label: Vec<u32> = (0..n as u32).map(root).collect();
    for v in &mut labels.data {
        *v = final_label[*v as usize];
    }
    labels.compact();
}

/// Merges each pair of regions into one, transitively; then renumbers.
pub(crate) fn merge_pairs(labels: &mut Labels, pairs: &[(u32, u32)]) {
    let n = labels.count as usize + 1;
    let mut parent: Vec<u32> = (0..n as u32).collect();
    fn find(parent: &mut [u32], mut l: u32) -> u32 {
        while parent[l as usize] != l {
            parent[l as usize] = parent[parent[l as usize] as usize];
            l = parent[l as usize];
        }
        l
    }
    for &(a, b) in pairs {
        let (ra, rb) = (find(&mut parent, a), find(&mut parent, b));
        if ra != rb {
            parent[ra.max(rb) as usize] = ra.min(rb);
        }
    }
    let root: Vec<u32> = (0..n as u32).map(|l| find(&mut parent, l)).collect();
    for v in &mut labels.data {
        *v = root[*v as usize];
    }
    labels.compact();
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_region_joins_its_longest_neighbour() {
        let mut l = Labels {
            width: 4,
            height: 2,
            data: vec![1, 1, 2, 3, 1, 1, 2, 3],
            count: 3,
        };
        merge_small(&mut l, 3);
        // 2 (2 px) joins 3? no: 3 is also small; 2 borders 1 and 3 equally, larger wins.
        assert_eq!(l.data[2], l.data[0]);
        assert_eq!(l.count, 1);
    }

    #[test]
    fn pairs_merge_transitively() {
        let mut l = Labels {
            width: 5,
            height: 1,
            data: vec![1, 2, 3, 4, 0],
            count: 4,
        };
        merge_pairs(&mut l, &[(3, 2), (2, 1)]);
        assert_eq!(l.data, vec![1, 1, 1, 2, 0]);
        assert_eq!(l.count, 2);
    }
}
