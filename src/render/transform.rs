//! The one transform from the map frame (metres, y up) to picture pixels
//! (y down): `u = left + (x − x_min)·s`, `v = top + (y_max − y)·s`.

use crate::grid::OccupancyGrid;
use crate::model::Point;

/// Map frame → picture pixels: a scale and a flip of y.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapTransform {
    /// Smallest x shown (m).
    pub x_min: f64,
    /// Largest y shown (m).
    pub y_max: f64,
    /// Pixels per metre.
    pub px_per_m: f64,
    /// Picture position of `(x_min, y_max)`, in pixels.
    pub offset: [f64; 2],
}

impl MapTransform {
    /// Picture position of a map point.
    ///
    /// ```
    /// use nrgdb::render::MapTransform;
    /// let t = MapTransform { x_min: 0.0, y_max: 10.0, px_per_m: 2.0, offset: [5.0, 5.0] };
    /// assert_eq!(t.apply([0.0, 10.0]), [5.0, 5.0]);
    /// assert_eq!(t.apply([1.0, 0.0]), [7.0, 25.0]); // y up in metres, down in pixels
    /// ```
    pub fn apply(&self, p: Point) -> [f64; 2] {
        [
            self.offset[0] + (p[0] - self.x_min) * self.px_per_m,
            self.offset[1] + (self.y_max - p[1]) * self.px_per_m,
        ]
    }

    /// The map point at a picture position (inverse of [`MapTransform::apply`]).
    pub fn invert(&self, uv: [f64; 2]) -> Point {
        [
            self.x_min + (uv[0] - self.offset[0]) / self.px_per_m,
            self.y_max - (uv[1] - self.offset[1]) / self.px_per_m,
        ]
    }

    /// A length in metres as pixels.
    pub fn length(&self, metres: f64) -> f64 {
        metres * self.px_per_m
    }

    /// The affine map `[a, b, c, d, e, f]` from grid pixels `(col, row)` to
    /// picture pixels: `u = a·col + c·row + e`, `v = b·col + d·row + f` (the
    /// SVG `matrix()` order). Composes the grid's own pixel → metre map
    /// (origin and yaw included) with this transform.
    pub fn grid_affine(&self, grid: &OccupancyGrid) -> [f64; 6] {
        let o = self.apply(grid.pixel_to_metres(0.0, 0.0));
        let c = self.apply(grid.pixel_to_metres(1.0, 0.0));
        let r = self.apply(grid.pixel_to_metres(0.0, 1.0));
        [
            c[0] - o[0],
            c[1] - o[1],
            r[0] - o[0],
            r[1] - o[1],
            o[0],
            o[1],
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::Cell;

    #[test]
    fn invert_undoes_apply() {
        let t = MapTransform {
            x_min: -3.0,
            y_max: 4.5,
            px_per_m: 17.0,
            offset: [10.0, 20.0],
        };
        for p in [[0.0, 0.0], [-3.0, 4.5], [12.25, -7.5]] {
            let q = t.invert(t.apply(p));
            assert!((q[0] - p[0]).abs() < 1e-9 && (q[1] - p[1]).abs() < 1e-9);
        }
    }

    #[test]
    fn grid_affine_puts_the_top_left_pixel_at_the_top_left() {
        // A 4×2 grid of 0.5 m pixels with its lower-left corner at (1, 2).
        let g = OccupancyGrid::from_cells(4, 2, 0.5, [1.0, 2.0, 0.0], vec![Cell::Free; 8]);
        let t = MapTransform {
            x_min: 1.0,
            y_max: 3.0,
            px_per_m: 10.0,
            offset: [0.0, 0.0],
        };
        let [a, b, c, d, e, f] = t.grid_affine(&g);
        assert_eq!([a, b, c, d, e, f], [5.0, 0.0, 0.0, 5.0, 0.0, 0.0]);
        // The lower-right corner of the grid (col 4, row 2) lands at (20, 10).
        assert_eq!([a * 4.0 + c * 2.0 + e, b * 4.0 + d * 2.0 + f], [20.0, 10.0]);
    }
}
