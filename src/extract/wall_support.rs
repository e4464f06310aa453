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
        WallSupport {
            runs: directions
                .iter()
                .map(|&d| WallRuns::new(&face, d, min_run, limits.gap))
                .collect(),
            building_runs: directions
                .iter()
                .map(|&d| WallRuns::new(&building_face, d, min_run, limits.gap))
                .collect(),
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
        let r = self.limits.end_reach;
        let (w, h) = (i64::from(self.width), i64::from(self.height));
        let (cx, cy) = (p[0].round() as i64, p[1].round() as i64);
        let mut any = false;
        for y in (cy - r).max(0)..=(cy + r).min(h - 1) {
            for x in (cx - r).max(0)..=(cx + r).min(w - 1) {
                if (x - cx).pow(2) + (y - cy).pow(2) > r * r {
                    continue;
                }
                match self.ground[(y * w + x) as usize] {
                    Ground::Free => {}
                    Ground::Clutter => any = true,
                    Ground::LinedClutter if !gap => any = true,
                    Ground::LinedClutter | Ground::Wall => return false,
                }
            }
        }
        any
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
    /// both faces of the wall, within twice `long_run`; as a corridor's side
    /// walls do where the line joins two wall ends across it, or a room's
    /// front wall where the line runs from furniture standing out from the
    /// back wall to the front (with a doorway beside the end, the wall may
    /// go on past that face only in a short piece). A room's side wall
    /// meeting its front at an opening's end stops at the front. Only the
    /// building's walls count: a table or shelf near an opening's end
    /// (clutter, see `furniture::clutter_pixels`) is no passage's side,
    /// unless the end itself stands on clutter (within `tolerance`), where
    /// the line may run between two pieces of furniture.
    pub(crate) fn crosses_passage(&self, pixels: &[u32]) -> bool {
        let Some((a, b)) = border_ends(self.width, pixels) else {
            return false;
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
            let runs: Vec<Run> = runs
                .near(j, project(p, across), l.tolerance)
                .filter(|&r| length(r) >= l.tie_run)
                .collect();
            let lower = runs
                .iter()
                .any(|r| (r.0 as f64) < t - l.reach && r.1 as f64 > t - window);
            let upper = runs
                .iter()
                .any(|r| r.1 as f64 > t + l.reach && (r.0 as f64) < t + window);
            lower && upper
        };
        both(a) || both(b)
    }

    /// Whether clutter (lined or not) lies within `r` pixels of `p`.
    fn clutter_within(&self, p: [f64; 2], r: i64) -> bool {
        let (w, h) = (i64::from(self.width), i64::from(self.height));
        let (cx, cy) = (p[0].round() as i64, p[1].round() as i64);
        ((cy - r).max(0)..=(cy + r).min(h - 1)).any(|y| {
            ((cx - r).max(0)..=(cx + r).min(w - 1)).any(|x| {
                (x - cx).pow(2) + (y - cy).pow(2) <= r * r
                    && matches!(
                        self.ground[(y * w + x) as usize],
                        Ground::Clutter | Ground::LinedClutter
                    )
            })
        })
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
mod tests {
    use super::*;
    use crate::extract::furniture::islands;

    /// The limits `pixel_config` sets at 0.1 m/px.
    const AT_10_CM: SupportLimits = SupportLimits {
        long_run: 15.0,
        pair_run: 10.0,
        tie_run: 3.0,
        gap: 1,
        tolerance: 5,
        reach: 6.0,
        near: 20.0,
        clutter_max: 20.0,
        wall_elongation: 3.0,
        end_reach: 1,
        lines: LineLimits {
            min_run: 25.0,
            gap: 1,
            tolerance: 1,
        },
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
        let g = OccupancyGrid::from_ascii(&rows.join("\n"), 0.1);
        WallSupport::new(&g, &islands(&g), 0.0, &[], AT_10_CM)
    }

    #[test]
    fn a_line_joining_wall_ends_across_a_corridor_crosses_a_passage() {
        // A 3 m corridor (x 20..50) between walls at x = 19 and 50, rooms
        // either side divided along y = 30: the line across the corridor
        // between the dividers' ends has the corridor's walls going on
        // past both its faces.
        let w = 70;
        let line: Vec<u32> = (20..50).map(|x| (30 * w + x) as u32).collect();
        let corridor = grid(w, 60, |x, y| {
            x == 19 || x == 50 || (y == 30 && !(19..=50).contains(&x))
        });
        assert!(corridor.crosses_passage(&line));
        // A room's 3 m open front: the room's side wall meets the front
        // and stops there.
        let front = grid(w, 60, |x, y| {
            (y == 30 && !(20..50).contains(&x)) || (x == 19 && y < 30)
        });
        assert!(!front.crosses_passage(&line));
        // The same front with a 0.5 m x 0.8 m table standing in the room
        // below, 0.6 m from the line's end, in line with the side wall:
        // furniture is no passage's side wall. (Within `tolerance` of the
        // end, 0.5 m, the end would stand on it and its faces count.)
        let table = |x: usize, y: usize| (17..22).contains(&x) && (36..44).contains(&y);
        let furnished = grid(w, 60, |x, y| {
            (y == 30 && !(20..50).contains(&x)) || (x == 19 && y < 30) || table(x, y)
        });
        assert!(!furnished.crosses_passage(&line));
        // A wall piece as long standing there (3 m) is one: the line
        // would cross a passage between it and the side wall.
        let piece = grid(w, 60, |x, y| {
            (y == 30 && !(20..50).contains(&x))
                || (x == 19 && y < 30)
                || ((18..20).contains(&x) && (33..58).contains(&y))
        });
        assert!(piece.crosses_passage(&line));
    }

    #[test]
    fn a_border_ending_on_clutter_lacks_support() {
        // A 6 m room; a 0.6 m desk (x 30..36, y 20..26) stands 0.9 m from
        // the wall at y = 10: the border between them (x 33, y 11..20)
        // ends on the desk.
        let desk = |x: usize, y: usize| (30..36).contains(&x) && (20..26).contains(&y);
        let border: Vec<u32> = (11..20).map(|y| (y * 70 + 33) as u32).collect();
        let s = grid(70, 60, |x, y| y == 10 || desk(x, y));
        assert!(s.lacks(&border));
        // A free-standing piece of wall as long (3 m, 0.2 m thick) is a
        // jamb: the border's ends are judged by the runs, as before.
        let piece = |x: usize, y: usize| (18..48).contains(&x) && (20..22).contains(&y);
        let w = grid(70, 60, |x, y| y == 10 || piece(x, y));
        assert!(!w.on_clutter([33.0, 19.0], false));
        // The same desk against the wall is the wall's: no clutter.
        let against = grid(70, 60, |x, y| {
            y == 10 || ((30..36).contains(&x) && (11..17).contains(&y))
        });
        assert!(!against.on_clutter([33.0, 17.0], false));
    }

    #[test]
    fn a_doorway_in_a_long_wall_is_supported() {
        // Two 4 m rooms: a wall at x = 40, its doorway y 30..38 (0.8 m).
        let s = grid(81, 60, |x, y| x == 40 && !(30..38).contains(&y));
        assert_eq!(s.supported([40.0, 30.0], [40.0, 37.0], false), Some(true));
    }

    #[test]
    fn aligned_wall_ends_support_a_doorway_as_a_pair() {
        // A 1.1 m wall piece each side of a 0.8 m opening, standing free
        // 2 m into a 6 m room: short, but in line and facing each other.
        let piece = |x: usize, y: usize| y == 20 && ((9..20).contains(&x) || (28..39).contains(&x));
        let s = grid(60, 60, piece);
        assert_eq!(s.supported([20.0, 20.0], [27.0, 20.0], false), Some(true));
        // One end alone is not enough.
        let one = grid(60, 60, |x, y| y == 20 && (9..20).contains(&x));
        assert_eq!(
            one.supported([20.0, 20.0], [27.0, 20.0], false),
            Some(false)
        );
    }

    #[test]
    fn a_partition_tied_to_the_walls_at_both_ends_supports_its_doorway_gap() {
        // Two 2 m rooms; the wall between them (x = 22) runs 0.6 m from
        // each outer wall to a 0.8 m doorway (y 7..15).
        let s = grid(45, 22, |x, y| x == 22 && !(7..15).contains(&y));
        assert_eq!(s.supported([22.0, 7.0], [22.0, 14.0], true), Some(true));
        // As a border, ties do not count.
        assert_eq!(s.supported([22.0, 7.0], [22.0, 14.0], false), Some(false));
        // Tied at one end only: a stub, not a partition.
        let stub = grid(45, 22, |x, y| x == 22 && y < 7);
        assert_eq!(stub.supported([22.0, 7.0], [22.0, 14.0], true), Some(false));
    }

    #[test]
    fn doorway_gaps_in_a_wall_of_short_pieces_are_anchored() {
        // A 5 m wide building; the wall at y = 20 has a 0.8 m and a 1.5 m
        // doorway, with pieces of 0.7 m (to the outer wall), 1.1 m and
        // 0.7 m (to the outer wall): no piece is long, none pairs.
        let wall = |x: usize, y: usize| y == 20 && !((8..16).contains(&x) || (27..42).contains(&x));
        let s = grid(50, 40, wall);
        assert_eq!(s.supported([8.0, 20.0], [15.0, 20.0], true), Some(true));
        assert_eq!(s.supported([27.0, 20.0], [41.0, 20.0], true), Some(true));
        // Judged as a border, the first is unsupported.
        assert_eq!(s.supported([8.0, 20.0], [15.0, 20.0], false), Some(false));
    }

    #[test]
    fn a_gap_between_clutter_near_walls_is_unsupported() {
        // Two 0.5 m blocks 0.8 m apart, 1.5 m from a 6 m room's wall.
        let blocks = |x: usize, y: usize| {
            (14..19).contains(&y) && ((20..25).contains(&x) || (33..38).contains(&x))
        };
        let s = grid(60, 60, blocks);
        assert_eq!(s.supported([25.0, 16.0], [32.0, 16.0], false), Some(false));
        // As a doorway gap's line of pixels (row 16, columns 25..=32): the
        // gap is dropped.
        let line: Vec<u32> = (25..=32).map(|x| 16 * 60 + x).collect();
        assert!(s.lacks_gap(&line));
        assert!(!s.lacks(&[]), "no border, nothing to judge");
    }

    #[test]
    fn clutter_on_the_wall_lines_is_a_doorway_gaps_jamb() {
        // An 8 m building; its 0.4 m wall at y 19..23 runs 3 m from the
        // west wall to a 0.8 m doorway (x 30..38), stands as a 1 m block
        // (x 38..48), and after a second doorway (x 48..56) goes on to the
        // east wall. The block is small and blocky: clutter by its shape.
        let in_wall = |x: usize, y: usize| {
            (19..23).contains(&y) && !((30..38).contains(&x) || (48..56).contains(&x))
        };
        let s = grid(80, 40, in_wall);
        let doorway: Vec<u32> = (30..38).map(|x| 21 * 80 + x).collect();
        assert!(!s.lacks_gap(&doorway), "the block is the doorway's jamb");
        // The watershed's border there ends on clutter all the same.
        assert!(s.lacks(&doorway));
        // The same block 0.4 m off the wall's line is a desk: a gap from
        // it lacks support, though the wall beside it is long.
        let desk = |x: usize, y: usize| {
            ((19..23).contains(&y) && !(30..56).contains(&x))
                || ((38..48).contains(&x) && (27..31).contains(&y))
        };
        let off = grid(80, 40, desk);
        let to_desk: Vec<u32> = (30..38).map(|x| 29 * 80 + x).collect();
        assert!(off.lacks_gap(&to_desk));
    }

    #[test]
    fn a_doorway_in_a_wall_along_a_further_direction_is_judged_along_it() {
        // A diagonal wall (45 degrees, 2 px thick) across an 8 m room, with
        // a doorway 0.8 m along it.
        let rows: Vec<String> = (0..81)
            .map(|y| {
                (0..81)
                    .map(|x| {
                        let edge = x == 0 || y == 0 || x == 80 || y == 80;
                        let diagonal = (x == y || x == y + 1) && !(30..38).contains(&y);
                        if edge || diagonal { '#' } else { '.' }
                    })
                    .collect()
            })
            .collect();
        let g = OccupancyGrid::from_ascii(&rows.join("\n"), 0.1);
        let (a, b) = ([30.0, 30.0], [37.0, 37.0]);
        // Along the dominant directions only, the rule abstains…
        let along_axes = WallSupport::new(&g, &islands(&g), 0.0, &[], AT_10_CM);
        assert_eq!(along_axes.supported(a, b, true), None);
        // …with the wall's own direction, the wall going on beyond both
        // ends supports the doorway.
        let along_wall = WallSupport::new(&g, &islands(&g), 0.0, &[45.0], AT_10_CM);
        assert_eq!(along_wall.supported(a, b, true), Some(true));
    }

    #[test]
    fn the_rule_abstains_off_the_walls_directions_and_far_from_walls() {
        let s = grid(60, 60, |_, _| false);
        // A diagonal doorway line.
        assert_eq!(s.supported([20.0, 20.0], [25.0, 25.0], false), None);
        // A doorway line in the middle of a 10 m hall, 4.5 m from its walls.
        let hall = grid(101, 101, |_, _| false);
        assert_eq!(hall.supported([46.0, 50.0], [54.0, 50.0], false), None);
    }
}
