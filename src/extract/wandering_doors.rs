//! Doors whose border wanders away from their doorway. The border between
//! two regions usually crosses their doorway, and the doorway is sought
//! near the border's middle ([`door_span`](super::doorway::door_span)).
//! Where the floods met along a wall far from the jambs instead (a wide
//! opening at a room's corner), no opening crosses the border's middle and
//! the door would be a band along the whole border: a sliver metres long
//! beside a wall. Here the doorway's throat is sought along the whole
//! border, and a candidate is taken when a door there parts the two
//! regions: each keeps most of its pixels on a side of its own. Pixels on
//! the wrong side of the door then change sides, so the door is where the
//! two spaces meet.

use std::collections::VecDeque;

use super::chord_pixels::{Pixel, classifier, obstacle_in_regions};
use super::doors::Border;
use super::doorway::{DoorSpan, SpanLimits, Throat, border_frame, span, throat};
use crate::imaging::Labels;

/// Most places along one border where a throat is sought.
const MAX_PLACES: usize = 64;

/// Most throats tried as a door, shortest first.
const MAX_TRIES: usize = 6;

/// Per-pixel working memory of [`cut_along`], allocated once for all the
/// doors of a map: every entry is `FREE` between calls.
pub(super) struct Scratch {
    piece: Vec<u32>,
    touched: Vec<u32>,
}

const FREE: u32 = u32::MAX;
const CUT: u32 = u32::MAX - 1;

impl Scratch {
    /// For an image of `len` pixels.
    pub(super) fn new(len: usize) -> Scratch {
        Scratch {
            piece: vec![FREE; len],
            touched: Vec::new(),
        }
    }

    fn mark(&mut self, i: usize, value: u32) {
        self.piece[i] = value;
        self.touched.push(i as u32);
    }

    fn clear(&mut self) {
        for &i in &self.touched {
            self.piece[i as usize] = FREE;
        }
        self.touched.clear();
    }
}

/// One door to cut by [`cut_along`].
pub(super) struct DoorToCut<'a> {
    /// Its border.
    pub door: &'a Border,
    /// Its label.
    pub label: u32,
    /// The pixels of each of its two regions before any door was cut.
    pub pixels: [&'a [u32]; 2],
    /// The labels of the other doors between the same two regions: pixels
    /// changing sides may touch them (their regions settle round them).
    pub siblings: &'a [u32],
}

/// Cuts `cut.door` as `cut.label` into `out` at the first of its candidate
/// doorways along the border (shortest first) that parts its two regions,
/// moves the pixels on the wrong side of it, and returns its doorway line
/// (pixels); None, with `out` unchanged, when no candidate parts them.
/// `labels` are the regions before any door was cut (free = non-zero);
/// `outside` as for [`door_span`](super::doorway::door_span).
pub(super) fn cut_along(
    labels: &Labels,
    outside: Option<&[Pixel]>,
    out: &mut Labels,
    cut: &DoorToCut<'_>,
    limits: &SpanLimits,
    scratch: &mut Scratch,
) -> Option<[[f64; 2]; 2]> {
    spans_along(labels, outside, cut.door, limits)
        .iter()
        .find(|span| try_cut(out, cut, span, scratch))
        .map(|span| span.line)
}

/// Candidate doorways along `door`'s border: a throat sought at places
/// along it (a search's width apart, at most [`MAX_PLACES`] spread over
/// the border, each with the direction of the border around it), one per
/// opening, at most [`MAX_TRIES`], shortest first.
fn spans_along(
    labels: &Labels,
    outside: Option<&[Pixel]>,
    door: &Border,
    limits: &SpanLimits,
) -> Vec<DoorSpan> {
    let w = labels.width as usize;
    let pixel = classifier(labels, outside);
    let spacing = limits.search.max(2.0);
    let xy = |p: u32| ((p as usize % w) as f64, (p as usize / w) as f64);
    let apart = |p: (f64, f64), q: (f64, f64)| (p.0 - q.0).abs().max((p.1 - q.1).abs());
    let mut places: Vec<(f64, f64)> = Vec::new();
    for &p in &door.pixels {
        let q = xy(p);
        if labels.data.get(p as usize) == Some(&door.pair.0)
            && places.iter().all(|&c| apart(c, q) >= spacing)
        {
            places.push(q);
        }
    }
    // A very long border: places spread evenly over all of it.
    let step = places.len().div_ceil(MAX_PLACES).max(1);
    let places: Vec<(f64, f64)> = places.into_iter().step_by(step).collect();
    let mut throats: Vec<Throat> = places
        .iter()
        .filter_map(|&c| {
            let near: Vec<u32> = door
                .pixels
                .iter()
                .copied()
                .filter(|&p| apart(xy(p), c) <= 2.0 * spacing)
                .collect();
            let (centre, normal) = border_frame(labels, door.pair, &near)?;
            throat(&pixel, centre, normal, limits)
        })
        .collect();
    throats.sort_by(|x, y| x.length().total_cmp(&y.length()));
    // One throat per opening: places near each other find the same one.
    let mut distinct: Vec<Throat> = Vec::new();
    for th in throats {
        let c = th.middle();
        if distinct.iter().all(|d| {
            let e = d.middle();
            (c[0] - e[0]).abs().max((c[1] - e[1]).abs()) >= spacing
        }) {
            distinct.push(th);
            if distinct.len() >= MAX_TRIES {
                break;
            }
        }
    }
    let blocked = obstacle_in_regions(labels, outside);
    distinct
        .iter()
        .map(|th| span(&pixel, th, limits).clear_of(&blocked))
        .collect()
}

