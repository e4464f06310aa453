//! Narrow passages: a corridor stub or a strip corridor that opens into
//! wider space without narrowing first has no border of the watershed at
//! its mouth (the flood runs straight in), yet it is a space of its own
//! with a doorway where it opens out. Such passages become regions of their
//! own, so the door stage finds a border at each mouth.

use std::collections::VecDeque;

use super::doors::Border;
use super::interior::neighbours;
use crate::imaging::{Labels, Mask, dilate, label_runs};

/// What makes a narrow passage, in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct StubLimits {
    /// A passage is what a disk of this radius, inside free space, cannot
    /// reach (half the widest door).
    pub radius_px: f32,
    /// Narrowest passage (a door's minimum width).
    pub width_min_px: f32,
    /// Shortest passage: its area over its width.
    pub length_min_px: f32,
    /// `door_constriction`: a passage opens out where the region it opens
    /// into is wider than its width over this.
    pub constriction: f64,
}

/// Splits the narrow passages of `labels` off into regions of their own:
/// the 4-connected components of labelled pixels that a disk of
/// `radius_px` (at pixels at least that far from obstacles, `dist`) cannot
/// reach, at least `width_min_px` wide and `length_min_px` long, that open
/// onto reached pixels as a space of their own does (see [`openings_ok`];
/// `widest`: each region's widest inscribed diameter). Each label is then
/// split into its connected parts. Returns, per pixel, whether it lies in such a passage (empty if
/// none was found and nothing changed).
pub(crate) fn split_off_passages(
    labels: &mut Labels,
    dist: &[f32],
    widest: &[f64],
    limits: &StubLimits,
) -> Vec<bool> {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let r = limits.radius_px;
    if r <= 0.0 || w == 0 || h == 0 {
        return Vec::new();
    }
    // The disk reaches what is within r of a disk centre (beyond the
    // image's edge there is no centre): the centres dilated by r.
    let mask = |on: Vec<u8>| Mask::from_raw(labels.width, labels.height, on);
    let centres: Vec<u8> = (labels.data.iter().zip(dist))
        .map(|(&l, &d)| if l != 0 && d >= r { 255 } else { 0 })
        .collect();
    let Some(centres) = mask(centres) else {
        return Vec::new();
    };
    let reached = dilate(&centres, f64::from(r));
    let narrow: Vec<u8> = (labels.data.iter().zip(reached.as_raw()))
        .map(|(&l, &t)| if l != 0 && t == 0 { 255 } else { 0 })
        .collect();
    let Some(narrow) = mask(narrow) else {
        return Vec::new();
    };
    let parts = label_runs(&narrow, false);
    let narrow = narrow.as_raw();
    let n = parts.count as usize + 1;
    // Per part: area, widest half-width, and the reached pixels it opens
    // onto, as a bounding box per region.
    let mut area = vec![0usize; n];
    let mut half = vec![0f32; n];
    let mut mouths: Vec<Vec<(u32, [usize; 4])>> = vec![Vec::new(); n];
    for run in &parts.runs {
        let p = run.label as usize;
        let y = run.y as usize;
        for x in run.x0 as usize..run.x1 as usize {
            let i = y * w + x;
            area[p] += 1;
            half[p] = half[p].max(dist[i]);
            for j in neighbours(i, w, h) {
                let l = labels.data[j];
                if l == 0 || narrow[j] != 0 {
                    continue;
                }
                let (jx, jy) = (j % w, j / w);
                match mouths[p].iter_mut().find(|m| m.0 == l) {
                    Some((_, b)) => {
                        *b = [b[0].min(jx), b[1].min(jy), b[2].max(jx), b[3].max(jy)];
                    }
                    None => mouths[p].push((l, [jx, jy, jx, jy])),
                }
            }
        }
    }
    let keep: Vec<bool> = (0..n)
        .map(|p| {
            let width = 2.0 * half[p];
            let long = area[p] as f32 / width.max(1.0);
            let mouths_ok = openings_ok(&mouths[p], width, widest, limits.constriction);
            p > 0 && mouths_ok && width >= limits.width_min_px && long >= limits.length_min_px
        })
        .collect();
    if !keep.contains(&true) {
        return Vec::new();
    }
    let first_new = labels.count + 1;
    let mut in_passage = vec![false; w * h];
    // The regions that gave pixels to a passage: only they can fall apart.
    let mut cut = vec![false; first_new as usize];
    for run in parts.runs.iter().filter(|r| keep[r.label as usize]) {
        let row = run.y as usize * w;
        for i in row + run.x0 as usize..row + run.x1 as usize {
            cut[labels.data[i] as usize] = true;
            labels.data[i] = first_new + run.label;
            in_passage[i] = true;
        }
    }
    labels.count = first_new + parts.count;
    split_disconnected(labels, &cut);
    labels.compact();
    in_passage
}

