//! Free-space geodesic: the length of the shortest walk between two points
//! through the union of a model's space polygons, the yardstick route
//! lengths are measured against.
//!
//! Owns [`FreeSpaceGrid`] (the union of the spaces rasterised: a cell is
//! free when its centre is inside some space, exterior minus holes, by the
//! rule of [`point_in_ring`](crate::model::point_in_ring)) and the search on
//! it: Dijkstra, goal-directed by the straight-line distance (A*, which
//! returns the same length), over free cells with an any-angle
//! neighbourhood: every offset `(dx, dy)` with `max(|dx|, |dy|) <=`
//! [`SIGHT_RADIUS`] and `gcd(dx, dy) = 1`, allowed only when every cell the
//! straight segment between the two centres touches (the conservative
//! supercover, corners included) is free. With radius 6 the largest angle
//! between neighbouring directions is `atan(1/6)`, so a straight walk in
//! open space is at most `1/cos(atan(1/6)/2) - 1` = 0.34 % too long;
//! around corners the raster adds about a cell.
//!
//! Uses `model` only. Must not use `route`: this is the independent
//! measure of the router, so it shares no code with it.
//!
//! ```
//! use nrgdb::eval::free_space_geodesic;
//! use nrgdb::model::{Nrg, Space, SpaceId, SpaceKind};
//! let room = vec![[0.0, 0.0], [10.0, 0.0], [10.0, 4.0], [0.0, 4.0]];
//! let s = Space::new(SpaceId(1), SpaceKind::Room, [5.0, 2.0], room);
//! let nrg = Nrg::new(vec![s], vec![])?;
//! let d = free_space_geodesic(&nrg, [1.0, 1.0], [9.0, 3.0], 0.05).unwrap();
//! assert!((d / 68f64.sqrt() - 1.0).abs() < 0.005);
//! # Ok::<(), nrgdb::model::ModelError>(())
//! ```

mod raster;

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::ops::Range;

use serde::Serialize;

use super::EvalError;
use crate::model::{Nrg, Point};
use raster::{Raster, chessboard_clearance};

/// The most cells a [`FreeSpaceGrid`] may have (about 0.5 GB of search
/// state); a larger grid is refused with [`EvalError::TooManyCells`].
pub const GEODESIC_MAX_CELLS: usize = 50_000_000;

/// The reach of the any-angle neighbourhood, in cells (Chebyshev).
pub const SIGHT_RADIUS: i32 = 6;

/// How far (in cells, Chebyshev) a point outside every free cell may be
/// moved to the nearest free cell centre.
const SNAP_CELLS: i64 = 2;

/// A shortest walk found by [`FreeSpaceGrid::shortest_path`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GeodesicPath {
    /// Its length in metres (the sum of the segments of `points`).
    pub length_m: f64,
    /// `from`, the centres of the cells walked through, `to`.
    pub points: Vec<Point>,
}

/// One move of the neighbourhood.
#[derive(Debug, Clone)]
struct Step {
    /// Index offset of the target cell.
    delta: isize,
    /// `max(|dx|, |dy|)`: the move needs no sight check from a cell whose
    /// clearance exceeds it.
    reach: u8,
    /// Its length in cells.
    length_cells: f64,
    /// Its supercover cells (index offsets) in [`FreeSpaceGrid::sight`].
    sight: Range<usize>,
}

/// The spaces of a model rasterised for geodesic search (built once, then
/// queried for many pairs).
#[derive(Debug, Clone)]
pub struct FreeSpaceGrid {
    raster: Raster,
    /// Chessboard distance to the nearest blocked cell, 0 when blocked,
    /// capped at `SIGHT_RADIUS + 1`.
    clear: Vec<u8>,
    steps: Vec<Step>,
    sight: Vec<isize>,
}

impl FreeSpaceGrid {
    /// Rasterises the spaces of `nrg` with cells of `cell_m` metres over the
    /// bounding box of their exterior rings (plus a blocked border).
    ///
    /// Errors: `cell_m` not finite and > 0, a model without spaces, or more
    /// than [`GEODESIC_MAX_CELLS`] cells.
    pub fn new(nrg: &Nrg, cell_m: f64) -> Result<FreeSpaceGrid, EvalError> {
        FreeSpaceGrid::with_gap(nrg, cell_m, 0.0)
    }