/// Whether a door at `span` parts `door`'s two regions in `out` (whose
/// pixels were `door.pixels`): the door's pixels touch a piece holding
/// most of each region, and the pixels that would change sides are fewer
/// than half the smaller region's and touch no other space, nor a door but
/// `door.siblings`. If so, cuts it as
/// `label` and gives every piece of the two regions left on either side
/// the region most of it belongs to.
fn try_cut(out: &mut Labels, door: &DoorToCut<'_>, span: &DoorSpan, scratch: &mut Scratch) -> bool {
    let parts = parts(out, door, span, scratch);
    if let Some((cut, moved)) = &parts {
        let (a, b) = door.door.pair;
        for &(p, to_b) in moved {
            out.data[p as usize] = if to_b { b } else { a };
        }
        for &j in cut {
            out.data[j as usize] = door.label;
        }
    }
    scratch.clear();
    parts.is_some()
}

/// The pixels a door at `span` takes and those that change sides (with
/// whether they go to `door.pair.1`), if the door parts the two regions
/// (see [`try_cut`]); `scratch` is left marked, for the caller to clear.
#[allow(clippy::type_complexity)]
fn parts(
    out: &Labels,
    door: &DoorToCut<'_>,
    span: &DoorSpan,
    scratch: &mut Scratch,
) -> Option<(Vec<u32>, Vec<(u32, bool)>)> {
    let (w, h) = (i64::from(out.width), i64::from(out.height));
    let (a, b) = door.door.pair;
    let mine = |l: u32| l == a || l == b;
    let neighbours = move |p: u32| {
        let (x, y) = (i64::from(p) % w, i64::from(p) / w);
        [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)]
            .into_iter()
            .filter_map(move |(dx, dy)| {
                let (nx, ny) = (x + dx, y + dy);
                (nx >= 0 && ny >= 0 && nx < w && ny < h).then_some((ny * w + nx) as u32)
            })
    };
    let [x0, y0, x1, y1] = span.bounds(0.0);
    let mut cut = Vec::new();
    for y in y0.max(0)..=y1.min(h - 1) {
        for x in x0.max(0)..=x1.min(w - 1) {
            let j = (y * w + x) as usize;
            if mine(out.data[j]) && span.covers(x, y) {
                cut.push(j as u32);
                scratch.mark(j, CUT);
            }
        }
    }
    if cut.is_empty() {
        return None;
    }
    // The pieces left: per piece, its pixels of `a` and of `b`.
    let mut pieces: Vec<[usize; 2]> = Vec::new();
    let mut queue = VecDeque::new();
    for &start in door.pixels.iter().flat_map(|p| p.iter()) {
        if !mine(out.data[start as usize]) || scratch.piece[start as usize] != FREE {
            continue;
        }
        let piece = pieces.len() as u32;
        let mut count = [0usize; 2];
        scratch.mark(start as usize, piece);
        queue.push_back(start);
        while let Some(p) = queue.pop_front() {
            count[usize::from(out.data[p as usize] == b)] += 1;
            for j in neighbours(p) {
                if mine(out.data[j as usize]) && scratch.piece[j as usize] == FREE {
                    scratch.mark(j as usize, piece);
                    queue.push_back(j);
                }
            }
        }
        pieces.push(count);
    }
    let total = pieces
        .iter()
        .fold([0usize; 2], |t, c| [t[0] + c[0], t[1] + c[1]]);
    let home = |side: usize| {
        (0..pieces.len())
            .max_by_key(|&k| pieces[k][side])
            .filter(|&k| 2 * pieces[k][side] > total[side] && pieces[k][side] > pieces[k][1 - side])
    };
    let (home_a, home_b) = (home(0)?, home(1)?);
    if home_a == home_b {
        return None;
    }
    // The door lies between the two: it touches both home pieces.
    let touches = |piece: usize| {
        cut.iter()
            .any(|&p| neighbours(p).any(|j| scratch.piece[j as usize] == piece as u32))
    };
    if !touches(home_a) || !touches(home_b) {
        return None;
    }
    let mut moved = Vec::new();
    for &p in &scratch.touched {
        let piece = scratch.piece[p as usize];
        let Some(count) = pieces.get(piece as usize) else {
            continue;
        };
        let to_b = count[1] > count[0];
        if (out.data[p as usize] == b) != to_b {
            moved.push((p, to_b));
        }
    }
    // A modest correction next to nothing else, not a region given away.
    let smaller = total[0].min(total[1]);
    let alone = moved.iter().all(|&(p, _)| {
        neighbours(p).all(|j| {
            let l = out.data[j as usize];
            l == 0 || mine(l) || scratch.piece[j as usize] == CUT || door.siblings.contains(&l)
        })
    });
    (2 * moved.len() < smaller && alone).then_some((cut, moved))
}

