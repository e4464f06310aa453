//! Door matching by doorway: which door of the new revision continues which
//! door of the old, whatever the doors' thickness.
//!
//! A door space is the strip the extractor cuts across a doorway,
//! `door_depth_m` thick: 0.1 m is two pixels at 0.05 m/px, and traced
//! through pixel centres its outline encloses almost no area. Two such
//! strips barely overlap once a map is re-recorded in another frame, so
//! polygon overlap (IoU), right for rooms, says nothing about doors. A door
//! is a transition, and what identifies it is what it joins and where:
//!
//! * its **doorway line** ([`doorway`](crate::model::doorway())): the line
//!   the extractor measured across the opening, else the midline, along
//!   the long side, of the door polygon's minimum-area rectangle, so a
//!   strip 1 or 6 pixels thick gives the same line;
//! * the **non-door spaces it opens onto** (its connections).
//!
//! Two doors are candidates for the same door when their doorway centres
//! lie at most [`MatchParams::door_shift_m`] apart (default 0.5 m: a door
//! may widen by up to a metre on one side, or be re-cut a few pixels away
//! after alignment, and still be the same door; moved along its wall by
//! more than half a metre, or to another wall, it is a different door),
//! or the shorter doorway's centre lies that near the longer doorway's
//! line (a doorway widened further on one side, as when the wall beside
//! it is taken down, is the same doorway, wider),
//! and they join the same spaces: every non-door space one opens onto
//! corresponds to one the other opens onto, and back. Spaces correspond
//! when the IoU matching (run first, on the non-door spaces only) pairs
//! them, or when the smaller lies at least `min_iou` of its area (or
//! 1 m²) inside the larger (a room split or merged around the door, or
//! one that took over the corridor piece beside it, is still the room the
//! door opens onto). Among the candidates the assignment is optimal
//! and one-to-one (Kuhn–Munkres on closeness, 1 − d / 2 `door_shift_m`),
//! as for the other spaces.
//!
//! Splits and merges use the same line: a door is a part of a space of
//! the other revision when at least `part_cover` of its doorway line lies
//! inside that space ([`line_share`]), the 1-D counterpart of the area
//! share used for rooms.

use std::collections::HashMap;

use super::overlaps::{DoorSide, Overlaps};
use super::params::MatchParams;
use crate::model::{Nrg, Point, Ring, SpaceKind, doorway, point_in_ring};

/// One entry per space of `nrg` (in its order): the door's side for
/// doors, None for every other kind.
pub(crate) fn door_sides(nrg: &Nrg) -> Vec<Option<DoorSide>> {
    let index: HashMap<_, usize> = nrg
        .spaces()
        .iter()
        .enumerate()
        .map(|(i, s)| (s.id, i))
        .collect();
    let mut sides: Vec<Option<DoorSide>> = nrg
        .spaces()
        .iter()
        .map(|s| {
            (s.kind == SpaceKind::Door).then(|| DoorSide {
                line: doorway(s).map(|d| d.line),
                neighbours: Vec::new(),
            })
        })
        .collect();
    for c in nrg.connections() {
        let (Some(&a), Some(&b)) = (index.get(&c.a), index.get(&c.b)) else {
            continue;
        };
        for (door, other) in [(a, b), (b, a)] {
            if sides[other].is_some() {
                continue;
            }
            if let Some(side) = sides[door].as_mut() {
                side.neighbours.push(other);
            }
        }
    }
    for side in sides.iter_mut().flatten() {
        side.neighbours.sort_unstable();
        side.neighbours.dedup();
    }
    sides
}

