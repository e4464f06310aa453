//! Conflicts of simplified boundary arcs: where simplifying the arcs of
//! `boundaries.rs` changed the topology of the label tiling.
//!
//! Three exact tests in integer corner coordinates:
//! * two segments (of any arcs) cross, touch or overlap other than at a
//!   shared end point (an rstar index finds the candidate pairs);
//! * the arcs leave a junction in another cyclic order than before;
//! * a ring flips or loses its area, or a hole leaves its exterior or
//!   enters another hole of the same label.
//!
//! Each test returns the arcs to simplify again, less. The unsimplified
//! arcs pass all three, so lowering the tolerance always ends.

use std::collections::HashMap;

use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{AABB, RTree};

use super::boundaries::{Arc, RingArcs, ring_corners, twice_area};
use super::simplify::Corner;

type Segment = GeomWithData<Rectangle<Corner>, (u32, u32)>;

/// Marks `bad[k]` for every arc `k` with a segment that crosses, touches or
/// overlaps another segment. With `changed`, only pairs involving a
/// changed arc are tested (the others were fine before and did not move).
pub(crate) fn mark_crossings(geom: &[Vec<Corner>], changed: Option<&[bool]>, bad: &mut [bool]) {
    let segments: Vec<Segment> = geom
        .iter()
        .enumerate()
        .flat_map(|(k, pts)| {
            pts.windows(2).enumerate().map(move |(i, s)| {
                GeomWithData::new(Rectangle::from_corners(s[0], s[1]), (k as u32, i as u32))
            })
        })
        .collect();
    let seg = |d: (u32, u32)| {
        let p = &geom[d.0 as usize];
        (p[d.1 as usize], p[d.1 as usize + 1])
    };
    let tree = RTree::bulk_load(segments);
    let mut test = |a: (u32, u32), b: (u32, u32)| {
        if conflict(seg(a), seg(b)) {
            bad[a.0 as usize] = true;
            bad[b.0 as usize] = true;
        }
    };
    match changed {
        None => {
            for (a, b) in tree.intersection_candidates_with_other_tree(&tree) {
                if a.data < b.data {
                    test(a.data, b.data);
                }
            }
        }
        Some(changed) => {
            for (k, pts) in geom.iter().enumerate() {
                if !changed[k] {
                    continue;
                }
                for (i, s) in pts.windows(2).enumerate() {
                    let me = (k as u32, i as u32);
                    let env = AABB::from_corners(s[0], s[1]);
                    for other in tree.locate_in_envelope_intersecting(&env) {
                        let o = other.data;
                        // A pair of changed arcs is seen from both sides: once is enough.
                        if o != me && (!changed[o.0 as usize] || me < o) {
                            test(me, o);
                        }
                    }
                }
            }
        }
    }
}

fn orient(a: Corner, b: Corner, c: Corner) -> i64 {
    let (ux, uy) = (i64::from(b[0] - a[0]), i64::from(b[1] - a[1]));
    let (vx, vy) = (i64::from(c[0] - a[0]), i64::from(c[1] - a[1]));
    (ux * vy - uy * vx).signum()
}

/// `p`, collinear with `a`–`b`, lies on the closed segment.
fn within(a: Corner, b: Corner, p: Corner) -> bool {
    (a[0].min(b[0])..=a[0].max(b[0])).contains(&p[0])
        && (a[1].min(b[1])..=a[1].max(b[1])).contains(&p[1])
}

/// Whether two segments meet anywhere but at one shared end point.
pub(crate) fn conflict((a, b): (Corner, Corner), (c, d): (Corner, Corner)) -> bool {
    if a == b || c == d || (a == c && b == d) || (a == d && b == c) {
        return true;
    }
    let shared = if a == c || a == d {
        Some((a, b, if a == c { d } else { c }))
    } else if b == c || b == d {
        Some((b, a, if b == c { d } else { c }))
    } else {
        None
    };
    if let Some((p, u, v)) = shared {
        // Only a fold back along the same line meets beyond p.
        let dot = i64::from(u[0] - p[0]) * i64::from(v[0] - p[0])
            + i64::from(u[1] - p[1]) * i64::from(v[1] - p[1]);
        return orient(p, u, v) == 0 && dot > 0;
    }
    let (o1, o2) = (orient(a, b, c), orient(a, b, d));
    let (o3, o4) = (orient(c, d, a), orient(c, d, b));
    if o1 * o2 < 0 && o3 * o4 < 0 {
        return true;
    }
    (o1 == 0 && within(a, b, c))
        || (o2 == 0 && within(a, b, d))
        || (o3 == 0 && within(c, d, a))
        || (o4 == 0 && within(c, d, b))
}

/// An arc end at a junction: the arc, and its first step from the junction.
#[derive(Clone, Copy)]
struct End {
    arc: usize,
    at_start: bool,
    step: Corner,
}

/// The arc ends at each junction, in the cyclic order of the unsimplified
/// arcs' first steps.
pub(crate) struct Junctions(Vec<Vec<End>>);

impl Junctions {
    pub(crate) fn new(arcs: &[Arc]) -> Junctions {
        let mut at: HashMap<Corner, Vec<End>> = HashMap::new();
        for (k, a) in arcs.iter().enumerate() {
            if !a.at_junctions || a.pts.len() < 2 {
                continue;
            }
            let (n, p) = (a.pts.len(), &a.pts);
            for (at_start, j, next) in [(true, p[0], p[1]), (false, p[n - 1], p[n - 2])] {
                at.entry(j).or_default().push(End {
                    arc: k,
                    at_start,
                    step: [next[0] - j[0], next[1] - j[1]],
                });
            }
        }
        let mut list: Vec<Vec<End>> = at.into_values().filter(|e| e.len() > 2).collect();
        for ends in &mut list {
            ends.sort_by(|x, y| angle(x.step).total_cmp(&angle(y.step)));
        }
        Junctions(list)
    }

