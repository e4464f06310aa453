//! A door's doorway: the line across its opening, from one jamb to the
//! other, and its width. The one definition every module uses (query,
//! route, diff, render, IndoorGML, GeoJSON).
//!
//! A door space is the piece of floor in a doorway, from one face of the
//! wall to the other. Its **doorway line** runs across the opening, through
//! the middle of the wall's thickness, and ends at the jambs (where an
//! obstacle stands in the opening, it is the longest stretch left clear,
//! the width one can pass); its **width**
//! is that line's length, unless the space declares a `width_m` attribute
//! (a door leaf narrower than its frame, a width taken from a plan). The
//! extractor measures the line from the map and stores it in
//! [`Space::doorway`](super::Space::doorway); a door that comes without one (a hand-made or
//! imported model) gets the midline, along its long side, of its polygon's
//! minimum-area rectangle (Freeman & Shapira 1975, "Determining the
//! minimum-area encasing rectangle"; [`geo::MinimumRotatedRect`]).

use geo::{ConvexHull, Coord, MinimumRotatedRect, MultiPoint};

use serde_json::{Map, Value};

use super::geometry::Point;

/// A door's doorway line and width (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Doorway {
    /// The two ends of the doorway line, at the jambs, metres in the map
    /// frame.
    pub line: [Point; 2],
    /// The door's width in metres: the declared `width_m` attribute, else
    /// the line's length.
    pub width_m: f64,
}

impl Doorway {
    /// The middle of the doorway line: where a door's anchor belongs.
    pub fn middle(&self) -> Point {
        let [a, b] = self.line;
        [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0]
    }

    /// The length of the doorway line in metres.
    pub fn length_m(&self) -> f64 {
        let [a, b] = self.line;
        (b[0] - a[0]).hypot(b[1] - a[1])
    }
}

/// The doorway of a door with the `stored` doorway line, `polygon` and
/// `attributes` (see [`doorway`](super::doorway()), which calls this for a
/// door space): the stored line when finite, else the polygon's midline;
/// the `width_m` attribute when positive and finite, else the line's
/// length. `None` for a polygon without points.
pub(super) fn door_doorway(
    stored: Option<[Point; 2]>,
    polygon: &[Point],
    attributes: &Map<String, Value>,
) -> Option<Doorway> {
    let finite = |l: &[Point; 2]| l.iter().flatten().all(|c| c.is_finite());
    let line = match stored.filter(finite) {
        Some(line) => line,
        None => polygon_doorway(polygon)?,
    };
    let length = (line[1][0] - line[0][0]).hypot(line[1][1] - line[0][1]);
    let declared = attributes
        .get("width_m")
        .and_then(serde_json::Value::as_f64)
        .filter(|w| w.is_finite() && *w > 0.0);
    Some(Doorway {
        line,
        width_m: declared.unwrap_or(length),
    })
}

