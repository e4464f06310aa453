//! Whole extraction pipeline: willow-full (when NRGDB_SHARED or ../shared
//! has it) and the largest dev map, else a generated floor plan.

use std::path::PathBuf;

use criterion::{Criterion, criterion_group, criterion_main};
use nrgdb::extract::{ExtractParams, extract};
use nrgdb::grid::{Cell, LoadOptions, OccupancyGrid, load_map};

fn shared_map(name: &str) -> Option<OccupancyGrid> {
    let dir = std::env::var("NRGDB_SHARED")
        .map(PathBuf::from)
        .unwrap_or_else(|_| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared"));
    load_map(
        &dir.join("maps").join(format!("{name}.yaml")),
        &LoadOptions::default(),
    )
    .ok()
}

/// A 60 m × 60 m grid of 4 m rooms off 2 m corridors at 0.1 m/px.
fn generated() -> OccupancyGrid {
    let (w, h) = (600u32, 600u32);
    let cells = (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let (cx, cy) = (x % 60, y % 60);
            let wall = cx < 2
                || cy < 2
                || (cx == 40 && !(10..19).contains(&cy))
                || (cy == 40 && !(10..19).contains(&cx));
            if wall { Cell::Occupied } else { Cell::Free }
        })
        .collect();
    OccupancyGrid::from_cells(w, h, 0.1, [0.0; 3], cells)
}

fn bench(c: &mut Criterion) {
    let params = ExtractParams::default();
    let mut maps = vec![("generated_600x600", generated())];
    for name in ["willow-full", "office_g"] {
        match shared_map(name) {
            Some(g) => maps.push((name, g)),
            None => eprintln!("skipping {name}: shared maps not found"),
        }
    }
    let mut group = c.benchmark_group("extract");
    group.sample_size(10);
    for (name, grid) in &maps {
        group.bench_function(*name, |b| b.iter(|| extract(grid, &params)));
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
