//! The component tree of nested level sets: for an image of small integer
//! depths, the 8-connected components of every set `{depth ≥ k}`, each
//! linked to the component of `{depth ≥ k - 1}` that contains it.
//!
//! Built top-down in one pass with union–find (the sets only grow as `k`
//! falls), so a pixel is visited once however many levels there are,
//! instead of labelling the whole image once per level.

/// No parent: a node of level 1.
pub const NO_PARENT: u32 = u32::MAX;

/// The components of `{depth ≥ k}` for `k = 1..=max depth`, as a tree.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ThresholdTree {
    /// Per node: its `k`.
    pub level: Vec<u8>,
    /// Per node: the node of level `k - 1` containing it, or [`NO_PARENT`].
    /// A parent's id is always greater than its children's.
    pub parent: Vec<u32>,
    /// Per node: its pixel count (all of `{depth ≥ k}` in the component).
    pub area: Vec<u32>,
    /// Per pixel: 1 + the node of level `depth` containing it (0 where depth is 0).
    pub finest: Vec<u32>,
}

impl ThresholdTree {
    /// The ancestor-or-self of `node` at level `k` (`k` ≤ the node's level).
    pub fn ancestor_at(&self, mut node: u32, k: u8) -> u32 {
        while self.level[node as usize] > k {
            node = self.parent[node as usize];
        }
        node
    }
}

/// Builds the [`ThresholdTree`] of a `width`×`height` image of `depth`s.
///
/// ```
/// use nrgdb::imaging::threshold_tree;
/// // Two peaks of depth 2 on one plateau of depth 1.
/// let t = threshold_tree(&[1, 2, 1, 2, 1], 5, 1);
/// assert_eq!(t.level, vec![2, 2, 1]);
/// assert_eq!(t.parent[..2], [2, 2]);
/// assert_eq!(t.area, vec![1, 1, 5]);
/// ```
pub fn threshold_tree(depth: &[u8], width: u32, height: u32) -> ThresholdTree {
    let (w, h) = (width as usize, height as usize);
    let n = (w * h).min(depth.len());
    let max_k = depth[..n].iter().copied().max().unwrap_or(0) as usize;
    // Pixels by depth, raster order within a depth.
    let mut buckets = vec![Vec::new(); max_k + 1];
    for (p, &d) in depth[..n].iter().enumerate() {
        if d != 0 {
            buckets[d as usize].push(p as u32);
        }
    }
    let mut sets = vec![0u32; n];
    // Per union–find root: 1 + its node at the level being built (stale
    // entries point at a node of a deeper level).
    let mut tag = vec![0u32; n];
    let mut tree = ThresholdTree {
        level: Vec::new(),
        parent: Vec::new(),
        area: Vec::new(),
        finest: vec![0u32; n],
    };
    let mut rep: Vec<u32> = Vec::new();
    let mut deeper = 0..0;
    for k in (1..=max_k).rev() {
        let bucket = std::mem::take(&mut buckets[k]);
        for &p in &bucket {
            sets[p as usize] = p;
        }
        // A pixel joins its deeper neighbours and, of its neighbours at
        // this depth, those before it (the others join it in their turn).
        // The bucket is in raster order, so the row is tracked, not divided.
        let mut y = 0;
        for &p in &bucket {
            let p = p as usize;
            while p >= (y + 1) * w {
                y += 1;
            }
            let x = p - y * w;
            let (x0, x1) = (x.saturating_sub(1), (x + 1).min(w - 1));
            let (y0, y1) = (y.saturating_sub(1), (y + 1).min(h - 1));
            let mut root = find(&mut sets, p as u32);
            for yy in y0..=y1 {
                let first = yy * w + x0;
                for (q, &dq) in (first..).zip(&depth[first..=yy * w + x1]) {
                    let dq = dq as usize;
                    if dq > k || (dq == k && q < p) {
                        let other = find(&mut sets, q as u32);
                        if other != root {
                            // Union by index: the smaller root stays.
                            let (lo, hi) = (root.min(other), root.max(other));
                            sets[hi as usize] = lo;
                            root = lo;
                        }
                    }
                }
            }
        }
        let level_first = tree.level.len() as u32;
        let mut node_of = |root: u32, tree: &mut ThresholdTree, rep: &mut Vec<u32>| {
            let t = tag[root as usize];
            if t > level_first {
                return t - 1;
            }
            let id = tree.level.len() as u32;
            tree.level.push(k as u8);
            tree.parent.push(NO_PARENT);
            tree.area.push(0);
            rep.push(root);
            tag[root as usize] = id + 1;
            id
        };
        for child in deeper.clone() {
            let root = find(&mut sets, rep[child as usize]);
            let node = node_of(root, &mut tree, &mut rep);
            tree.parent[child as usize] = node;
        }
        for &p in &bucket {
            let root = find(&mut sets, p);
            let node = node_of(root, &mut tree, &mut rep);
            tree.finest[p as usize] = node + 1;
            tree.area[node as usize] += 1;
        }
        deeper = level_first..tree.level.len() as u32;
    }
    for node in 0..tree.level.len() {
        let parent = tree.parent[node];
        if parent != NO_PARENT {
            tree.area[parent as usize] += tree.area[node];
        }
    }
    tree
}