    /// [`FreeSpaceGrid::new`], then also frees every cell within
    /// `round(gap_m / cell_m)` cells (Chebyshev) of a free cell: a square
    /// dilation that bridges gaps up to about `2 gap_m` wide between spaces
    /// that should touch but do not (extracted outlines run through the
    /// centres of their boundary pixels, so neighbours are a pixel apart).
    /// It also bridges walls thinner than that; 0 is the exact union.
    ///
    /// Errors: those of [`FreeSpaceGrid::new`], and `gap_m` not finite and
    /// >= 0.
    pub fn with_gap(nrg: &Nrg, cell_m: f64, gap_m: f64) -> Result<FreeSpaceGrid, EvalError> {
        if !(cell_m.is_finite() && cell_m > 0.0) {
            return Err(EvalError::BadCellSize { cell_m });
        }
        if !(gap_m.is_finite() && gap_m >= 0.0) {
            return Err(EvalError::BadGap { gap_m });
        }
        let grow = (gap_m / cell_m).round().min(250.0) as usize;
        let bounds = nrg
            .spaces()
            .iter()
            .filter_map(|s| crate::model::bounds(&s.polygon))
            .reduce(|a, b| {
                [
                    a[0].min(b[0]),
                    a[1].min(b[1]),
                    a[2].max(b[2]),
                    a[3].max(b[3]),
                ]
            })
            .ok_or(EvalError::NoSpaces)?;
        let pad = SIGHT_RADIUS as usize + 1 + grow;
        let nx_f = ((bounds[2] - bounds[0]) / cell_m).ceil() + 2.0 * pad as f64 + 1.0;
        let ny_f = ((bounds[3] - bounds[1]) / cell_m).ceil() + 2.0 * pad as f64 + 1.0;
        if nx_f * ny_f > GEODESIC_MAX_CELLS as f64 {
            return Err(EvalError::TooManyCells {
                cells: nx_f * ny_f,
                limit: GEODESIC_MAX_CELLS,
                cell_m,
            });
        }
        let raster = Raster {
            origin: [
                bounds[0] - pad as f64 * cell_m,
                bounds[1] - pad as f64 * cell_m,
            ],
            cell_m,
            nx: nx_f as usize,
            ny: ny_f as usize,
        };
        let mut free = vec![0u8; raster.nx * raster.ny];
        raster.fill_spaces(nrg, &mut free);
        if grow > 0 {
            let blocked: Vec<u8> = free.iter().map(|&f| 1 - f.min(1)).collect();
            let to_free = chessboard_clearance(&blocked, raster.nx, raster.ny, grow as u8 + 1);
            for (f, d) in free.iter_mut().zip(&to_free) {
                if usize::from(*d) <= grow {
                    *f = 1;
                }
            }
        }
        let clear = chessboard_clearance(&free, raster.nx, raster.ny, SIGHT_RADIUS as u8 + 1);
        let (steps, sight) = neighbourhood(raster.nx);
        Ok(FreeSpaceGrid {
            raster,
            clear,
            steps,
            sight,
        })
    }

    /// Cells in the grid (free or not).
    pub fn cells(&self) -> usize {
        self.clear.len()
    }

    /// Free cells in the grid.
    pub fn free_cells(&self) -> usize {
        self.clear.iter().filter(|&&c| c > 0).count()
    }

    /// Whether the cell containing `p` is free.
    pub fn is_free(&self, p: Point) -> bool {
        self.cell_of(p).is_some_and(|c| self.clear[c] > 0)
    }

    /// The index of the cell containing `p`, if `p` is on the grid.
    fn cell_of(&self, p: Point) -> Option<usize> {
        let r = &self.raster;
        let i = ((p[0] - r.origin[0]) / r.cell_m).floor();
        let j = ((p[1] - r.origin[1]) / r.cell_m).floor();
        let on_grid = i >= 0.0 && j >= 0.0 && i < r.nx as f64 && j < r.ny as f64;
        on_grid.then(|| j as usize * r.nx + i as usize)
    }

    fn centre(&self, c: usize) -> Point {
        let r = &self.raster;
        [r.centre_x(c % r.nx), r.centre_y(c / r.nx)]
    }

    /// The free cell whose centre is nearest to `p` among the cells within
    /// [`SNAP_CELLS`] of the cell containing `p` (that cell itself when free).
    fn snap(&self, p: Point) -> Option<usize> {
        let r = &self.raster;
        let i = ((p[0] - r.origin[0]) / r.cell_m).floor();
        let j = ((p[1] - r.origin[1]) / r.cell_m).floor();
        if !(i.is_finite() && j.is_finite()) {
            return None;
        }
        let (i, j) = (i as i64, j as i64);
        let mut best: Option<(f64, usize)> = None;
        for dj in -SNAP_CELLS..=SNAP_CELLS {
            for di in -SNAP_CELLS..=SNAP_CELLS {
                let (ci, cj) = (i + di, j + dj);
                if ci < 0 || cj < 0 || ci >= r.nx as i64 || cj >= r.ny as i64 {
                    continue;
                }
                let c = cj as usize * r.nx + ci as usize;
                if self.clear[c] == 0 {
                    continue;
                }
                let d = distance(p, self.centre(c));
                if best.is_none_or(|(bd, _)| d < bd) {
                    best = Some((d, c));
                }
            }
        }
        best.map(|(_, c)| c)
    }

