//! Geometry shared by the edits: spaces as `geo` polygons and back, the
//! interior point a reshaped space is anchored at, nearest points on
//! outlines, and straight connection lengths.

use geo::{Area, BooleanOps, Coord, LineString, MultiPolygon, Polygon};

use crate::model::{
    Connection, ConnectionKind, Point, Space, SpaceId, pole_of_inaccessibility, reshaped, to_geo,
};

/// Pieces smaller than this (m²) are rounding left by boolean operations.
pub(super) const CRUMB_M2: f64 = 1e-6;

/// The space as a `geo` polygon.
pub(super) fn polygon(space: &Space) -> Polygon {
    to_geo(space)
}

/// The pieces of `shape` larger than a crumb, largest first.
pub(super) fn pieces(shape: MultiPolygon) -> Vec<Polygon> {
    let mut out: Vec<Polygon> = shape
        .into_iter()
        .filter(|p| p.unsigned_area() > CRUMB_M2)
        .collect();
    out.sort_by(|a, b| b.unsigned_area().total_cmp(&a.unsigned_area()));
    out
}

/// `space` minus `cut`, which must leave it in one piece (`Err` with the
/// number of pieces otherwise). The anchor stays where it is unless the
/// cut took it.
pub(super) fn cut_out(space: &Space, cut: &Polygon) -> Result<Space, usize> {
    let left = pieces(polygon(space).difference(cut));
    match left.as_slice() {
        [one] => Ok(reshaped(space, one)),
        more => Err(more.len()),
    }
}

/// `space` with its anchor moved to the pole of inaccessibility of its
/// outline (the anchor every reshaped room and corridor gets); a door's
/// anchor is its doorway's middle.
pub(super) fn reanchored(space: &Space) -> Space {
    let mut out = space.clone();
    if let Some(d) = crate::model::doorway(&out) {
        out.anchor = d.middle();
    } else if let Some((pole, _)) = pole_of_inaccessibility(&out.polygon, &out.holes, 0.01) {
        out.anchor = pole;
    }
    out
}

/// A rectangle centred on `c`, `along` metres long in direction `t` (a
/// unit vector) and `across` metres wide.
pub(super) fn rectangle(c: Point, t: Point, along: f64, across: f64) -> Polygon {
    let n = [-t[1], t[0]];
    let (h, w) = (along / 2.0, across / 2.0);
    let corner = |s: f64, u: f64| Coord {
        x: c[0] + t[0] * s + n[0] * u,
        y: c[1] + t[1] * s + n[1] * u,
    };
    Polygon::new(
        LineString::new(vec![
            corner(-h, -w),
            corner(h, -w),
            corner(h, w),
            corner(-h, w),
            corner(-h, -w),
        ]),
        vec![],
    )
}

/// The point of `space`'s outline (shell and holes) nearest `p`.
pub(super) fn nearest_on_outline(space: &Space, p: Point) -> Point {
    let mut best = (f64::INFINITY, p);
    for ring in std::iter::once(&space.polygon).chain(&space.holes) {
        for i in 0..ring.len() {
            let q = nearest_on_segment(p, ring[i], ring[(i + 1) % ring.len()]);
            let d = distance(p, q);
            if d < best.0 {
                best = (d, q);
            }
        }
    }
    best.1
}

/// The point of segment `a`–`b` nearest `p`.
pub(super) fn nearest_on_segment(p: Point, a: Point, b: Point) -> Point {
    let d = [b[0] - a[0], b[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    if len2 == 0.0 {
        return a;
    }
    let t = (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0);
    [a[0] + d[0] * t, a[1] + d[1] * t]
}

/// Distance between two points.
pub(super) fn distance(a: Point, b: Point) -> f64 {
    (b[0] - a[0]).hypot(b[1] - a[1])
}

/// A connection of `kind` between `a` and `b` of `spaces`, as long as the
/// straight line between their anchors (walked later).
pub(super) fn link(spaces: &[Space], a: SpaceId, b: SpaceId, kind: ConnectionKind) -> Connection {
    let anchor = |id: SpaceId| {
        spaces
            .iter()
            .find(|s| s.id == id)
            .map_or([0.0, 0.0], |s| s.anchor)
    };
    Connection {
        a,
        b,
        kind,
        length_m: distance(anchor(a), anchor(b)),
    }
}

/// `connections` with every length that touches a space in `moved`
/// recomputed as the straight line between anchors.
pub(super) fn relength(
    spaces: &[Space],
    connections: Vec<Connection>,
    moved: &[SpaceId],
) -> Vec<Connection> {
    connections
        .into_iter()
        .map(|c| {
            if moved.contains(&c.a) || moved.contains(&c.b) {
                link(spaces, c.a, c.b, c.kind)
            } else {
                c
            }
        })
        .collect()
}

/// The stronger of two relations between the same pair (a door beats an
/// open boundary beats a wall; a vertical link is kept as it is).
pub(super) fn stronger(a: ConnectionKind, b: ConnectionKind) -> ConnectionKind {
    let rank = |k: ConnectionKind| match k {
        ConnectionKind::Vertical => 3,
        ConnectionKind::Door => 2,
        ConnectionKind::Open => 1,
        ConnectionKind::Adjacent => 0,
    };
    if rank(b) > rank(a) { b } else { a }
}

/// Checks that every coordinate is finite.
pub(super) fn finite(points: &[Point], what: &'static str) -> Result<(), super::EditError> {
    if points.iter().flatten().all(|c| c.is_finite()) {
        Ok(())
    } else {
        Err(super::EditError::NotFinite { what })
    }
}

/// Checks a door width (the default when `None`) and returns it.
pub(super) fn door_width(width_m: Option<f64>) -> Result<f64, super::EditError> {
    let w = width_m.unwrap_or(super::DEFAULT_DOOR_WIDTH_M);
    if !w.is_finite() {
        return Err(super::EditError::NotFinite {
            what: "the door width",
        });
    }
    if !(super::MIN_DOOR_WIDTH_M..=super::MAX_DOOR_WIDTH_M).contains(&w) {
        return Err(super::EditError::DoorWidth {
            width_m: w,
            min: super::MIN_DOOR_WIDTH_M,
            max: super::MAX_DOOR_WIDTH_M,
        });
    }
    Ok(w)
}
