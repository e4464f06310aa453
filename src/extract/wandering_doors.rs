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

use super::doors::Border;
use super::doorway::{DoorSpan, SpanLimits, Throat, border_frame, classifier, span, throat};
use crate::imaging::Labels;

/// Most places along one border where a throat is sought.
const MAX_PLACES: usize = 64;

/// Most throats tried as a door, shortest first.
const MAX_TRIES: usize = 6;

/// Cuts `door` as `label` into `out` at the first of its candidate
/// doorways along the border (shortest first) that parts its two regions,
/// moves the pixels on the wrong side of it, and returns its doorway line
/// (pixels); None, with `out` unchanged, when no candidate parts them.
/// `labels` are the regions before any door was cut (free = non-zero);
/// `walls` as for [`door_span`](super::doorway::door_span).
pub(super) fn cut_along(
    labels: &Labels,
    walls: Option<&[bool]>,
    out: &mut Labels,
    door: &Border,
    label: u32,
    limits: &SpanLimits,
) -> Option<[[f64; 2]; 2]> {
    let spans = spans_along(labels, walls, door, limits);
    if spans.is_empty() {
        return None;
    }
    let (a, b) = door.pair;
    let members: Vec<u32> = (0..out.data.len() as u32)
        .filter(|&j| {
            let l = out.data[j as usize];
            l == a || l == b
        })
        .collect();
    let mut scratch = vec![u32::MAX; out.data.len()];
    spans
        .iter()
        .find(|span| try_cut(out, door, span, label, &members, &mut scratch))
        .map(|span| span.line)
}

/// Candidate doorways along `door`'s border: a throat sought at places
/// along it (a search's width apart, each with the direction of the border
/// around it), shortest first, one per place.
fn spans_along(
    labels: &Labels,
    walls: Option<&[bool]>,
    door: &Border,
    limits: &SpanLimits,
) -> Vec<DoorSpan> {
    let w = labels.width as usize;
    let pixel = classifier(labels, walls);
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
            if places.len() >= MAX_PLACES {
                break;
            }
        }
    }
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
        let (c, _) = th.middle();
        if distinct.iter().all(|d| {
            let (e, _) = d.middle();
            (c[0] - e[0]).abs().max((c[1] - e[1]).abs()) >= spacing
        }) {
            distinct.push(th);
            if distinct.len() >= MAX_TRIES {
                break;
            }
        }
    }
    distinct.iter().map(|th| span(&pixel, th, limits)).collect()
}

/// Whether a door at `span` parts `door`'s two regions in `out` (whose
/// pixels are `members`); if so, cuts it as `label` and gives every piece
/// of the two regions left on either side the region most of it belongs
/// to. `scratch` (one entry per pixel, all `u32::MAX`) is left so.
fn try_cut(
    out: &mut Labels,
    door: &Border,
    span: &DoorSpan,
    label: u32,
    members: &[u32],
    scratch: &mut [u32],
) -> bool {
    const CUT: u32 = u32::MAX - 1;
    let (w, h) = (i64::from(out.width), i64::from(out.height));
    let (a, b) = door.pair;
    let [x0, y0, x1, y1] = span.bounds(0.0);
    let mut cut = Vec::new();
    for y in y0.max(0)..=y1.min(h - 1) {
        for x in x0.max(0)..=x1.min(w - 1) {
            let j = (y * w + x) as usize;
            let l = out.data[j];
            if (l == a || l == b) && span.covers(x, y) {
                cut.push(j as u32);
                scratch[j] = CUT;
            }
        }
    }
    // The pieces left: per piece, its pixels of `a` and of `b`.
    let mut pieces: Vec<[usize; 2]> = Vec::new();
    let mut queue = VecDeque::new();
    for &start in members {
        if scratch[start as usize] != u32::MAX {
            continue;
        }
        let piece = pieces.len() as u32;
        let mut count = [0usize; 2];
        scratch[start as usize] = piece;
        queue.push_back(start);
        while let Some(p) = queue.pop_front() {
            count[usize::from(out.data[p as usize] == b)] += 1;
            let (x, y) = (i64::from(p) % w, i64::from(p) / w);
            for (dx, dy) in [(-1, 0), (1, 0), (0, -1), (0, 1)] {
                let (nx, ny) = (x + dx, y + dy);
                if nx < 0 || ny < 0 || nx >= w || ny >= h {
                    continue;
                }
                let j = (ny * w + nx) as usize;
                let l = out.data[j];
                if (l == a || l == b) && scratch[j] == u32::MAX {
                    scratch[j] = piece;
                    queue.push_back(j as u32);
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
    let parts = matches!((home(0), home(1)), (Some(x), Some(y)) if x != y);
    if parts {
        for &p in members {
            let piece = scratch[p as usize];
            if let Some(count) = pieces.get(piece as usize) {
                out.data[p as usize] = if count[1] > count[0] { b } else { a };
            }
        }
        for &j in &cut {
            out.data[j as usize] = label;
        }
    }
    for &p in members {
        scratch[p as usize] = u32::MAX;
    }
    parts
}

#[cfg(test)]
mod tests {
    use super::super::doors::{borders, cut_doors};
    use super::*;

    #[test]
    fn a_border_that_wanders_from_its_doorway_gets_its_door_in_the_doorway() {
        // A 30 x 21 px map: a wall across row 10 with a 5 px gap at columns
        // 12..17. Region 1 is everything above the wall, the gap, and the
        // strip x < 8 below it; region 2 the rest below. Their border runs
        // down along x = 8 and along the gap's foot: its middle lies in open
        // space below the wall, far from the gap.
        let (w, h) = (30usize, 21usize);
        let mut data = vec![0u32; w * h];
        for y in 0..h {
            for x in 0..w {
                data[y * w + x] = match y {
                    10 if !(12..17).contains(&x) => 0,
                    0..=10 => 1,
                    _ if x < 8 => 1,
                    _ => 2,
                };
            }
        }
        let labels = Labels {
            width: w as u32,
            height: h as u32,
            data,
            count: 2,
        };
        let dist = vec![1.0f32; w * h];
        let found = borders(&labels, &dist, 5);
        assert_eq!(found.len(), 1, "one border");
        let limits = SpanLimits {
            max_width: 7.0,
            search: 2.0,
            min_depth: 1.0,
            max_depth: 3.0,
            slack: 1.0,
        };
        let (cut, lines) = cut_doors(&labels, None, &[&found[0]], &dist, &limits);
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