/// Gives each 4-connected part but the first (in raster order) of every
/// label marked in `which` a new label of its own (labels past the end of
/// `which` are left alone).
pub(crate) fn split_disconnected(labels: &mut Labels, which: &[bool]) {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let marked = |l: u32| which.get(l as usize).copied().unwrap_or(false);
    let mut seen = vec![false; w * h];
    let mut first_part_done = vec![false; which.len()];
    let mut queue = VecDeque::new();
    for s in 0..w * h {
        let l = labels.data[s];
        if !marked(l) || seen[s] {
            continue;
        }
        let new = if first_part_done[l as usize] {
            labels.count += 1;
            labels.count
        } else {
            first_part_done[l as usize] = true;
            l
        };
        seen[s] = true;
        labels.data[s] = new;
        queue.push_back(s);
        while let Some(i) = queue.pop_front() {
            for j in neighbours(i, w, h) {
                if labels.data[j] == l && !seen[j] {
                    seen[j] = true;
                    labels.data[j] = new;
                    queue.push_back(j);
                }
            }
        }
    }
}

/// Per label of `labels`, whether most of its pixels are in `in_passage`.
pub(crate) fn passage_labels(labels: &Labels, in_passage: &[bool]) -> Vec<bool> {
    let mut count = vec![(0usize, 0usize); labels.count as usize + 1];
    for (&l, &m) in labels.data.iter().zip(in_passage) {
        let c = &mut count[l as usize];
        c.0 += usize::from(m);
        c.1 += 1;
    }
    count
        .iter()
        .enumerate()
        .map(|(l, c)| l > 0 && 2 * c.0 > c.1)
        .collect()
}

/// The width (px) a border is measured against: the narrower region's
/// widest inscribed diameter near the border (`Border::near_px`, where
/// measured; else anywhere in the region, `widest`), but where one side is
/// a passage (`is_passage`), the other side's: a passage's mouth is judged
/// by the space it opens into.
pub(crate) fn compared_width(b: &Border, widest: &[f64], is_passage: &[bool]) -> f64 {
    let (a, c) = (b.pair.0 as usize, b.pair.1 as usize);
    let widths = (widest[a].min(b.near_px.0), widest[c].min(b.near_px.1));
    match (is_passage[a], is_passage[c]) {
        (true, false) => widths.1,
        (false, true) => widths.0,
        _ => widths.0.min(widths.1),
    }
}

