//! Reader of CARMEN 2D-laser logs (`FLASER` and `ROBOTLASER1` lines) into
//! [`Scan`]s with the logged (corrected) poses. Plain or gzip-compressed.

use std::io::Read;
use std::path::Path;

use super::SimError;
use super::lidar::Scan;
use super::robot_path::Pose;

/// Readings at or above this count as "no return" when the log states no
/// `robot_front_laser_max` (CARMEN writes about 81.9 m for no return).
pub const DEFAULT_NO_RETURN_M: f32 = 80.0;

/// Reads a CARMEN log (gzip detected by its magic bytes).
pub fn read_carmen(path: &Path) -> Result<Vec<Scan>, SimError> {
    let io = |source| SimError::Io {
        path: path.to_path_buf(),
        source,
    };
    let bytes = std::fs::read(path).map_err(io)?;
    let text = if bytes.starts_with(&[0x1f, 0x8b]) {
        let mut out = Vec::new();
        flate2::read::MultiGzDecoder::new(&bytes[..])
            .read_to_end(&mut out)
            .map_err(io)?;
        out
    } else {
        bytes
    };
    parse_carmen(&String::from_utf8_lossy(&text), path)
}

/// Parses the text of a CARMEN log; `path` only names it in errors.
/// Lines other than `FLASER`, `ROBOTLASER1` and `PARAM` are ignored.
///
/// ```
/// use nrgdb::sim::parse_carmen;
/// let log = "PARAM robot_frontlaser_offset 0.0 nohost 0\n\
///            FLASER 2 1.5 2.0 1.0 2.0 0.5 1.0 2.0 0.5 0.1 host 0.1\n";
/// let scans = parse_carmen(log, "x.log".as_ref())?;
/// assert_eq!(scans[0].ranges_m, vec![1.5, 2.0]);
/// assert_eq!(scans[0].pose.x, 1.0);
/// # Ok::<(), nrgdb::sim::SimError>(())
/// ```
pub fn parse_carmen(text: &str, path: &Path) -> Result<Vec<Scan>, SimError> {
    let mut scans = Vec::new();
    let mut offset_m = 0.0;
    let mut max_m = DEFAULT_NO_RETURN_M;
    for (i, line) in text.lines().enumerate() {
        let bad = |message: String| SimError::BadLogLine {
            path: path.to_path_buf(),
            line: i + 1,
            message,
        };
        let fields: Vec<&str> = line.split_whitespace().collect();
        match fields.first().copied() {
            Some("PARAM") => match (fields.get(1).copied(), fields.get(2)) {
                (Some("robot_frontlaser_offset"), Some(v)) => {
                    offset_m = v
                        .parse()
                        .map_err(|_| bad(format!("bad laser offset {v:?}")))?;
                }
                (Some("robot_front_laser_max"), Some(v)) => {
                    max_m = v.parse().map_err(|_| bad(format!("bad laser max {v:?}")))?;
                }
                _ => {}
            },
            Some("FLASER") => scans.push(flaser(&fields, offset_m, max_m).map_err(bad)?),
            Some("ROBOTLASER1") => scans.push(robotlaser1(&fields).map_err(bad)?),
            _ => {}
        }
    }
    if scans.is_empty() {
        return Err(SimError::NoScans {
            path: path.to_path_buf(),
        });
    }
    Ok(scans)
}

fn num<T: std::str::FromStr>(fields: &[&str], i: usize, what: &str) -> Result<T, String> {
    let f = fields
        .get(i)
        .ok_or_else(|| format!("line ends before the {what} (field {})", i + 1))?;
    f.parse()
        .map_err(|_| format!("{what} (field {}) is {f:?}, not a number", i + 1))
}

fn count(fields: &[&str], i: usize, what: &str) -> Result<usize, String> {
    let n: usize = num(fields, i, what)?;
    if n == 0 || n > 100_000 {
        return Err(format!("{what} is {n}; expected 1..=100000"));
    }
    Ok(n)
}

fn finite(x: f64, what: &str) -> Result<f64, String> {
    x.is_finite()
        .then_some(x)
        .ok_or_else(|| format!("{what} is not finite"))
}