    /// Straight links from `p` to cell centres: when `p` is in a free cell,
    /// to every cell within [`SIGHT_RADIUS`] (Chebyshev) such that all the
    /// cells of the rectangle spanned by the two are free (the segment
    /// stays in that rectangle); otherwise to the nearest free cell within
    /// two cells only. Each link is `(cell, length in metres)`.
    fn links(&self, p: Point) -> Option<Vec<(usize, f64)>> {
        let Some(s) = self.cell_of(p).filter(|&c| self.clear[c] > 0) else {
            let c = self.snap(p)?;
            return Some(vec![(c, distance(p, self.centre(c)))]);
        };
        let nx = self.raster.nx as isize;
        let mut out = Vec::new();
        for dy in -SIGHT_RADIUS..=SIGHT_RADIUS {
            for dx in -SIGHT_RADIUS..=SIGHT_RADIUS {
                let reach = dx.abs().max(dy.abs());
                let open = reach < i32::from(self.clear[s])
                    || (dy.min(0)..=dy.max(0)).all(|b| {
                        (dx.min(0)..=dx.max(0)).all(|a| {
                            let d = b as isize * nx + a as isize;
                            self.clear[s.wrapping_add_signed(d)] > 0
                        })
                    });
                if open {
                    let t = s.wrapping_add_signed(dy as isize * nx + dx as isize);
                    out.push((t, distance(p, self.centre(t))));
                }
            }
        }
        Some(out)
    }

    /// The shortest walk from `from` to `to` through free cells: straight
    /// from the point to a cell centre near it (see below), any-angle moves
    /// between free cell centres, then straight to `to`; or straight from
    /// `from` to `to` when they are that close. A point in a free cell links
    /// to the centres within [`SIGHT_RADIUS`] cells it sees; a point in a
    /// blocked cell to the nearest free centre within two cells. `None`
    /// when a point is not on or next to free space or the two are not
    /// connected.
    pub fn shortest_path(&self, from: Point, to: Point) -> Option<GeodesicPath> {
        let starts = self.links(from)?;
        let goals = self.links(to)?;
        let goal_cell = self.cell_of(to);
        if goal_cell.is_some_and(|g| starts.iter().any(|&(c, _)| c == g)) {
            return Some(GeodesicPath {
                length_m: distance(from, to),
                points: vec![from, to],
            });
        }
        let (parent, last) = self.search(&starts, &goals, to)?;
        let mut cells = vec![last];
        let mut c = last;
        while parent[c] != u32::MAX {
            c = parent[c] as usize;
            cells.push(c);
        }
        let mut points = vec![from];
        points.extend(cells.iter().rev().map(|&c| self.centre(c)));
        points.push(to);
        let length_m = points.windows(2).map(|w| distance(w[0], w[1])).sum();
        Some(GeodesicPath { length_m, points })
    }

