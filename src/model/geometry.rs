//! Planar geometry on the model's rings: area, centroid, orientation,
//! point-in-ring and bounds. Metres in the map frame; rings are open (first point not
//! repeated).

/// A point `[x, y]` in metres in the map frame.
pub type Point = [f64; 2];

/// A ring of points, open: the last point joins the first implicitly.
pub type Ring = Vec<Point>;

/// Signed area of a ring by the shoelace formula: positive when
/// counter-clockwise.
///
/// ```
/// use nrgdb::model::polygon_area;
/// let square = vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
/// assert_eq!(polygon_area(&square), 4.0);
/// ```
pub fn polygon_area(ring: &[Point]) -> f64 {
    let n = ring.len();
    if n < 3 {
        return 0.0;
    }
    let mut twice = 0.0;
    for i in 0..n {
        let [x0, y0] = ring[i];
        let [x1, y1] = ring[(i + 1) % n];
        twice += x0 * y1 - x1 * y0;
    }
    twice / 2.0
}

/// Whether a ring runs counter-clockwise (positive signed area).
pub fn ring_is_ccw(ring: &[Point]) -> bool {
    polygon_area(ring) > 0.0
}

/// Area-weighted centroid of a ring; the vertex mean when the area is zero.
///
/// ```
/// use nrgdb::model::polygon_centroid;
/// let square = vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
/// assert_eq!(polygon_centroid(&square), Some([1.0, 1.0]));
/// ```
pub fn polygon_centroid(ring: &[Point]) -> Option<Point> {
    let n = ring.len();
    if n == 0 {
        return None;
    }
    let area = polygon_area(ring);
    if area.abs() < 1e-12 {
        let (sx, sy) = ring
            .iter()
            .fold((0.0, 0.0), |(sx, sy), p| (sx + p[0], sy + p[1]));
        return Some([sx / n as f64, sy / n as f64]);
    }
    let (mut cx, mut cy) = (0.0, 0.0);
    for i in 0..n {
        let [x0, y0] = ring[i];
        let [x1, y1] = ring[(i + 1) % n];
        let cross = x0 * y1 - x1 * y0;
        cx += (x0 + x1) * cross;
        cy += (y0 + y1) * cross;
    }
    Some([cx / (6.0 * area), cy / (6.0 * area)])
}

/// Distance from `p` to the segment `a`–`b`, metres.
///
/// ```
/// use nrgdb::model::segment_distance;
/// assert_eq!(segment_distance([1.0, 2.0], [0.0, 0.0], [3.0, 0.0]), 2.0);
/// assert_eq!(segment_distance([5.0, 0.0], [0.0, 0.0], [3.0, 0.0]), 2.0);
/// ```
pub fn segment_distance(p: Point, a: Point, b: Point) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - a[0] - t * dx).hypot(p[1] - a[1] - t * dy)
}

/// Whether `p` lies inside the ring (even-odd rule; points on an edge may
/// go either way).
///
/// ```
/// use nrgdb::model::point_in_ring;
/// let square = vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
/// assert!(point_in_ring([1.0, 1.0], &square));
/// assert!(!point_in_ring([3.0, 1.0], &square));
/// ```
pub fn point_in_ring(p: Point, ring: &[Point]) -> bool {
    let n = ring.len();
    let mut inside = false;
    let mut j = n.wrapping_sub(1);
    for i in 0..n {
        let [xi, yi] = ring[i];
        let [xj, yj] = ring[j];
        if (yi > p[1]) != (yj > p[1]) && p[0] < (xj - xi) * (p[1] - yi) / (yj - yi) + xi {
            inside = !inside;
        }
        j = i;
    }
    inside
}

/// `[min x, min y, max x, max y]` of some points, `None` when there are
/// none.
///
/// ```
/// use nrgdb::model::bounds;
/// assert_eq!(bounds(&[[1.0, 5.0], [-2.0, 3.0]]), Some([-2.0, 3.0, 1.0, 5.0]));
/// assert_eq!(bounds(&[]), None);
/// ```
pub fn bounds<'a>(points: impl IntoIterator<Item = &'a Point>) -> Option<[f64; 4]> {
    let mut points = points.into_iter();
    let first = points.next()?;
    Some(
        points.fold([first[0], first[1], first[0], first[1]], |b, p| {
            [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ]
        }),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clockwise_ring_has_negative_area() {
        let cw = vec![[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]];
        assert_eq!(polygon_area(&cw), -1.0);
        assert!(!ring_is_ccw(&cw));
    }

    #[test]
    fn centroid_of_l_shape_is_area_weighted() {
        let l = vec![
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ];
        let c = polygon_centroid(&l).unwrap();
        assert!((c[0] - 5.0 / 6.0).abs() < 1e-12 && (c[1] - 5.0 / 6.0).abs() < 1e-12);
    }

    #[test]
    fn point_in_concave_ring() {
        let l = vec![
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ];
        assert!(point_in_ring([0.5, 1.5], &l));
        assert!(!point_in_ring([1.5, 1.5], &l));
    }
}
