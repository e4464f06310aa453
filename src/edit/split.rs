//! SPLIT: a space cut in two by a line, optionally with a doorway on it.
//!
//! The cut is exact: the line's two crossings of the outline are inserted
//! into the ring and the ring is walked from one to the other each way, so
//! the two pieces share the cut edge bit for bit (a route crosses it where
//! the boundary is open).

use geo::{Distance, Euclidean};

use super::shape::{
    cut_out, distance, door_width, finite, link, polygon, reanchored, rectangle, relength,
};
use super::{DOOR_DEPTH_M, EditError, Edited, NewDoor};
use crate::model::{
    ConnectionKind, Nrg, Point, Ring, Space, SpaceId, SpaceKind, point_in_ring, polygon_area,
    segment_distance,
};

/// Shortest split line, metres.
const MIN_LINE_M: f64 = 0.05;
/// Smallest piece a cut may leave, m².
const MIN_PIECE_M2: f64 = 0.01;
/// Farthest a split's door may lie from the line, metres.
const MAX_DOOR_OFF_M: f64 = 0.3;
/// Two spaces closer than this (metres) touch.
const TOUCH_M: f64 = 1e-6;
/// How far (metres) a split line may stop short of the outline at
/// either end: it is extended that far.
const END_SLACK_M: f64 = 1.0;
/// A point this close (metres) to an outline lies on it.
const CONTACT_M: f64 = 1e-7;

/// `id` cut along `line`; see [`super::Edit::Split`].
pub(super) fn split(
    nrg: &Nrg,
    id: SpaceId,
    line: [Point; 2],
    door: Option<NewDoor>,
    next_id: SpaceId,
) -> Result<Edited, EditError> {
    finite(&line, "a split line's end")?;
    let length = distance(line[0], line[1]);
    if length < MIN_LINE_M {
        return Err(EditError::LineTooShort { length_m: length });
    }
    let space = nrg.space(id).ok_or(EditError::UnknownSpace(id))?;
    if space.kind == SpaceKind::Door {
        return Err(EditError::DoorKind(space.label()));
    }
    let (first, second, cut) = cut_ring(space, line)?;
    let mut big = space.clone();
    big.polygon = first;
    let mut small = space.clone();
    small.polygon = second;
    small.id = next_id;
    small.name = None;
    for piece in [&mut big, &mut small] {
        piece.holes = space
            .holes
            .iter()
            .filter(|h| h.first().is_some_and(|p| point_in_ring(*p, &piece.polygon)))
            .cloned()
            .collect();
        piece.update_area();
        if piece.area_m2 < MIN_PIECE_M2 {
            return Err(EditError::Sliver {
                label: space.label(),
                area_m2: piece.area_m2,
            });
        }
    }
    if small.area_m2 > big.area_m2 {
        std::mem::swap(&mut big.polygon, &mut small.polygon);
        std::mem::swap(&mut big.holes, &mut small.holes);
        big.update_area();
        small.update_area();
    }
    let (mut big, mut small) = (reanchored(&big), reanchored(&small));
    let mut created = vec![small.id];
    let mut door_space = None;
    if let Some(d) = door {
        let made = lay_door(
            space,
            &big,
            &small,
            cut,
            d,
            SpaceId(next_id.0.saturating_add(1)),
        )?;
        big = made.0;
        small = made.1;
        created.push(made.2.id);
        door_space = Some(made.2);
    }

    let mut spaces: Vec<Space> = nrg
        .spaces()
        .iter()
        .filter(|s| s.id != id)
        .cloned()
        .collect();
    spaces.push(big.clone());
    spaces.push(small.clone());
    let mut connections = Vec::new();
    let (big_shape, small_shape) = (polygon(&big), polygon(&small));
    for c in nrg.connections() {
        let Some(other) = c.other(id) else {
            connections.push(c.clone());
            continue;
        };
        let Some(neighbour) = nrg.space(other) else {
            continue;
        };
        let touching = c.kind != ConnectionKind::Adjacent;
        let (big_contact, small_contact) = (contact(neighbour, &big), contact(neighbour, &small));
        let (to_big, to_small) = if touching && big_contact.max(small_contact) >= 2 {
            // Along a shared edge (two or more points in common), not
            // at a corner: the piece with the longer contact is nearer.
            let rank = |n: usize| if n >= 2 { -(n as f64) } else { f64::INFINITY };
            (rank(big_contact), rank(small_contact))
        } else {
            let shape = polygon(neighbour);
            (
                Euclidean.distance(&shape, &big_shape),
                Euclidean.distance(&shape, &small_shape),
            )
        };
        // A door joins one piece; anything else every piece it reaches
        // as closely as the nearest (a corridor along both).
        let both = neighbour.kind != SpaceKind::Door
            && if touching {
                big_contact >= 2 && small_contact >= 2
            } else {
                (to_big - to_small).abs() <= TOUCH_M
            };
        if both || to_big <= to_small {
            connections.push(crate::model::Connection {
                a: big.id,
                b: other,
                ..c.clone()
            });
        }
        if both || to_small < to_big {
            connections.push(crate::model::Connection {
                a: small.id,
                b: other,
                ..c.clone()
            });
        }
    }
    match &door_space {
        Some(door) => {
            spaces.push(door.clone());
            connections.push(link(&spaces, big.id, door.id, ConnectionKind::Door));
            connections.push(link(&spaces, door.id, small.id, ConnectionKind::Door));
            connections.push(link(&spaces, big.id, small.id, ConnectionKind::Adjacent));
        }
        None => connections.push(link(&spaces, big.id, small.id, ConnectionKind::Open)),
    }
    let connections = relength(&spaces, connections, &[big.id, small.id]);
    Ok(Edited {
        nrg: Nrg::new(spaces, connections)?,
        created,
        removed: vec![],
    })
}

