//! Wall support: whether a door-wide constriction between two regions is a
//! doorway in the building's walls or a gap between pieces of clutter.
//!
//! The idea is ROSE²'s (Luperto et al., RA-L 2022): rooms are cells bounded
//! by the building's walls, which are long, straight and run along the
//! map's few dominant directions; cells whose shared edge has no wall on
//! it are one room. Here it judges the doorway gaps `wall_gaps.rs` finds
//! (an unsupported one is dropped: a gap between pieces of clutter) and
//! the borders the watershed draws at door-wide constrictions that no
//! kept gap marks. Such a line is **unsupported**, and the regions on
//! either side are one, when it runs along a dominant direction, or along
//! a further one of a wing built at another angle
//! (`imaging::further_wall_directions`; each pair of directions has its
//! own runs), within [`MIN_COS`], where the walls follow those directions
//! (a long run within [`SupportLimits::near`] of its middle), and
//! - no long run of wall face ([`SupportLimits::long_run`]) goes on in line
//!   beyond either end (the wall the doorway is cut in);
//! - no long run across the line passes either end (a reveal, or the wall
//!   the doorway opens from);
//! - the two ends are not both ends of shorter in-line runs
//!   ([`SupportLimits::pair_run`]): aligned wall ends facing each other;
//! - and, for a doorway gap, the two ends are not both anchored: tied to
//!   the building (an in-line run of at least [`SupportLimits::tie_run`]
//!   beyond the end reaching a long wall across: a short partition between
//!   two walls) or on a wall line that goes on in pieces (in-line runs of
//!   at least `tie_run` adding up to `pair_run` within twice `long_run`
//!   beyond the end: a wall with several doorways). Borders are not judged
//!   so: on real maps clutter touching a room's walls is tied too.
//!
//! Anywhere else the rule abstains and the gap or border stays. A border
//! is also unsupported, at any angle, when an end of it lies on clutter
//! and on nothing else within [`SupportLimits::end_reach`]: an island
//! standing free, small and no piece of wall (`furniture::clutter_pixels`).
//! So is a doorway gap, unless that island lies on the building's wall
//! lines (at least [`JAMB_ON_LINE_MIN_FRACTION`] of its outline; see
//! `clutter::WallLines`): the piece of wall between two doorways of a wall
//! that stands in short pieces. A border is drawn anywhere a room narrows;
//! a doorway gap is already a break in a line of wall. Lengths are in
//! pixels here; `pixel_config.rs` sets them in metres.

use super::clutter::{LineLimits, WallLines, on_wall_lines};
use super::furniture::{Islands, clutter_pixels};
use super::wall_runs::{Run, WallRuns, along, project};
use crate::grid::{Cell, OccupancyGrid};

/// A doorway line is along a dominant direction when the cosine of the
/// angle between them is at least this (about 10 degrees).
pub(crate) const MIN_COS: f64 = 0.985;

/// A clutter island with at least this share of its outline on the
/// building's wall lines is a jamb for a doorway gap (a piece of a wall
/// that stands in short pieces). Measured on the 19 development buildings
/// (benches/README.md, "Clutter is no jamb for doorway gaps either"): 0.01
/// to 0.35 measure the same; at 0.4, the clutter rule's own share
/// (`clutter::ON_LINE_MIN_FRACTION`), lab_ipa_furnitures loses three
/// doorways in a wall of blocks that furniture stands against.
pub(crate) const JAMB_ON_LINE_MIN_FRACTION: f64 = 0.25;