    /// Marks the arcs of every junction whose simplified arcs leave it in
    /// another cyclic order (or two along the same line).
    pub(crate) fn mark_turned(&self, geom: &[Vec<Corner>], bad: &mut [bool]) {
        for ends in &self.0 {
            let steps: Vec<Corner> = ends
                .iter()
                .map(|e| {
                    let p = &geom[e.arc];
                    let (j, next) = if e.at_start {
                        (p[0], p[1])
                    } else {
                        (p[p.len() - 1], p[p.len() - 2])
                    };
                    [next[0] - j[0], next[1] - j[1]]
                })
                .collect();
            // Rank of each end in the new order; the old order is 0..n.
            let mut order: Vec<usize> = (0..ends.len()).collect();
            order.sort_by(|&x, &y| angle(steps[x]).total_cmp(&angle(steps[y])));
            let n = order.len();
            let rotated = (0..n).all(|i| (order[(i + 1) % n] + n - order[i]) % n == 1);
            let same_line = (0..n).any(|i| {
                let (u, v) = (steps[order[i]], steps[order[(i + 1) % n]]);
                orient([0, 0], u, v) == 0
                    && i64::from(u[0]) * i64::from(v[0]) + i64::from(u[1]) * i64::from(v[1]) > 0
            });
            if !rotated || same_line {
                for e in ends {
                    bad[e.arc] = true;
                }
            }
        }
    }
}

fn angle(v: Corner) -> f64 {
    f64::from(v[1]).atan2(f64::from(v[0]))
}

/// A label's rings split into its exterior and its holes (by the sign of
/// the unsimplified ring).
pub(crate) struct LabelRings {
    pub exterior: RingArcs,
    pub holes: Vec<RingArcs>,
}

/// Marks the arcs of rings that flipped or lost their area, and of holes
/// outside their exterior or inside another hole.
pub(crate) fn mark_bad_rings(
    labels: &[Option<LabelRings>],
    geom: &[Vec<Corner>],
    bad: &mut [bool],
) {
    let mark = |r: &RingArcs, bad: &mut [bool]| {
        for &(k, _) in &r.arcs {
            bad[k] = true;
        }
    };
    for l in labels.iter().flatten() {
        let ext = ring_corners(&l.exterior, geom);
        if ext.len() < 3 || twice_area(&ext) >= 0 {
            mark(&l.exterior, bad);
            continue;
        }
        let holes: Vec<Vec<Corner>> = l.holes.iter().map(|h| ring_corners(h, geom)).collect();
        let boxes: Vec<[i32; 4]> = holes.iter().map(|h| bbox(h)).collect();
        let ext_box = bbox(&ext);
        for (i, h) in holes.iter().enumerate() {
            let flipped = h.len() < 3 || twice_area(h) <= 0;
            let outside = !overlaps(ext_box, boxes[i]) || !inside(h[0], &ext);
            let nested = (0..holes.len()).any(|j| {
                j != i
                    && overlaps(boxes[i], boxes[j])
                    && holes[j].len() >= 3
                    && inside(h[0], &holes[j])
            });
            if flipped || outside || nested {
                mark(&l.holes[i], bad);
                mark(&l.exterior, bad);
            }
        }
    }
}

fn bbox(r: &[Corner]) -> [i32; 4] {
    r.iter()
        .fold([i32::MAX, i32::MAX, i32::MIN, i32::MIN], |b, p| {
            [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ]
        })
}

fn overlaps(a: [i32; 4], b: [i32; 4]) -> bool {
    a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3]
}

/// Even–odd test of corner `p` against a ring (p off the ring's edges).
fn inside(p: Corner, ring: &[Corner]) -> bool {
    let n = ring.len();
    let mut odd = false;
    for i in 0..n {
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        if (a[1] > p[1]) != (b[1] > p[1]) {
            // x of the edge at p's row, compared exactly: p.x < a.x + (p.y-a.y)(b.x-a.x)/(b.y-a.y).
            let lhs = i64::from(p[0] - a[0]) * i64::from(b[1] - a[1]);
            let rhs = i64::from(p[1] - a[1]) * i64::from(b[0] - a[0]);
            if (b[1] > a[1] && lhs < rhs) || (b[1] < a[1] && lhs > rhs) {
                odd = !odd;
            }
        }
    }
    odd
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segments_meeting_at_an_end_are_fine_unless_they_fold() {
        assert!(!conflict(([0, 0], [2, 0]), ([2, 0], [2, 2])));
        assert!(!conflict(([0, 0], [2, 0]), ([2, 0], [4, 0])));
        assert!(conflict(([0, 0], [2, 0]), ([2, 0], [1, 0])));
        assert!(conflict(([0, 0], [2, 0]), ([0, 0], [2, 0])));
    }

    #[test]
    fn crossing_and_touching_segments_conflict() {
        assert!(conflict(([0, 0], [2, 2]), ([0, 2], [2, 0])));
        assert!(conflict(([0, 0], [4, 0]), ([2, 0], [2, 3])));
        assert!(conflict(([0, 0], [4, 0]), ([1, 0], [3, 0])));
        assert!(!conflict(([0, 0], [4, 0]), ([0, 1], [4, 1])));
    }

    #[test]
    fn even_odd_inside() {
        let sq = [[0, 0], [4, 0], [4, 4], [0, 4]];
        assert!(inside([1, 1], &sq));
        assert!(!inside([5, 1], &sq));
        assert!(!inside([-1, 2], &sq));
    }
}