/// The two rings `space`'s shell makes when cut along `line`, and the cut
/// (where the line enters and leaves).
fn cut_ring(space: &Space, line: [Point; 2]) -> Result<(Ring, Ring, [Point; 2]), EditError> {
    let ring = &space.polygon;
    let label = || space.label();
    // The line is read as drawn by hand: its ends may fall short of the
    // outline (inside the space, at most END_SLACK_M from where it
    // leaves); the cut is the piece of the extended line around the
    // drawn line's middle, between the crossings on either side of it.
    let length = distance(line[0], line[1]);
    let d = [
        (line[1][0] - line[0][0]) / length,
        (line[1][1] - line[0][1]) / length,
    ];
    let long = [
        [
            line[0][0] - d[0] * END_SLACK_M,
            line[0][1] - d[1] * END_SLACK_M,
        ],
        [
            line[1][0] + d[0] * END_SLACK_M,
            line[1][1] + d[1] * END_SLACK_M,
        ],
    ];
    let total = length + 2.0 * END_SLACK_M;
    let (start, end) = (END_SLACK_M / total, (END_SLACK_M + length) / total);
    let hits =
        crossings(ring, long).map_err(|()| EditError::LineAlongOutline { label: label() })?;
    let drawn = hits.iter().filter(|h| (start..=end).contains(&h.t)).count();
    let before = hits.iter().rev().find(|h| h.t < 0.5).copied();
    let after = hits.iter().find(|h| h.t > 0.5).copied();
    let middle = [
        (line[0][0] + line[1][0]) / 2.0,
        (line[0][1] + line[1][1]) / 2.0,
    ];
    let (Some(h0), Some(h1)) = (before, after) else {
        return Err(EditError::LineDoesNotCross {
            label: label(),
            crossings: drawn,
        });
    };
    // Crossings of the drawn line besides the cut's two: it would cut
    // the space more than once.
    let extra = hits
        .iter()
        .filter(|h| (start..=end).contains(&h.t) && h.t != h0.t && h.t != h1.t)
        .count();
    if !point_in_ring(middle, ring) {
        return Err(EditError::MiddleOutside {
            label: label(),
            x: middle[0],
            y: middle[1],
        });
    }
    if extra > 0 {
        return Err(EditError::LineDoesNotCross {
            label: label(),
            crossings: drawn,
        });
    }
    for hole in &space.holes {
        let inside = crossings(hole, [h0.point, h1.point])
            .map_err(|()| EditError::LineCrossesHole { label: label() })?;
        if !inside.is_empty() {
            return Err(EditError::LineCrossesHole { label: label() });
        }
    }
    let n = ring.len();
    // Walk from crossing `from` along the ring to crossing `to`.
    let walk = |from: &Hit, to: &Hit| -> Ring {
        let mut out = vec![from.point];
        let mut i = (from.edge + 1) % n;
        let stop = (to.edge + 1) % n;
        let mut steps = 0;
        loop {
            if i == stop && !(from.edge == to.edge && steps == 0 && from.along > to.along) {
                break;
            }
            out.push(ring[i]);
            i = (i + 1) % n;
            steps += 1;
            if steps > n {
                break;
            }
        }
        out.push(to.point);
        out.dedup();
        while out.len() > 1 && out.first() == out.last() {
            out.pop();
        }
        out
    };
    let mut a = walk(&h0, &h1);
    let mut b = walk(&h1, &h0);
    for r in [&mut a, &mut b] {
        if polygon_area(r) < 0.0 {
            r.reverse();
        }
    }
    Ok((a, b, [h0.point, h1.point]))
}