fn find(sets: &mut [u32], mut i: u32) -> u32 {
    while sets[i as usize] != i {
        let grand = sets[sets[i as usize] as usize];
        sets[i as usize] = grand;
        i = grand;
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::{Labels, Mask, label_components};

    /// Per pixel, the node of level `k` containing it, numbered by first
    /// appearance in raster order (0 outside `{depth ≥ k}`).
    fn level_partition(t: &ThresholdTree, depth: &[u8], k: u8, w: u32, h: u32) -> Labels {
        let data = depth
            .iter()
            .zip(&t.finest)
            .map(|(&d, &f)| {
                if d >= k {
                    t.ancestor_at(f - 1, k) + 1
                } else {
                    0
                }
            })
            .collect();
        let mut l = Labels {
            width: w,
            height: h,
            data,
            count: t.level.len() as u32 + 1,
        };
        l.compact();
        l
    }

    #[test]
    fn nested_rings() {
        // A depth-1 frame around two depth-2 blocks, one holding a depth-3 pixel.
        let depth = [
            1, 1, 1, 1, 1, 1, //
            1, 2, 0, 0, 2, 1, //
            1, 3, 0, 0, 2, 1, //
            1, 1, 1, 1, 1, 1, //
        ];
        let t = threshold_tree(&depth, 6, 4);
        assert_eq!(t.level, vec![3, 2, 2, 1]);
        assert_eq!(t.parent, vec![1, 3, 3, NO_PARENT]);
        assert_eq!(t.area, vec![1, 2, 2, 20]);
        assert_eq!(t.finest[2 * 6 + 1], 1);
        assert_eq!(t.finest[0], 4);
        assert_eq!(t.finest[6 + 2], 0);
    }

    #[test]
    fn diagonal_neighbours_join() {
        let t = threshold_tree(&[2, 0, 0, 2], 2, 2);
        assert_eq!((t.level, t.area), (vec![2, 1], vec![2, 2]));
    }

    #[test]
    fn every_level_agrees_with_label_components() {
        let mut seed = 3u64;
        for round in 0..60u32 {
            let (w, h) = (1 + round % 17, 1 + (round * 5) % 13);
            let depth: Vec<u8> = (0..w * h)
                .map(|_| {
                    seed = seed
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    ((seed >> 33) % 5) as u8
                })
                .collect();
            let t = threshold_tree(&depth, w, h);
            for k in 1..=4u8 {
                let m = Mask::from_fn(w, h, |x, y| {
                    image::Luma([if depth[(y * w + x) as usize] >= k {
                        255
                    } else {
                        0
                    }])
                });
                let want = label_components(&m, true);
                let got = level_partition(&t, &depth, k, w, h);
                assert_eq!(got.data, want.data, "{w}x{h} k={k}");
                let areas = want.areas();
                for (i, &l) in want.data.iter().enumerate() {
                    if l != 0 {
                        let node = t.ancestor_at(t.finest[i] - 1, k);
                        assert_eq!(t.area[node as usize] as usize, areas[l as usize]);
                    }
                }
            }
        }
    }
}
