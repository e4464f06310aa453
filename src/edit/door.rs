//! ADD DOOR and REMOVE DOOR.

use geo::{Area, BooleanOps, BoundingRect, Intersects};

use super::shape::{
    cut_out, distance, door_width, finite, link, nearest_on_outline, polygon, rectangle, relength,
};
use super::split::open_rectangle;
use super::{DOOR_DEPTH_M, EditError, Edited, MAX_WALL_GAP_M};
use crate::model::{ConnectionKind, MIN_OVERLAP_M2, Nrg, Point, Space, SpaceId, SpaceKind};

/// Farthest the asked position may lie from the boundary, metres.
const MAX_OFF_BOUNDARY_M: f64 = 1.0;
/// A gap narrower than this (metres) is two spaces touching.
const TOUCHING_M: f64 = 0.01;

/// A door between `a` and `b` near `at`; see [`super::Edit::AddDoor`].
pub(super) fn add_door(
    nrg: &Nrg,
    a: SpaceId,
    b: SpaceId,
    at: Point,
    width_m: Option<f64>,
    id: SpaceId,
) -> Result<Edited, EditError> {
    finite(&[at], "the door position")?;
    let width = door_width(width_m)?;
    let sa = nrg.space(a).ok_or(EditError::UnknownSpace(a))?;
    let sb = nrg.space(b).ok_or(EditError::UnknownSpace(b))?;
    if a == b {
        return Err(EditError::BadDoorSides(format!(
            "both sides are {}",
            sa.label()
        )));
    }
    for s in [sa, sb] {
        if s.kind == SpaceKind::Door {
            return Err(EditError::BadDoorSides(format!("{} is a door", s.label())));
        }
    }
    let (ca, cb) = (nearest_on_outline(sa, at), nearest_on_outline(sb, at));
    let gap = distance(ca, cb);
    if gap > MAX_WALL_GAP_M {
        return Err(EditError::NotAdjacent {
            a: sa.label(),
            b: sb.label(),
            gap_m: gap,
            x: at[0],
            y: at[1],
            limit: MAX_WALL_GAP_M,
        });
    }
    let off = distance(at, ca).min(distance(at, cb));
    if off > MAX_OFF_BOUNDARY_M {
        return Err(EditError::FarFromBoundary {
            a: sa.label(),
            b: sb.label(),
            off_m: off,
            x: at[0],
            y: at[1],
        });
    }
    // Across the wall: from a's face to b's; along it: the tangent.
    let normal = if gap > TOUCHING_M {
        [(cb[0] - ca[0]) / gap, (cb[1] - ca[1]) / gap]
    } else {
        outline_normal(sa, ca)
    };
    let tangent = [-normal[1], normal[0]];
    let centre = [(ca[0] + cb[0]) / 2.0, (ca[1] + cb[1]) / 2.0];
    let rect = rectangle(centre, tangent, width, gap + DOOR_DEPTH_M);
    // The door lies between its two sides only.
    let bounds = rect.bounding_rect();
    for s in nrg.spaces().iter().filter(|s| s.id != a && s.id != b) {
        let shape = polygon(s);
        let near = match (shape.bounding_rect(), bounds) {
            (Some(x), Some(y)) => x.intersects(&y),
            _ => false,
        };
        if near && shape.intersection(&rect).unsigned_area() > MIN_OVERLAP_M2 {
            return Err(EditError::DoorOverlaps(s.label()));
        }
    }
    let new_a = cut_out(sa, &rect).map_err(|pieces| broken(sa, pieces))?;
    let new_b = cut_out(sb, &rect).map_err(|pieces| broken(sb, pieces))?;
    let mut door = Space::new(id, SpaceKind::Door, centre, open_rectangle(&rect));
    door.doorway = Some([
        [
            centre[0] - tangent[0] * width / 2.0,
            centre[1] - tangent[1] * width / 2.0,
        ],
        [
            centre[0] + tangent[0] * width / 2.0,
            centre[1] + tangent[1] * width / 2.0,
        ],
    ]);
    door.update_doorway();
    let mut spaces: Vec<Space> = nrg
        .spaces()
        .iter()
        .filter(|s| s.id != a && s.id != b)
        .cloned()
        .collect();
    spaces.extend([new_a, new_b, door]);
    let mut connections = nrg.connections().to_vec();
    connections.push(link(&spaces, a, id, ConnectionKind::Door));
    connections.push(link(&spaces, id, b, ConnectionKind::Door));
    if nrg.connection(a, b).is_none() {
        connections.push(link(&spaces, a, b, ConnectionKind::Adjacent));
    }
    let connections = relength(&spaces, connections, &[a, b]);
    Ok(Edited {
        nrg: Nrg::new(spaces, connections)?,
        created: vec![id],
        removed: vec![],
    })
}

/// The outward unit normal of `space`'s outline at `p` (a point on it):
/// that of the nearest edge.
fn outline_normal(space: &Space, p: Point) -> Point {
    let mut best = (f64::INFINITY, [0.0, 1.0]);
    for ring in std::iter::once(&space.polygon).chain(&space.holes) {
        for i in 0..ring.len() {
            let (u, v) = (ring[i], ring[(i + 1) % ring.len()]);
            let q = super::shape::nearest_on_segment(p, u, v);
            let len = distance(u, v);
            if len > 0.0 && distance(p, q) < best.0 {
                // Shells run counter-clockwise and holes clockwise, so the
                // right-hand side of an edge is outside the space.
                best = (distance(p, q), [(v[1] - u[1]) / len, -(v[0] - u[0]) / len]);
            }
        }
    }
    best.1
}

/// `door` removed; see [`super::Edit::RemoveDoor`].
pub(super) fn remove_door(nrg: &Nrg, door: SpaceId) -> Result<Edited, EditError> {
    let space = nrg.space(door).ok_or(EditError::UnknownSpace(door))?;
    if space.kind != SpaceKind::Door {
        return Err(EditError::NotADoor {
            label: space.label(),
            kind: space.kind.to_string(),
        });
    }
    let sides: Vec<SpaceId> = nrg
        .connections_of(door)
        .filter_map(|c| c.other(door))
        .collect();
    let spaces: Vec<Space> = nrg
        .spaces()
        .iter()
        .filter(|s| s.id != door)
        .cloned()
        .collect();
    let mut connections: Vec<_> = nrg
        .connections()
        .iter()
        .filter(|c| c.a != door && c.b != door)
        .cloned()
        .collect();
    for (i, &x) in sides.iter().enumerate() {
        for &y in &sides[i + 1..] {
            if nrg.connection(x, y).is_none() {
                connections.push(link(&spaces, x, y, ConnectionKind::Adjacent));
            }
        }
    }
    Ok(Edited {
        nrg: Nrg::new(spaces, connections)?,
        created: vec![],
        removed: vec![door],
    })
}

/// The refusal of a cut that breaks `space` into `pieces`.
fn broken(space: &Space, pieces: usize) -> EditError {
    EditError::WouldBreak {
        label: space.label(),
        pieces,
    }
}
