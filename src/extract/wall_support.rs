//! Wall support: whether a door-wide constriction between two regions is a
//! doorway in the building's walls or a gap between pieces of clutter.
//!
//! The idea is ROSE²'s (Luperto et al., RA-L 2022): rooms are cells bounded
//! by the building's walls, which are long, straight and run along the
//! map's few dominant directions; cells whose shared edge has no wall on
//! it are one room. Here it judges the borders the watershed draws at
//! door-wide constrictions that no wall gap marks (doorways found by
//! `wall_gaps.rs` are never judged). Such a border is **unsupported**, and
//! its two regions are one, when its line runs along a dominant direction
//! (within [`MIN_COS`]) where the walls follow those directions (a long run
//! within [`SupportLimits::near`] of its middle), and
//! - no long run of wall face ([`SupportLimits::long_run`]) goes on in line
//!   beyond either end (the wall the doorway is cut in);
//! - no long run across the line passes either end (a reveal, or the wall
//!   the doorway opens from);
//! - and the two ends are not both ends of shorter in-line runs
//!   ([`SupportLimits::pair_run`]): aligned wall ends facing each other.
//!
//! Anywhere else the rule abstains and the border stays. Lengths are in
//! pixels here; `pixel_config.rs` sets them in metres.

use super::wall_runs::{Run, WallRuns, along, project};
use crate::grid::{Cell, OccupancyGrid};

/// A doorway line is along a dominant direction when the cosine of the
/// angle between them is at least this (about 10 degrees).
pub(crate) const MIN_COS: f64 = 0.985;

/// The wall support rule's lengths, in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SupportLimits {
    /// Shortest run of wall face that supports a doorway by itself.
    pub long_run: f64,
    /// Shortest in-line runs that support a doorway when both ends have one.
    pub pair_run: f64,
    /// Longest break bridged in a run, whole pixels.
    pub gap: i64,
    /// How far across its line a run may lie from a doorway end, whole
    /// pixels.
    pub tolerance: i64,
    /// How far along its line a run may end from a doorway end.
    pub reach: f64,
    /// How far from a doorway's middle a long run shows that the walls
    /// there follow the dominant directions.
    pub near: f64,
}

/// The wall runs of one map, ready to judge borders.
pub(crate) struct WallSupport {
    runs: WallRuns,
    width: u32,
    limits: SupportLimits,
}

impl WallSupport {
    /// The runs of wall face (cells that are not free next to a free one)
    /// of `grid`, along its dominant directions `deg` and a quarter turn
    /// from it (degrees, see `imaging::dominant_orientation`).
    pub(crate) fn new(grid: &OccupancyGrid, deg: f64, limits: SupportLimits) -> WallSupport {
        let (w, h) = (grid.width as usize, grid.height as usize);
        let is_free = |x: usize, y: usize| grid.cells[y * w + x] == Cell::Free;
        let mut face = Vec::new();
        for y in 0..h {
            for x in 0..w {
                let edge = !is_free(x, y)
                    && ((x > 0 && is_free(x - 1, y))
                        || (x + 1 < w && is_free(x + 1, y))
                        || (y > 0 && is_free(x, y - 1))
                        || (y + 1 < h && is_free(x, y + 1)));
                if edge {
                    face.push([x as u32, y as u32]);
                }
            }
        }
        let min_run = limits.long_run.min(limits.pair_run);
        WallSupport {
            runs: WallRuns::new(&face, deg, min_run, limits.gap),
            width: grid.width,
            limits,
        }
    }

    /// Whether the border through `pixels` (indices into the grid) is
    /// judged and has no wall support (see the module doc).
    pub(crate) fn lacks(&self, pixels: &[u32]) -> bool {
        border_ends(self.width, pixels).is_some_and(|(a, b)| self.supported(a, b) == Some(false))
    }

    /// Whether the doorway `a`–`b` (pixels) has wall support; `None` where
    /// the rule abstains.
    fn supported(&self, a: [f64; 2], b: [f64; 2]) -> Option<bool> {
        let l = &self.limits;
        let d = [b[0] - a[0], b[1] - a[1]];
        let len = d[0].hypot(d[1]);
        if len <= 0.0 {
            return None;
        }
        let k =
            (0..2).find(|&k| (project(d, along(self.runs.across(k))) / len).abs() >= MIN_COS)?;
        let middle = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
        if !self.walls_near(middle) {
            return None;
        }
        let in_line = |min: f64| self.in_line(k, a, b, min);
        let long = in_line(l.long_run);
        if long.0 || long.1 || self.across_end(1 - k, a) || self.across_end(1 - k, b) {
            return Some(true);
        }
        let pair = in_line(l.pair_run);
        Some(pair.0 && pair.1)
    }

    /// Whether a long run lies within `near` of `p`.
    fn walls_near(&self, p: [f64; 2]) -> bool {
        let (near, long) = (self.limits.near, self.limits.long_run);
        (0..2).any(|k| {
            let across = self.runs.across(k);
            let t = project(p, along(across));
            self.runs
                .near(k, project(p, across), near.round() as i64)
                .any(|r| length(r) >= long && r.0 as f64 <= t + near && r.1 as f64 >= t - near)
        })
    }

