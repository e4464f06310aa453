//! Merging regions smaller than a minimum area into a neighbour.

use crate::imaging::{Labels, region_adjacency};

/// Merges every region under `min_px` pixels into the neighbour it shares
/// the longest border with (smallest first, repeatedly), then renumbers.
/// Small regions with no neighbour are removed.
pub(crate) fn merge_small(labels: &mut Labels, min_px: usize) {
    loop {
        let areas = labels.areas();
        let rag = region_adjacency(labels);
        let mut small: Vec<u32> = (1..=labels.count)
            .filter(|&l| areas[l as usize] > 0 && areas[l as usize] < min_px)
            .collect();
        small.sort_by_key(|&l| areas[l as usize]);
        let mut target = vec![0u32; labels.count as usize + 1];
        let mut changed = false;
        for l in small {
            // Skip regions already used as a target or merged this round.
            if target[l as usize] != 0 {
                continue;
            }
            let best = rag
                .iter()
                .filter_map(|(&(a, b), &n)| {
                    if a == l {
                        Some((b, n))
                    } else if b == l {
                        Some((a, n))
                    } else {
                        None
                    }
                })
                .filter(|&(o, _)| target[o as usize] == 0)
                .max_by_key(|&(o, n)| (n, areas[o as usize]));
            if let Some((o, _)) = best {
                target[l as usize] = o;
                target[o as usize] = o;
                changed = true;
            }
        }
        if !changed {
            // What is still small has no neighbour left to join: drop it.
            for v in &mut labels.data {
                if *v != 0 && areas[*v as usize] < min_px {
                    *v = 0;
                }
            }
            break;
        }
        for v in &mut labels.data {
            let t = target[*v as usize];
            if *v != 0 && t != 0 && t != *v {
                *v = t;
            }
        }
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
}
