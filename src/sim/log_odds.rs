//! Occupancy mapping with known poses, by one of two rules
//! ([`OccupancyRule`]):
//!
//! - **log-odds** updates (the paper's Eq. 3, after Thrun et al. 2005):
//!   `l_t = tau_t - l_0 + l_{t-1}`, where the inverse sensor model `tau`
//!   gives `l_free` to every cell a beam crosses and `l_occ` to the cell it
//!   ends in, clamped to `[l_min, l_max]`. Recent beams outweigh old ones:
//!   a wall cell crossed by enough beams after its hits turns free.
//! - **hit ratio** (the counting or reflection model of GMapping's and
//!   Karto's maps): a cell is occupied when at least `min_ratio` of the
//!   beams that reached it ended in it, free otherwise, unknown when fewer
//!   than `min_visits` reached it. The order of the beams does not matter,
//!   so the walls of a corridor stay when, late in a log, beams down the
//!   corridor graze them (with the small pose and bearing errors of a real
//!   log, each such beam crosses a wall cell or two).

use super::SimError;
use super::bresenham::bresenham;
use super::lidar::Scan;
use crate::model::Point;

/// The most cells a map may have (one `f32` each, or two `u32` under the
/// hit-ratio rule: at most 1.6 GB).
pub const MAX_CELLS: usize = 200_000_000;

/// How a cell's beams decide what it is (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum OccupancyRule {
    /// Log-odds updates with the `l_*` fields of [`LogOddsParams`].
    LogOdds,
    /// Occupied when at least `min_ratio` of the beams reaching the cell
    /// ended in it; unknown when fewer than `min_visits` reached it.
    HitRatio {
        /// Smallest share of hits among visits for an occupied cell (0..1].
        min_ratio: f32,
        /// Fewest beams (hits and crossings) for a known cell.
        min_visits: u32,
    },
}

impl OccupancyRule {
    /// The hit-ratio rule with GMapping's threshold (`occ_thresh` 0.25)
    /// and two visits at least (Karto's `minPassThrough`): what recorded
    /// logs are mapped with.
    pub const RECORDED: OccupancyRule = OccupancyRule::HitRatio {
        min_ratio: 0.25,
        min_visits: 2,
    };
}

/// Inverse sensor model and beam handling of the mapper.
#[derive(Debug, Clone, PartialEq)]
pub struct LogOddsParams {
    /// What the beams make of a cell.
    pub rule: OccupancyRule,
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
            rule: OccupancyRule::LogOdds,
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

/// What the mapper keeps per cell, row 0 at the bottom (y up): log-odds,
/// or hits and crossings for the hit-ratio rule.
#[derive(Debug, Clone)]
pub struct LogOddsMap {
    width: usize,
    height: usize,
    resolution_m: f64,
    origin_m: Point,
    /// Log-odds per cell (the log-odds rule; empty otherwise).
    cells: Vec<f32>,
    /// Hits and crossings per cell (the hit-ratio rule; empty otherwise).
    counts: Vec<[u32; 2]>,
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
        let n = width * height;
        let (cells, counts) = match params.rule {
            OccupancyRule::LogOdds => (vec![params.l_prior; n], Vec::new()),
            OccupancyRule::HitRatio { .. } => (Vec::new(), vec![[0, 0]; n]),
        };
        Ok(LogOddsMap {
            width,
            height,
            resolution_m,
            origin_m: [bounds[0] - margin_m, bounds[1] - margin_m],
            cells,
            counts,
            params,
        })
    }

    /// Columns and rows.
    pub fn size(&self) -> (usize, usize) {
        (self.width, self.height)
    }

    /// The log-odds of cell `(col, row)`, row 0 at the bottom (`None`
    /// outside the map or under the hit-ratio rule).
    pub fn get(&self, col: usize, row: usize) -> Option<f32> {
        (col < self.width).then(|| self.cells.get(row * self.width + col).copied())?
    }

    /// The hits and crossings of cell `(col, row)`, row 0 at the bottom
    /// (`None` outside the map or under the log-odds rule).
    pub fn counts(&self, col: usize, row: usize) -> Option<[u32; 2]> {
        (col < self.width).then(|| self.counts.get(row * self.width + col).copied())?
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

    /// One beam from `from` to `to` (metres): cells crossed get `l_free`
    /// (or a crossing), the end cell `l_occ` (or a hit) when `hit` (else
    /// it is crossed too). Cells outside the map are ignored.
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
        let inside = move |x: i64, y: i64| {
            (x >= 0 && y >= 0 && x < w && y < h).then(|| (y * w + x) as usize)
        };
        // One loop per rule, so the log-odds loop stays as it was.
        if matches!(p.rule, OccupancyRule::LogOdds) {
            let cells = &mut self.cells;
            bresenham(x0, y0, x1, y1, |x, y| {
                let tau = if hit && x == x1 && y == y1 { occ } else { free };
                if let Some(c) = inside(x, y).and_then(|i| cells.get_mut(i)) {
                    *c = (*c + tau).clamp(lo, hi);
                }
            });
        } else {
            let counts = &mut self.counts;
            bresenham(x0, y0, x1, y1, |x, y| {
                let k = usize::from(!(hit && x == x1 && y == y1));
                if let Some(c) = inside(x, y).and_then(|i| counts.get_mut(i)) {
                    c[k] = c[k].saturating_add(1);
                }
            });
        }
    }

