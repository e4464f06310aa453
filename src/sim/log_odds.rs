//! Occupancy mapping with known poses by log-odds updates (the paper's
//! Eq. 3, after Thrun et al. 2005): `l_t = tau_t - l_0 + l_{t-1}`, where
//! the inverse sensor model `tau` gives `l_free` to every cell a beam
//! crosses and `l_occ` to the cell it ends in, clamped to `[l_min, l_max]`.

use super::SimError;
use super::bresenham::bresenham;
use super::lidar::Scan;
use crate::model::Point;

/// The most cells a map may have (a f32 each).
pub const MAX_CELLS: usize = 200_000_000;

/// Inverse sensor model and beam handling of the mapper.
#[derive(Debug, Clone, PartialEq)]
pub struct LogOddsParams {
    /// Log-odds added to the cell a beam ends in (`tau` for a hit).
    pub l_occ: f32,
    /// Log-odds added to each cell a beam crosses (`tau` for free, < 0).
    pub l_free: f32,
    /// Prior log-odds `l_0` (0 = probability 0.5).
    pub l_prior: f32,
    /// Lower clamp.
    pub l_min: f32,
    /// Upper clamp.
    pub l_max: f32,
    /// Ranges beyond this are cut here and count as free only (no hit).
    pub usable_range_m: f64,
    /// Whether a "no return" beam (range >= the sensor maximum) clears the
    /// cells up to `usable_range_m`; otherwise it is skipped.
    pub clear_on_no_return: bool,
}

impl Default for LogOddsParams {
    /// One hit makes a cell occupied (p 0.70 > 0.65), three passes free.
    fn default() -> LogOddsParams {
        LogOddsParams {
            l_occ: 0.85,
            l_free: -0.7,
            l_prior: 0.0,
            l_min: -2.0,
            l_max: 3.5,
            usable_range_m: 30.0,
            clear_on_no_return: true,
        }
    }
}

/// A map as grey bytes in ROS trinary form: free 254, occupied 0, unknown
/// 205; row 0 is the top row (as in the PGM), `origin_m` is the lower-left
/// corner of the lower-left cell in the map frame.
#[derive(Debug, Clone, PartialEq)]
pub struct GreyMap {
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// Metres per cell.
    pub resolution_m: f64,
    /// Map-frame position of the lower-left corner, metres.
    pub origin_m: Point,
    /// `width * height` grey values, row-major, top row first.
    pub grey: Vec<u8>,
}

/// Log-odds per cell, row 0 at the bottom (y up).
#[derive(Debug, Clone)]
pub struct LogOddsMap {
    width: usize,
    height: usize,
    resolution_m: f64,
    origin_m: Point,
    cells: Vec<f32>,
    params: LogOddsParams,
}

/// Checks a map resolution given on the command line or in parameters.
pub(super) fn check_resolution(resolution_m: f64) -> Result<(), SimError> {
    if resolution_m > 0.0 && resolution_m.is_finite() {
        return Ok(());
    }
    Err(SimError::BadParameter {
        name: "--resolution",
        value: resolution_m.to_string(),
        expected: "a finite number > 0 (metres per cell)",
        hint: "0.05 is usual for indoor maps",
    })
}

impl LogOddsMap {
    /// An all-unknown map covering `[min_x, min_y, max_x, max_y]` plus
    /// `margin_m` on every side.
    pub fn covering(
        bounds: [f64; 4],
        margin_m: f64,
        resolution_m: f64,
        params: LogOddsParams,
    ) -> Result<LogOddsMap, SimError> {
        check_resolution(resolution_m)?;
        let (w_m, h_m) = (
            bounds[2] - bounds[0] + 2.0 * margin_m,
            bounds[3] - bounds[1] + 2.0 * margin_m,
        );
        let too_large = || SimError::TooLarge {
            width_m: w_m,
            height_m: h_m,
            resolution: resolution_m,
            max_cells: MAX_CELLS,
        };
        if !(w_m.is_finite() && h_m.is_finite() && w_m > 0.0 && h_m > 0.0) {
            return Err(too_large());
        }
        let (wf, hf) = ((w_m / resolution_m).ceil(), (h_m / resolution_m).ceil());
        if wf * hf > MAX_CELLS as f64 {
            return Err(too_large());
        }
        let (width, height) = (wf.max(1.0) as usize, hf.max(1.0) as usize);
        Ok(LogOddsMap {
            width,
            height,
            resolution_m,
            origin_m: [bounds[0] - margin_m, bounds[1] - margin_m],
            cells: vec![params.l_prior; width * height],
            params,
        })
    }

    /// Columns and rows.
    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// The log-odds of cell `(col, row)`, row 0 at the bottom.
    pub fn get(&self, col: usize, row: usize) -> Option<f32> {
        (col < self.width).then(|| self.cells.get(row * self.width + col).copied())?
    }

