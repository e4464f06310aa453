//! The occupancy grid and its pixel ↔ metre conversion.

/// The state of one grid cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cell {
    /// Traversable space.
    Free,
    /// An obstacle.
    Occupied,
    /// Never observed.
    Unknown,
}

impl Cell {
    /// The ROS map_server grey of the cell: free 255, occupied 0, unknown 205.
    pub fn grey(self) -> u8 {
        match self {
            Cell::Free => 255,
            Cell::Occupied => 0,
            Cell::Unknown => 205,
        }
    }
}

/// A loaded occupancy grid: cells in row-major order, row 0 at the top of the
/// image (ROS image convention).
#[derive(Debug, Clone, PartialEq)]
pub struct OccupancyGrid {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Metres per pixel.
    pub resolution: f64,
    /// Map-frame pose `[x, y, yaw]` of the lower-left pixel's outer corner.
    pub origin: [f64; 3],
    /// Grey per pixel after negate/alpha handling: 255 = free, 0 = occupied.
    pub grey: Vec<u8>,
    /// Classified cells.
    pub cells: Vec<Cell>,
}

impl OccupancyGrid {
    /// Builds a grid from classified cells (grey is derived: 255/0/205).
    ///
    /// ```
    /// use nrgdb::grid::{Cell, OccupancyGrid};
    /// let g = OccupancyGrid::from_cells(2, 1, 0.1, [0.0, 0.0, 0.0], vec![Cell::Free, Cell::Occupied]);
    /// assert_eq!(g.free_count(), 1);
    /// ```
    pub fn from_cells(
        width: u32,
        height: u32,
        resolution: f64,
        origin: [f64; 3],
        cells: Vec<Cell>,
    ) -> OccupancyGrid {
        let grey = cells.iter().map(|c| c.grey()).collect();
        OccupancyGrid {
            width,
            height,
            resolution,
            origin,
            grey,
            cells,
        }
    }

    /// Parses an ASCII picture (lines trimmed): `.` free, `#` occupied,
    /// anything else unknown. Handy for tests and examples.
    pub fn from_ascii(text: &str, resolution: f64) -> OccupancyGrid {
        let rows: Vec<&str> = text
            .lines()
            .map(str::trim)
            .filter(|l| !l.is_empty())
            .collect();
        let width = rows.iter().map(|r| r.chars().count()).max().unwrap_or(0);
        let mut cells = Vec::with_capacity(width * rows.len());
        for r in &rows {
            let mut n = 0;
            for ch in r.chars() {
                cells.push(match ch {
                    '.' => Cell::Free,
                    '#' => Cell::Occupied,
                    _ => Cell::Unknown,
                });
                n += 1;
            }
            cells.extend(std::iter::repeat_n(Cell::Unknown, width - n));
        }
        OccupancyGrid::from_cells(width as u32, rows.len() as u32, resolution, [0.0; 3], cells)
    }

    /// Number of pixels.
    pub fn len(&self) -> usize {
        self.cells.len()
    }

    /// Whether the grid has no pixels.
    pub fn is_empty(&self) -> bool {
        self.cells.is_empty()
    }

    /// The cell at column `col`, row `row` (row 0 = top), if inside.
    pub fn cell(&self, col: u32, row: u32) -> Option<Cell> {
        if col < self.width && row < self.height {
            self.cells.get((row * self.width + col) as usize).copied()
        } else {
            None
        }
    }

    /// Number of free cells.
    pub fn free_count(&self) -> usize {
        self.cells.iter().filter(|c| **c == Cell::Free).count()
    }

    /// Map-frame metres of an image position in pixels (`col`, `row` may be
    /// fractional; `(0, 0)` is the top-left corner of the top-left pixel).
    ///
    /// ```
    /// use nrgdb::grid::{Cell, OccupancyGrid};
    /// let g = OccupancyGrid::from_cells(4, 2, 0.5, [10.0, 20.0, 0.0], vec![Cell::Free; 8]);
    /// assert_eq!(g.pixel_to_metres(0.0, 2.0), [10.0, 20.0]); // lower-left corner
    /// assert_eq!(g.pixel_to_metres(4.0, 0.0), [12.0, 21.0]); // upper-right corner
    /// ```
    pub fn pixel_to_metres(&self, col: f64, row: f64) -> [f64; 2] {
        let lx = col * self.resolution;
        let ly = (f64::from(self.height) - row) * self.resolution;
        let (s, c) = self.origin[2].sin_cos();
        [
            self.origin[0] + c * lx - s * ly,
            self.origin[1] + s * lx + c * ly,
        ]
    }

    /// The inverse of [`OccupancyGrid::pixel_to_metres`]: fractional `[col, row]`.
    pub fn metres_to_pixel(&self, p: [f64; 2]) -> [f64; 2] {
        let dx = p[0] - self.origin[0];
        let dy = p[1] - self.origin[1];
        let (s, c) = self.origin[2].sin_cos();
        let lx = c * dx + s * dy;
        let ly = -s * dx + c * dy;
        [
            lx / self.resolution,
            f64::from(self.height) - ly / self.resolution,
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ascii_and_round_trip() {
        let g = OccupancyGrid::from_ascii("#..\n#?.\n", 0.1);
        assert_eq!((g.width, g.height), (3, 2));
        assert_eq!(g.cell(0, 0), Some(Cell::Occupied));
        assert_eq!(g.cell(1, 1), Some(Cell::Unknown));
        assert_eq!(g.free_count(), 3);
        let mut g = g;
        g.origin = [1.0, -2.0, 0.3];
        let p = g.pixel_to_metres(1.5, 0.5);
        let q = g.metres_to_pixel(p);
        assert!((q[0] - 1.5).abs() < 1e-9 && (q[1] - 0.5).abs() < 1e-9);
    }

    #[test]
    fn row_zero_is_the_top() {
        let g = OccupancyGrid::from_cells(1, 10, 1.0, [0.0; 3], vec![Cell::Free; 10]);
        assert_eq!(g.pixel_to_metres(0.5, 0.5), [0.5, 9.5]);
    }
}