/// The wall support rule's lengths, in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SupportLimits {
    /// Shortest run of wall face that supports a doorway by itself.
    pub long_run: f64,
    /// Shortest in-line runs that support a doorway when both ends have one.
    pub pair_run: f64,
    /// Shortest in-line run that ties a doorway end to a long wall across
    /// (the jamb of `wall_jamb_m`).
    pub tie_run: f64,
    /// Longest break bridged in a run, whole pixels.
    pub gap: i64,
    /// How far across its line a run may lie from a doorway end, whole
    /// pixels.
    pub tolerance: i64,
    /// How far along its line a run may end from a doorway end.
    pub reach: f64,
    /// How far apart across (whole pixels, between the lines runs are
    /// kept on) the runs past a passage's two faces may lie and be one
    /// wall line (`crosses_passage`).
    pub side_line: i64,
    /// How far from a doorway's middle a long run shows that the walls
    /// there follow the dominant directions.
    pub near: f64,
    /// Widest island that can be clutter (see `furniture::clutter_pixels`).
    pub clutter_max: f64,
    /// An island at least this many times as long as thick is a piece of
    /// wall, not clutter.
    pub wall_elongation: f64,
    /// How far round a border's end its obstacles are looked at, whole
    /// pixels.
    pub end_reach: i64,
    /// What makes a wall line: clutter on one is a doorway gap's jamb.
    pub lines: LineLimits,
}

/// What a pixel is to a border's end.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Ground {
    /// Free space.
    Free,
    /// Clutter (see `furniture::clutter_pixels`): no jamb.
    Clutter,
    /// Clutter lying on the building's wall lines: a doorway gap's jamb,
    /// no border's.
    LinedClutter,
    /// Any other obstacle: a wall, or what the sensor could not see.
    Wall,
}

/// The wall runs of one map, ready to judge doorway gaps and borders.
pub(crate) struct WallSupport {
    /// The runs along the dominant directions, then along each further one.
    runs: Vec<WallRuns>,
    /// The same directions' runs of the building's own walls: without the
    /// faces of clutter, lined or not (what tells a passage's side wall
    /// from a table standing near an opening's end).
    building_runs: Vec<WallRuns>,
    /// Per pixel: what a border's end may lie on.
    ground: Vec<Ground>,
    width: u32,
    height: u32,
    limits: SupportLimits,
}

