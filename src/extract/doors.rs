//! Doors: narrow borders between two basins become door spaces, each
//! spanning its doorway ([`door_span`]).

use std::collections::{BTreeMap, HashSet, VecDeque};

use super::chord_pixels::Pixel;
use super::doorway::{DoorSpan, SpanLimits, border_line, door_span};
use super::wandering_doors::{DoorToCut, Scratch, cut_along};
use crate::imaging::Labels;

/// One border between two regions.
#[derive(Debug, Clone)]
pub(crate) struct Border {
    /// The two regions, `a < b`.
    pub pair: (u32, u32),
    /// Widest passage across the border, in pixels.
    pub width_px: f64,
    /// Pixels on either side of the border.
    pub pixels: Vec<u32>,
    /// The widest inscribed diameter (px) of `pair.0` and of `pair.1`
    /// near the border (see `regions::measure_near`): how wide the spaces
    /// are where they meet. Infinite until measured.
    pub near_px: (f64, f64),
}

/// A 4-neighbour pair across a border: (pixel on one side, pixel on the
/// other, half the passage width there).
type Crossing = (u32, u32, f32);

/// Every border between two labels with its passage width (twice the
/// largest distance to an obstacle along it). Two regions may meet in
/// several places (a room with two doorways onto one corridor): each
/// separate stretch of border (pixels more than `join_px` apart) is a
/// border of its own.
pub(crate) fn borders(labels: &Labels, dist: &[f32], join_px: i64) -> Vec<Border> {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let d = &labels.data;
    // Per pair: (pixel on one side, pixel on the other, half width there).
    let mut crossings: BTreeMap<(u32, u32), Vec<Crossing>> = BTreeMap::new();
    let mut add = |i: usize, j: usize| {
        let (a, b) = (d[i], d[j]);
        if a == 0 || b == 0 || a == b {
            return;
        }
        crossings.entry((a.min(b), a.max(b))).or_default().push((
            i as u32,
            j as u32,
            dist[i].min(dist[j]),
        ));
    };
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if x + 1 < w {
                add(i, i + 1);
            }
            if y + 1 < h {
                add(i, i + w);
            }
        }
    }
    let mut out = Vec::new();
    for (pair, list) in crossings {
        for stretch in stretches(&list, w, join_px.max(1)) {
            let half = stretch.iter().map(|&k| list[k].2).fold(0.0f32, f32::max);
            out.push(Border {
                pair,
                width_px: 2.0 * f64::from(half),
                pixels: stretch
                    .iter()
                    .flat_map(|&k| [list[k].0, list[k].1])
                    .collect(),
                near_px: (f64::INFINITY, f64::INFINITY),
            });
        }
    }
    out
}

/// Groups crossings whose first pixels lie within `join_px` (Chebyshev) of each
/// other, transitively; returns index lists, in order of first crossing.
/// `list` is in raster order of first pixel (as [`borders`] makes it), so
/// each crossing is compared only with those after it up to `join_px`
/// rows down, and groups are joined by union-find.
fn stretches(list: &[Crossing], w: usize, join_px: i64) -> Vec<Vec<usize>> {
    let mut parent: Vec<usize> = (0..list.len()).collect();
    fn root(parent: &mut [usize], mut k: usize) -> usize {
        while parent[k] != k {
            parent[k] = parent[parent[k]];
            k = parent[k];
        }
        k
    }
    let xy = |k: usize| {
        let p = list[k].0 as i64;
        (p % w as i64, p / w as i64)
    };
    for k in 0..list.len() {
        let (x, y) = xy(k);
        for j in k + 1..list.len() {
            let (xj, yj) = xy(j);
            if yj > y + join_px {
                break;
            }
            if (xj - x).abs() <= join_px {
                let (a, b) = (root(&mut parent, k), root(&mut parent, j));
                if a != b {
                    parent[a.max(b)] = a.min(b);
                }
            }
        }
    }
    let mut group_of = vec![usize::MAX; list.len()];
    let mut out: Vec<Vec<usize>> = Vec::new();
    for k in 0..list.len() {
        let r = root(&mut parent, k);
        if group_of[r] == usize::MAX {
            group_of[r] = out.len();
            out.push(Vec::new());
        }
        out[group_of[r]].push(k);
    }
    out
}