#[cfg(test)]
mod tests {
    use super::super::doors::{borders, cut_doors};
    use super::*;

    /// The test map: a wall across row 10 with a gap at columns 12..17;
    /// `label(x, y)` labels the free pixels.
    fn map(label: impl Fn(usize, usize) -> u32, count: u32) -> Labels {
        let (w, h) = (30usize, 21usize);
        let data = (0..w * h)
            .map(|i| {
                let (x, y) = (i % w, i / w);
                if y == 10 && !(12..17).contains(&x) {
                    0
                } else {
                    label(x, y)
                }
            })
            .collect();
        Labels {
            width: w as u32,
            height: h as u32,
            data,
            count,
        }
    }

    const LIMITS: SpanLimits = SpanLimits {
        max_width: 7.0,
        search: 2.0,
        min_depth: 1.0,
        max_depth: 3.0,
        slack: 1.0,
        noise_run: 2.0,
    };

    #[test]
    fn pixels_that_would_change_sides_next_to_a_third_space_stay() {
        // As below, but a third region (3) lies against the strip of
        // region 1 under the wall: moving the strip to region 2 would make
        // 2 meet 3 where the graph does not know it, so the door stays a
        // band along the border and no pixel changes region.
        let labels = map(
            |x, y| match (x, y) {
                (_, 0..=10) => 1,
                (0..3, _) => 3,
                (3..8, _) => 1,
                _ => 2,
            },
            3,
        );
        let dist = vec![1.0f32; labels.data.len()];
        let found: Vec<Border> = borders(&labels, &dist, 5)
            .into_iter()
            .filter(|b| b.pair == (1, 2))
            .collect();
        assert_eq!(found.len(), 1);
        let (cut, _) = cut_doors(&labels, None, &[&found[0]], &dist, &LIMITS);
        for (i, (&before, &after)) in labels.data.iter().zip(&cut.data).enumerate() {
            assert!(
                after == before || after == 4,
                "pixel {i}: {before} -> {after}"
            );
        }
        let strip_door = (11..21).any(|y| cut.data[y * 30 + 7] == 4);
        assert!(strip_door, "the door is the band along the border");
    }

    #[test]
    fn a_border_that_wanders_from_its_doorway_gets_its_door_in_the_doorway() {
        // A 30 x 21 px map: a wall across row 10 with a 5 px gap at columns
        // 12..17. Region 1 is everything above the wall, the gap, and the
        // strip x < 8 below it; region 2 the rest below. Their border runs
        // down along x = 8 and along the gap's foot: its middle lies in open
        // space below the wall, far from the gap.
        let w = 30usize;
        let labels = map(
            |x, y| match (x, y) {
                (_, 0..=10) => 1,
                (0..8, _) => 1,
                _ => 2,
            },
            2,
        );
        let dist = vec![1.0f32; labels.data.len()];
        let found = borders(&labels, &dist, 5);
        assert_eq!(found.len(), 1, "one border");
        let (cut, lines) = cut_doors(&labels, None, &[&found[0]], &dist, &LIMITS);
        let door = 3;
        // The door lies in the gap, across it.
        for (i, &l) in cut.data.iter().enumerate() {
            let (x, y) = (i % w, i / w);
            if l == door {
                assert!(
                    (12..17).contains(&x) && (9..=11).contains(&y),
                    "door pixel at ({x}, {y})"
                );
            }
        }
        assert!(cut.data.iter().filter(|&&l| l == door).count() >= 5);
        let [p, q] = lines[0].expect("a doorway line");
        assert!((p[1] - q[1]).abs() < 0.5, "across the gap: {p:?} {q:?}");
        assert!(
            ((p[0] - q[0]).abs() - 5.0).abs() < 0.5,
            "5 px wide: {p:?} {q:?}"
        );
        // Everything below the wall is region 2 now, everything above 1.
        for (i, &l) in cut.data.iter().enumerate() {
            let (x, y) = (i % w, i / w);
            if l != 0 && l != door && y != 10 {
                assert_eq!(l, if y > 10 { 2 } else { 1 }, "pixel ({x}, {y})");
            }
        }
    }
}
