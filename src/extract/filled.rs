//! The width of a space with the clutter standing in it filled: what tells
//! a corridor from a room. The widest inscribed circle of the free pixels
//! shrinks around every desk, so furnished offices and labs looked long and
//! narrow and were called corridors (willow-full: 32 corridors, 20 of them
//! under 15 m²); with their holes filled they are as wide as their walls
//! make them (11 corridors, the corridor network).

use crate::imaging::{Labels, Mask, distance_to_background, max_distance};

/// The widest inscribed diameter (px) of each region `1..=regions` with
/// its holes filled (index 0 and labels above `regions`: 0). A hole is
/// what the region encloses that holds no other space: a desk cluster, a
/// shelf, a pillar. A hole holding another space (rooms inside a ring
/// corridor, a courtyard) stays outside, and so does a hole wider than
/// `max_hole` px (its widest inscribed diameter): a block of rooms the
/// sensor never entered, which a corridor runs round.
pub(crate) fn filled_diameters(labels: &Labels, regions: u32, max_hole: f64) -> Vec<f64> {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let boxes = labels.bounding_boxes();
    let mut out = vec![0.0; labels.count as usize + 1];
    for l in 1..=regions.min(labels.count) {
        let b = boxes[l as usize];
        if b[0] > b[2] {
            continue;
        }
        // The box grown by one, so the outside surrounds the region.
        let (x0, y0) = (b[0] as i64 - 1, b[1] as i64 - 1);
        let (bw, bh) = ((b[2] - b[0] + 3) as usize, (b[3] - b[1] + 3) as usize);
        // The label at box pixel (x, y); None beyond the map.
        let label_at = |x: usize, y: usize| {
            let (gx, gy) = (x0 + x as i64, y0 + y as i64);
            (gx >= 0 && gy >= 0 && (gx as usize) < w && (gy as usize) < h)
                .then(|| labels.data[gy as usize * w + gx as usize])
        };
        // Outside: reached from the box's edge without crossing the region.
        let mut outside = vec![false; bw * bh];
        let mut stack: Vec<(usize, usize)> = Vec::new();
        for x in 0..bw {
            stack.push((x, 0));
            stack.push((x, bh - 1));
        }
        for y in 0..bh {
            stack.push((0, y));
            stack.push((bw - 1, y));
        }
        // A hole holding another space (a block of rooms inside a ring
        // corridor, a courtyard) is no clutter: outside too.
        for y in 0..bh {
            for x in 0..bw {
                if label_at(x, y).is_some_and(|m| m != 0 && m != l) {
                    stack.push((x, y));
                }
            }
        }
        flood(&mut stack, bw, bh, |i| {
            let enter = !outside[i] && label_at(i % bw, i / bw) != Some(l);
            outside[i] |= enter;
            enter
        });
        wide_holes_outside(
            &mut outside,
            bw,
            bh,
            |x, y| label_at(x, y) == Some(l),
            max_hole,
        );
        let mask = Mask::from_fn(bw as u32, bh as u32, |x, y| {
            image::Luma([if outside[y as usize * bw + x as usize] {
                0
            } else {
                255
            }])
        });
        let d = distance_to_background(&mask);
        out[l as usize] = 2.0 * f64::from(max_distance(&d));
    }
    out
}

/// Marks outside every hole (a 4-connected piece of the box that is
/// neither outside nor the region: `mine(x, y)`) wider than `max_hole` px.
fn wide_holes_outside(
    outside: &mut [bool],
    bw: usize,
    bh: usize,
    mine: impl Fn(usize, usize) -> bool,
    max_hole: f64,
) {
    let mut hole: Vec<bool> = (0..bw * bh)
        .map(|i| !outside[i] && !mine(i % bw, i / bw))
        .collect();
    if !hole.contains(&true) {
        return;
    }
    let mask = Mask::from_fn(bw as u32, bh as u32, |x, y| {
        image::Luma([if hole[y as usize * bw + x as usize] {
            255
        } else {
            0
        }])
    });
    let d = distance_to_background(&mask);
    // A hole w px wide has pixels (w + 1) / 2 from its edge.
    let radius = ((max_hole + 1.0) / 2.0) as f32;
    let mut stack: Vec<(usize, usize)> = (0..bw * bh)
        .filter(|&i| d[i] > radius)
        .map(|i| (i % bw, i / bw))
        .collect();
    flood(&mut stack, bw, bh, |i| {
        let enter = hole[i];
        hole[i] = false;
        outside[i] |= enter;
        enter
    });
}

/// A 4-connected flood over a `bw` × `bh` box from the pixels on `stack`:
/// `enter(i)` marks pixel `i` and says whether the flood goes on from it
/// (it must say no once a pixel is marked).
fn flood(
    stack: &mut Vec<(usize, usize)>,
    bw: usize,
    bh: usize,
    mut enter: impl FnMut(usize) -> bool,
) {
    while let Some((x, y)) = stack.pop() {
        if !enter(y * bw + x) {
            continue;
        }
        if x > 0 {
            stack.push((x - 1, y));
        }
        if x + 1 < bw {
            stack.push((x + 1, y));
        }
        if y > 0 {
            stack.push((x, y - 1));
        }
        if y + 1 < bh {
            stack.push((x, y + 1));
        }
    }
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
}