    /// Whether each end of `a`–`b`, which runs along direction `k`, has a
    /// run of at least `min` going on in line beyond it.
    fn in_line(&self, k: usize, a: [f64; 2], b: [f64; 2], min: f64) -> (bool, bool) {
        let across = self.runs.across(k);
        let t = |p| project(p, along(across));
        let (lo, hi) = if t(a) <= t(b) { (a, b) } else { (b, a) };
        let l = &self.limits;
        let beyond = |p: [f64; 2], outward: f64| {
            let tp = t(p);
            self.runs
                .near(k, project(p, across), l.tolerance)
                .filter(|&r| length(r) >= min)
                .any(|(r0, r1)| {
                    let (r0, r1) = (r0 as f64, r1 as f64);
                    if outward < 0.0 {
                        (r1 - tp).abs() <= l.reach && r0 < tp
                    } else {
                        (r0 - tp).abs() <= l.reach && r1 > tp
                    }
                })
        };
        (beyond(lo, -1.0), beyond(hi, 1.0))
    }

    /// Whether a long run along direction `k` (across the doorway) passes
    /// end `p` or ends near it.
    fn across_end(&self, k: usize, p: [f64; 2]) -> bool {
        let l = &self.limits;
        let across = self.runs.across(k);
        let t = project(p, along(across));
        self.runs.near(k, project(p, across), l.tolerance).any(|r| {
            length(r) >= l.long_run && r.0 as f64 - l.reach <= t && t <= r.1 as f64 + l.reach
        })
    }
}

/// A run's length in pixels.
fn length(r: Run) -> f64 {
    (r.1 - r.0 + 1) as f64
}

/// The two ends (pixels `[x, y]`) of a border through `pixels` (indices
/// into a `width`-wide grid): its extremes along its principal axis.
fn border_ends(width: u32, pixels: &[u32]) -> Option<([f64; 2], [f64; 2])> {
    if pixels.len() < 2 || width == 0 {
        return None;
    }
    let pts: Vec<[f64; 2]> = pixels
        .iter()
        .map(|&p| [f64::from(p % width), f64::from(p / width)])
        .collect();
    let n = pts.len() as f64;
    let m = pts
        .iter()
        .fold([0.0; 2], |s, p| [s[0] + p[0] / n, s[1] + p[1] / n]);
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for p in &pts {
        let (dx, dy) = (p[0] - m[0], p[1] - m[1]);
        sxx += dx * dx;
        sxy += dx * dy;
        syy += dy * dy;
    }
    let angle = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    let u = [angle.cos(), angle.sin()];
    let t = |p: &[f64; 2]| (p[0] - m[0]) * u[0] + (p[1] - m[1]) * u[1];
    let lo = pts.iter().min_by(|a, b| t(a).total_cmp(&t(b)))?;
    let hi = pts.iter().max_by(|a, b| t(a).total_cmp(&t(b)))?;
    Some((*lo, *hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The limits `pixel_config` sets at 0.1 m/px.
    const AT_10_CM: SupportLimits = SupportLimits {
        long_run: 15.0,
        pair_run: 10.0,
        gap: 1,
        tolerance: 5,
        reach: 6.0,
        near: 20.0,
    };

    /// A `w` x `h` grid at 0.1 m/px, walled round, with `wall(x, y)` cells
    /// occupied inside.
    fn grid(w: usize, h: usize, wall: impl Fn(usize, usize) -> bool) -> WallSupport {
        let rows: Vec<String> = (0..h)
            .map(|y| {
                (0..w)
                    .map(|x| {
                        let edge = x == 0 || y == 0 || x == w - 1 || y == h - 1;
                        if edge || wall(x, y) { '#' } else { '.' }
                    })
                    .collect()
            })
            .collect();
        WallSupport::new(
            &OccupancyGrid::from_ascii(&rows.join("\n"), 0.1),
            0.0,
            AT_10_CM,
        )
    }

    #[test]
    fn a_doorway_in_a_long_wall_is_supported() {
        // Two 4 m rooms: a wall at x = 40, its doorway y 30..38 (0.8 m).
        let s = grid(81, 60, |x, y| x == 40 && !(30..38).contains(&y));
        assert_eq!(s.supported([40.0, 30.0], [40.0, 37.0]), Some(true));
    }

    #[test]
    fn aligned_wall_ends_support_a_doorway_as_a_pair() {
        // A 1.1 m wall piece each side of a 0.8 m opening, standing free
        // 2 m into a 6 m room: short, but in line and facing each other.
        let piece = |x: usize, y: usize| y == 20 && ((9..20).contains(&x) || (28..39).contains(&x));
        let s = grid(60, 60, piece);
        assert_eq!(s.supported([20.0, 20.0], [27.0, 20.0]), Some(true));
        // One end alone is not enough.
        let one = grid(60, 60, |x, y| y == 20 && (9..20).contains(&x));
        assert_eq!(one.supported([20.0, 20.0], [27.0, 20.0]), Some(false));
    }

    #[test]
    fn a_gap_between_clutter_near_walls_is_unsupported() {
        // Two 0.5 m blocks 0.8 m apart, 1.5 m from a 6 m room's wall.
        let blocks = |x: usize, y: usize| {
            (14..19).contains(&y) && ((20..25).contains(&x) || (33..38).contains(&x))
        };
        let s = grid(60, 60, blocks);
        assert_eq!(s.supported([25.0, 16.0], [32.0, 16.0]), Some(false));
        assert!(!s.lacks(&[]), "no border, nothing to judge");
    }

    #[test]
    fn the_rule_abstains_off_the_walls_directions_and_far_from_walls() {
        let s = grid(60, 60, |_, _| false);
        // A diagonal doorway line.
        assert_eq!(s.supported([20.0, 20.0], [25.0, 25.0]), None);
        // A doorway line in the middle of a 10 m hall, 4.5 m from its walls.
        let hall = grid(101, 101, |_, _| false);
        assert_eq!(hall.supported([46.0, 50.0], [54.0, 50.0]), None);
    }
}
