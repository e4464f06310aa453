//! Watershed segmentation of free space into basins (paper §4.3.2, Tab. 3),
//! with markers from the distance transform so corridors are not cut up.

use crate::imaging::{
    Labels, Mask, NO_PARENT, label_runs, max_distance, threshold_tree, watershed,
};

/// Basins of the free space: markers are the components of the places
/// farther than `core_px` from any obstacle (a passage narrower than
/// `2 core_px` separates two of them); the flood runs from the highest
/// distance down, so basin borders settle on the narrowest point of each
/// passage. Free pixels no basin reaches (narrow closets) become basins of
/// their own if they have at least `min_px` pixels.
pub(crate) fn segment_basins(
    clean: &Mask,
    reachable: &[bool],
    dist: &[f32],
    core_px: f64,
    min_px: usize,
    split_min_px: usize,
) -> Labels {
    let (w, h) = clean.dimensions();
    let max_d = max_distance(dist);
    let markers = split_markers(w, h, dist, max_d, core_px, split_min_px);
    let elevation: Vec<u16> = dist
        .iter()
        .map(|&d| ((max_d - d) * 4.0).clamp(0.0, 65535.0) as u16)
        .collect();
    let mut basins = watershed(&elevation, &markers, reachable);
    fill_unreached(&mut basins, reachable, min_px);
    basins
}

/// Markers: the 8-connected components of the places farther than
/// `core_px` from any obstacle, refined through rising distance levels
/// (×1.25 each): a marker whose pixels above the next level fall into two
/// or more components of at least `split_min_px` pixels is replaced by
/// those components. Rooms joined by a doorway wider than `2 core_px` split
/// this way, while a corridor, whose core thins out evenly, stays one
/// marker. Numbered 1..=n in raster order of their first pixel.
///
/// The components of all levels come from one [`threshold_tree`]; a marker
/// is a node of it, and its pixels are the node's.
fn split_markers(
    w: u32,
    h: u32,
    dist: &[f32],
    max_d: f32,
    core_px: f64,
    split_min_px: usize,
) -> Labels {
    // Level 0 is the core (d > core_px); levels 1.. the thresholds.
    let mut thresholds = Vec::new();
    let mut level = core_px.max(1.0) * 1.25;
    while level < f64::from(max_d) && thresholds.len() < usize::from(u8::MAX) - 1 {
        thresholds.push(level as f32);
        level *= 1.25;
    }
    // Depth: 0 outside the core, else 1 + the thresholds exceeded. Every
    // threshold is above `core_px`, so that is [d > core] + Σ [d > t]: a
    // few compare-and-add passes over cache-sized blocks, which vectorise.
    let mut depth = vec![0u8; dist.len()];
    for (dp, ds) in depth.chunks_mut(4096).zip(dist.chunks(4096)) {
        for (p, &d) in dp.iter_mut().zip(ds) {
            *p = u8::from(f64::from(d) > core_px);
        }
        for &t in &thresholds {
            for (p, &d) in dp.iter_mut().zip(ds) {
                *p += u8::from(d > t);
            }
        }
    }
    let tree = threshold_tree(&depth, w, h);
    drop(depth);
    let nodes = tree.level.len();
    let mut is_marker: Vec<bool> = tree.level.iter().map(|&k| k == 1).collect();
    // The marker holding `node`'s pixels, if any.
    let marker_of = |node: u32, is_marker: &[bool]| {
        let mut n = node;
        while !is_marker[n as usize] {
            n = tree.parent[n as usize];
            if n == NO_PARENT {
                return None;
            }
        }
        Some(n)
    };
    let max_k = tree.level.iter().copied().max().unwrap_or(0);
    let mut big_children = vec![Vec::new(); nodes];
    for k in 2..=max_k {
        let mut touched = Vec::new();
        for c in 0..nodes as u32 {
            if tree.level[c as usize] != k || (tree.area[c as usize] as usize) < split_min_px {
                continue;
            }
            if let Some(m) = marker_of(c, &is_marker) {
                if big_children[m as usize].is_empty() {
                    touched.push(m);
                }
                big_children[m as usize].push(c);
            }
        }
        for m in touched {
            let children = std::mem::take(&mut big_children[m as usize]);
            if children.len() >= 2 {
                is_marker[m as usize] = false;
                children.iter().for_each(|&c| is_marker[c as usize] = true);
            }
        }
    }
    // Final marker per node (parents have greater ids), then per pixel,
    // numbered by first appearance.
    let mut final_marker = vec![NO_PARENT; nodes];
    for node in (0..nodes).rev() {
        final_marker[node] = if is_marker[node] {
            node as u32
        } else {
            match tree.parent[node] {
                NO_PARENT => NO_PARENT,
                p => final_marker[p as usize],
            }
        };
    }
    let mut number = vec![0u32; nodes];
    let mut count = 0;
    let mut data = tree.finest;
    for l in &mut data {
        if *l == 0 {
            continue;
        }
        let m = final_marker[*l as usize - 1];
        *l = if m == NO_PARENT {
            0
        } else {
            let slot = &mut number[m as usize];
            if *slot == 0 {
                count += 1;
                *slot = count;
            }
            *slot
        };
    }
    Labels {
        width: w,
        height: h,
        data,
        count,
    }
}

