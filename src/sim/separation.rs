//! Separating-axis gap between two convex polygons: a lower bound of their
//! distance, used to keep generated rooms a wall's thickness apart.

use crate::model::Point;

/// The largest gap between the projections of two convex polygons over the
/// edge normals of both (separating axis theorem). Negative when they
/// overlap; when positive it is a lower bound of their distance.
///
/// ```
/// use nrgdb::sim::separation_gap;
/// let a = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let b = [[1.5, 0.0], [2.0, 0.0], [2.0, 1.0], [1.5, 1.0]];
/// assert!((separation_gap(&a, &b) - 0.5).abs() < 1e-12);
/// ```
pub fn separation_gap(a: &[Point], b: &[Point]) -> f64 {
    let mut best = f64::NEG_INFINITY;
    for poly in [a, b] {
        let n = poly.len();
        for i in 0..n {
            let p = poly[i];
            let q = poly[(i + 1) % n];
            let (ex, ey) = (q[0] - p[0], q[1] - p[1]);
            let len = (ex * ex + ey * ey).sqrt();
            if len < 1e-12 {
                continue;
            }
            let axis = [-ey / len, ex / len];
            let (amin, amax) = project(a, axis);
            let (bmin, bmax) = project(b, axis);
            best = best.max((bmin - amax).max(amin - bmax));
        }
    }
    best
}

fn project(poly: &[Point], axis: Point) -> (f64, f64) {
    poly.iter()
        .map(|p| p[0] * axis[0] + p[1] * axis[1])
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn overlapping_squares_have_negative_gap() {
        let a = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        let b = [[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]];
        assert!(separation_gap(&a, &b) < 0.0);
    }

    #[test]
    fn rotated_square_gap_is_a_lower_bound() {
        let a = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        // A diamond whose left tip is 1 m right of a's right edge.
        let b = [[2.0, 0.5], [2.5, 0.0], [3.0, 0.5], [2.5, 1.0]];
        let g = separation_gap(&a, &b);
        assert!(g > 0.7 && g <= 1.0 + 1e-12, "{g}");
    }
}