    /// The map in ROS trinary grey: occupied 0, free 254, unknown 205.
    /// Log-odds: occupied when p > 0.65, free when p < 0.196 (the
    /// thresholds `map.yaml` states); hit ratio: as its rule says.
    pub fn to_grey(&self) -> GreyMap {
        let occ = (0.65f32 / 0.35).ln();
        let free = (0.196f32 / 0.804).ln();
        let class = |i: usize| -> u8 {
            match self.params.rule {
                OccupancyRule::LogOdds => {
                    let l = self.cells[i];
                    if l > occ {
                        0
                    } else if l < free {
                        254
                    } else {
                        205
                    }
                }
                OccupancyRule::HitRatio {
                    min_ratio,
                    min_visits,
                } => {
                    let [hits, crossings] = self.counts[i];
                    let visits = hits.saturating_add(crossings);
                    if visits < min_visits.max(1) {
                        205
                    } else if f64::from(hits) >= f64::from(min_ratio) * f64::from(visits) {
                        0
                    } else {
                        254
                    }
                }
            }
        };
        let mut grey = vec![205u8; self.width * self.height];
        for row in 0..self.height {
            let top = self.height - 1 - row;
            for col in 0..self.width {
                grey[top * self.width + col] = class(row * self.width + col);
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

    /// A wall cell (column 7 of row 0) hit by `hits` beams and crossed by
    /// `crossings` beams that graze past it, hits first or last.
    fn wall_cell(params: LogOddsParams, hits: usize, crossings: usize, hits_first: bool) -> u8 {
        let mut m = map(params);
        let hit = |m: &mut LogOddsMap| m.update_beam([0.05, 0.05], [0.75, 0.05], true);
        let graze = |m: &mut LogOddsMap| m.update_beam([0.05, 0.05], [0.95, 0.05], true);
        for pass in [hits_first, !hits_first] {
            for _ in 0..if pass { hits } else { crossings } {
                if pass { hit(&mut m) } else { graze(&mut m) }
            }
        }
        m.to_grey().grey[9 * 10 + 7]
    }

    #[test]
    fn a_wall_grazed_after_its_hits_stays_under_the_hit_ratio() {
        let log_odds = LogOddsParams::default();
        let ratio = LogOddsParams {
            rule: OccupancyRule::RECORDED,
            ..LogOddsParams::default()
        };
        // 5 hits, then 10 crossings: log-odds forgets the wall.
        assert_eq!(wall_cell(log_odds.clone(), 5, 10, true), 254);
        assert_eq!(wall_cell(log_odds, 5, 10, false), 0);
        // The hit ratio (5 of 15) keeps it, in either order...
        assert_eq!(wall_cell(ratio.clone(), 5, 10, true), 0);
        assert_eq!(wall_cell(ratio.clone(), 5, 10, false), 0);
        // ...and frees a cell hit by under a quarter of its beams (3 of 15).
        assert_eq!(wall_cell(ratio.clone(), 3, 12, true), 254);
        // One beam is not enough to know a cell.
        assert_eq!(wall_cell(ratio, 1, 0, true), 205);
    }

    #[test]
    fn the_hit_ratio_rule_counts_and_keeps_no_log_odds() {
        let mut m = map(LogOddsParams {
            rule: OccupancyRule::RECORDED,
            ..LogOddsParams::default()
        });
        m.update_beam([0.05, 0.05], [0.35, 0.05], true);
        assert_eq!(m.counts(0, 0), Some([0, 1]));
        assert_eq!(m.counts(3, 0), Some([1, 0]));
        assert_eq!(m.counts(4, 0), Some([0, 0]));
        assert_eq!(m.get(0, 0), None);
    }

    #[test]
    fn bad_resolution_is_named() {
        for r in [0.0, -1.0, f64::NAN] {
            let e = LogOddsMap::covering([0.0; 4], 1.0, r, LogOddsParams::default());
            assert!(e.unwrap_err().to_string().contains("--resolution"));
        }
    }
}