/// The doorway line a polygon implies: the midline, along the long side,
/// of its minimum-area rectangle (a strip one pixel or six pixels deep
/// gives the same line), lower x (then y) first. A single point gives a
/// line of length 0; `None` for no finite point.
///
/// ```
/// use nrgdb::model::polygon_doorway;
/// let strip = [[0.0, 0.0], [1.2, 0.0], [1.2, 0.1], [0.0, 0.1]];
/// let [a, b] = polygon_doorway(&strip).unwrap();
/// assert!((a[1] - 0.05).abs() < 1e-9 && (b[1] - 0.05).abs() < 1e-9);
/// assert!(((b[0] - a[0]).abs() - 1.2).abs() < 1e-9);
/// ```
pub fn polygon_doorway(polygon: &[Point]) -> Option<[Point; 2]> {
    let points = finite_points(polygon);
    let first = *points.first()?;
    if points.iter().all(|p| *p == first) {
        return Some([first, first]);
    }
    // Translated to the first point, for precision far from the origin.
    let local: MultiPoint<f64> = points
        .iter()
        .map(|p| Coord {
            x: p[0] - first[0],
            y: p[1] - first[1],
        })
        .collect::<Vec<_>>()
        .into();
    let rect = local.minimum_rotated_rect()?;
    let c: Vec<Point> = rect
        .exterior()
        .coords()
        .map(|q| [q.x + first[0], q.y + first[1]])
        .collect();
    let (p0, p1, p2, p3) = (*c.first()?, *c.get(1)?, *c.get(2)?, *c.get(3)?);
    let mid = |a: Point, b: Point| [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
    let len = |a: Point, b: Point| (b[0] - a[0]).hypot(b[1] - a[1]);
    // The long sides are p0–p1 and p2–p3, or p1–p2 and p3–p0: the line
    // joins the middles of the two short sides, lower x (then y) first.
    let [a, b] = if len(p0, p1) >= len(p1, p2) {
        [mid(p3, p0), mid(p1, p2)]
    } else {
        [mid(p0, p1), mid(p2, p3)]
    };
    Some(if (b[0], b[1]) < (a[0], a[1]) {
        [b, a]
    } else {
        [a, b]
    })
}

/// The convex hull of the finite points, counter-clockwise, open (the first
/// point not repeated) and without repeated points; fewer than three
/// points come back as they are (deduplicated).
///
/// ```
/// use nrgdb::model::convex_hull;
/// let hull = convex_hull(&[[0.0, 0.0], [2.0, 0.0], [1.0, 0.5], [2.0, 2.0], [0.0, 2.0]]);
/// assert_eq!(hull.len(), 4);
/// assert!(nrgdb::model::ring_is_ccw(&hull));
/// ```
pub fn convex_hull(points: &[Point]) -> Vec<Point> {
    let mut pts = finite_points(points);
    pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let multi: MultiPoint<f64> = pts
        .iter()
        .map(|p| Coord { x: p[0], y: p[1] })
        .collect::<Vec<_>>()
        .into();
    let mut hull: Vec<Point> = multi
        .convex_hull()
        .exterior()
        .coords()
        .map(|c| [c.x, c.y])
        .collect();
    if hull.len() > 1 && hull.first() == hull.last() {
        hull.pop();
    }
    hull.dedup();
    hull
}

fn finite_points(points: &[Point]) -> Vec<Point> {
    points
        .iter()
        .copied()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn of(ring: &[Point]) -> Option<Doorway> {
        door_doorway(None, ring, &Map::new())
    }

    #[test]
    fn l_shaped_door_uses_its_rectangle() {
        let l = vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 0.2],
            [0.2, 0.2],
            [0.2, 0.5],
            [0.0, 0.5],
        ];
        let d = of(&l).unwrap();
        assert!((d.width_m - 1.0).abs() < 1e-9, "{d:?}");
        assert_eq!(of(&[]), None);
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
            let [mut a, mut b] = polygon_doorway(&ring).unwrap();
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

    #[test]
    fn stored_line_and_declared_width_win() {
        let ring = [[0.0, 0.0], [1.0, 0.0], [1.0, 0.3], [0.0, 0.3]];
        // A 0.3 m wall with a doorway 0.4 m wide: the stored line says
        // which side is the opening, whatever the rectangle's long side.
        let line = Some([[0.5, 0.0], [0.5, 0.4]]);
        let mut attributes = Map::new();
        let width = |a: &Map<String, Value>| door_doorway(line, &ring, a).unwrap().width_m;
        assert!((width(&attributes) - 0.4).abs() < 1e-12);
        attributes.insert("width_m".into(), serde_json::json!(0.35));
        assert_eq!(width(&attributes), 0.35);
        attributes.insert("width_m".into(), serde_json::json!("wide"));
        assert!((width(&attributes) - 0.4).abs() < 1e-12);
    }

    #[test]
    fn far_from_the_origin_stays_exact_enough() {
        let ring = vec![
            [1.0e5, 2.0e5],
            [1.0e5 + 1.1, 2.0e5],
            [1.0e5 + 1.1, 2.0e5 + 0.1],
            [1.0e5, 2.0e5 + 0.1],
        ];
        let [a, b] = polygon_doorway(&ring).unwrap();
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        assert!((len - 1.1).abs() < 1e-6, "{len}");
    }

    #[test]
    fn hull_of_a_square_with_an_inner_point() {
        let hull = convex_hull(&[
            [0.0, 0.0],
            [1.0, 0.0],
            [0.5, 0.5],
            [1.0, 1.0],
            [0.0, 1.0],
            [0.0, 0.0],
        ]);
        assert_eq!(hull.len(), 4);
        assert!(crate::model::ring_is_ccw(&hull));
        assert_eq!(convex_hull(&[[1.0, 1.0], [1.0, 1.0]]), vec![[1.0, 1.0]]);
    }
}