/// Where a line crosses a ring's edge.
#[derive(Debug, Clone, Copy)]
struct Hit {
    /// Position along the line (0 at its start, 1 at its end).
    t: f64,
    /// The ring edge crossed (from vertex `edge` to the next).
    edge: usize,
    /// Position along that edge.
    along: f64,
    /// The crossing point.
    point: Point,
}

/// The crossings of `line` with `ring`'s edges, in order along the line,
/// one per distinct point; `Err` when the line runs along an edge.
fn crossings(ring: &[Point], line: [Point; 2]) -> Result<Vec<Hit>, ()> {
    let [p, q] = line;
    let d = [q[0] - p[0], q[1] - p[1]];
    let mut hits = Vec::new();
    for i in 0..ring.len() {
        let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
        let e = [b[0] - a[0], b[1] - a[1]];
        let denom = d[0] * e[1] - d[1] * e[0];
        let ap = [a[0] - p[0], a[1] - p[1]];
        if denom.abs() < 1e-15 {
            // Parallel: collinear and overlapping means along the outline.
            let cross = ap[0] * d[1] - ap[1] * d[0];
            if cross.abs() < 1e-12 {
                let len2 = d[0] * d[0] + d[1] * d[1];
                let ta = (ap[0] * d[0] + ap[1] * d[1]) / len2;
                let tb = ((b[0] - p[0]) * d[0] + (b[1] - p[1]) * d[1]) / len2;
                if ta.max(tb) > 0.0 && ta.min(tb) < 1.0 {
                    return Err(());
                }
            }
            continue;
        }
        let t = (ap[0] * e[1] - ap[1] * e[0]) / denom;
        let u = (ap[0] * d[1] - ap[1] * d[0]) / denom;
        if (0.0..=1.0).contains(&t) && (0.0..1.0).contains(&u) {
            let point = if u == 0.0 {
                a
            } else {
                [p[0] + d[0] * t, p[1] + d[1] * t]
            };
            hits.push(Hit {
                t,
                edge: i,
                along: u,
                point,
            });
        }
    }
    hits.sort_by(|x, y| x.t.total_cmp(&y.t));
    hits.dedup_by(|x, y| (x.t - y.t).abs() < 1e-12);
    Ok(hits)
}

