//! The store engines side by side (issue 23): importing one revision of a
//! willow-sized building (150 spaces; every import moves one room, so each
//! is a real revision matched against the latest) and loading a revision
//! (what the server's cache holds), on memory, SQLite and PostgreSQL in one
//! run. PostgreSQL runs in a fresh database of a throw-away server the
//! bench starts itself (scripts/pg-throwaway.sh), or of the server named
//! by `NRGDB_TEST_POSTGRES`.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::hint::black_box;

use criterion::Criterion;
use nrgdb::model::SpaceId;
use nrgdb::store::ImportMeta;

#[path = "../tests/it/store_building.rs"]
#[allow(dead_code)]
mod store_building;
#[path = "../tests/it/store_engines.rs"]
#[allow(dead_code)]
mod store_engines;

use store_building::{building, nudge};

fn bench(c: &mut Criterion) {
    let base = building(30, 0.0, 1);
    let moved = [nudge(&base, SpaceId(7), 0.1), nudge(&base, SpaceId(7), 0.2)];
    for engine in store_engines::engines() {
        let mut store = engine.open();
        store
            .import("willow", &base, ImportMeta::new("base", "bench"))
            .unwrap();
        let mut k = 0usize;
        c.bench_function(
            &format!("store_engines/import/{}/willow-150", engine.name),
            |b| {
                b.iter(|| {
                    k += 1;
                    let done = store
                        .import(
                            "willow",
                            black_box(&moved[k % 2]),
                            ImportMeta::new("m", "bench"),
                        )
                        .unwrap();
                    assert!(!done.unchanged);
                })
            },
        );
        c.bench_function(
            &format!("store_engines/load/{}/willow-150", engine.name),
            |b| b.iter(|| black_box(store.load("willow", None).unwrap())),
        );
        c.bench_function(
            &format!("store_engines/locate/{}/willow-150", engine.name),
            |b| b.iter(|| black_box(store.locate("willow", None, 3.0, 1.0).unwrap())),
        );
        eprintln!(
            "{}: {} revisions after the bench",
            engine.name,
            store.revisions("willow").unwrap().len()
        );
    }
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c);
    c.final_summary();
}
