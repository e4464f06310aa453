//! Doors at passage mouths: where two regions meet inside a passage of
//! even width (a short corridor into a room), the watershed border lies
//! wherever the two floods happened to meet, often mid-passage. A doorway
//! is where the passage opens into the wider space, so the passage is given
//! to the narrower region and the border moves to that mouth.

use std::collections::VecDeque;

use super::doors::Border;
use crate::imaging::{Labels, Mask, erode};

/// Where a passage around a door border is sought, in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PassageLimits {
    /// How far from the border the passage may run.
    pub window: usize,
    /// The disk that cannot enter the passage: its radius is half the
    /// border's width times `disk_slack`, plus `disk_margin`.
    pub disk_slack: f64,
    /// See `disk_slack`.
    pub disk_margin: f64,
}

/// For each border in `doors`, finds the passage it lies in: the pixels of
/// its two regions, within `limits.window` of the border, that a disk a
/// little wider than the border cannot reach (the free space opened by
/// that disk), 4-connected to the border. If the passage is bounded (it stays
/// inside the window) and opens into the wider region (`widest`, the
/// widest inscribed diameter of each region), its pixels in the wider
/// region go to the narrower one. Returns whether any label changed.
pub(crate) fn give_passages_to_narrow_side(
    labels: &mut Labels,
    dist: &[f32],
    doors: &[&Border],
    widest: &[f64],
    limits: &PassageLimits,
) -> bool {
    let mut changed = false;
    for door in doors {
        let (a, b) = door.pair;
        let (narrow, wide) = if widest[a as usize] <= widest[b as usize] {
            (a, b)
        } else {
            (b, a)
        };
        if let Some(passage) = passage(labels, dist, door, limits) {
            for p in passage {
                if labels.data[p] == wide {
                    labels.data[p] = narrow;
                    changed = true;
                }
            }
        }
    }
    changed
}

/// The passage pixels (image indices) around `door`'s border, or None if
/// the passage is unbounded within the window or does not open into both
/// regions.
fn passage(
    labels: &Labels,
    dist: &[f32],
    door: &Border,
    limits: &PassageLimits,
) -> Option<Vec<usize>> {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let (a, b) = door.pair;
    let window_px = limits.window;
    // Disk radius: a little over half the passage width.
    let r = (door.width_px / 2.0 * limits.disk_slack + limits.disk_margin) as f32;
    if !long_passage(labels, dist, door, r, window_px / 3) {
        return None;
    }
    let xs = door.pixels.iter().map(|&p| p as usize % w);
    let ys = door.pixels.iter().map(|&p| p as usize / w);
    let (x0, x1) = (xs.clone().min()?, xs.max()?);
    let (y0, y1) = (ys.clone().min()?, ys.max()?);
    let (x0, y0) = (x0.saturating_sub(window_px), y0.saturating_sub(window_px));
    let (x1, y1) = ((x1 + window_px + 1).min(w), (y1 + window_px + 1).min(h));
    let (ww, wh) = (x1 - x0, y1 - y0);
    let at = |x: usize, y: usize| (y0 + y) * w + x0 + x;
    // The opening of the free space by the disk: pixels within r of a
    // pixel at least r from any obstacle, or of the window's edge (what
    // lies beyond it is not known here). Those are the pixels that the
    // erosion by r of the other pixels removes.
    let mut not_centre = Vec::with_capacity(ww * wh);
    for y in y0..y1 {
        let (row, d) = (
            &labels.data[y * w + x0..y * w + x1],
            &dist[y * w + x0..y * w + x1],
        );
        not_centre.extend(row.iter().zip(d).map(
            |(&l, &d)| {
                if l != 0 && d >= r { 0u8 } else { 255 }
            },
        ));
    }
    let not_centre = Mask::from_raw(ww as u32, wh as u32, not_centre)?;
    let far = erode(&not_centre, f64::from(r));
    let opened = |x: usize, y: usize| far.as_raw()[y * ww + x] == 0;
    let mine = |i: usize| labels.data[i] == a || labels.data[i] == b;
    // The passage: unopened pixels of the two regions joined to the border.
    let mut seen = vec![false; ww * wh];
    let mut queue: VecDeque<(usize, usize)> = VecDeque::new();
    for &p in &door.pixels {
        let (x, y) = (p as usize % w - x0, p as usize / w - y0);
        if !opened(x, y) && !seen[y * ww + x] {
            seen[y * ww + x] = true;
            queue.push_back((x, y));
        }
    }
    let mut out = Vec::new();
    // Opened pixels of each region the passage touches.
    let (mut opens_a, mut opens_b) = (false, false);
    while let Some((x, y)) = queue.pop_front() {
        if x == 0 || y == 0 || x + 1 == ww || y + 1 == wh {
            return None;
        }
        out.push(at(x, y));
        for (nx, ny) in [(x - 1, y), (x + 1, y), (x, y - 1), (x, y + 1)] {
            let j = at(nx, ny);
            if !mine(j) {
                continue;
            }
            if opened(nx, ny) {
                opens_a |= labels.data[j] == a;
                opens_b |= labels.data[j] == b;
            } else if !seen[ny * ww + nx] {
                seen[ny * ww + nx] = true;
                queue.push_back((nx, ny));
            }
        }
    }
    (opens_a && opens_b).then_some(out)
}