    /// Integrates every beam of `scan`; returns how many beams were used.
    pub fn integrate(&mut self, scan: &Scan) -> usize {
        let p = &self.params;
        let origin = [scan.pose.x, scan.pose.y];
        let (usable, clear) = (p.usable_range_m, p.clear_on_no_return);
        let mut used = 0;
        for (i, &r) in scan.ranges_m.iter().enumerate() {
            let r = f64::from(r);
            if !(r > 0.0 && r.is_finite()) {
                continue;
            }
            let (d, hit) = if r >= f64::from(scan.max_range_m) {
                if !clear {
                    continue;
                }
                (usable.min(f64::from(scan.max_range_m)), false)
            } else if r > usable {
                (usable, false)
            } else {
                (r, true)
            };
            let a = scan.pose.theta + scan.angle_min_rad + i as f64 * scan.angle_step_rad;
            self.update_beam(
                origin,
                [origin[0] + d * a.cos(), origin[1] + d * a.sin()],
                hit,
            );
            used += 1;
        }
        used
    }

    /// One beam from `from` to `to` (metres): cells crossed get `l_free`,
    /// the end cell `l_occ` when `hit` (else `l_free` too). Cells outside
    /// the map are ignored.
    pub fn update_beam(&mut self, from: Point, to: Point, hit: bool) {
        let inv = 1.0 / self.resolution_m;
        let cell = |p: Point, o: Point| {
            (
                ((p[0] - o[0]) * inv).floor() as i64,
                ((p[1] - o[1]) * inv).floor() as i64,
            )
        };
        let (x0, y0) = cell(from, self.origin_m);
        let (x1, y1) = cell(to, self.origin_m);
        let (w, h) = (self.width as i64, self.height as i64);
        let p = &self.params;
        let free = p.l_free - p.l_prior;
        let occ = p.l_occ - p.l_prior;
        let (lo, hi) = (p.l_min, p.l_max);
        let cells = &mut self.cells;
        bresenham(x0, y0, x1, y1, |x, y| {
            if x < 0 || y < 0 || x >= w || y >= h {
                return;
            }
            let tau = if hit && x == x1 && y == y1 { occ } else { free };
            if let Some(c) = cells.get_mut((y * w + x) as usize) {
                *c = (*c + tau).clamp(lo, hi);
            }
        });
    }

    /// The map in ROS trinary grey: occupied (p > 0.65) 0, free
    /// (p < 0.196) 254, otherwise 205 — the thresholds `map.yaml` states.
    pub fn to_grey(&self) -> GreyMap {
        let occ = (0.65f32 / 0.35).ln();
        let free = (0.196f32 / 0.804).ln();
        let mut grey = vec![205u8; self.width * self.height];
        for (row, line) in self.cells.chunks_exact(self.width.max(1)).enumerate() {
            let top = self.height - 1 - row;
            let out = &mut grey[top * self.width..(top + 1) * self.width];
            for (g, &l) in out.iter_mut().zip(line) {
                *g = if l > occ {
                    0
                } else if l < free {
                    254
                } else {
                    205
                };
            }
        }
        GreyMap {
            width: self.width as u32,
            height: self.height as u32,
            resolution_m: self.resolution_m,
            origin_m: self.origin_m,
            grey,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(params: LogOddsParams) -> LogOddsMap {
        LogOddsMap::covering([0.0, 0.0, 1.0, 1.0], 0.0, 0.1, params).unwrap()
    }

    #[test]
    fn beam_frees_its_path_and_occupies_its_end() {
        let mut m = map(LogOddsParams::default());
        m.update_beam([0.05, 0.05], [0.75, 0.05], true);
        for x in 0..7 {
            assert_eq!(m.get(x, 0), Some(-0.7));
        }
        assert_eq!(m.get(7, 0), Some(0.85));
        assert_eq!(m.get(8, 0), Some(0.0));
        assert_eq!(m.get(0, 1), Some(0.0));
    }

    #[test]
    fn log_odds_are_clamped() {
        let mut m = map(LogOddsParams::default());
        for _ in 0..100 {
            m.update_beam([0.05, 0.55], [0.35, 0.55], true);
        }
        assert_eq!(m.get(0, 5), Some(-2.0));
        assert_eq!(m.get(3, 5), Some(3.5));
        let g = m.to_grey();
        // row 5 from the bottom is row 4 from the top
        assert_eq!(&g.grey[40..45], &[254, 254, 254, 0, 205]);
    }

    #[test]
    fn beams_leaving_the_map_do_not_panic() {
        let mut m = map(LogOddsParams::default());
        m.update_beam([-5.0, -5.0], [7.0, 3.0], true);
        m.update_beam([0.5, 0.5], [0.5, 90.0], false);
        assert!(m.get(5, 9).unwrap() < 0.0);
    }

    #[test]
    fn bad_resolution_is_named() {
        for r in [0.0, -1.0, f64::NAN] {
            let e = LogOddsMap::covering([0.0; 4], 1.0, r, LogOddsParams::default());
            assert!(e.unwrap_err().to_string().contains("--resolution"));
        }
    }
}