impl WallSupport {
    /// The runs of wall face (cells that are not free next to a free one)
    /// of `grid`, along its dominant directions `deg` and a quarter turn
    /// from it (degrees, see `imaging::dominant_orientation`). Clutter lies
    /// on wall lines along those directions or along the `further` ones of
    /// wings built at other angles (see `imaging::further_wall_directions`).
    pub(crate) fn new(
        grid: &OccupancyGrid,
        islands: &Islands,
        deg: f64,
        further: &[f64],
        limits: SupportLimits,
    ) -> WallSupport {
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
        let min_run = limits.long_run.min(limits.pair_run).min(limits.tie_run);
        let mut ground: Vec<Ground> = grid
            .cells
            .iter()
            .zip(clutter_pixels(
                islands,
                limits.clutter_max,
                limits.wall_elongation,
            ))
            .map(|(c, clutter)| match (c, clutter) {
                (Cell::Free, _) => Ground::Free,
                (_, true) => Ground::Clutter,
                _ => Ground::Wall,
            })
            .collect();
        for &d in std::iter::once(&deg).chain(further) {
            mark_lined_clutter(&mut ground, grid, islands, &face, d, &limits.lines);
        }
        let building_face: Vec<[u32; 2]> = face
            .iter()
            .copied()
            .filter(|p| ground[p[1] as usize * w + p[0] as usize] == Ground::Wall)
            .collect();
        let directions: Vec<f64> = std::iter::once(deg)
            .chain(further.iter().copied())
            .collect();
        // The two sets of runs, one on each core.
        let runs_of = |face: &[[u32; 2]]| -> Vec<WallRuns> {
            directions
                .iter()
                .map(|&d| WallRuns::new(face, d, min_run, limits.gap))
                .collect()
        };
        let (runs, building_runs) = std::thread::scope(|scope| {
            let building = scope.spawn(|| runs_of(&building_face));
            let runs = runs_of(&face);
            let building = building
                .join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic));
            (runs, building)
        });
        WallSupport {
            runs,
            building_runs,
            ground,
            width: grid.width,
            height: grid.height,
            limits,
        }
    }

    /// Whether the border through `pixels` (indices into the grid) has no
    /// wall support: an end of it lies on clutter, or it is judged and
    /// unsupported (see the module doc).
    pub(crate) fn lacks(&self, pixels: &[u32]) -> bool {
        border_ends(self.width, pixels).is_some_and(|(a, b)| {
            self.on_clutter(a, false)
                || self.on_clutter(b, false)
                || self.supported(a, b, false) == Some(false)
        })
    }

    /// Whether the obstacles within `end_reach` of `p` are all clutter
    /// (and there are some): a border's end on a piece of furniture, not
    /// on a jamb. For a doorway gap's end (`gap`), clutter on the wall
    /// lines is a jamb.
    fn on_clutter(&self, p: [f64; 2], gap: bool) -> bool {
        let mut any = false;
        for ground in self.disc(p, self.limits.end_reach) {
            match ground {
                Ground::Free => {}
                Ground::Clutter => any = true,
                Ground::LinedClutter if !gap => any = true,
                Ground::LinedClutter | Ground::Wall => return false,
            }
        }
        any
    }

    /// What lies at each pixel within `r` pixels of `p` (a disc, clipped
    /// to the grid).
    fn disc(&self, p: [f64; 2], r: i64) -> impl Iterator<Item = Ground> + '_ {
        let (w, h) = (i64::from(self.width), i64::from(self.height));
        let (cx, cy) = (p[0].round() as i64, p[1].round() as i64);
        ((cy - r).max(0)..=(cy + r).min(h - 1)).flat_map(move |y| {
            ((cx - r).max(0)..=(cx + r).min(w - 1))
                .filter(move |x| (x - cx).pow(2) + (y - cy).pow(2) <= r * r)
                .map(move |x| self.ground[(y * w + x) as usize])
        })
    }

    /// Whether the doorway gap whose line is `pixels` has an end on clutter
    /// off the wall lines, or is judged and has no wall support (a
    /// partition tied at both ends counting as support).
    pub(crate) fn lacks_gap(&self, pixels: &[u32]) -> bool {
        border_ends(self.width, pixels).is_some_and(|(a, b)| {
            self.on_clutter(a, true)
                || self.on_clutter(b, true)
                || self.supported(a, b, true) == Some(false)
        })
    }

    /// Whether the doorway gap whose line is `pixels` has wall support
    /// (not merely no finding against it): what every gap needs in a
    /// building with wings at other angles, where a line drawn along one
    /// pair of directions in a wing of another (across its corridor) gets
    /// no finding either way.
    pub(crate) fn backs_gap(&self, pixels: &[u32]) -> bool {
        border_ends(self.width, pixels)
            .is_some_and(|(a, b)| self.supported(a, b, true) == Some(true))
    }

    /// Whether the opening whose line is `pixels` crosses a passage: at one
    /// of its ends a wall line across (runs of at least `tie_run`, a jamb,
    /// within `tolerance` of the end's line) goes on more than `reach` past
    /// both faces of the wall, within twice `long_run`, **one** line on
    /// both faces (the runs past the two faces lie within `side_line` of
    /// each other across, not two walls that each pass the end at another
    /// distance, such as a room's side wall and the jamb of the next room's
    /// front); as a corridor's side walls do where the line joins two wall
    /// ends across it, or a room's front wall where the line runs from
    /// furniture standing out from the back wall to the front (with a
    /// doorway beside the end, the wall may go on past that face only in a
    /// short piece). A room's side wall meeting its front at an opening's
    /// end stops at the front. Only the building's walls count: a table or shelf near an opening's end
    /// (clutter, see `furniture::clutter_pixels`) is no passage's side,
    /// unless the end itself stands on clutter (within `tolerance`), where
    /// the line may run between two pieces of furniture. At an end beside
    /// a room's corner (`corner_ends`, for the line's first and last pixel;
    /// see `wall_gaps::WallGap::corner_ends`) the wall across is the room's
    /// side, which the opening's own piece of wall runs into, unless the
    /// other end has a wall passing both faces too: a line from one side
    /// of a corridor to the other, where the walls of the rooms either side
    /// stand out into it a little.
    pub(crate) fn crosses_passage(&self, pixels: &[u32], corner_ends: [bool; 2]) -> bool {
        let Some((a, b)) = border_ends(self.width, pixels) else {
            return false;
        };
        // Which of `a` and `b` is the line's first end.
        let first = pixels.first().map_or([0.0; 2], |&p| {
            [f64::from(p % self.width), f64::from(p / self.width)]
        });
        let dist = |p: [f64; 2]| (p[0] - first[0]).hypot(p[1] - first[1]);
        let [corner_a, corner_b] = if dist(a) <= dist(b) {
            corner_ends
        } else {
            [corner_ends[1], corner_ends[0]]
        };
        let Some((i, k)) = self.direction_set(a, b) else {
            return false;
        };
        let building = &self.building_runs[i];
        let l = &self.limits;
        let j = 1 - k;
        let across = building.across(j);
        let window = 2.0 * l.long_run;
        let both = |p: [f64; 2]| {
            let t = project(p, along(across));
            // An end standing on furniture has it for a jamb: its faces
            // count there, as they did before the rule.
            let runs = if self.clutter_within(p, l.tolerance) {
                &self.runs[i]
            } else {
                building
            };
            // The lines (offsets across) with a run past each face.
            let off = project(p, across).round() as i64;
            let (mut lower, mut upper) = (Vec::new(), Vec::new());
            for line in off - l.tolerance..=off + l.tolerance {
                for r in runs
                    .near(j, line as f64, 0)
                    .filter(|&r| length(r) >= l.tie_run)
                {
                    if (r.0 as f64) < t - l.reach && r.1 as f64 > t - window {
                        lower.push(line);
                    }
                    if r.1 as f64 > t + l.reach && (r.0 as f64) < t + window {
                        upper.push(line);
                    }
                }
            }
            lower
                .iter()
                .any(|a| upper.iter().any(|b| (a - b).abs() <= l.side_line))
        };
        match (both(a), both(b)) {
            (true, true) => true,
            (true, false) => !corner_a,
            (false, true) => !corner_b,
            (false, false) => false,
        }
    }

    /// Whether clutter (lined or not) lies within `r` pixels of `p`.
    fn clutter_within(&self, p: [f64; 2], r: i64) -> bool {
        self.disc(p, r)
            .any(|g| matches!(g, Ground::Clutter | Ground::LinedClutter))
    }

    /// Whether the doorway `a`–`b` (pixels) has wall support, judged
    /// along the wall directions it runs along; `None` where the rule
    /// abstains (see [`Judge::supported`]).
    fn supported(&self, a: [f64; 2], b: [f64; 2], ties: bool) -> Option<bool> {
        self.judge(a, b)?.0.supported(a, b, ties)
    }

    /// The runs of the first wall directions (the dominant ones, then the
    /// further ones) that line `a`–`b` runs along, within [`MIN_COS`], and
    /// which of their two directions (0 or 1) it is.
    fn judge(&self, a: [f64; 2], b: [f64; 2]) -> Option<(Judge<'_>, usize)> {
        let (i, k) = self.direction_set(a, b)?;
        Some((self.judge_on(i), k))
    }

    /// The index into [`WallSupport::runs`] of the first wall directions
    /// that line `a`–`b` runs along, within [`MIN_COS`], and which of
    /// their two directions (0 or 1) it is.
    fn direction_set(&self, a: [f64; 2], b: [f64; 2]) -> Option<(usize, usize)> {
        (0..self.runs.len()).find_map(|i| self.judge_on(i).direction(a, b).map(|k| (i, k)))
    }

    /// The rule along the `i`-th wall directions.
    fn judge_on(&self, i: usize) -> Judge<'_> {
        Judge {
            runs: &self.runs[i],
            limits: &self.limits,
        }
    }
}