/// The share (0..1) of a line's length inside a polygon given as its
/// rings (exterior first, then holes; even-odd rule). A zero-length line
/// counts as its point: 1 inside, 0 outside.
///
/// The line is cut at every crossing with an edge of the rings; each piece
/// lies wholly inside or outside, which its midpoint tells.
pub(crate) fn line_share(line: [Point; 2], rings: &[Ring]) -> f64 {
    let [p, q] = line;
    let d = [q[0] - p[0], q[1] - p[1]];
    let len = d[0].hypot(d[1]);
    let inside = |x: Point| rings.iter().filter(|r| point_in_ring(x, r)).count() % 2 == 1;
    if len.is_nan() || len <= 0.0 {
        return if inside(p) { 1.0 } else { 0.0 };
    }
    let mut cuts = vec![0.0, 1.0];
    for ring in rings {
        let n = ring.len();
        for k in 0..n {
            let (a, b) = (ring[k], ring[(k + 1) % n]);
            let e = [b[0] - a[0], b[1] - a[1]];
            let denom = d[0] * e[1] - d[1] * e[0];
            if denom == 0.0 {
                continue; // parallel: pieces' midpoints decide
            }
            let w = [a[0] - p[0], a[1] - p[1]];
            let t = (w[0] * e[1] - w[1] * e[0]) / denom;
            let s = (w[0] * d[1] - w[1] * d[0]) / denom;
            if (0.0..=1.0).contains(&t) && (0.0..=1.0).contains(&s) {
                cuts.push(t);
            }
        }
    }
    cuts.sort_by(f64::total_cmp);
    let mut share = 0.0;
    for w in cuts.windows(2) {
        let (t0, t1) = (w[0], w[1]);
        if t1 <= t0 {
            continue;
        }
        let tm = (t0 + t1) / 2.0;
        if inside([p[0] + tm * d[0], p[1] + tm * d[1]]) {
            share += t1 - t0;
        }
    }
    share.clamp(0.0, 1.0)
}

/// Two spaces sharing at least this much floor (m²) correspond for door
/// matching even when it is under `min_iou` of the smaller: a room that
/// took over the corridor piece beside a door is still a space the door
/// opens onto.
const SHARED_FLOOR_M2: f64 = 1.0;

