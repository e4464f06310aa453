//! Door width: the long side of a door space's minimum-area bounding
//! rectangle (rotating calipers over the convex hull; Freeman & Shapira
//! 1975, "Determining the minimum-area encasing rectangle").
//!
//! A door space is the strip cut across a doorway: its long side spans the
//! opening (the width a person or robot passes through), its short side is
//! the wall's depth. Connection lengths are anchor-to-anchor distances and
//! say nothing about the opening, so the diff reports this width instead.

use crate::model::{Point, Space};

/// The width in metres of a door space's opening (see the module doc); 0
/// for degenerate polygons.
///
/// ```
/// use nrgdb::diff::door_width;
/// use nrgdb::model::{Space, SpaceId, SpaceKind};
/// // A 0.9 m wide doorway through a 0.2 m wall, rotated 30°.
/// let (s, c) = 30f64.to_radians().sin_cos();
/// let rect = [[0.0, 0.0], [0.9, 0.0], [0.9, 0.2], [0.0, 0.2]]
///     .map(|[x, y]| [c * x - s * y, s * x + c * y]).to_vec();
/// let door = Space::new(SpaceId(1), SpaceKind::Door, [0.0, 0.0], rect);
/// assert!((door_width(&door) - 0.9).abs() < 1e-9);
/// ```
pub fn door_width(space: &Space) -> f64 {
    let hull = convex_hull(&space.polygon);
    let n = hull.len();
    if n < 2 {
        return 0.0;
    }
    let mut best = (f64::INFINITY, 0.0);
    for i in 0..n {
        let (a, b) = (hull[i], hull[(i + 1) % n]);
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        if len <= 0.0 {
            continue;
        }
        let (ux, uy) = ((b[0] - a[0]) / len, (b[1] - a[1]) / len);
        let (mut lo_u, mut hi_u, mut lo_v, mut hi_v) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for p in &hull {
            let (u, v) = (p[0] * ux + p[1] * uy, -p[0] * uy + p[1] * ux);
            lo_u = lo_u.min(u);
            hi_u = hi_u.max(u);
            lo_v = lo_v.min(v);
            hi_v = hi_v.max(v);
        }
        let (w, h) = (hi_u - lo_u, hi_v - lo_v);
        if w * h < best.0 {
            best = (w * h, w.max(h));
        }
    }
    best.1
}

/// Andrew's monotone chain; counter-clockwise, no repeated point.
pub(crate) fn convex_hull(points: &[Point]) -> Vec<Point> {
    let mut pts: Vec<Point> = points
        .iter()
        .copied()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
        .collect();
    pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let cross = |o: Point, a: Point, b: Point| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut hull: Vec<Point> = Vec::with_capacity(2 * pts.len());
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &Point>> = if pass == 0 {
            Box::new(pts.iter())
        } else {
            Box::new(pts.iter().rev())
        };
        for &p in iter {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{SpaceId, SpaceKind};

    #[test]
    fn l_shaped_door_uses_its_hull() {
        let l = vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 0.2],
            [0.2, 0.2],
            [0.2, 0.5],
            [0.0, 0.5],
        ];
        let d = Space::new(SpaceId(1), SpaceKind::Door, [0.1, 0.1], l);
        assert!((door_width(&d) - 1.0).abs() < 1e-9);
        let empty = Space::new(SpaceId(2), SpaceKind::Door, [0.0, 0.0], vec![]);
        assert_eq!(door_width(&empty), 0.0);
    }
}
