//! Routes across levels (issue 25): a 10-level building of 5 030 spaces
//! (`fixtures::storeys(10, 250)`: 250 rooms a floor, stairs and a lift),
//! from a room on level 0 to a room at the far end of level 9, with and
//! without stairs. Target: ≤ 2 ms a route. The floors' layers are built by
//! the first route and kept with the revision, as the server keeps them.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::hint::black_box;
use std::sync::Arc;

use criterion::{Criterion, criterion_group, criterion_main};
use nrgdb::model::SpaceId;
use nrgdb::route::{Budget, NavMesh, Profile, RouteRequest, shortest_route};

fn bench(c: &mut Criterion) {
    let nrg = nrgdb::route::walked_model(&nrgdb::fixtures::storeys(10, 250)).nrg;
    assert_eq!(nrg.spaces().len(), 10 * (1 + 2 * 250 + 2));
    let nav = NavMesh::new(Arc::new(nrg));
    // Room 10 on level 0 to room 259 (the last) on level 9.
    let request = RouteRequest::new(SpaceId(10), SpaceId(900_259));
    let mut no_stairs = request.clone();
    no_stairs.profile = Profile {
        no_stairs: true,
        ..Profile::default()
    };
    let budget = Budget::unlimited();
    assert!(!shortest_route(&nav, &request, &budget).unwrap().is_empty());
    let mut g = c.benchmark_group("route-levels");
    g.bench_function("10-levels-5030-spaces", |b| {
        b.iter(|| black_box(shortest_route(&nav, &request, &budget).unwrap()))
    });
    g.bench_function("10-levels-5030-spaces-no-stairs", |b| {
        b.iter(|| black_box(shortest_route(&nav, &no_stairs, &budget).unwrap()))
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
