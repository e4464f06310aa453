//! Douglas–Peucker simplification of a closed ring.

use crate::model::Point;

/// Simplifies an open ring (first point not repeated) with tolerance `eps`,
/// keeping the first point and the point farthest from it as anchors.
pub(crate) fn simplify_ring(ring: &[Point], eps: f64) -> Vec<Point> {
    if ring.len() <= 4 || eps <= 0.0 {
        return ring.to_vec();
    }
    let far = (1..ring.len())
        .max_by(|&i, &j| dist2(ring[0], ring[i]).total_cmp(&dist2(ring[0], ring[j])))
        .unwrap_or(ring.len() / 2);
    let mut keep = vec![false; ring.len()];
    keep[0] = true;
    keep[far] = true;
    douglas_peucker(ring, 0, far, eps, &mut keep);
    let mut closed: Vec<Point> = ring[far..].to_vec();
    closed.push(ring[0]);
    let mut keep2 = vec![false; closed.len()];
    douglas_peucker(&closed, 0, closed.len() - 1, eps, &mut keep2);
    for (k, &v) in keep2.iter().enumerate() {
        if v && k + far < ring.len() {
            keep[k + far] = true;
        }
    }
    ring.iter()
        .zip(&keep)
        .filter(|(_, k)| **k)
        .map(|(p, _)| *p)
        .collect()
}

fn dist2(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)
}

fn douglas_peucker(pts: &[Point], first: usize, last: usize, eps: f64, keep: &mut [bool]) {
    let mut stack = vec![(first, last)];
    while let Some((f, l)) = stack.pop() {
        if l <= f + 1 {
            continue;
        }
        let (a, b) = (pts[f], pts[l]);
        let len = dist2(a, b).sqrt();
        let mut best = (0.0, f);
        for (i, p) in pts.iter().enumerate().take(l).skip(f + 1) {
            let d = if len == 0.0 {
                dist2(a, *p).sqrt()
            } else {
                ((b[0] - a[0]) * (a[1] - p[1]) - (a[0] - p[0]) * (b[1] - a[1])).abs() / len
            };
            if d > best.0 {
                best = (d, i);
            }
        }
        if best.0 > eps {
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
    fn square_with_collinear_points_keeps_corners() {
        let ring = vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [2.0, 2.0],
            [1.0, 2.0],
            [0.0, 2.0],
            [0.0, 1.0],
        ];
        let s = simplify_ring(&ring, 0.1);
        assert_eq!(s, vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
    }
}
