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
    min_rectangle(&convex_hull(&space.polygon)).map_or(0.0, |(width, _)| width)
}

/// The doorway line of a door space: the midline of its minimum-area
/// rectangle along the long side, from one jamb to the other. A strip one
/// pixel or six pixels deep gives the same line; None for an empty
/// polygon.
pub(crate) fn doorway(space: &Space) -> Option<[Point; 2]> {
    let hull = convex_hull(&space.polygon);
    match hull.as_slice() {
        [] => None,
        [p] => Some([*p, *p]),
        _ => min_rectangle(&hull).map(|(_, line)| line),
    }
}

/// The minimum-area rectangle around a convex hull (at least two points):
/// its long side's length and its midline along that side.
fn min_rectangle(hull: &[Point]) -> Option<(f64, [Point; 2])> {
    let n = hull.len();
    if n < 2 {
        return None;
    }
    let mut best: Option<(f64, f64, [Point; 2])> = None;
    for i in 0..n {
        let (a, b) = (hull[i], hull[(i + 1) % n]);
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        if len <= 0.0 {
            continue;
        }
        let (ux, uy) = ((b[0] - a[0]) / len, (b[1] - a[1]) / len);
        let (mut lo_u, mut hi_u, mut lo_v, mut hi_v) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for p in hull {
            let (u, v) = (p[0] * ux + p[1] * uy, -p[0] * uy + p[1] * ux);
            lo_u = lo_u.min(u);
            hi_u = hi_u.max(u);
            lo_v = lo_v.min(v);
            hi_v = hi_v.max(v);
        }
        let (w, h) = (hi_u - lo_u, hi_v - lo_v);
        if best.is_none_or(|(area, _, _)| w * h < area) {
            // Back from (u, v) to (x, y): x = u·ux − v·uy, y = u·uy + v·ux.
            let at = |u: f64, v: f64| [u * ux - v * uy, u * uy + v * ux];
            let line = if w >= h {
                let v = (lo_v + hi_v) / 2.0;
                [at(lo_u, v), at(hi_u, v)]
            } else {
                let u = (lo_u + hi_u) / 2.0;
                [at(u, lo_v), at(u, hi_v)]
            };
            best = Some((w * h, w.max(h), line));
        }
    }
    best.map(|(_, width, line)| (width, line))
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
        assert_eq!(doorway(&empty), None);
    }

    #[test]
    fn doorway_is_the_midline_whatever_the_depth() {
        // A 0.9 m doorway at 30°, cut 0.3 m deep and as a line (no area).
        let (s, c) = 30f64.to_radians().sin_cos();
        let turn = |[x, y]: Point| [c * x - s * y, s * x + c * y];
        for depth in [0.3, 0.0] {
            let ring = [[0.0, 0.0], [0.9, 0.0], [0.9, depth], [0.0, depth]]
                .map(turn)
                .to_vec();
            let door = Space::new(SpaceId(1), SpaceKind::Door, [0.0, 0.0], ring);
            let [a, b] = doorway(&door).unwrap();
            let (mut a, mut b) = (a, b);
            if a[0] > b[0] {
                std::mem::swap(&mut a, &mut b);
            }
            let (wa, wb) = (turn([0.0, depth / 2.0]), turn([0.9, depth / 2.0]));
            for (p, q) in [(a, wa), (b, wb)] {
                assert!(
                    (p[0] - q[0]).hypot(p[1] - q[1]) < 1e-9,
                    "{depth}: {p:?} {q:?}"
                );
            }
        }
    }
}
