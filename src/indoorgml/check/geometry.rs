//! Geometric validity of cell and boundary geometry: closed rings with at
//! least four positions, no self-intersection, 2D exteriors
//! counter-clockwise and holes clockwise, 3D shells facing outwards, and
//! every solid with surfaces (OGC ETS Req 1).

use geo::{Coord, LineString as GeoLine, Polygon as GeoPolygon};

use super::super::document::{BoundaryGeometry, CellGeometry, Coords, Document, Polygon, Solid};
use super::{Finding, finding};
use crate::model::polygon_area;
use crate::model::validity::{PolygonError, polygon_errors};

pub fn check_geometry(doc: &Document, out: &mut Vec<Finding>) {
    for c in doc.cells() {
        let (id, line) = (c.info.id.as_str(), c.info.line);
        match &c.geometry {
            Some(CellGeometry::Surface(p)) => check_polygon(p, true, id, line, out),
            Some(CellGeometry::Solid(s)) => check_solid(s, id, line, out),
            None => {}
        }
    }
    for b in doc.boundaries() {
        match &b.geometry {
            Some(BoundaryGeometry::Surface(p)) => {
                check_polygon(p, false, &b.info.id, b.info.line, out)
            }
            Some(BoundaryGeometry::Curve(l)) if l.coords.len() < 2 => {
                out.push(finding(
                    "degenerate",
                    &b.info.id,
                    b.info.line,
                    "curve has fewer than 2 positions".into(),
                ));
            }
            _ => {}
        }
    }
}

fn check_solid(s: &Solid, id: &str, line: usize, out: &mut Vec<Finding>) {
    if s.exterior.is_empty() {
        out.push(finding(
            "empty-solid",
            id,
            line,
            "gml:Solid has no surfaceMember (OGC ETS Req 1)".into(),
        ));
        return;
    }
    for p in s.exterior.iter().chain(s.interiors.iter().flatten()) {
        check_polygon(p, false, id, line, out);
    }
    let volume: f64 = s.exterior.iter().map(|p| signed_volume(&p.exterior)).sum();
    if volume < 0.0 {
        out.push(finding(
            "wrong-orientation",
            id,
            line,
            format!("the solid's exterior shell faces inwards (signed volume {volume:.3} m³ < 0)"),
        ));
    }
}

/// `planar_2d`: the polygon is a 2D surface, whose orientation is checked.
fn check_polygon(p: &Polygon, planar_2d: bool, id: &str, line: usize, out: &mut Vec<Finding>) {
    let name =
        p.id.as_deref()
            .map_or_else(|| format!("a polygon of {id}"), |g| format!("polygon {g}"));
    for (i, ring) in std::iter::once(&p.exterior).chain(&p.interiors).enumerate() {
        let role = if i == 0 {
            "exterior".to_string()
        } else {
            format!("interior {i}")
        };
        let n = ring.len();
        if n < 4 {
            out.push(finding(
                "degenerate",
                id,
                line,
                format!("{name}: {role} ring has {n} positions, at least 4 needed"),
            ));
            continue;
        }
        let first = &ring.values[..ring.dim];
        let last = &ring.values[ring.values.len() - ring.dim..];
        if first != last {
            out.push(finding(
                "unclosed-ring",
                id,
                line,
                format!("{name}: {role} ring is not closed (first and last positions differ)"),
            ));
        }
    }
    let (project, normal_ok) = projection(&p.exterior);
    if !normal_ok {
        out.push(finding(
            "degenerate",
            id,
            line,
            format!("{name}: exterior ring has no area"),
        ));
        return;
    }
    let ring2d = |c: &Coords| -> GeoLine {
        GeoLine::new(c.values.chunks_exact(c.dim.max(1)).map(project).collect())
    };
    let poly = GeoPolygon::new(
        ring2d(&p.exterior),
        p.interiors.iter().map(ring2d).collect(),
    );
    for err in polygon_errors(&poly) {
        let (code, err) = match err {
            PolygonError::SelfIntersection(m) => ("self-intersection", m),
            PolygonError::Invalid(m) => ("invalid-polygon", m),
        };
        out.push(finding(code, id, line, format!("{name}: {err}")));
    }
    if planar_2d {
        let xy = |c: &Coords| -> Vec<[f64; 2]> { c.xy().collect() };
        if polygon_area(&xy(&p.exterior)) < 0.0 {
            out.push(finding(
                "wrong-orientation",
                id,
                line,
                format!("{name}: exterior ring is clockwise (must be counter-clockwise)"),
            ));
        }
        for (i, r) in p.interiors.iter().enumerate() {
            if polygon_area(&xy(r)) > 0.0 {
                out.push(finding(
                    "wrong-orientation",
                    id,
                    line,
                    format!(
                        "{name}: interior ring {} is counter-clockwise (must be clockwise)",
                        i + 1
                    ),
                ));
            }
        }
    }
}

/// Projects a (possibly 3D) planar ring to 2D by dropping the axis its
/// Newell normal points along most; false when the ring has no area.
fn projection(ring: &Coords) -> (fn(&[f64]) -> Coord, bool) {
    let get = |p: &[f64], i: usize| p.get(i).copied().unwrap_or(0.0);
    let pts: Vec<&[f64]> = ring.values.chunks_exact(ring.dim.max(1)).collect();
    let mut n = [0.0f64; 3];
    for w in 0..pts.len() {
        let (a, b) = (pts[w], pts[(w + 1) % pts.len()]);
        n[0] += (get(a, 1) - get(b, 1)) * (get(a, 2) + get(b, 2));
        n[1] += (get(a, 2) - get(b, 2)) * (get(a, 0) + get(b, 0));
        n[2] += (get(a, 0) - get(b, 0)) * (get(a, 1) + get(b, 1));
    }
    let [nx, ny, nz] = n.map(f64::abs);
    let ok = nx + ny + nz > 1e-12;
    let f: fn(&[f64]) -> Coord = if nz >= nx && nz >= ny {
        |p| Coord {
            x: p[0],
            y: p.get(1).copied().unwrap_or(0.0),
        }
    } else if ny >= nx {
        |p| Coord {
            x: p.get(2).copied().unwrap_or(0.0),
            y: p[0],
        }
    } else {
        |p| Coord {
            x: p.get(1).copied().unwrap_or(0.0),
            y: p.get(2).copied().unwrap_or(0.0),
        }
    };
    (f, ok)
}

/// Contribution of one face to the solid's signed volume (divergence
/// theorem over a fan of triangles from the first vertex).
fn signed_volume(ring: &Coords) -> f64 {
    if ring.dim != 3 {
        return 0.0;
    }
    let pts: Vec<&[f64]> = ring.values.chunks_exact(3).collect();
    let mut v = 0.0;
    for i in 1..pts.len().saturating_sub(1) {
        let (a, b, c) = (pts[0], pts[i], pts[i + 1]);
        v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
            + a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    v / 6.0
}