/// Whether a passage `width_px` wide, touching reached pixels of regions in
/// the boxes `mouths` (one per region), opens out like a space of its own:
/// the boxes, joined where they touch, make one or two openings, each no
/// wider than about twice the passage (a region reached through two
/// openings has a box spanning both: the passage is an aisle beside it),
/// and each opens into a region the passage is a constriction of.
fn openings_ok(
    mouths: &[(u32, [usize; 4])],
    width_px: f32,
    widest: &[f64],
    constriction: f64,
) -> bool {
    // Openings: (box, widest region reached through it).
    let mut openings: Vec<([usize; 4], f64)> = Vec::new();
    for &(l, b) in mouths {
        let wide = widest[l as usize];
        let touching = openings.iter().position(|(o, _)| {
            b[0] <= o[2] + 2 && o[0] <= b[2] + 2 && b[1] <= o[3] + 2 && o[1] <= b[3] + 2
        });
        match touching {
            Some(k) => {
                let (o, w) = &mut openings[k];
                *o = [
                    o[0].min(b[0]),
                    o[1].min(b[1]),
                    o[2].max(b[2]),
                    o[3].max(b[3]),
                ];
                *w = w.max(wide);
            }
            None => openings.push((b, wide)),
        }
    }
    let single = |o: &[usize; 4]| {
        let (dx, dy) = ((o[2] - o[0]) as f32, (o[3] - o[1]) as f32);
        (dx * dx + dy * dy).sqrt() <= 2.0 * width_px + 2.0
    };
    (1..=2).contains(&openings.len())
        && openings
            .iter()
            .all(|(o, wide)| single(o) && f64::from(width_px) <= constriction * wide)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::distance_to_background;

    const LIMITS: StubLimits = StubLimits {
        radius_px: 5.0,
        width_min_px: 2.0,
        length_min_px: 8.0,
        constriction: 0.7,
    };

    /// A `w` × `h` map, free where `free(x, y)`, all free pixels labelled
    /// 1; with its distances and widest diameters.
    fn one_region(w: u32, h: u32, free: impl Fn(u32, u32) -> bool) -> (Labels, Vec<f32>, Vec<f64>) {
        let mask = Mask::from_fn(w, h, |x, y| image::Luma([if free(x, y) { 255 } else { 0 }]));
        let dist = distance_to_background(&mask);
        let mut labels = Labels::new(w, h);
        for (l, &m) in labels.data.iter_mut().zip(mask.as_raw()) {
            *l = u32::from(m != 0);
        }
        labels.count = 1;
        let widest = vec![0.0, 2.0 * f64::from(crate::imaging::max_distance(&dist))];
        (labels, dist, widest)
    }

    /// A 38 × 24 room (rows 1-24) with a 6-px stub `len` rows long going
    /// down from its floor at columns 10-15.
    fn room_with_stub(len: u32) -> (Labels, Vec<f32>, Vec<f64>) {
        one_region(40, 26 + len, move |x, y| {
            (1..39).contains(&x) && (1..25).contains(&y)
                || (10..16).contains(&x) && (25..25 + len).contains(&y)
        })
    }

    #[test]
    fn a_long_stub_becomes_a_region_of_its_own() {
        let (mut labels, dist, widest) = room_with_stub(14);
        let in_passage = split_off_passages(&mut labels, &dist, &widest, &LIMITS);
        assert_eq!(labels.count, 2);
        let at = |x: usize, y: usize| labels.data[y * 40 + x];
        assert_ne!(at(12, 35), at(20, 10));
        assert_eq!(at(12, 35), at(12, 28));
        assert!(in_passage[35 * 40 + 12] && !in_passage[10 * 40 + 20]);
        assert!(passage_labels(&labels, &in_passage)[at(12, 35) as usize]);
    }

    #[test]
    fn a_short_stub_stays_in_its_room() {
        let (mut labels, dist, widest) = room_with_stub(5);
        assert!(split_off_passages(&mut labels, &dist, &widest, &LIMITS).is_empty());
        assert_eq!(labels.count, 1);
    }

    #[test]
    fn an_aisle_open_at_both_ends_into_one_room_stays() {
        // A 58 × 58 room with a 30 × 14 block 5 px below its top wall: the
        // 5-px aisle above the block opens into the room at both ends.
        let (mut labels, dist, widest) = one_region(60, 60, |x, y| {
            (1..59).contains(&x)
                && (1..59).contains(&y)
                && !((15..45).contains(&x) && (6..20).contains(&y))
        });
        assert!(split_off_passages(&mut labels, &dist, &widest, &LIMITS).is_empty());
        assert_eq!(labels.count, 1);
    }

    #[test]
    fn disconnected_parts_of_a_label_get_labels_of_their_own() {
        let mut l = Labels {
            width: 5,
            height: 1,
            data: vec![1, 1, 0, 1, 2],
            count: 2,
        };
        // Only label 1 is looked at; its second part gets label 3.
        split_disconnected(&mut l, &[false, true]);
        assert_eq!(l.data, vec![1, 1, 0, 3, 2]);
        assert_eq!(l.count, 3);
    }

    #[test]
    fn a_passage_mouth_is_measured_against_the_space_it_opens_into() {
        let widest = [0.0, 10.0, 40.0, 30.0];
        let border = |pair, near_px| Border {
            pair,
            width_px: 5.0,
            pixels: Vec::new(),
            near_px,
        };
        let far = (f64::INFINITY, f64::INFINITY);
        assert_eq!(
            compared_width(&border((1, 2), far), &widest, &[false; 4]),
            10.0
        );
        assert_eq!(
            compared_width(&border((1, 2), far), &widest, &[false, true, false, false]),
            40.0
        );
        assert_eq!(
            compared_width(&border((2, 3), far), &widest, &[false, false, true, true]),
            30.0
        );
        // Near the border the hall is only 25 px wide: that counts.
        assert_eq!(
            compared_width(
                &border((1, 2), (12.0, 25.0)),
                &widest,
                &[false, true, false, false]
            ),
            25.0
        );
    }
}
