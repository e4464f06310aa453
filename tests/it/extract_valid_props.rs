//! Issue 19: extracted cells are valid on maps nobody drew by hand. A
//! property test extracts random grids (free rectangles carved out of a
//! wall, clutter and speckle in them) and simulated buildings mapped by
//! the simulated robot, and runs `nrgdb check`'s geometric checks on the
//! model: rings simple, holes inside their shell, no overlapping cells.

use nrgdb::extract::{ExtractError, ExtractParams, extract};
use nrgdb::grid::{Cell, LoadOptions, OccupancyGrid, load_map};
use nrgdb::indoorgml::{check, from_nrg};
use nrgdb::sim::{SimParams, simulate, write_simulation};
use proptest::prelude::*;

/// The findings on the extracted model; none when the grid holds no space
/// big enough (a clear error, not a model).
fn geometric_findings(grid: &OccupancyGrid) -> Vec<String> {
    let x = match extract(grid, &ExtractParams::default()) {
        Ok(x) => x,
        Err(ExtractError::NoSpace { .. }) => return Vec::new(),
        Err(e) => panic!("extraction failed: {e}"),
    };
    check(&from_nrg(&x.nrg))
        .into_iter()
        .map(|f| f.to_string())
        .collect()
}

/// A `w` × `h` grid at 5 cm: wall everywhere, `rooms` carved free, then
/// `clutter` pixels set occupied and `speckle` pixels set free anywhere.
fn carved(
    w: u32,
    h: u32,
    rooms: &[(u32, u32, u32, u32)],
    clutter: &[(u32, u32)],
    speckle: &[(u32, u32)],
) -> OccupancyGrid {
    let mut cells = vec![Cell::Occupied; (w * h) as usize];
    let mut set = |x: u32, y: u32, c: Cell| {
        if x < w && y < h {
            cells[(y * w + x) as usize] = c;
        }
    };
    for &(x0, y0, rw, rh) in rooms {
        for y in y0..y0 + rh {
            for x in x0..x0 + rw {
                set(x, y, Cell::Free);
            }
        }
    }
    for &(x, y) in clutter {
        set(x, y, Cell::Occupied);
    }
    for &(x, y) in speckle {
        set(x, y, Cell::Free);
    }
    OccupancyGrid::from_cells(w, h, 0.05, [0.0, 0.0, 0.0], cells)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    #[test]
    fn random_maps_extract_to_valid_cells(
        w in 40u32..140,
        h in 40u32..140,
        rooms in prop::collection::vec((1u32..120, 1u32..120, 24u32..80, 24u32..80), 1..7),
        clutter in prop::collection::vec((0u32..140, 0u32..140), 0..60),
        speckle in prop::collection::vec((0u32..140, 0u32..140), 0..60),
    ) {
        let grid = carved(w, h, &rooms, &clutter, &speckle);
        let found = geometric_findings(&grid);
        prop_assert!(found.is_empty(), "{found:#?}");
    }
}

#[test]
fn simulated_buildings_extract_to_valid_cells() {
    let dir = tempfile::tempdir().unwrap();
    for seed in 1..=4 {
        let sim = simulate(&SimParams::new(seed)).unwrap();
        let files = write_simulation(&dir.path().join(seed.to_string()), &sim).unwrap();
        let grid = load_map(&files.yaml, &LoadOptions::default()).unwrap();
        let found = geometric_findings(&grid);
        assert!(found.is_empty(), "seed {seed}: {found:#?}");
    }
}