/// Lays `door` across the cut between the pieces: a rectangle
/// [`DOOR_DEPTH_M`] deep cut out of both, its doorway on the line.
fn lay_door(
    space: &Space,
    big: &Space,
    small: &Space,
    cut: [Point; 2],
    door: NewDoor,
    id: SpaceId,
) -> Result<(Space, Space, Space), EditError> {
    finite(&[door.at], "the door position")?;
    let width = door_width(door.width_m)?;
    let length = distance(cut[0], cut[1]);
    let t = [
        (cut[1][0] - cut[0][0]) / length,
        (cut[1][1] - cut[0][1]) / length,
    ];
    let along = (door.at[0] - cut[0][0]) * t[0] + (door.at[1] - cut[0][1]) * t[1];
    let off = ((door.at[0] - cut[0][0]) * -t[1] + (door.at[1] - cut[0][1]) * t[0]).abs();
    if off > MAX_DOOR_OFF_M || along < 0.0 || along > length {
        return Err(EditError::DoorOffLine {
            x: door.at[0],
            y: door.at[1],
            off_m: off.max(-along).max(along - length),
        });
    }
    if width > length {
        return Err(EditError::DoorWidth {
            width_m: width,
            min: super::MIN_DOOR_WIDTH_M,
            max: length,
        });
    }
    // A door near an end of the cut slides in until it fits.
    let along = along.clamp(width / 2.0, length - width / 2.0);
    let c = [cut[0][0] + t[0] * along, cut[0][1] + t[1] * along];
    let rect = rectangle(c, t, width, DOOR_DEPTH_M);
    let big = cut_out(big, &rect).map_err(|pieces| broken(space, pieces))?;
    let small = cut_out(small, &rect).map_err(|pieces| broken(space, pieces))?;
    let mut door_space = Space::new(id, SpaceKind::Door, c, open_rectangle(&rect));
    door_space.doorway = Some([
        [c[0] - t[0] * width / 2.0, c[1] - t[1] * width / 2.0],
        [c[0] + t[0] * width / 2.0, c[1] + t[1] * width / 2.0],
    ]);
    door_space.update_doorway();
    Ok((big, small, door_space))
}

/// A closed `geo` ring as an open counter-clockwise ring.
pub(super) fn open_rectangle(rect: &geo::Polygon) -> Ring {
    let mut ring: Ring = rect.exterior().coords().map(|c| [c.x, c.y]).collect();
    ring.pop();
    if polygon_area(&ring) < 0.0 {
        ring.reverse();
    }
    ring
}

/// The refusal of a cut that breaks `space` into `pieces`.
fn broken(space: &Space, pieces: usize) -> EditError {
    EditError::WouldBreak {
        label: space.label(),
        pieces,
    }
}

/// How many distinct points of `a`'s and `b`'s outlines lie on the other's
/// outline: two or more for spaces sharing an edge, one for spaces
/// touching at a corner.
fn contact(a: &Space, b: &Space) -> usize {
    let rings = |s: &Space| -> Vec<Ring> {
        std::iter::once(s.polygon.clone())
            .chain(s.holes.iter().cloned())
            .collect()
    };
    let (ra, rb) = (rings(a), rings(b));
    let on = |p: Point, rings: &[Ring]| {
        rings.iter().any(|r| {
            (0..r.len()).any(|i| segment_distance(p, r[i], r[(i + 1) % r.len()]) <= CONTACT_M)
        })
    };
    let mut points: Vec<Point> = ra
        .iter()
        .flatten()
        .filter(|p| on(**p, &rb))
        .chain(rb.iter().flatten().filter(|p| on(**p, &ra)))
        .copied()
        .collect();
    points.sort_by(|x, y| x[0].total_cmp(&y[0]).then(x[1].total_cmp(&y[1])));
    points.dedup_by(|x, y| (x[0] - y[0]).hypot(x[1] - y[1]) <= CONTACT_M);
    points.len()
}