/// `FLASER n r1..rn x y theta odom_x odom_y odom_theta ts host logger_ts`;
/// beams span 180 degrees from -90 (step pi/n, or pi/(n-1) for odd n).
fn flaser(fields: &[&str], offset_m: f64, max_m: f32) -> Result<Scan, String> {
    let n = count(fields, 1, "beam count")?;
    let ranges = (0..n)
        .map(|k| num::<f32>(fields, 2 + k, "range reading"))
        .collect::<Result<Vec<_>, _>>()?;
    let x = finite(num(fields, 2 + n, "pose x")?, "pose x")?;
    let y = finite(num(fields, 3 + n, "pose y")?, "pose y")?;
    let theta = finite(num(fields, 4 + n, "pose theta")?, "pose theta")?;
    let step = std::f64::consts::PI / if n % 2 == 1 { (n - 1).max(1) } else { n } as f64;
    Ok(Scan {
        pose: Pose {
            x: x + offset_m * theta.cos(),
            y: y + offset_m * theta.sin(),
            theta,
        },
        angle_min_rad: -std::f64::consts::FRAC_PI_2,
        angle_step_rad: step,
        ranges_m: ranges,
        max_range_m: max_m,
    })
}

/// `ROBOTLASER1 type start_angle fov resolution max_range accuracy
/// remission_mode n r1..rn m rem1..remm laser_x laser_y laser_theta ...`.
fn robotlaser1(fields: &[&str]) -> Result<Scan, String> {
    let start = finite(num(fields, 2, "start angle")?, "start angle")?;
    let res = finite(num(fields, 4, "angular resolution")?, "angular resolution")?;
    let max: f32 = num(fields, 5, "maximum range")?;
    let n = count(fields, 8, "beam count")?;
    let ranges = (0..n)
        .map(|k| num::<f32>(fields, 9 + k, "range reading"))
        .collect::<Result<Vec<_>, _>>()?;
    let m: usize = num(fields, 9 + n, "remission count")?;
    let at = 10usize
        .checked_add(n)
        .and_then(|v| v.checked_add(m))
        .ok_or("remission count too large")?;
    Ok(Scan {
        pose: Pose {
            x: finite(num(fields, at, "laser x")?, "laser x")?,
            y: finite(num(fields, at + 1, "laser y")?, "laser y")?,
            theta: finite(num(fields, at + 2, "laser theta")?, "laser theta")?,
        },
        angle_min_rad: start,
        angle_step_rad: res,
        ranges_m: ranges,
        max_range_m: if max > 0.0 { max } else { DEFAULT_NO_RETURN_M },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flaser_with_180_beams_steps_one_degree() {
        let mut line = String::from("FLASER 180");
        for _ in 0..180 {
            line.push_str(" 2.5");
        }
        line.push_str(" 1 2 0.5 1 2 0.5 12.3 pippo 12.3");
        let scans = parse_carmen(
            &format!("ODOM 0 0 0 0 0 0 1 h 1\n{line}\n"),
            "a.log".as_ref(),
        )
        .unwrap();
        assert_eq!(scans.len(), 1);
        assert!((scans[0].angle_step_rad - 1f64.to_radians()).abs() < 1e-12);
        assert_eq!(scans[0].pose.theta, 0.5);
        assert_eq!(scans[0].max_range_m, DEFAULT_NO_RETURN_M);
    }

    #[test]
    fn malformed_lines_name_file_and_line() {
        let cases = [
            "FLASER 3 1.0 2.0\n",
            "FLASER x 1.0\n",
            "FLASER 2 1.0 abc 1 2 3 1 2 3 0 h 0\n",
            "FLASER 2 1.0 1.0 1 nan 3 1 2 3 0 h 0\n",
            "ROBOTLASER1 0 -1.5 3.1 0.01 80 0.1 0 2 1 1 0\n",
        ];
        for c in cases {
            let text = format!("# comment\nPARAM x 1 h 0\n{c}");
            let e = parse_carmen(&text, "b.log".as_ref())
                .unwrap_err()
                .to_string();
            assert!(e.starts_with("b.log:3: "), "{e}");
        }
    }

    #[test]
    fn robotlaser1_uses_the_laser_pose() {
        let line = "ROBOTLASER1 0 -1.57 3.14 0.0174 81.9 0.01 0 3 1 2 3 0 4 5 0.1 4 5 0.1 0 0 0 0 0 12 h 12";
        let s = parse_carmen(line, "c.log".as_ref()).unwrap();
        assert_eq!(
            s[0].pose,
            Pose {
                x: 4.0,
                y: 5.0,
                theta: 0.1
            }
        );
        assert_eq!(s[0].ranges_m, vec![1.0, 2.0, 3.0]);
        assert_eq!(s[0].angle_min_rad, -1.57);
    }

    #[test]
    fn log_without_scans_and_missing_file_are_errors() {
        let e = parse_carmen("ODOM 0 0 0\n", "d.log".as_ref()).unwrap_err();
        assert!(e.to_string().contains("d.log"));
        let e = read_carmen("/nonexistent/e.log.gz".as_ref()).unwrap_err();
        assert!(e.to_string().contains("/nonexistent/e.log.gz"));
    }
}
