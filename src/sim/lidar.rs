//! A simulated 2D LiDAR: beams cast exactly against the walls, with
//! Gaussian angle and range noise and max-range returns when nothing is hit.

use super::SimError;
use super::prng::SplitMix64;
use super::ray_cast::WallIndex;
use super::robot_path::Pose;

/// One laser scan: a pose and its ranges, beam `i` pointing at
/// `pose.theta + angle_min_rad + i * angle_step_rad`.
#[derive(Debug, Clone, PartialEq)]
pub struct Scan {
    /// Sensor pose (known, exact).
    pub pose: Pose,
    /// Angle of the first beam relative to the heading, radians.
    pub angle_min_rad: f64,
    /// Angle between beams, radians.
    pub angle_step_rad: f64,
    /// Measured ranges in metres; `>= max_range_m` means "no return".
    pub ranges_m: Vec<f32>,
    /// The sensor's maximum range in metres.
    pub max_range_m: f32,
}

/// The sensor model.
#[derive(Debug, Clone, PartialEq)]
pub struct LidarParams {
    /// Beams per scan.
    pub beams: usize,
    /// Field of view in radians, centred on the heading (TAU = all round).
    pub fov_rad: f64,
    /// Maximum range in metres; beams that hit nothing return this.
    pub max_range_m: f64,
    /// Standard deviation of the range noise, metres.
    pub range_noise_m: f64,
    /// Standard deviation of the beam-direction noise, radians.
    pub angle_noise_rad: f64,
    /// Seed of the noise.
    pub seed: u64,
}

impl Default for LidarParams {
    /// 360 beams all round, 10 m range, 1 cm and 0.1 degree noise.
    fn default() -> LidarParams {
        LidarParams {
            beams: 360,
            fov_rad: std::f64::consts::TAU,
            max_range_m: 10.0,
            range_noise_m: 0.01,
            angle_noise_rad: 0.1f64.to_radians(),
            seed: 0,
        }
    }
}

impl LidarParams {
    /// Checks the parameters; the error names the bad one.
    pub fn validate(&self) -> Result<(), SimError> {
        let bad = |name, value: String, expected, hint| {
            Err(SimError::BadParameter {
                name,
                value,
                expected,
                hint,
            })
        };
        if self.beams == 0 || self.beams > 100_000 {
            return bad(
                "beams",
                self.beams.to_string(),
                "in 1..=100000",
                "360 is typical",
            );
        }
        if !(self.fov_rad > 0.0 && self.fov_rad <= std::f64::consts::TAU) {
            return bad(
                "fov_rad",
                self.fov_rad.to_string(),
                "in (0, 2 pi]",
                "use TAU for all round",
            );
        }
        if !(self.max_range_m > 0.0 && self.max_range_m < 1000.0) {
            return bad(
                "max_range_m",
                self.max_range_m.to_string(),
                "in (0, 1000) m",
                "10 m is typical",
            );
        }
        if !(self.range_noise_m >= 0.0 && self.angle_noise_rad >= 0.0) {
            return bad(
                "noise",
                format!("{} m, {} rad", self.range_noise_m, self.angle_noise_rad),
                ">= 0",
                "use 0 for no noise",
            );
        }
        Ok(())
    }
}

/// Scans the walls from every pose (deterministic in `params.seed`).
pub fn simulate_scans(walls: &WallIndex, poses: &[Pose], params: &LidarParams) -> Vec<Scan> {
    let mut rng = SplitMix64::new(params.seed ^ 0x5EED_11DA);
    let n = params.beams;
    let full = (params.fov_rad - std::f64::consts::TAU).abs() < 1e-9;
    let step = if full || n == 1 {
        params.fov_rad / n as f64
    } else {
        params.fov_rad / (n - 1) as f64
    };
    let angle_min = -params.fov_rad / 2.0;
    let max = params.max_range_m;
    poses
        .iter()
        .map(|pose| {
            let ranges = (0..n)
                .map(|i| {
                    let mut a = pose.theta + angle_min + i as f64 * step;
                    if params.angle_noise_rad > 0.0 {
                        a += params.angle_noise_rad * rng.gaussian();
                    }
                    match walls.cast([pose.x, pose.y], a, max) {
                        Some(t) => {
                            let noisy = t + params.range_noise_m * rng.gaussian();
                            noisy.clamp(0.0, max * (1.0 - 1e-6)) as f32
                        }
                        None => max as f32,
                    }
                })
                .collect();
            Scan {
                pose: *pose,
                angle_min_rad: angle_min,
                angle_step_rad: step,
                ranges_m: ranges,
                max_range_m: max as f32,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn square_room() -> WallIndex {
        let c = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        WallIndex::new((0..4).map(|i| [c[i], c[(i + 1) % 4]]).collect(), 1.0)
    }

    #[test]
    fn noiseless_scan_in_a_square_measures_the_walls() {
        let p = LidarParams {
            beams: 4,
            range_noise_m: 0.0,
            angle_noise_rad: 0.0,
            ..LidarParams::default()
        };
        let pose = Pose {
            x: 1.0,
            y: 2.0,
            theta: 0.0,
        };
        let scans = simulate_scans(&square_room(), &[pose], &p);
        // beams at -180, -90, 0, 90 degrees
        let r = &scans[0].ranges_m;
        assert!((r[0] - 1.0).abs() < 1e-6 && (r[1] - 2.0).abs() < 1e-6);
        assert!((r[2] - 3.0).abs() < 1e-6 && (r[3] - 2.0).abs() < 1e-6);
    }

    #[test]
    fn open_space_gives_max_range_and_noise_is_seeded() {
        let p = LidarParams {
            max_range_m: 1.5,
            ..LidarParams::default()
        };
        let pose = Pose {
            x: 2.0,
            y: 2.0,
            theta: 0.3,
        };
        let a = simulate_scans(&square_room(), &[pose], &p);
        assert!(a[0].ranges_m.iter().all(|&r| r == 1.5));
        let p = LidarParams::default();
        let b = simulate_scans(&square_room(), &[pose], &p);
        assert_eq!(b, simulate_scans(&square_room(), &[pose], &p));
        assert!(b[0].ranges_m.iter().all(|&r| r > 1.9 && r < 2.9));
    }

    #[test]
    fn bad_beam_count_is_named() {
        let p = LidarParams {
            beams: 0,
            ..LidarParams::default()
        };
        assert!(p.validate().unwrap_err().to_string().contains("beams"));
    }
}