/// Cuts a door space across each border in `doors`, labelled
/// `labels.count + 1 + k` for the k-th door; returns the new labels and
/// each door's doorway line (pixel coordinates).
///
/// Where the border crosses a bounded opening, the door's line is the
/// opening's narrowest chord ([`door_span`]) and the door is the opening
/// from one face of the wall to the other (its [`DoorSpan`]): the pixels
/// of its two regions there; the regions then settle on either side of it
/// ([`settle_sides`]). Where there is no opening narrower than
/// `limits.max_width` through the border's centre, the doorway is sought
/// along the whole border ([`cut_along`]); where none there parts the two
/// regions either (open space), the door
/// is the band within `limits.min_depth / 2` of the border and its line
/// the diameter of the widest circle on the border ([`border_line`];
/// `dist` is each pixel's distance to the nearest obstacle).
pub(crate) fn cut_doors(
    labels: &Labels,
    outside: Option<&[Pixel]>,
    doors: &[&Border],
    dist: &[f32],
    limits: &SpanLimits,
) -> (Labels, Vec<Option<[[f64; 2]; 2]>>) {
    let mut out = labels.clone();
    let mut lines = Vec::with_capacity(doors.len());
    let mut banded: Vec<(usize, &Border)> = Vec::new();
    let mut spanned: Vec<(u32, &Border, DoorSpan)> = Vec::new();
    for (k, door) in doors.iter().enumerate() {
        let label = labels.count + 1 + k as u32;
        match door_span(labels, outside, door.pair, &door.pixels, limits) {
            Some(span) => {
                fill_span(labels, &mut out, door, &span, label);
                lines.push(Some(span.line));
                spanned.push((label, door, span));
            }
            None => {
                banded.push((k, door));
                lines.push(None);
            }
        }
    }
    // Borders that cross no opening at their middle: the doorway may lie
    // elsewhere along them; else a band across the border.
    let mut scratch = Scratch::new(out.data.len());
    let pixels_of = region_pixels(
        labels,
        banded.iter().flat_map(|(_, d)| [d.pair.0, d.pair.1]),
    );
    let none: Vec<u32> = Vec::new();
    banded.retain(|&(k, door)| {
        let label = labels.count + 1 + k as u32;
        let of = |l: u32| pixels_of.get(&l).unwrap_or(&none).as_slice();
        let siblings: Vec<u32> = (0..doors.len())
            .filter(|&j| j != k && doors[j].pair == door.pair)
            .map(|j| labels.count + 1 + j as u32)
            .collect();
        let cut = DoorToCut {
            door,
            label,
            pixels: [of(door.pair.0), of(door.pair.1)],
            siblings: &siblings,
        };
        let line = cut_along(labels, outside, &mut out, &cut, limits, &mut scratch);
        let kept = line.is_none();
        lines[k] = line.or_else(|| border_line(labels, door.pair, &door.pixels, dist));
        kept
    });
    cut_bands(labels, &mut out, &banded, limits.min_depth);
    // Only once every door has its pixels: the regions settle around them.
    for (label, door, span) in &spanned {
        settle_sides(labels, &mut out, door, span, *label, limits.search + 2.0);
    }
    out.count = labels.count + doors.len() as u32;
    (out, lines)
}

/// The pixels of each label in `wanted` (one pass over the image).
fn region_pixels(labels: &Labels, wanted: impl Iterator<Item = u32>) -> BTreeMap<u32, Vec<u32>> {
    let mut out: BTreeMap<u32, Vec<u32>> = wanted.map(|l| (l, Vec::new())).collect();
    if out.is_empty() {
        return out;
    }
    for (i, &l) in labels.data.iter().enumerate() {
        if let Some(list) = out.get_mut(&l) {
            list.push(i as u32);
        }
    }
    out
}

/// Labels `label` the pixels of `door`'s two regions that `span` covers
/// and no other door has taken.
fn fill_span(labels: &Labels, out: &mut Labels, door: &Border, span: &DoorSpan, label: u32) {
    let (w, h) = (i64::from(labels.width), i64::from(labels.height));
    let (a, b) = door.pair;
    let [x0, y0, x1, y1] = span.bounds(0.0);
    for y in y0.max(0)..=y1.min(h - 1) {
        for x in x0.max(0)..=x1.min(w - 1) {
            let j = (y * w + x) as usize;
            let l = labels.data[j];
            if (l == a || l == b) && out.data[j] == l && span.covers(x, y) {
                out.data[j] = label;
            }
        }
    }
}

/// After the doors are cut: where `door`'s border lay beside its opening
/// (within `reach` of a face, between the jambs), its regions' pixels on
/// the wrong side of the door (`label`) change sides, so the regions meet
/// at the door; then any border pixel still touching the other region (a
/// border that strays out of the opening) joins the door, so it always
/// cuts the two regions apart.
fn settle_sides(
    labels: &Labels,
    out: &mut Labels,
    door: &Border,
    span: &DoorSpan,
    label: u32,
    reach: f64,
) {
    let (w, h) = (i64::from(labels.width), i64::from(labels.height));
    let (a, b) = door.pair;
    let [x0, y0, x1, y1] = span.bounds(reach);
    for y in y0.max(0)..=y1.min(h - 1) {
        for x in x0.max(0)..=x1.min(w - 1) {
            let j = (y * w + x) as usize;
            if out.data[j] != labels.data[j] {
                continue;
            }
            match (span.side(x, y, reach), labels.data[j]) {
                (Some(true), l) if l == a => out.data[j] = b,
                (Some(false), l) if l == b => out.data[j] = a,
                _ => {}
            }
        }
    }
    for &p in &door.pixels {
        let (x, y) = (i64::from(p) % w, i64::from(p) / w);
        let mine = out.data[p as usize];
        if mine != a && mine != b {
            continue;
        }
        let other = if mine == a { b } else { a };
        let touches = [(-1, 0), (1, 0), (0, -1), (0, 1)].iter().any(|(dx, dy)| {
            let (nx, ny) = (x + dx, y + dy);
            nx >= 0 && ny >= 0 && nx < w && ny < h && out.data[(ny * w + nx) as usize] == other
        });
        if touches {
            out.data[p as usize] = label;
        }
    }
}