/// The wall support rule along one pair of wall directions.
struct Judge<'a> {
    runs: &'a WallRuns,
    limits: &'a SupportLimits,
}

impl Judge<'_> {
    /// Whether the doorway `a`–`b` (pixels) has wall support; `None` where
    /// the rule abstains. With `ties`, both ends anchored support it
    /// ([`Self::tied`], [`Self::walled_line`]).
    fn supported(&self, a: [f64; 2], b: [f64; 2], ties: bool) -> Option<bool> {
        let l = self.limits;
        let k = self.direction(a, b)?;
        let middle = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
        if !self.walls_near(middle) {
            return None;
        }
        let in_line = |min: f64| self.in_line(k, a, b, min);
        let long = in_line(l.long_run);
        if long.0 || long.1 || self.across_end(1 - k, a) || self.across_end(1 - k, b) {
            return Some(true);
        }
        if ties {
            let tied = self.tied(k, a, b);
            let walled = self.walled_line(k, a, b);
            if (tied.0 || walled.0) && (tied.1 || walled.1) {
                return Some(true);
            }
        }
        let pair = in_line(l.pair_run);
        Some(pair.0 && pair.1)
    }

    /// The direction (0 or 1) line `a`–`b` runs along, within
    /// [`MIN_COS`].
    fn direction(&self, a: [f64; 2], b: [f64; 2]) -> Option<usize> {
        let d = [b[0] - a[0], b[1] - a[1]];
        let len = d[0].hypot(d[1]);
        if len <= 0.0 {
            return None;
        }
        (0..2).find(|&k| (project(d, along(self.runs.across(k))) / len).abs() >= MIN_COS)
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
        let [lo, hi] = self.ends_beyond(k, a, b, min, |_| true);
        (lo, hi)
    }

    /// Whether each end of `a`–`b`, which runs along direction `k`, has an
    /// in-line run of at least `tie_run` going on beyond it to a long wall
    /// across (see [`Self::across_end`]): the piece of wall the doorway is
    /// cut in, however short, is tied to the building.
    fn tied(&self, k: usize, a: [f64; 2], b: [f64; 2]) -> (bool, bool) {
        let [lo, hi] = self.ends_beyond(k, a, b, self.limits.tie_run, |far| {
            self.across_end(1 - k, far)
        });
        (lo, hi)
    }

    /// Whether, beyond each end of `a`–`b` (along direction `k`) and within
    /// twice `long_run` of it, runs of at least `tie_run` on the doorway's
    /// line cover `pair_run` of it: the wall the doorway is in goes on, in
    /// pieces (between further doorways).
    fn walled_line(&self, k: usize, a: [f64; 2], b: [f64; 2]) -> (bool, bool) {
        let (across, [lo, hi]) = self.frame(k, a, b);
        let u = along(across);
        let t = |p| project(p, u);
        let l = self.limits;
        let window = 2.0 * l.long_run;
        let covered = |p: [f64; 2], outward: f64| {
            let tp = t(p);
            let (w0, w1) = if outward < 0.0 {
                (tp - window, tp)
            } else {
                (tp, tp + window)
            };
            // The along-line stretch they cover, once (a wall's two faces
            // lie side by side).
            let mut pieces: Vec<(f64, f64)> = self
                .runs
                .near(k, project(p, across), l.tolerance)
                .filter(|&r| length(r) >= l.tie_run)
                .map(|(r0, r1)| ((r0 as f64).max(w0), (r1 as f64 + 1.0).min(w1)))
                .filter(|(a, b)| b > a)
                .collect();
            pieces.sort_by(|x, y| x.0.total_cmp(&y.0));
            let mut covered = 0.0;
            let mut reached = f64::NEG_INFINITY;
            for (a, b) in pieces {
                covered += (b - a.max(reached)).max(0.0);
                reached = reached.max(b);
            }
            covered >= l.pair_run
        };
        (covered(lo, -1.0), covered(hi, 1.0))
    }

    /// Direction `k`'s unit vector across, and the ends of `a`–`b`
    /// ordered along the direction.
    fn frame(&self, k: usize, a: [f64; 2], b: [f64; 2]) -> ((f64, f64), [[f64; 2]; 2]) {
        let across = self.runs.across(k);
        let u = along(across);
        let ends = if project(a, u) <= project(b, u) {
            [a, b]
        } else {
            [b, a]
        };
        (across, ends)
    }

    /// For the lower and the upper end of `a`–`b` along direction `k`:
    /// whether a run of at least `min` starts within `reach` of it and goes
    /// on outwards, with `accept(far)` true for the run's far end (a point
    /// on the doorway's line).
    fn ends_beyond(
        &self,
        k: usize,
        a: [f64; 2],
        b: [f64; 2],
        min: f64,
        accept: impl Fn([f64; 2]) -> bool,
    ) -> [bool; 2] {
        let (across, [lo, hi]) = self.frame(k, a, b);
        let u = along(across);
        let t = |p| project(p, u);
        let l = self.limits;
        let beyond = |p: [f64; 2], outward: f64| {
            let tp = t(p);
            self.runs
                .near(k, project(p, across), l.tolerance)
                .filter(|&r| length(r) >= min)
                .filter_map(|(r0, r1)| {
                    let (r0, r1) = (r0 as f64, r1 as f64);
                    if outward < 0.0 {
                        ((r1 - tp).abs() <= l.reach && r0 < tp).then_some(r0)
                    } else {
                        ((r0 - tp).abs() <= l.reach && r1 > tp).then_some(r1)
                    }
                })
                .any(|far| accept([p[0] + (far - tp) * u.0, p[1] + (far - tp) * u.1]))
        };
        [beyond(lo, -1.0), beyond(hi, 1.0)]
    }

    /// Whether a long run along direction `k` (across the doorway) passes
    /// end `p` or ends near it.
    fn across_end(&self, k: usize, p: [f64; 2]) -> bool {
        let l = self.limits;
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

/// Marks as [`Ground::LinedClutter`] the clutter islands of `ground` with
/// at least [`JAMB_ON_LINE_MIN_FRACTION`] of their outline on the wall
/// lines (along `deg` and a quarter turn from it) of the faces in `face`
/// that are no clutter.
fn mark_lined_clutter(
    ground: &mut [Ground],
    grid: &OccupancyGrid,
    islands: &Islands,
    face: &[[u32; 2]],
    deg: f64,
    limits: &LineLimits,
) {
    let w = grid.width as usize;
    let wall_face: Vec<[u32; 2]> = face
        .iter()
        .copied()
        .filter(|p| ground[p[1] as usize * w + p[0] as usize] == Ground::Wall)
        .collect();
    let lines = WallLines::new(&wall_face, deg, limits);
    let h = grid.height as usize;
    let free = |x: usize, y: usize| ground[y * w + x] == Ground::Free;
    let mut outlines: Vec<Vec<[u32; 2]>> = vec![Vec::new(); islands.pieces.count as usize + 1];
    for r in &islands.pieces.runs {
        let y = r.y as usize;
        for x in r.x0 as usize..r.x1 as usize {
            let outline = ground[y * w + x] == Ground::Clutter
                && ((x > 0 && free(x - 1, y))
                    || (x + 1 < w && free(x + 1, y))
                    || (y > 0 && free(x, y - 1))
                    || (y + 1 < h && free(x, y + 1)));
            if outline {
                outlines[r.label as usize].push([x as u32, y as u32]);
            }
        }
    }
    let lined: Vec<bool> = outlines
        .iter()
        .map(|o| on_wall_lines(o, &lines, JAMB_ON_LINE_MIN_FRACTION))
        .collect();
    for r in islands
        .pieces
        .runs
        .iter()
        .filter(|r| lined[r.label as usize])
    {
        let i = r.y as usize * w;
        ground[i + r.x0 as usize..i + r.x1 as usize].fill(Ground::LinedClutter);
    }
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
#[path = "wall_support_tests.rs"]
mod tests;
