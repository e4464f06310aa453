//! The width of a space with the clutter standing in it filled: what tells
//! a corridor from a room. The widest inscribed circle of the free pixels
//! shrinks around every desk, so furnished offices and labs looked long and
//! narrow and were called corridors (willow-full: 32 corridors, 20 of them
//! under 15 m²); with their holes filled they are as wide as their walls
//! make them (11 corridors, the corridor network).

use std::borrow::Cow;

use crate::imaging::{Labels, Mask, Run, distance_within_labels, label_runs, widest_within_labels};

/// The widest inscribed diameter (px) of each region `1..=regions` with
/// its holes filled (index 0 and labels above `regions`: 0). A hole is
/// what the region encloses that holds no other space: a desk cluster, a
/// shelf, a pillar. A hole holding another space (rooms inside a ring
/// corridor, a courtyard) stays outside, and so does a hole wider than
/// `max_hole` px (its widest inscribed diameter): a block of rooms the
/// sensor never entered, which a corridor runs round.
///
/// The unlabelled pixels are taken apart once into 4-connected pieces; a
/// piece is a hole of region `l` when every pixel beside it is `l` and it
/// does not reach the map's edge. The holes' widths
/// ([`distance_within_labels`] over their bounding box) and then every
/// region's filled width ([`widest_within_labels`] over the map) come from
/// one distance transform each.
pub(crate) fn filled_diameters(labels: &Labels, regions: u32, max_hole: f64) -> Vec<f64> {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let mut out = vec![0.0; labels.count as usize + 1];
    if w == 0 || h == 0 || labels.data.len() != w * h {
        return out;
    }
    let regions = regions.min(labels.count);
    let holes = holes(labels, regions);
    // The labels with the narrow holes given to their regions (a copy only
    // when there is a hole).
    let mut filled = Cow::Borrowed(labels.data.as_slice());
    if !holes.runs.is_empty() {
        // A hole w px wide has pixels (w + 1) / 2 from its edge.
        let radius = ((max_hole + 1.0) / 2.0) as f32;
        let wide = wide_holes(&holes, w, h, radius);
        for (run, &owner) in holes.runs.iter().zip(&holes.owner_of_run) {
            if !wide[run.label as usize] {
                let row = run.y as usize * w;
                filled.to_mut()[row + run.x0 as usize..row + run.x1 as usize].fill(owner);
            }
        }
    }
    let widest = widest_within_labels(&filled, w, h, regions);
    for l in 1..=regions as usize {
        out[l] = 2.0 * f64::from(widest[l]);
    }
    out
}

/// The holes of the regions `1..=regions`: the 4-connected pieces of
/// unlabelled pixels that stay off the map's edge with pixels of one such
/// region all round them.
struct Holes {
    /// The holes' runs, `label` numbering the piece of unlabelled pixels.
    runs: Vec<Run>,
    /// The region enclosing each run's hole.
    owner_of_run: Vec<u32>,
}

/// The [`Holes`] of `labels`' regions `1..=regions`.
fn holes(labels: &Labels, regions: u32) -> Holes {
    const MIXED: u32 = u32::MAX;
    let (w, h) = (labels.width as usize, labels.height as usize);
    let unlabelled = Mask::from_raw(
        labels.width,
        labels.height,
        labels
            .data
            .iter()
            .map(|&l| if l == 0 { 255 } else { 0 })
            .collect(),
    )
    .unwrap_or_else(|| Mask::new(labels.width, labels.height));
    let pieces = label_runs(&unlabelled, false);
    // The one label beside each piece (0: none yet, MIXED: several or the
    // map's edge).
    let mut beside = vec![0u32; pieces.count as usize + 1];
    for (piece, edge) in beside.iter_mut().zip(pieces.touches_border()) {
        if edge {
            *piece = MIXED;
        }
    }
    // Meeting label `l` (0: an unlabelled pixel, the same piece).
    let meet = |b: &mut u32, l: u32| {
        if l != 0 && *b != l {
            *b = if *b == 0 { l } else { MIXED };
        }
    };
    for run in &pieces.runs {
        let b = &mut beside[run.label as usize];
        if *b == MIXED {
            // Already no hole (the map's outside, most of all).
            continue;
        }
        let (y, x0, x1) = (run.y as usize, run.x0 as usize, run.x1 as usize);
        let row = &labels.data[y * w..(y + 1) * w];
        if x0 > 0 {
            meet(b, row[x0 - 1]);
        }
        if x1 < w {
            meet(b, row[x1]);
        }
        for near in [y.wrapping_sub(1), y + 1].into_iter().filter(|&r| r < h) {
            for &l in &labels.data[near * w + x0..near * w + x1] {
                meet(b, l);
            }
        }
    }
    let owner = |piece: u32| {
        let l = beside[piece as usize];
        (l != 0 && l != MIXED && l <= regions).then_some(l)
    };
    let (runs, owner_of_run) = pieces
        .runs
        .iter()
        .filter_map(|r| owner(r.label).map(|l| (*r, l)))
        .unzip();
    Holes { runs, owner_of_run }
}