/// The doors of `doors` (k-th door labelled `labels.count + 1 + k`) as
/// bands of thickness `depth_px` across their borders: each grows
/// breadth-first from its border pixels over the labelled pixels within
/// `depth_px / 2 - 0.5` of the border (Euclidean) that no door has taken,
/// so two doors side by side split the band between them. Only the band is
/// visited: a few thousand pixels, whatever the map's size.
fn cut_bands(labels: &Labels, out: &mut Labels, doors: &[(usize, &Border)], depth_px: f64) {
    let (w, h) = (labels.width as i64, labels.height as i64);
    let r = (depth_px / 2.0 - 0.5).max(0.0);
    let reach = r.floor() as i64;
    let mut band: HashSet<u32> = HashSet::new();
    for (_, door) in doors {
        for &p in &door.pixels {
            let (x, y) = (i64::from(p) % w, i64::from(p) / w);
            for dy in -reach..=reach {
                for dx in -reach..=reach {
                    let (nx, ny) = (x + dx, y + dy);
                    let inside = nx >= 0 && ny >= 0 && nx < w && ny < h;
                    if inside && ((dx * dx + dy * dy) as f64) <= r * r {
                        let j = (ny * w + nx) as u32;
                        let l = labels.data[j as usize];
                        if l != 0 && out.data[j as usize] == l {
                            band.insert(j);
                        }
                    }
                }
            }
        }
    }
    let mut queue: VecDeque<u32> = VecDeque::new();
    for (k, door) in doors {
        for &p in &door.pixels {
            if band.remove(&p) {
                out.data[p as usize] = labels.count + 1 + *k as u32;
                queue.push_back(p);
            }
        }
    }
    while let Some(p) = queue.pop_front() {
        let (x, y) = (i64::from(p) % w, i64::from(p) / w);
        for (dx, dy) in [(-1, 0), (1, 0), (0, -1), (0, 1)] {
            let (nx, ny) = (x + dx, y + dy);
            if nx < 0 || ny < 0 || nx >= w || ny >= h {
                continue;
            }
            let j = (ny * w + nx) as u32;
            if band.remove(&j) {
                out.data[j as usize] = out.data[p as usize];
                queue.push_back(j);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn border_width_and_door_cut() {
        // Two regions side by side, 3 rows tall, distance 1 at the middle row.
        let labels = Labels {
            width: 6,
            height: 3,
            data: vec![1, 1, 1, 2, 2, 2, 1, 1, 1, 2, 2, 2, 1, 1, 1, 2, 2, 2],
            count: 2,
        };
        let dist = vec![
            1.0f32, 1., 1., 1., 1., 1., 1., 2., 2., 2., 2., 1., 1., 1., 1., 1., 1., 1.,
        ];
        let b = borders(&labels, &dist, 2);
        assert_eq!(b.len(), 1);
        assert_eq!(b[0].pair, (1, 2));
        assert_eq!(b[0].width_px, 4.0);
        // Open space all round (no opening): a band two pixels thick.
        let limits = SpanLimits {
            max_width: 2.5,
            search: 1.0,
            min_depth: 2.0,
            max_depth: 4.0,
            slack: 1.0,
            noise_run: 2.0,
        };
        let (cut, lines) = cut_doors(&labels, None, &[&b[0]], &dist, &limits);
        assert_eq!(cut.count, 3);
        assert_eq!(cut.data[..6], [1, 1, 3, 3, 2, 2]);
        // Its line: the widest circle on the border (radius 2, row 1),
        // across it.
        let [p, q] = lines[0].unwrap();
        assert!(
            (p[1] - q[1]).abs() > 3.9 && (p[0] - q[0]).abs() < 1e-9,
            "{p:?} {q:?}"
        );
    }

    #[test]
    fn two_doorways_between_the_same_regions_are_two_borders() {
        // Region 1 above, 2 below, joined at columns 0-1 and 6-7 only.
        let labels = Labels {
            width: 8,
            height: 2,
            data: vec![1, 1, 1, 1, 1, 1, 1, 1, 2, 2, 0, 0, 0, 0, 2, 2],
            count: 2,
        };
        let b = borders(&labels, &[1.0; 16], 2);
        assert_eq!(b.len(), 2);
        assert!(b.iter().all(|b| b.pair == (1, 2) && b.pixels.len() == 4));
    }
}