/// Whether the passage through `door`'s border runs on for more than
/// `min_px` (counting both sides): walking both ways across the border from
/// its widest point, over labelled pixels no farther than `r` from an
/// obstacle. A doorway through a thin wall opens out within a few pixels
/// and is left as it is, which spares the opening of a window per door.
fn long_passage(labels: &Labels, dist: &[f32], door: &Border, r: f32, min_px: usize) -> bool {
    let w = labels.width as usize;
    let n = door.pixels.len() as f64;
    let xy = |p: u32| ((p as usize % w) as f64, (p as usize / w) as f64);
    let (mx, my) = door
        .pixels
        .iter()
        .map(|&p| xy(p))
        .fold((0.0, 0.0), |(sx, sy), (x, y)| (sx + x / n, sy + y / n));
    // The border's direction (principal axis); the walk goes across it.
    let (sxx, syy, sxy) =
        door.pixels
            .iter()
            .map(|&p| xy(p))
            .fold((0.0, 0.0, 0.0), |(a, b, c), (x, y)| {
                let (dx, dy) = (x - mx, y - my);
                (a + dx * dx, b + dy * dy, c + dx * dy)
            });
    let along = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    let (ux, uy) = (-along.sin(), along.cos());
    let Some(&start) = door
        .pixels
        .iter()
        .max_by(|&&p, &&q| dist[p as usize].total_cmp(&dist[q as usize]))
    else {
        return false;
    };
    let (x0, y0) = xy(start);
    let h = labels.height as f64;
    let walk = |sign: f64| {
        (1..=min_px)
            .take_while(|&k| {
                let (x, y) = (x0 + sign * ux * k as f64, y0 + sign * uy * k as f64);
                let (x, y) = (x.round(), y.round());
                if x < 0.0 || y < 0.0 || x >= w as f64 || y >= h {
                    return false;
                }
                let i = y as usize * w + x as usize;
                labels.data[i] != 0 && dist[i] <= r
            })
            .count()
    };
    walk(1.0) + walk(-1.0) >= min_px
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extract::doors::borders;
    use crate::imaging::distance_to_background;

    /// A 20 × 30 map, free where `free(x, y)` inside a one-pixel frame,
    /// labelled 1 above row `split` and 2 from it on; with its distances.
    fn two_regions(free: impl Fn(usize, usize) -> bool, split: usize) -> (Labels, Vec<f32>) {
        let (w, h) = (20usize, 30usize);
        let mask = Mask::from_fn(w as u32, h as u32, |x, y| {
            let f = free(x as usize, y as usize) && x > 0 && x < 19 && y > 0 && y < 29;
            image::Luma([if f { 255 } else { 0 }])
        });
        let dist = distance_to_background(&mask);
        let mut labels = Labels::new(w as u32, h as u32);
        for (i, l) in labels.data.iter_mut().enumerate() {
            if mask.as_raw()[i] != 0 {
                *l = if i / w < split { 1 } else { 2 };
            }
        }
        labels.count = 2;
        (labels, dist)
    }

    const LIMITS: PassageLimits = PassageLimits {
        window: 12,
        disk_slack: 1.15,
        disk_margin: 1.0,
    };

    #[test]
    fn a_door_mid_passage_moves_to_the_mouth_of_the_wider_room() {
        // A 4-px-wide passage (columns 8-11, rows 8-15) from a 7-px
        // corridor (rows 1-7, region 1) down into a 13-px room (rows 16-28,
        // region 2); the two regions meet mid-passage, at row 12.
        let (mut labels, dist) =
            two_regions(|x, y| !(8..16).contains(&y) || (8..12).contains(&x), 12);
        let all = borders(&labels, &dist, 2);
        assert_eq!(all.len(), 1);
        let widest = [0.0, 7.0, 13.0];
        assert!(give_passages_to_narrow_side(
            &mut labels,
            &dist,
            &[&all[0]],
            &widest,
            &LIMITS
        ));
        // The passage belongs to the corridor now; the border lies at the
        // room's edge.
        for y in 1..15 {
            assert_eq!(labels.data[y * 20 + 9], 1, "row {y}");
        }
        assert_eq!(labels.data[18 * 20 + 9], 2);
    }

    #[test]
    fn a_doorway_through_a_thin_wall_stays_put() {
        // Two rooms (rows 1-9 and 11-28) joined by a 4-px doorway through a
        // one-pixel wall at row 10: no passage to move the door along.
        let (mut labels, dist) = two_regions(|x, y| y != 10 || (8..12).contains(&x), 11);
        let all = borders(&labels, &dist, 2);
        let before = labels.clone();
        let widest = [0.0, 9.0, 18.0];
        assert!(!give_passages_to_narrow_side(
            &mut labels,
            &dist,
            &[&all[0]],
            &widest,
            &LIMITS
        ));
        assert_eq!(labels.data, before.data);
    }
}