    /// A* from the start links to the goal links (a virtual source and
    /// sink), goal-directed by the distance to `target`. Returns the parent
    /// of each reached cell (`u32::MAX` for cells linked to the source) and
    /// the cell the walk leaves for the sink, or `None` when the sink is
    /// not reached.
    fn search(
        &self,
        starts: &[(usize, f64)],
        goals: &[(usize, f64)],
        target: Point,
    ) -> Option<(Vec<u32>, usize)> {
        let n = self.clear.len();
        let sink = n;
        let mut goals = goals.to_vec();
        goals.sort_by_key(|&(c, _)| c);
        let (lo, hi) = (goals.first()?.0, goals.last()?.0);
        let h = |c: usize| distance(self.centre(c), target);
        let mut best = vec![f64::INFINITY; n];
        let mut parent = vec![u32::MAX; n];
        let mut closed = vec![false; n];
        let mut heap = BinaryHeap::new();
        for &(c, d) in starts {
            if d < best[c] {
                best[c] = d;
                heap.push(Reverse(((d + h(c)).to_bits(), c as u32)));
            }
        }
        let (mut sink_best, mut sink_parent) = (f64::INFINITY, usize::MAX);
        while let Some(Reverse((_, c))) = heap.pop() {
            let c = c as usize;
            if c == sink {
                return Some((parent, sink_parent));
            }
            if closed[c] {
                continue;
            }
            closed[c] = true;
            let (g, clear) = (best[c], self.clear[c]);
            if (lo..=hi).contains(&c)
                && let Ok(k) = goals.binary_search_by_key(&c, |&(gc, _)| gc)
                && g + goals[k].1 < sink_best
            {
                sink_best = g + goals[k].1;
                sink_parent = c;
                heap.push(Reverse((sink_best.to_bits(), sink as u32)));
            }
            for step in &self.steps {
                // Free cells are at least SIGHT_RADIUS + 1 cells from the
                // grid's edge, so every offset stays on the grid.
                let next = c.wrapping_add_signed(step.delta);
                if closed[next] {
                    continue;
                }
                if step.reach >= clear
                    && !self.sight[step.sight.clone()]
                        .iter()
                        .all(|&d| self.clear[c.wrapping_add_signed(d)] > 0)
                {
                    continue;
                }
                let d = g + step.length_cells * self.raster.cell_m;
                if d < best[next] {
                    best[next] = d;
                    parent[next] = c as u32;
                    heap.push(Reverse(((d + h(next)).to_bits(), next as u32)));
                }
            }
        }
        None
    }
}

/// The length in metres of the shortest walk from `from` to `to` through
/// the spaces of `nrg`, on a raster of `cell_m` metres (see the module
/// docs). `None` when there is no such walk, and also when the raster is
/// refused (bad `cell_m`, no spaces, more than [`GEODESIC_MAX_CELLS`]
/// cells): use [`FreeSpaceGrid::new`] to tell the two apart.
pub fn free_space_geodesic(nrg: &Nrg, from: Point, to: Point, cell_m: f64) -> Option<f64> {
    let grid = FreeSpaceGrid::new(nrg, cell_m).ok()?;
    grid.shortest_path(from, to).map(|p| p.length_m)
}

/// [`free_space_geodesic`] with the walk itself and the raster's refusal as
/// an error.
pub fn free_space_geodesic_path(
    nrg: &Nrg,
    from: Point,
    to: Point,
    cell_m: f64,
) -> Result<Option<GeodesicPath>, EvalError> {
    Ok(FreeSpaceGrid::new(nrg, cell_m)?.shortest_path(from, to))
}

/// The moves of the any-angle neighbourhood for a grid `nx` cells wide,
/// and their supercover cells (one flat list, ranges in the steps).
fn neighbourhood(nx: usize) -> (Vec<Step>, Vec<isize>) {
    let (mut steps, mut sight) = (Vec::new(), Vec::new());
    let row = nx as isize;
    for dy in -SIGHT_RADIUS..=SIGHT_RADIUS {
        for dx in -SIGHT_RADIUS..=SIGHT_RADIUS {
            if gcd(dx.unsigned_abs(), dy.unsigned_abs()) != 1 {
                continue;
            }
            let first = sight.len();
            for b in dy.min(0)..=dy.max(0) {
                for a in dx.min(0)..=dx.max(0) {
                    if (a, b) != (0, 0) && segment_touches_cell(dx, dy, a, b) {
                        sight.push(b as isize * row + a as isize);
                    }
                }
            }
            steps.push(Step {
                delta: dy as isize * row + dx as isize,
                reach: dx.abs().max(dy.abs()) as u8,
                length_cells: f64::from(dx).hypot(f64::from(dy)),
                sight: first..sight.len(),
            });
        }
    }
    (steps, sight)
}

/// Whether the segment from the centre of cell (0, 0) to the centre of cell
/// `(dx, dy)` touches the closed square of cell `(a, b)` (a cell of the
/// segment's bounding box). Exact, in doubled integer coordinates: the
/// segment runs from (1, 1) to (2dx + 1, 2dy + 1) and the cell spans
/// `[2a, 2a + 2] x [2b, 2b + 2]`; within the bounding box only the side of
/// the segment's line can separate them.
fn segment_touches_cell(dx: i32, dy: i32, a: i32, b: i32) -> bool {
    let side = |x: i32, y: i32| dy * (x - 1) - dx * (y - 1);
    let corners = [
        side(2 * a, 2 * b),
        side(2 * a + 2, 2 * b),
        side(2 * a, 2 * b + 2),
        side(2 * a + 2, 2 * b + 2),
    ];
    corners.iter().any(|&s| s <= 0) && corners.iter().any(|&s| s >= 0)
}

fn gcd(mut a: u32, mut b: u32) -> u32 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

fn distance(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

#[cfg(test)]
mod tests;