/// Gives every 8-connected group of at least `min_px` reachable but
/// unlabelled pixels a new label (smaller groups stay unlabelled).
pub(crate) fn fill_unreached(basins: &mut Labels, reachable: &[bool], min_px: usize) {
    let (w, h) = (basins.width, basins.height);
    let rest_data = basins
        .data
        .iter()
        .zip(reachable)
        .map(|(&l, &r)| if l == 0 && r { 255 } else { 0 })
        .collect();
    let rest = Mask::from_raw(w, h, rest_data).unwrap_or_else(|| Mask::new(w, h));
    if rest.iter().all(|&p| p == 0) {
        return;
    }
    let extra = label_runs(&rest, true);
    let areas = extra.areas();
    // Kept groups numbered by first appearance (runs are in raster order).
    let mut number = vec![0u32; areas.len()];
    let mut kept = 0;
    for r in extra
        .runs
        .iter()
        .filter(|r| areas[r.label as usize] >= min_px)
    {
        let n = &mut number[r.label as usize];
        if *n == 0 {
            kept += 1;
            *n = kept;
        }
        let i = r.y as usize * w as usize;
        basins.data[i + r.x0 as usize..i + r.x1 as usize].fill(basins.count + *n);
    }
    basins.count += kept;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::{ascii_mask, distance_to_background, label_components};

    #[test]
    fn two_rooms_split_at_the_doorway() {
        let m = ascii_mask(
            "...............
             .######.######.
             .######.######.
             .#############.
             .######.######.
             .######.######.
             ...............",
        );
        let d = distance_to_background(&m);
        let reach: Vec<bool> = m.iter().map(|&p| p != 0).collect();
        let b = segment_basins(&m, &reach, &d, 1.5, 1, 1000);
        assert_eq!(b.count, 2);
        let w = 15;
        assert_ne!(b.data[2 * w + 3], b.data[2 * w + 11]);
        assert!(b.data.iter().zip(&reach).all(|(&l, &r)| (l != 0) == r));
    }

    /// The former implementation: one full-image labelling per level.
    fn reference_markers(
        dist: &[f32],
        w: u32,
        h: u32,
        core_px: f64,
        split_min_px: usize,
    ) -> Labels {
        let mask = |t: f64| {
            Mask::from_fn(w, h, |x, y| {
                image::Luma([if f64::from(dist[(y * w + x) as usize]) > t {
                    255
                } else {
                    0
                }])
            })
        };
        let mut markers = label_components(&mask(core_px), true);
        let max_d = f64::from(dist.iter().copied().fold(0.0f32, f32::max));
        let mut level = core_px.max(1.0) * 1.25;
        while level < max_d {
            let comps = label_components(&mask(f64::from(level as f32)), true);
            let n = comps.count as usize + 1;
            let mut areas = vec![0usize; n];
            let mut parent = vec![0u32; n];
            for (&c, &m) in comps.data.iter().zip(&markers.data) {
                if c != 0 {
                    areas[c as usize] += 1;
                    parent[c as usize] = m;
                }
            }
            let mut big_children = vec![0usize; markers.count as usize + 1];
            for c in 1..n {
                if areas[c] >= split_min_px && parent[c] != 0 {
                    big_children[parent[c] as usize] += 1;
                }
            }
            if big_children.iter().any(|&k| k >= 2) {
                let base = markers.count;
                for (m, &c) in markers.data.iter_mut().zip(&comps.data) {
                    if *m != 0 && big_children[*m as usize] >= 2 {
                        *m = if c != 0 && areas[c as usize] >= split_min_px {
                            base + c
                        } else {
                            0
                        };
                    }
                }
                markers.count = base + comps.count;
                markers.compact();
            }
            level *= 1.25;
        }
        markers
    }

    #[test]
    fn markers_agree_with_per_level_labelling() {
        let mut seed = 9u64;
        let mut rand = move || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            seed >> 33
        };
        let mut splits = 0;
        for round in 0..40u32 {
            let (w, h) = (20 + round % 41, 15 + (round * 7) % 37);
            // Rooms: random walls and pillars in an open floor.
            let walls: Vec<(u32, u32, bool)> = (0..3 + round % 5)
                .map(|_| (rand() as u32 % w, rand() as u32 % h, rand() % 2 == 0))
                .collect();
            let pillars: Vec<(u32, u32)> = (0..round % 7)
                .map(|_| (rand() as u32 % w, rand() as u32 % h))
                .collect();
            let m = Mask::from_fn(w, h, |x, y| {
                let wall = walls.iter().any(|&(wx, wy, vertical)| {
                    if vertical {
                        x == wx && y.abs_diff(wy) > 2
                    } else {
                        y == wy && x.abs_diff(wx) > 2
                    }
                });
                let pillar = pillars.contains(&(x, y));
                image::Luma([if wall || pillar { 0 } else { 255 }])
            });
            let d = distance_to_background(&m);
            let max_d = max_distance(&d);
            assert_eq!(max_d, d.iter().copied().fold(0.0f32, f32::max));
            for core in [0.0, 0.7, 1.0, 1.5, 2.5] {
                for split in [0, 1, 4, 12] {
                    let want = reference_markers(&d, w, h, core, split);
                    let got = split_markers(w, h, &d, max_d, core, split);
                    assert_eq!(got, want, "round {round} core {core} split {split}");
                    let cores = Mask::from_fn(w, h, |x, y| {
                        image::Luma([u8::from(f64::from(d[(y * w + x) as usize]) > core)])
                    });
                    splits += usize::from(label_components(&cores, true) != got);
                }
            }
        }
        assert!(splits > 50, "only {splits} cases split a marker");
    }

    #[test]
    fn unreached_groups_agree_with_the_painted_version() {
        let mut seed = 17u64;
        let mut rand = move |m: u64| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 33) % m
        };
        for round in 0..40u32 {
            let (w, h) = (2 + round % 19, 2 + (round * 5) % 17);
            let reach: Vec<bool> = (0..w * h).map(|_| rand(3) != 0).collect();
            let mut basins = Labels::new(w, h);
            for (b, &r) in basins.data.iter_mut().zip(&reach) {
                if r && rand(2) == 0 {
                    *b = 1 + rand(3) as u32;
                }
            }
            basins.count = 3;
            for min_px in [0, 1, 3, 8] {
                let mut ours = basins.clone();
                fill_unreached(&mut ours, &reach, min_px);
                // The former version: paint, drop small groups, compact, add.
                let rest = Mask::from_fn(w, h, |x, y| {
                    let i = (y * w + x) as usize;
                    image::Luma([u8::from(basins.data[i] == 0 && reach[i])])
                });
                let mut extra = label_components(&rest, true);
                let areas = extra.areas();
                extra.data.iter_mut().for_each(|e| {
                    if areas[*e as usize] < min_px {
                        *e = 0;
                    }
                });
                extra.compact();
                let mut theirs = basins.clone();
                for (b, &e) in theirs.data.iter_mut().zip(&extra.data) {
                    if e != 0 {
                        *b = theirs.count + e;
                    }
                }
                theirs.count += extra.count;
                assert_eq!(ours, theirs, "{w}x{h} min {min_px}");
            }
        }
    }
}
