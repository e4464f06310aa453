//! Test support for the diff tests: a generated floor as an occupancy
//! grid, painting edits on grids, and extraction.

use std::path::Path;

use nrgdb::diff::{ChangeSet, DiffParams, apply, diff};
use nrgdb::extract::{ExtractParams, extract};
use nrgdb::grid::{Cell, OccupancyGrid};
use nrgdb::model::{Nrg, SpaceKind};

/// Pixel rectangles `(col0, row0, col1, row1)`, ends exclusive.
pub type Rect = (u32, u32, u32, u32);

/// Where the generated floor's features are (pixels, 0.05 m/px).
pub struct Floor {
    pub grid: OccupancyGrid,
    /// Door gaps, one per room, left to right: room 0's leads into room 1,
    /// the others into the corridor.
    pub doors: Vec<Rect>,
    /// The wall between room 0 and room 1 (door 0 in it).
    pub wall_0_1: Rect,
    /// A line across room 3 (the rightmost), door side larger.
    pub split_3: Rect,
}

/// A 24 m × 14 m floor at 0.05 m/px: a corridor along the bottom and four
/// rooms of different widths above it, each with a 0.9 m door (room 0's
/// into room 1, the others into the corridor).
pub fn floor() -> Floor {
    let (w, h) = (480u32, 280u32);
    let mut cells = vec![Cell::Unknown; (w * h) as usize];
    let set = |r: Rect, c: Cell, cells: &mut Vec<Cell>| {
        for row in r.1..r.3 {
            for col in r.0..r.2 {
                cells[(row * w + col) as usize] = c;
            }
        }
    };
    set((10, 10, 470, 270), Cell::Occupied, &mut cells); // outer wall
    set((14, 14, 466, 266), Cell::Free, &mut cells);
    set((14, 196, 466, 200), Cell::Occupied, &mut cells); // corridor wall
    // Room walls at these columns: rooms 0..3 are 4.8, 6.8, 5.6, 5.2 m wide.
    let walls = [110u32, 250, 366];
    for c in walls {
        set((c, 14, c + 4, 196), Cell::Occupied, &mut cells);
    }
    let lefts = [14u32, 114, 254, 370];
    let mut doors: Vec<Rect> = lefts.iter().map(|&l| (l + 30, 196, l + 48, 200)).collect();
    doors[0] = (110, 100, 114, 118);
    for d in &doors {
        set(*d, Cell::Free, &mut cells);
    }
    Floor {
        grid: OccupancyGrid::from_cells(w, h, 0.05, [-1.0, 2.0, 0.0], cells),
        doors,
        wall_0_1: (110, 14, 114, 196),
        split_3: (440, 14, 444, 196),
    }
}

/// Sets every pixel of `r` to `c`.
pub fn paint(grid: &mut OccupancyGrid, r: Rect, c: Cell) {
    for row in r.1..r.3.min(grid.height) {
        for col in r.0..r.2.min(grid.width) {
            let i = (row * grid.width + col) as usize;
            grid.cells[i] = c;
            grid.grey[i] = match c {
                Cell::Free => 255,
                Cell::Occupied => 0,
                Cell::Unknown => 205,
            };
        }
    }
}

/// The grid turned a quarter turn counter-clockwise in its pixels, framed
/// by `pad` unknown pixels, under a new origin: the same building from
/// another mapping run, in another frame.
pub fn turned(grid: &OccupancyGrid, pad: u32, origin: [f64; 3]) -> OccupancyGrid {
    let (w, h) = (grid.height + 2 * pad, grid.width + 2 * pad);
    let mut cells = vec![Cell::Unknown; (w * h) as usize];
    for row in 0..grid.height {
        for col in 0..grid.width {
            // (col, row) → (row, width-1-col): counter-clockwise on screen.
            let (nc, nr) = (row + pad, grid.width - 1 - col + pad);
            cells[(nr * w + nc) as usize] = grid.cells[(row * grid.width + col) as usize];
        }
    }
    OccupancyGrid::from_cells(w, h, grid.resolution, origin, cells)
}

/// Writes `grid` as `<stem>.pgm` + `<stem>.yaml` in `dir`.
pub fn write_map(dir: &Path, stem: &str, grid: &OccupancyGrid) {
    let mut pgm = format!("P5\n{} {}\n255\n", grid.width, grid.height).into_bytes();
    pgm.extend(grid.cells.iter().map(|c| match c {
        Cell::Free => 255u8,
        Cell::Occupied => 0,
        Cell::Unknown => 205,
    }));
    std::fs::write(dir.join(format!("{stem}.pgm")), pgm).unwrap();
    let [x, y, yaw] = grid.origin;
    let yaml = format!(
        "image: {stem}.pgm\nresolution: {}\norigin: [{x}, {y}, {yaw}]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n",
        grid.resolution
    );
    std::fs::write(dir.join(format!("{stem}.yaml")), yaml).unwrap();
}

/// The default extraction of a grid.
pub fn extracted(grid: &OccupancyGrid) -> Nrg {
    extract(grid, &ExtractParams::default()).unwrap().nrg
}

/// Diffs `a` and `b`, checks the change set replays and survives JSON, and
/// returns it.
pub fn checked_diff(a: &Nrg, b: &Nrg) -> ChangeSet {
    let cs = diff(a, b, &DiffParams::default());
    let back = ChangeSet::from_json(&cs.to_json()).unwrap();
    assert_eq!(back, cs);
    assert_eq!(&apply(a, &back).unwrap(), b);
    cs
}

/// Number of spaces of each kind, for messages.
pub fn kinds(nrg: &Nrg) -> String {
    SpaceKind::ALL
        .iter()
        .map(|k| {
            format!(
                "{k}: {}",
                nrg.spaces().iter().filter(|s| s.kind == *k).count()
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}
