//! Routing on the navigation layer: a ROUTE with its walked geometry and
//! steps between random room pairs of the willow-full extraction (when
//! NRGDB_SHARED or ../shared has it) and corner to corner on the generated
//! 10 001-space building; building the layer next to extracting the map.
//! Targets (issue 18): ≤ 30 µs median on willow-full, ≤ 2 ms on 10 000
//! spaces, building the layer ≤ 20 % of extraction time. The layer's
//! tables and contraction hierarchy are built by the first route of a
//! clearance (`nav-build-and-first-route` measures that).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::hint::black_box;
use std::path::PathBuf;
use std::sync::Arc;

use criterion::{Criterion, criterion_group, criterion_main};
use nrgdb::extract::{ExtractParams, extract};
use nrgdb::grid::{LoadOptions, load_map};
use nrgdb::model::{Nrg, SpaceId, SpaceKind};
use nrgdb::query::demo;
use nrgdb::route::{Budget, NavMesh, Profile, RouteRequest, shortest_route};
use nrgdb::sim::SplitMix64;

/// 25 room pairs drawn with a fixed SplitMix64 stream.
fn pairs(nrg: &Nrg) -> Vec<(SpaceId, SpaceId)> {
    let rooms: Vec<SpaceId> = nrg
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Room)
        .map(|s| s.id)
        .collect();
    let mut rng = SplitMix64::new(0x5EED);
    let mut next = |n: usize| (rng.next_u64() % n as u64) as usize;
    let mut out = Vec::new();
    while out.len() < 25 && rooms.len() > 1 {
        let (a, b) = (rooms[next(rooms.len())], rooms[next(rooms.len())]);
        if a != b {
            out.push((a, b));
        }
    }
    out
}

fn willow(c: &mut Criterion) {
    let dir = std::env::var("NRGDB_SHARED")
        .map(PathBuf::from)
        .unwrap_or_else(|_| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared"));
    let Ok(grid) = load_map(
        &dir.join("maps").join("willow-full.yaml"),
        &LoadOptions::default(),
    ) else {
        eprintln!("notice: willow-full not found (NRGDB_SHARED); skipping its route benchmarks");
        return;
    };
    let params = ExtractParams::default();
    c.bench_function("route/extract/willow-full", |b| {
        b.iter(|| extract(black_box(&grid), &params).unwrap())
    });
    let nrg = Arc::new(extract(&grid, &params).unwrap().nrg);
    c.bench_function("route/nav-build/willow-full", |b| {
        b.iter(|| NavMesh::new(black_box(nrg.clone())))
    });
    let requests: Vec<RouteRequest> = pairs(&nrg)
        .into_iter()
        .map(|(a, b)| RouteRequest::new(a, b))
        .collect();
    // What the first route of a revision pays on top: every space's table
    // and the contraction hierarchy of its clearance.
    c.bench_function("route/nav-build-and-first-route/willow-full", |b| {
        b.iter(|| {
            let nav = NavMesh::new(black_box(nrg.clone()));
            shortest_route(&nav, &requests[0], &Budget::unlimited()).unwrap()
        })
    });
    let nav = NavMesh::new(nrg.clone());
    for (name, profile) in [
        ("clearance-0.2", Profile::default()),
        ("exact", Profile::exact()),
    ] {
        let requests: Vec<RouteRequest> = requests
            .iter()
            .cloned()
            .map(|mut r| {
                r.profile = profile;
                r
            })
            .collect();
        // Warm the layer of this clearance.
        let found = requests
            .iter()
            .filter(|r| {
                !shortest_route(&nav, r, &Budget::unlimited())
                    .unwrap()
                    .is_empty()
            })
            .count();
        eprintln!(
            "willow-full {name}: {found} of {} pairs have a route",
            requests.len()
        );
        let mut i = 0;
        c.bench_function(&format!("route/shortest/willow-full/{name}"), |b| {
            b.iter(|| {
                i = (i + 1) % requests.len();
                shortest_route(&nav, black_box(&requests[i]), &Budget::unlimited()).unwrap()
            })
        });
    }
}

fn generated(c: &mut Criterion) {
    let nrg = Arc::new(demo::building(1875));
    let spaces = nrg.spaces().len();
    c.bench_function(&format!("route/nav-build/generated-{spaces}"), |b| {
        b.iter(|| NavMesh::new(black_box(nrg.clone())))
    });
    let nav = NavMesh::new(nrg);
    let request = RouteRequest::new(SpaceId(3), SpaceId(9375));
    let first = std::time::Instant::now();
    assert_eq!(
        shortest_route(&nav, &request, &Budget::unlimited())
            .unwrap()
            .len(),
        1
    );
    eprintln!(
        "generated-{spaces}: first route (tables and hierarchy) {:?}",
        first.elapsed()
    );
    c.bench_function(&format!("route/shortest/generated-{spaces}"), |b| {
        b.iter(|| shortest_route(&nav, black_box(&request), &Budget::unlimited()).unwrap())
    });
}

fn bench(c: &mut Criterion) {
    willow(c);
    generated(c);
}

criterion_group!(benches, bench);
criterion_main!(benches);
