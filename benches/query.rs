//! Parse + plan + execute a ROUTE end to end through `query::Session`, on
//! the generated demo building: willow-sized (~150 spaces) and 10 000 spaces.
//! Targets (issue 5): ≤ 50 µs and ≤ 2 ms.
#![allow(clippy::unwrap_used)]

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use nrgdb::model::SpaceId;
use nrgdb::query::{MemorySource, Session, demo};
use std::sync::Arc;

use nrgdb::route::{
    Budget, Endpoint, NavMesh, Profile, RouteRequest, reachable_within, shortest_route,
};

fn session(columns: usize) -> (Session<MemorySource>, usize) {
    let nrg = demo::building(columns);
    let spaces = nrg.spaces().len();
    let mut source = MemorySource::new();
    source.insert("demo", nrg);
    (Session::with_default_map(source).unwrap(), spaces)
}

fn route_willow_full(c: &mut Criterion) {
    let Some(nrg) = nrgdb::fixtures::shared_map_nrg("willow-full") else {
        eprintln!("notice: willow-full not found (NRGDB_SHARED); skipping its ROUTE benchmark");
        return;
    };
    // From the first room to the room farthest from it along the graph.
    let nav = NavMesh::new(Arc::new(nrg.clone()));
    let rooms: Vec<SpaceId> = nrg
        .spaces()
        .iter()
        .filter(|s| s.kind == nrgdb::model::SpaceKind::Room)
        .map(|s| s.id)
        .collect();
    let from = rooms[0];
    let reach = reachable_within(
        &nav,
        &Endpoint::Space(from),
        f64::MAX,
        &Profile::default(),
        &Budget::unlimited(),
    )
    .unwrap();
    let to = reach
        .iter()
        .rev()
        .map(|(id, _)| *id)
        .find(|id| rooms.contains(id))
        .unwrap();
    let spaces = nrg.spaces().len();
    let mut source = MemorySource::new();
    source.insert("willow", nrg);
    let mut s = Session::with_default_map(source).unwrap();
    let query = format!("ROUTE FROM space {from} TO space {to}");
    assert!(!s.execute(&query).unwrap().is_empty());
    c.bench_function(
        &format!("query/route/willow-full-extracted-{spaces}-spaces"),
        |b| b.iter(|| s.execute(black_box(&query)).unwrap()),
    );
}

fn route(c: &mut Criterion) {
    route_willow_full(c);
    for columns in [28, 1875] {
        let (mut s, spaces) = session(columns);
        // Corner to corner: the upper room of the first segment to the
        // lower room of the last one, so Dijkstra settles every node.
        let query = format!("ROUTE FROM room 3 TO room {}", 5 * (columns - 1) + 5);
        assert!(!s.execute(&query).unwrap().is_empty());
        c.bench_function(&format!("query/route/{spaces}-spaces"), |b| {
            b.iter(|| s.execute(black_box(&query)).unwrap())
        });
    }
    // The same search without the query layer, to see where the time goes.
    let nrg = demo::building(1875);
    let far = nrg.spaces().len();
    let nav = NavMesh::new(Arc::new(nrg));
    let from = Endpoint::Space(SpaceId(3));
    let p = Profile::default();
    c.bench_function(&format!("route/reachable-all/{far}-spaces"), |b| {
        b.iter(|| reachable_within(&nav, &from, 1e9, &p, &Budget::unlimited()).unwrap())
    });
    let request = RouteRequest::new(SpaceId(3), SpaceId(9375));
    c.bench_function(&format!("route/shortest/{far}-spaces"), |b| {
        b.iter(|| shortest_route(&nav, black_box(&request), &Budget::unlimited()).unwrap())
    });
    let (mut s, spaces) = session(28);
    let query = "ROUTE FROM \"Kitchen\" TO \"Lounge\" ALTERNATIVES 3";
    c.bench_function(
        &format!("query/route-alternatives-3/{spaces}-spaces"),
        |b| b.iter(|| s.execute(black_box(query)).unwrap()),
    );
    c.bench_function("query/parse/route", |b| {
        b.iter(|| {
            nrgdb::query::parse(black_box(
                "ROUTE FROM room 3 TO \"Lounge\" VIA 8 AVOID door 12",
            ))
            .unwrap()
        })
    });
}

criterion_group!(benches, route);
criterion_main!(benches);
