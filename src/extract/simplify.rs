//! Douglas–Peucker simplification of a boundary arc between pixel corners
//! (Douglas & Peucker 1973), in integer corner coordinates so that an arc
//! shared by two spaces is simplified once and identically for both.
//!
//! Uses nothing else of the crate; the arcs come from `boundaries.rs`.
//!
//! ```text
//! simplify_arc(&[[0, 0], [1, 0], [2, 1], [3, 0], [9, 0]], 1.5) == [[0, 0], [9, 0]]
//! ```

/// A pixel corner `[col, row]`.
pub(crate) type Corner = [i32; 2];

/// Simplifies an arc with tolerance `eps` (pixels), keeping both end points.
/// A closed arc (first point = last point) also keeps the point farthest
/// from its start, so that it never collapses to a single point. With
/// `eps <= 0` only collinear middle points go.
pub(crate) fn simplify_arc(pts: &[Corner], eps: f64) -> Vec<Corner> {
    let n = pts.len();
    if n <= 2 {
        return pts.to_vec();
    }
    let mut keep = vec![false; n];
    keep[0] = true;
    keep[n - 1] = true;
    if pts[0] == pts[n - 1] {
        let far = (1..n - 1)
            .max_by(|&i, &j| {
                dist2(pts[0], pts[i])
                    .total_cmp(&dist2(pts[0], pts[j]))
                    .then(j.cmp(&i))
            })
            .unwrap_or(n / 2);
        keep[far] = true;
        douglas_peucker(pts, 0, far, eps, &mut keep);
        douglas_peucker(pts, far, n - 1, eps, &mut keep);
    } else {
        douglas_peucker(pts, 0, n - 1, eps, &mut keep);
    }
    pts.iter()
        .zip(&keep)
        .filter(|(_, k)| **k)
        .map(|(p, _)| *p)
        .collect()
}

fn dist2(a: Corner, b: Corner) -> f64 {
    let (dx, dy) = (f64::from(b[0] - a[0]), f64::from(b[1] - a[1]));
    dx * dx + dy * dy
}

/// Marks the points of `pts[first..=last]` that Douglas–Peucker keeps.
/// A point off the chord by more than `eps` (or, with `eps <= 0`, by
/// anything) is kept.
fn douglas_peucker(pts: &[Corner], first: usize, last: usize, eps: f64, keep: &mut [bool]) {
    let mut stack = vec![(first, last)];
    while let Some((f, l)) = stack.pop() {
        if l <= f + 1 {
            continue;
        }
        let (a, b) = (pts[f], pts[l]);
        let (dx, dy) = (i64::from(b[0] - a[0]), i64::from(b[1] - a[1]));
        let len = ((dx * dx + dy * dy) as f64).sqrt();
        // Twice the triangle area is exact in integers; the first farthest
        // point wins ties.
        let mut best = (0i64, f);
        for (i, p) in pts.iter().enumerate().take(l).skip(f + 1) {
            let (px, py) = (i64::from(p[0] - a[0]), i64::from(p[1] - a[1]));
            let d = if len == 0.0 {
                // Scaled like the cross product below would be for len 1.
                px * px + py * py
            } else {
                (dx * py - dy * px).abs()
            };
            if d > best.0 {
                best = (d, i);
            }
        }
        let off = if len == 0.0 {
            (best.0 as f64).sqrt()
        } else {
            best.0 as f64 / len
        };
        if best.0 > 0 && off > eps {
            keep[best.1] = true;
            stack.push((f, best.1));
            stack.push((best.1, l));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_open_arc_keeps_its_ends_and_its_corners() {
        let arc = [[0, 0], [1, 0], [2, 1], [3, 0], [9, 0]];
        assert_eq!(simplify_arc(&arc, 1.5), [[0, 0], [9, 0]]);
        assert_eq!(simplify_arc(&arc, 0.4), arc);
        assert_eq!(simplify_arc(&arc, 0.5), [[0, 0], [2, 1], [3, 0], [9, 0]]);
    }

    #[test]
    fn zero_tolerance_drops_only_collinear_points() {
        let arc = [[0, 0], [1, 0], [2, 0], [2, 1], [2, 3]];
        assert_eq!(simplify_arc(&arc, 0.0), [[0, 0], [2, 0], [2, 3]]);
    }

    #[test]
    fn a_closed_arc_keeps_its_start_and_farthest_point() {
        let square = [[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]];
        assert_eq!(simplify_arc(&square, 1.0), square);
        // A one-pixel square: the diagonal is within 1 px of the others.
        let pixel = [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]];
        assert_eq!(simplify_arc(&pixel, 1.0), [[0, 0], [1, 1], [0, 0]]);
    }
}
