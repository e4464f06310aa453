//! The free-space raster behind the geodesic: which cells of a regular grid
//! have their centre inside some space (exterior minus holes), and each free
//! cell's chessboard distance to the nearest blocked cell.

use crate::model::{Nrg, Point};

/// Scanline crossings of `ring` with the horizontal line `y = py`, sorted.
///
/// Uses the very test of [`point_in_ring`](crate::model::point_in_ring), so
/// that `px` is inside the ring exactly when `c[2k] <= px < c[2k + 1]` for
/// some `k` (the number of crossings right of `px` is then odd).
pub(super) fn crossings(ring: &[Point], py: f64, out: &mut Vec<f64>) {
    out.clear();
    let n = ring.len();
    let mut j = n.wrapping_sub(1);
    for i in 0..n {
        let [xi, yi] = ring[i];
        let [xj, yj] = ring[j];
        if (yi > py) != (yj > py) {
            out.push((xj - xi) * (py - yi) / (yj - yi) + xi);
        }
        j = i;
    }
    out.sort_by(f64::total_cmp);
}

/// A row-major raster, row 0 at the bottom (`y` grows with the row), with
/// cell `(i, j)` centred on `origin + ((i + 0.5) cell, (j + 0.5) cell)`.
#[derive(Debug, Clone)]
pub(super) struct Raster {
    pub origin: Point,
    pub cell_m: f64,
    pub nx: usize,
    pub ny: usize,
}

impl Raster {
    /// The centre of column `i` (x) or row `j` (y) along one axis.
    pub fn centre_x(&self, i: usize) -> f64 {
        self.origin[0] + (i as f64 + 0.5) * self.cell_m
    }

    pub fn centre_y(&self, j: usize) -> f64 {
        self.origin[1] + (j as f64 + 0.5) * self.cell_m
    }

    /// The first column whose centre is `>= x` (clamped to `0..=nx`).
    fn first_col_at_or_right_of(&self, x: f64) -> usize {
        let guess = ((x - self.origin[0]) / self.cell_m - 0.5).ceil();
        let mut i = guess.clamp(0.0, self.nx as f64) as usize;
        while i > 0 && self.centre_x(i - 1) >= x {
            i -= 1;
        }
        while i < self.nx && self.centre_x(i) < x {
            i += 1;
        }
        i
    }

    /// Rows whose centre lies in `[y0, y1]`.
    fn rows_between(&self, y0: f64, y1: f64) -> std::ops::Range<usize> {
        let lo = ((y0 - self.origin[1]) / self.cell_m - 0.5).floor().max(0.0) as usize;
        let hi = ((y1 - self.origin[1]) / self.cell_m + 0.5).ceil().max(0.0) as usize;
        lo.min(self.ny)..hi.min(self.ny)
    }

    /// Marks `free[c] = 1` for every cell whose centre is inside a space of
    /// `nrg` (inside the exterior ring and inside none of its holes).
    pub fn fill_spaces(&self, nrg: &Nrg, free: &mut [u8]) {
        let mut cross = Vec::new();
        let mut row: Vec<u8> = Vec::new();
        for space in nrg.spaces() {
            let Some([x0, y0, x1, y1]) = crate::model::bounds(&space.polygon) else {
                continue;
            };
            let c0 = self.first_col_at_or_right_of(x0);
            let c1 = self.first_col_at_or_right_of(x1).max(c0);
            for j in self.rows_between(y0, y1) {
                let py = self.centre_y(j);
                row.clear();
                row.resize(c1 - c0, 0);
                crossings(&space.polygon, py, &mut cross);
                self.paint_spans(&cross, c0, &mut row, 1);
                for hole in &space.holes {
                    crossings(hole, py, &mut cross);
                    self.paint_spans(&cross, c0, &mut row, 0);
                }
                let base = j * self.nx + c0;
                for (f, r) in free[base..base + row.len()].iter_mut().zip(&row) {
                    *f |= *r;
                }
            }
        }
    }

    /// Sets `row[i - c0] = value` for the columns inside the spans of the
    /// sorted crossings `cross`.
    fn paint_spans(&self, cross: &[f64], c0: usize, row: &mut [u8], value: u8) {
        for span in cross.chunks_exact(2) {
            let lo = self.first_col_at_or_right_of(span[0]).max(c0);
            let hi = self.first_col_at_or_right_of(span[1]).min(c0 + row.len());
            if lo < hi {
                row[lo - c0..hi - c0].fill(value);
            }
        }
    }
}

/// Chessboard distance of each cell to the nearest blocked cell (blocked
/// cells get 0), capped at `cap`, by the exact two-pass chamfer with unit
/// weights (Rosenfeld & Pfaltz 1966). `free` is 0/1 per cell; the outermost
/// ring of cells must be blocked.
pub(super) fn chessboard_clearance(free: &[u8], nx: usize, ny: usize, cap: u8) -> Vec<u8> {
    let mut d: Vec<u8> = free.iter().map(|&f| if f == 0 { 0 } else { cap }).collect();
    if nx < 3 || ny < 3 {
        return d;
    }
    for j in 1..ny - 1 {
        for i in 1..nx - 1 {
            let c = j * nx + i;
            if d[c] == 0 {
                continue;
            }
            let m = d[c - 1]
                .min(d[c - nx - 1])
                .min(d[c - nx])
                .min(d[c - nx + 1]);
            d[c] = d[c].min(m.saturating_add(1));
        }
    }
    for j in (1..ny - 1).rev() {
        for i in (1..nx - 1).rev() {
            let c = j * nx + i;
            if d[c] == 0 {
                continue;
            }
            let m = d[c + 1]
                .min(d[c + nx + 1])
                .min(d[c + nx])
                .min(d[c + nx - 1]);
            d[c] = d[c].min(m.saturating_add(1));
        }
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::point_in_ring;

    #[test]
    fn scanline_agrees_with_point_in_ring() {
        let ring = vec![[0.1, 0.2], [3.3, 0.0], [2.0, 1.7], [3.1, 2.9], [0.4, 2.5]];
        let raster = Raster {
            origin: [-0.5, -0.5],
            cell_m: 0.1,
            nx: 45,
            ny: 40,
        };
        let mut cross = Vec::new();
        for j in 0..raster.ny {
            let py = raster.centre_y(j);
            crossings(&ring, py, &mut cross);
            let mut row = vec![0u8; raster.nx];
            raster.paint_spans(&cross, 0, &mut row, 1);
            for (i, r) in row.iter().enumerate() {
                let p = [raster.centre_x(i), py];
                assert_eq!(*r == 1, point_in_ring(p, &ring), "cell ({i}, {j})");
            }
        }
    }

    #[test]
    fn clearance_is_chessboard_distance() {
        let (nx, ny) = (9, 7);
        let mut free = vec![0u8; nx * ny];
        for j in 1..ny - 1 {
            for i in 1..nx - 1 {
                free[j * nx + i] = 1;
            }
        }
        let d = chessboard_clearance(&free, nx, ny, 200);
        for j in 0..ny {
            for i in 0..nx {
                let want = i.min(j).min(nx - 1 - i).min(ny - 1 - j) as u8;
                assert_eq!(d[j * nx + i], want, "({i}, {j})");
            }
        }
    }
}
