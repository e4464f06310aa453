//! Mapping recorded scans (e.g. a CARMEN log) with the known-pose mapper.

use std::path::Path;

use super::SimError;
use super::carmen::read_carmen;
use super::lidar::Scan;
use super::log_odds::{GreyMap, LogOddsMap, LogOddsParams, OccupancyRule, check_resolution};

/// What [`map_scans`] built.
#[derive(Debug, Clone, PartialEq)]
pub struct LogMap {
    /// The occupancy map.
    pub map: GreyMap,
    /// Scans read.
    pub scans: usize,
    /// Beams integrated.
    pub beams: usize,
}

/// Maps `scans` (poses known) at `resolution_m`; the map covers every pose
/// and every beam end point that the mapper will use, plus `margin_m`.
pub fn map_scans(
    scans: &[Scan],
    resolution_m: f64,
    margin_m: f64,
    params: LogOddsParams,
) -> Result<LogMap, SimError> {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    let mut grow = |x: f64, y: f64| b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
    for s in scans {
        grow(s.pose.x, s.pose.y);
        for (i, &r) in s.ranges_m.iter().enumerate() {
            let r = f64::from(r);
            if !(r > 0.0 && r.is_finite())
                || (r >= f64::from(s.max_range_m) && !params.clear_on_no_return)
            {
                continue;
            }
            let d = r.min(params.usable_range_m).min(f64::from(s.max_range_m));
            let a = s.pose.theta + s.angle_min_rad + i as f64 * s.angle_step_rad;
            grow(s.pose.x + d * a.cos(), s.pose.y + d * a.sin());
        }
    }
    if !b[0].is_finite() {
        b = [0.0; 4];
    }
    let mut grid = LogOddsMap::covering(b, margin_m, resolution_m, params)?;
    let beams = scans.iter().map(|s| grid.integrate(s)).sum();
    Ok(LogMap {
        map: grid.to_grey(),
        scans: scans.len(),
        beams,
    })
}

/// Reads a CARMEN log (plain or gzip) and maps it by `rule` (usually
/// [`OccupancyRule::RECORDED`]): "no return" readings are skipped, longer
/// ranges are cut at `usable_range_m` (free only).
pub fn map_carmen_log(
    path: &Path,
    resolution_m: f64,
    usable_range_m: f64,
    rule: OccupancyRule,
) -> Result<LogMap, SimError> {
    check_resolution(resolution_m)?;
    if !(usable_range_m > 0.0 && usable_range_m.is_finite()) {
        return Err(SimError::BadParameter {
            name: "--max-range",
            value: usable_range_m.to_string(),
            expected: "a finite number > 0 (metres)",
            hint: "20 m suits indoor logs",
        });
    }
    if let OccupancyRule::HitRatio { min_ratio, .. } = rule
        && !(min_ratio > 0.0 && min_ratio <= 1.0)
    {
        return Err(SimError::BadParameter {
            name: "hit ratio",
            value: min_ratio.to_string(),
            expected: "a share in (0, 1]",
            hint: "0.25 is GMapping's",
        });
    }
    let scans = read_carmen(path)?;
    let params = LogOddsParams {
        rule,
        usable_range_m,
        clear_on_no_return: false,
        ..LogOddsParams::default()
    };
    map_scans(&scans, resolution_m, 1.0, params)
}