/// Which pieces (by their number in `holes.runs`) are wider than a hole:
/// some pixel lies more than `radius` from everything but the holes of the
/// same region (the map's outside included), in a `w` × `h` map.
fn wide_holes(holes: &Holes, w: usize, h: usize, radius: f32) -> Vec<bool> {
    let pieces = holes.runs.iter().map(|r| r.label).max().unwrap_or(0);
    let mut wide = vec![false; pieces as usize + 1];
    // Only the holes' bounding box: every pixel outside it is no hole, as
    // the transform takes the outside of its image to be.
    let (mut x0, mut y0, mut x1, mut y1) = (w, h, 0, 0);
    for r in &holes.runs {
        (x0, y0) = (x0.min(r.x0 as usize), y0.min(r.y as usize));
        (x1, y1) = (x1.max(r.x1 as usize), y1.max(r.y as usize + 1));
    }
    let bw = x1.saturating_sub(x0);
    let bh = y1.saturating_sub(y0);
    let mut owners = vec![0u32; bw * bh];
    for (r, &owner) in holes.runs.iter().zip(&holes.owner_of_run) {
        let row = (r.y as usize - y0) * bw;
        owners[row + r.x0 as usize - x0..row + r.x1 as usize - x0].fill(owner);
    }
    let d = distance_within_labels(&owners, bw, bh);
    for r in &holes.runs {
        let row = (r.y as usize - y0) * bw;
        let part = &d[row + r.x0 as usize - x0..row + r.x1 as usize - x0];
        if part.iter().any(|&v| v > radius) {
            wide[r.label as usize] = true;
        }
    }
    wide
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::ascii_labels;

    #[test]
    fn clutter_inside_a_room_is_filled() {
        // A 9 × 9 room with a desk in the middle: as wide as its walls.
        let l = ascii_labels(&[
            "###########",
            "#aaaaaaaaa#",
            "#aaaaaaaaa#",
            "#aaaaaaaaa#",
            "#aaa###aaa#",
            "#aaa###aaa#",
            "#aaa###aaa#",
            "#aaaaaaaaa#",
            "#aaaaaaaaa#",
            "#aaaaaaaaa#",
            "###########",
        ]);
        // The desk's pixels count as the room's, the walls do not: the
        // widest circle is the room's (radius 5 to the walls' pixels;
        // without the desk filled, 3).
        let d = filled_diameters(&l, 2, 100.0);
        assert_eq!(d[1], 10.0, "{d:?}");
    }

    #[test]
    fn a_ring_corridor_keeps_the_rooms_it_encloses_outside() {
        // Corridor `a` runs round room `b`: the room is no clutter, so the
        // corridor stays one pixel wide, however big its ring.
        let l = ascii_labels(&[
            "#########",
            "#aaaaaaa#",
            "#a#####a#",
            "#a#bbb#a#",
            "#a#bbb#a#",
            "#a#bbb#a#",
            "#a#####a#",
            "#aaaaaaa#",
            "#########",
        ]);
        let d = filled_diameters(&l, 2, 100.0);
        assert_eq!(d[1], 2.0, "{d:?}");
        assert_eq!(d[2], 4.0, "{d:?}");
    }

    #[test]
    fn a_ring_corridor_round_a_block_never_entered_keeps_it_outside() {
        // Corridor `a` runs round a 5 × 5 block no space is in (rooms the
        // sensor never saw): clutter no wider than 3 px is filled, a wider
        // block stays outside and the corridor one pixel wide.
        let l = ascii_labels(&[
            "#########",
            "#aaaaaaa#",
            "#a#####a#",
            "#a#####a#",
            "#a#####a#",
            "#a#####a#",
            "#a#####a#",
            "#aaaaaaa#",
            "#########",
        ]);
        assert_eq!(filled_diameters(&l, 1, 3.0)[1], 2.0);
        assert_eq!(filled_diameters(&l, 1, 4.0)[1], 2.0);
        assert_eq!(filled_diameters(&l, 1, 5.0)[1], 8.0);
        assert_eq!(filled_diameters(&l, 1, 100.0)[1], 8.0);
    }

    #[test]
    fn holes_at_the_maps_edge_or_beside_a_door_stay_outside() {
        // Room `a` with a desk `#` in its middle and a notch `#` open to the
        // map's edge at the right; `b` (above `regions`, a door) touches the
        // second desk at the bottom.
        let l = ascii_labels(&[
            "aaaaaaaaa",
            "aaaaaaaaa",
            "aaa##aaa#",
            "aaa##aaa#",
            "aaaaaaaaa",
            "aa##aaaaa",
            "aa##bbaaa",
        ]);
        // Filled: the first desk only, so the room's width is that of the
        // room with the desk's four pixels given to it.
        let d = filled_diameters(&l, 1, 100.0);
        let mut filled = l.clone();
        for (x, y) in [(3, 2), (4, 2), (3, 3), (4, 3)] {
            filled.data[y * 9 + x] = 1;
        }
        // Its width, by the plain transform of that mask.
        let room = Mask::from_fn(9, 7, |x, y| {
            image::Luma([if filled.data[(y * 9 + x) as usize] == 1 {
                255
            } else {
                0
            }])
        });
        let want = 2.0
            * f64::from(crate::imaging::max_distance(
                &crate::imaging::distance_to_background(&room),
            ));
        assert_eq!(d[1], want, "{d:?}");
        assert_eq!(d[2], 0.0, "labels above `regions` are not measured");
        // Filling the notch and the desk beside the door too would widen
        // it, so the test tells the two apart.
        let mut all = filled.clone();
        for (x, y) in [(8, 2), (8, 3), (2, 5), (3, 5), (2, 6), (3, 6)] {
            all.data[y * 9 + x] = 1;
        }
        let wider = crate::imaging::distance_within_labels(&all.data, 9, 7);
        let wider = 2.0 * f64::from(wider.iter().copied().fold(0.0, f32::max));
        assert!(wider > want, "{wider} {want}");
    }
}