/// The candidate door pairs `(old index, new index, closeness)` given the
/// matching of the non-door spaces (`matched`: old index → new index).
pub(crate) fn door_candidates(
    ov: &Overlaps,
    matched: &HashMap<usize, usize>,
    params: &MatchParams,
) -> Vec<(usize, usize, f64)> {
    let inter: HashMap<(usize, usize), f64> = ov
        .pairs
        .iter()
        .map(|&(i, j, area)| ((i, j), area))
        .collect();
    let corresponds = |i: usize, j: usize| {
        if matched.get(&i) == Some(&j) {
            return true;
        }
        let smaller = ov.old_area[i].min(ov.new_area[j]);
        inter
            .get(&(i, j))
            .is_some_and(|&a| smaller > 0.0 && a >= (params.min_iou * smaller).min(SHARED_FLOOR_M2))
    };
    let mut out = Vec::new();
    let reach = params.door_shift_m;
    for (i, old) in ov.old_sides.iter().enumerate() {
        let Some(old) = old.as_ref() else {
            continue;
        };
        for (j, new) in ov.new_sides.iter().enumerate() {
            let Some((new, dist)) = new.as_ref().and_then(|s| Some((s, old.distance(s)?))) else {
                continue;
            };
            if dist.is_nan() || dist > reach {
                continue;
            }
            let joined = old
                .neighbours
                .iter()
                .all(|&n| new.neighbours.iter().any(|&m| corresponds(n, m)))
                && new
                    .neighbours
                    .iter()
                    .all(|&m| old.neighbours.iter().any(|&n| corresponds(n, m)));
            if joined {
                let closeness = if reach > 0.0 {
                    1.0 - dist / (2.0 * reach)
                } else {
                    1.0
                };
                out.push((i, j, closeness));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diff::{RigidTransform, match_spaces};
    use crate::model::{Connection, ConnectionKind, Space, SpaceId};

    fn rect(id: u32, kind: SpaceKind, x0: f64, y0: f64, x1: f64, y1: f64) -> Space {
        let poly = vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
        Space::new(SpaceId(id), kind, [(x0 + x1) / 2.0, (y0 + y1) / 2.0], poly)
    }

    /// A door with no area: the outline of a one-pixel line traced there
    /// and back through pixel centres, as the extractor makes it.
    fn line_door(id: u32, x: f64, y0: f64, y1: f64) -> Space {
        let poly = vec![[x, y0], [x, (y0 + y1) / 2.0], [x, y1], [x, (y0 + y1) / 2.0]];
        Space::new(SpaceId(id), SpaceKind::Door, [x, (y0 + y1) / 2.0], poly)
    }

    fn link(a: u32, b: u32) -> Connection {
        Connection {
            a: SpaceId(a),
            b: SpaceId(b),
            kind: ConnectionKind::Door,
            length_m: 1.0,
        }
    }

    /// Rooms 1 (0..5) and 2 (5..10) side by side, corridor 3 below both
    /// (y −2..0); door 4 in the wall between the rooms at y 1..1.9, door 5
    /// from room 1 to the corridor at x 1..1.9. Doors are lines.
    fn floor(door_4: Space, door_5: Space) -> Nrg {
        Nrg::new(
            vec![
                rect(1, SpaceKind::Room, 0.0, 0.0, 4.95, 4.0),
                rect(2, SpaceKind::Room, 5.05, 0.0, 10.0, 4.0),
                rect(3, SpaceKind::Corridor, 0.0, -2.0, 10.0, -0.1),
                door_4,
                door_5,
            ],
            vec![link(1, 4), link(2, 4), link(1, 5), link(3, 5)],
        )
        .unwrap()
    }

    /// A door onto the corridor: a horizontal line at y −0.05 from x0 to
    /// x1.
    fn corridor_door(id: u32, x0: f64, x1: f64) -> Space {
        let xm = (x0 + x1) / 2.0;
        let poly = vec![[x0, -0.05], [xm, -0.05], [x1, -0.05], [xm, -0.05]];
        Space::new(SpaceId(id), SpaceKind::Door, [xm, -0.05], poly)
    }

    fn pairs(old: &Nrg, new: &Nrg) -> Vec<(u32, u32)> {
        match_spaces(old, new, &MatchParams::default())
            .iter()
            .map(|m| (m.new.0, m.old.0))
            .collect()
    }

    #[test]
    fn thin_doors_shifted_and_turned_still_match() {
        let a = floor(line_door(4, 5.0, 1.0, 1.9), corridor_door(5, 1.0, 1.9));
        assert_eq!(a.space(SpaceId(4)).unwrap().area_m2, 0.0);
        // Re-recorded: doors re-cut 0.1 m away, everything turned 0.5° and
        // shifted 5 cm, as an alignment leaves it.
        let b = floor(line_door(4, 5.05, 1.05, 1.95), corridor_door(5, 1.1, 2.0));
        let b = RigidTransform::from_degrees(0.5, 0.05, -0.05)
            .apply_to_nrg(&b)
            .unwrap();
        assert_eq!(pairs(&a, &b), vec![(1, 1), (2, 2), (3, 3), (4, 4), (5, 5)]);
    }

    #[test]
    fn a_door_moved_to_another_wall_is_a_change() {
        let a = floor(line_door(4, 5.0, 1.0, 1.9), corridor_door(5, 1.0, 1.9));
        // Door 5 now leads from room 2 to the corridor, near the wall
        // between the rooms: 4.2 m away, and it joins another room.
        let (mut spaces, mut links) = a.clone().into_parts();
        spaces[4] = corridor_door(5, 5.3, 6.2);
        links.retain(|c| c.b != SpaceId(5));
        links.extend([link(2, 5), link(3, 5)]);
        let b = Nrg::new(spaces, links).unwrap();
        assert_eq!(pairs(&a, &b), vec![(1, 1), (2, 2), (3, 3), (4, 4)]);
    }

    #[test]
    fn a_near_door_onto_other_spaces_is_another_door() {
        // Door 4 (rooms 1–2, 0.5 m wide at the wall's foot) is walled up;
        // a door from room 2 to the corridor opens round the corner, its
        // centre 0.46 m away: close enough, but it joins other spaces.
        let a = floor(line_door(4, 5.0, 0.05, 0.55), corridor_door(5, 1.0, 1.9));
        let (mut spaces, mut links) = a.clone().into_parts();
        spaces[3] = corridor_door(4, 5.05, 5.55);
        links.retain(|c| c.b != SpaceId(4));
        links.extend([link(2, 4), link(3, 4)]);
        let b = Nrg::new(spaces, links).unwrap();
        let (old, new) = (door_sides(&a), door_sides(&b));
        let (co, cn) = (old[3].as_ref().unwrap(), new[3].as_ref().unwrap());
        let (co, cn) = (co.centre().unwrap(), cn.centre().unwrap());
        assert!((co[0] - cn[0]).hypot(co[1] - cn[1]) < 0.5);
        assert_eq!(pairs(&a, &b), vec![(1, 1), (2, 2), (3, 3), (5, 5)]);
    }

    #[test]
    fn a_door_moved_along_its_wall_beyond_the_shift_is_a_change() {
        let a = floor(line_door(4, 5.0, 1.0, 1.9), corridor_door(5, 1.0, 1.9));
        let b = floor(line_door(4, 5.0, 2.0, 2.9), corridor_door(5, 1.3, 2.2));
        // Door 4 moved by its width (1 m > 0.5 m), door 5 by 0.3 m.
        assert_eq!(pairs(&a, &b), vec![(1, 1), (2, 2), (3, 3), (5, 5)]);
    }

    #[test]
    fn a_doorway_widened_on_one_side_is_the_same_door() {
        let a = floor(line_door(4, 5.0, 2.0, 2.9), corridor_door(5, 1.0, 1.9));
        // The wall below door 4 is taken down to the floor's edge: its
        // centre moves 0.98 m, but its old line lies inside the new one.
        let b = floor(line_door(4, 5.0, 0.05, 2.9), corridor_door(5, 1.0, 1.9));
        assert_eq!(pairs(&a, &b), vec![(1, 1), (2, 2), (3, 3), (4, 4), (5, 5)]);
    }

    #[test]
    fn two_doors_in_one_wall_keep_their_order() {
        let two = |y0: f64, y1: f64| {
            Nrg::new(
                vec![
                    rect(1, SpaceKind::Room, 0.0, 0.0, 4.95, 4.0),
                    rect(2, SpaceKind::Room, 5.05, 0.0, 10.0, 4.0),
                    line_door(3, 5.0, y0, y0 + 0.3),
                    line_door(4, 5.0, y1, y1 + 0.3),
                ],
                vec![link(1, 3), link(2, 3), link(1, 4), link(2, 4)],
            )
            .unwrap()
        };
        // Two narrow doors 0.4 m apart, re-cut 0.1 m up: each could reach
        // both, the closest pairing wins.
        let (a, b) = (two(1.0, 1.4), two(1.1, 1.5));
        assert_eq!(pairs(&a, &b), vec![(1, 1), (2, 2), (3, 3), (4, 4)]);
    }

    #[test]
    fn doorway_line_share_inside_a_polygon() {
        let square: Ring = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let hole: Ring = vec![[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]];
        let rings = [square.clone(), hole];
        assert_eq!(
            line_share([[-1.0, 2.0], [3.0, 2.0]], std::slice::from_ref(&square)),
            0.75
        );
        // Through the hole: inside on [0, 1] and [3, 4] of [−1, 5].
        assert!((line_share([[-1.0, 2.0], [5.0, 2.0]], &rings) - 2.0 / 6.0).abs() < 1e-12);
        assert_eq!(line_share([[0.5, 0.5], [0.5, 0.5]], &rings), 1.0);
        assert_eq!(line_share([[2.0, 2.0], [2.0, 2.0]], &rings), 0.0);
        assert_eq!(line_share([[5.0, 0.0], [5.0, 4.0]], &[square]), 0.0);
    }
}
