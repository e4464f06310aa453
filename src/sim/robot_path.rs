//! Robot poses along a route: evenly spaced, heading along the travel
//! direction.

use crate::model::Point;

/// A robot (sensor) pose in the map frame: metres and radians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pose {
    /// x in metres.
    pub x: f64,
    /// y in metres.
    pub y: f64,
    /// Heading in radians, counter-clockwise from +x.
    pub theta: f64,
}

/// Poses every `step_m` metres along the polyline `route` (plus its last
/// point), each heading along its segment. Zero-length segments are skipped.
///
/// ```
/// use nrgdb::sim::sample_poses;
/// let poses = sample_poses(&[[0.0, 0.0], [1.0, 0.0]], 0.5);
/// assert_eq!(poses.len(), 3);
/// assert_eq!(poses[1].x, 0.5);
/// ```
pub fn sample_poses(route: &[Point], step_m: f64) -> Vec<Pose> {
    let step_m = if step_m > 0.0 { step_m } else { 0.25 };
    let mut poses = Vec::new();
    let mut carry = 0.0;
    let mut last_theta = 0.0;
    for pair in route.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let len = dx.hypot(dy);
        if len < 1e-9 {
            continue;
        }
        let theta = dy.atan2(dx);
        last_theta = theta;
        let mut s = carry;
        while s < len {
            let f = s / len;
            poses.push(Pose {
                x: a[0] + f * dx,
                y: a[1] + f * dy,
                theta,
            });
            s += step_m;
        }
        carry = s - len;
    }
    if let Some(p) = route.last() {
        poses.push(Pose {
            x: p[0],
            y: p[1],
            theta: last_theta,
        });
    }
    poses
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spacing_is_kept_across_corners() {
        let poses = sample_poses(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]], 0.3);
        for w in poses.windows(2).take(poses.len() - 2) {
            let d = (w[1].x - w[0].x).abs() + (w[1].y - w[0].y).abs();
            assert!(d <= 0.3 + 1e-9, "{d}");
        }
        assert_eq!(poses.last().unwrap().y, 1.0);
        assert!((poses[4].theta - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
    }
}
