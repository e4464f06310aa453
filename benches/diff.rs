//! Diff benchmarks (issue 6): two `willow-full` revisions without and with
//! alignment, the space matcher alone, and a generated building that needs
//! no shared data. Targets: ≤ 20 ms without alignment, ≤ 200 ms with it.
//! The willow cases are skipped with a notice without `$NRGDB_SHARED`
//! (default `../shared`).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::hint::black_box;
use std::path::PathBuf;

use criterion::Criterion;
use nrgdb::diff::{
    AlignMode, AlignParams, DiffOptions, DiffParams, MatchParams, Revision, RigidTransform,
    align_grids, compare, diff, match_spaces,
};
use nrgdb::extract::{ExtractParams, extract};
use nrgdb::grid::{Cell, LoadOptions, OccupancyGrid, load_map};
use nrgdb::model::{Nrg, SpaceKind};

fn willow_grid() -> Option<OccupancyGrid> {
    let shared =
        std::env::var_os("NRGDB_SHARED").map_or_else(|| PathBuf::from("../shared"), PathBuf::from);
    let grid = load_map(
        &shared.join("maps/willow-full.yaml"),
        &LoadOptions::default(),
    )
    .ok();
    if grid.is_none() {
        eprintln!(
            "notice: willow-full not found under {} (set NRGDB_SHARED); skipping",
            shared.display()
        );
    }
    grid
}

/// Revision 2: willow-full with its largest door painted shut, extracted
/// again (a realistic second revision: one door closed, the rest re-extracted).
fn door_shut(grid: &OccupancyGrid, a: &Nrg) -> (OccupancyGrid, Nrg) {
    let mut g = grid.clone();
    // The largest door: its pixels and those within 0.15 m of its corners.
    let door = a
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Door)
        .max_by(|x, y| x.area_m2.total_cmp(&y.area_m2));
    if let Some(door) = door {
        for row in 0..g.height {
            for col in 0..g.width {
                let p = g.pixel_to_metres(f64::from(col) + 0.5, f64::from(row) + 0.5);
                let near = door
                    .polygon
                    .iter()
                    .any(|q| (q[0] - p[0]).hypot(q[1] - p[1]) <= 0.15);
                if g.cells[(row * g.width + col) as usize] == Cell::Free
                    && (nrgdb::model::point_in_ring(p, &door.polygon) || near)
                {
                    g.cells[(row * g.width + col) as usize] = Cell::Occupied;
                    g.grey[(row * g.width + col) as usize] = 0;
                }
            }
        }
    }
    let b = extract(&g, &ExtractParams::default()).unwrap().nrg;
    (g, b)
}

fn bench(c: &mut Criterion) {
    let generated = nrgdb::fixtures::corridor_building(200);
    let shifted = RigidTransform::from_degrees(0.0, 0.3, 0.0)
        .apply_to_nrg(&generated)
        .unwrap();
    c.bench_function("diff/generated-401-spaces/shifted-0.3m", |b| {
        b.iter(|| {
            diff(
                black_box(&generated),
                black_box(&shifted),
                &DiffParams::default(),
            )
        })
    });

    let Some(grid) = willow_grid() else { return };
    let a = extract(&grid, &ExtractParams::default()).unwrap().nrg;
    let (grid_b, b) = door_shut(&grid, &a);
    eprintln!(
        "willow-full: {} spaces; revision 2: {} spaces",
        a.spaces().len(),
        b.spaces().len()
    );
    c.bench_function("diff/willow-full/same-extraction", |bn| {
        bn.iter(|| diff(black_box(&a), black_box(&a), &DiffParams::default()))
    });
    c.bench_function("diff/willow-full/door-shut", |bn| {
        bn.iter(|| diff(black_box(&a), black_box(&b), &DiffParams::default()))
    });
    c.bench_function("match/willow-full/door-shut", |bn| {
        bn.iter(|| match_spaces(black_box(&a), black_box(&b), &MatchParams::default()))
    });
    // Revision 2 in another frame: turned 25° and moved by its origin.
    let mut moved = grid_b.clone();
    moved.origin = [4.0, -3.0, 25f64.to_radians()];
    let b_moved = RigidTransform::from_degrees(25.0, 4.0, -3.0)
        .apply_to_nrg(&b)
        .unwrap();
    c.bench_function("align/willow-full/turned-25deg", |bn| {
        bn.iter(|| {
            align_grids(black_box(&grid), black_box(&moved), &AlignParams::default()).unwrap()
        })
    });
    let always = DiffOptions {
        align: AlignMode::Always,
        ..DiffOptions::default()
    };
    let check = compare(
        Revision::new(&a).with_grid(Some(&grid)),
        Revision::new(&b_moved).with_grid(Some(&moved)),
        &always,
    )
    .unwrap();
    eprintln!(
        "aligned: {:?}; plain diff: {}; aligned diff: {}",
        check.alignment,
        diff(&a, &b, &DiffParams::default()).summary_line(),
        check.changes.summary_line()
    );
    c.bench_function("diff/willow-full/door-shut-aligned", |bn| {
        bn.iter(|| {
            compare(
                Revision::new(&a).with_grid(Some(&grid)),
                Revision::new(&b_moved).with_grid(Some(&moved)),
                &always,
            )
            .unwrap()
        })
    });
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c);
    c.final_summary();
}
