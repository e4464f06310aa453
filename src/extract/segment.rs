//! Watershed segmentation of free space into basins (paper §4.3.2, Tab. 3),
//! with markers from the distance transform so corridors are not cut up.

use crate::imaging::{Labels, Mask, label_components, watershed};

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
    let cores_data = dist
        .iter()
        .map(|&d| if f64::from(d) > core_px { 255 } else { 0 })
        .collect();
    let cores = Mask::from_raw(w, h, cores_data).unwrap_or_else(|| Mask::new(w, h));
    let markers = split_markers(label_components(&cores, true), dist, core_px, split_min_px);
    let max_d = dist.iter().copied().fold(0.0f32, f32::max);
    let elevation: Vec<u16> = dist
        .iter()
        .map(|&d| ((max_d - d) * 4.0).clamp(0.0, 65535.0) as u16)
        .collect();
    let mut basins = watershed(&elevation, &markers, reachable);
    fill_unreached(&mut basins, reachable, min_px);
    basins
}

/// Refines markers through rising distance levels (×1.25 each): a marker
/// whose pixels above the next level fall into two or more components of at
/// least `split_min_px` pixels is replaced by those components. Rooms joined
/// by a doorway wider than `2 core_px` split this way, while a corridor,
/// whose core thins out evenly, stays one marker.
fn split_markers(mut markers: Labels, dist: &[f32], core_px: f64, split_min_px: usize) -> Labels {
    let (w, h) = (markers.width as usize, markers.height as usize);
    let max_d = f64::from(dist.iter().copied().fold(0.0f32, f32::max));
    let mut level = core_px.max(1.0) * 1.25;
    while level < max_d {
        let threshold = level as f32;
        let above_data = dist
            .iter()
            .map(|&d| if d > threshold { 255 } else { 0 })
            .collect();
        let above = Mask::from_raw(w as u32, h as u32, above_data)
            .unwrap_or_else(|| Mask::new(w as u32, h as u32));
        let comps = label_components(&above, true);
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
    let mut extra = label_components(&rest, true);
    let areas = extra.areas();
    extra.data.iter_mut().for_each(|e| {
        if areas[*e as usize] < min_px {
            *e = 0;
        }
    });
    extra.compact();
    for (b, &e) in basins.data.iter_mut().zip(&extra.data) {
        if e != 0 {
            *b = basins.count + e;
        }
    }
    basins.count += extra.count;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::{ascii_mask, distance_to_background};

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
}
