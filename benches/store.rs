//! Store benchmarks (issue 4): import and load of a willow-sized NRG
//! (150 spaces, ~265 connections), and the size of 100 revisions each
//! changing one room (printed, not timed).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::hint::black_box;

use criterion::{BatchSize, Criterion};
use nrgdb::model::SpaceId;
use nrgdb::store::{ImportMeta, Store};

#[path = "../tests/it/store_building.rs"]
#[allow(dead_code)]
mod store_building;
use store_building::{building, nudge};

const WILLOW_SEGMENTS: u32 = 30;

fn meta() -> ImportMeta {
    ImportMeta::new("bench", "bench")
}

/// Times importing `nrg` into a fresh copy of the database at `fixture`
/// (copied for each sample, so every timed import starts from the same state).
fn bench_import_onto(
    c: &mut Criterion,
    name: &str,
    fixture: &std::path::Path,
    nrg: &nrgdb::model::Nrg,
) {
    c.bench_function(name, |b| {
        b.iter_batched(
            || {
                let copy = tempfile::tempdir().unwrap();
                let path = copy.path().join("b.sqlite");
                std::fs::copy(fixture, &path).unwrap();
                let store = Store::open(&path).unwrap();
                (copy, store)
            },
            |(copy, mut store)| {
                store.import("willow", black_box(nrg), meta()).unwrap();
                (copy, store)
            },
            BatchSize::PerIteration,
        )
    });
}

/// Times importing `nrg` as the first revision of a new database.
fn bench_first_import(c: &mut Criterion, name: &str, nrg: &nrgdb::model::Nrg) {
    c.bench_function(name, |b| {
        b.iter_batched(
            || {
                let dir = tempfile::tempdir().unwrap();
                let store = Store::open(&dir.path().join("b.sqlite")).unwrap();
                (dir, store)
            },
            |(dir, mut store)| {
                store.import("willow", black_box(nrg), meta()).unwrap();
                (dir, store)
            },
            BatchSize::PerIteration,
        )
    });
}

fn import(c: &mut Criterion) {
    let nrg = building(WILLOW_SEGMENTS, 0.0, 1);
    bench_first_import(c, "store/import/first/willow-150", &nrg);
    // A re-mapping: every polygon moved, so every space is matched by
    // overlap and every row is replaced (the worst case), onto a history of
    // 1 and of 50 such revisions (the database is copied for each sample).
    for history in [1u64, 50] {
        let dir = tempfile::tempdir().unwrap();
        let fixture = dir.path().join("fixture.sqlite");
        {
            let mut store = Store::open(&fixture).unwrap();
            store.import("willow", &nrg, meta()).unwrap();
            for k in 1..history {
                let remap = building(WILLOW_SEGMENTS, 0.03, 100 + k);
                store.import("willow", &remap, meta()).unwrap();
            }
        }
        let remap = building(WILLOW_SEGMENTS, 0.03, 2);
        let name = format!("store/import/remapped-onto-{history}-revisions/willow-150");
        bench_import_onto(c, &name, &fixture, &remap);
    }
}

/// Import and load of the real `willow-full` NRG: a first import, and the
/// same extraction imported again (every space matched, nothing changed).
fn import_willow_full(c: &mut Criterion) {
    let Some(nrg) = nrgdb::fixtures::shared_map_nrg("willow-full") else {
        eprintln!("notice: willow-full not found (NRGDB_SHARED); skipping its store benchmarks");
        return;
    };
    let spaces = nrg.spaces().len();
    bench_first_import(c, &format!("store/import/first/willow-full-{spaces}"), &nrg);
    let dir = tempfile::tempdir().unwrap();
    let fixture = dir.path().join("fixture.sqlite");
    Store::open(&fixture)
        .unwrap()
        .import("willow", &nrg, meta())
        .unwrap();
    bench_import_onto(
        c,
        &format!("store/import/again/willow-full-{spaces}"),
        &fixture,
        &nrg,
    );
    let store = Store::open(&fixture).unwrap();
    c.bench_function(&format!("store/load/latest/willow-full-{spaces}"), |b| {
        b.iter(|| nrgdb::model::ConnectivityGraph::new(&store.load("willow", None).unwrap()))
    });
}

fn matching(c: &mut Criterion) {
    let old = building(WILLOW_SEGMENTS, 0.0, 1);
    let new = building(WILLOW_SEGMENTS, 0.03, 2);
    let params = nrgdb::diff::MatchParams::default();
    c.bench_function("diff/match_spaces/willow-150", |b| {
        b.iter(|| nrgdb::diff::match_spaces(black_box(&old), black_box(&new), &params))
    });
}

fn load(c: &mut Criterion) {
    let dir = tempfile::tempdir().unwrap();
    let mut store = Store::open(&dir.path().join("l.sqlite")).unwrap();
    store
        .import("willow", &building(WILLOW_SEGMENTS, 0.0, 1), meta())
        .unwrap();
    for k in 0..20 {
        store
            .import("willow", &building(WILLOW_SEGMENTS, 0.03, k), meta())
            .unwrap();
    }
    c.bench_function("store/load/latest/willow-150", |b| {
        b.iter(|| store.load(black_box("willow"), None).unwrap())
    });
    c.bench_function("store/load/rev1-of-21/willow-150", |b| {
        b.iter(|| store.load(black_box("willow"), Some(1)).unwrap())
    });
    c.bench_function("store/locate/willow-150", |b| {
        b.iter(|| {
            store
                .locate("willow", None, black_box(61.0), black_box(4.0))
                .unwrap()
        })
    });
}

/// Bytes of the database file after a checkpoint.
fn db_bytes(path: &std::path::Path) -> i64 {
    let raw = rusqlite::Connection::open(path).unwrap();
    raw.query_row("PRAGMA wal_checkpoint(TRUNCATE)", [], |_| Ok(()))
        .unwrap();
    let pages: i64 = raw
        .query_row("PRAGMA page_count", [], |r| r.get(0))
        .unwrap();
    let size: i64 = raw.query_row("PRAGMA page_size", [], |r| r.get(0)).unwrap();
    pages * size
}

/// 100 revisions each changing one room: prints the database size against
/// 1.5 × one revision plus the bytes of the changed rows.
fn size_report() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("s.sqlite");
    let mut store = Store::open(&path).unwrap();
    store
        .import("willow", &building(WILLOW_SEGMENTS, 0.0, 1), meta())
        .unwrap();
    let one = db_bytes(&path);
    for k in 0..100u32 {
        let room = SpaceId(2 + 5 * (k % WILLOW_SEGMENTS));
        let current = store.load("willow", None).unwrap();
        store
            .import("willow", &nudge(&current, room, 0.01), meta())
            .unwrap();
    }
    let all = db_bytes(&path);
    let raw = rusqlite::Connection::open(&path).unwrap();
    // Payload of the rows the 100 revisions added (spaces + boxes + revisions).
    let deltas: i64 = raw
        .query_row(
            "SELECT (SELECT COALESCE(SUM(length(geometry) + length(attributes) + length(kind)
                       + COALESCE(length(name), 0) + 40), 0) FROM spaces WHERE valid_from > 1)
                  + (SELECT COUNT(*) * 40 FROM spaces WHERE valid_from > 1)
                  + (SELECT COALESCE(SUM(length(message) + length(author) + 80), 0)
                     FROM revisions WHERE seq > 1)",
            [],
            |r| r.get(0),
        )
        .unwrap();
    let bound = 1.5 * one as f64 + deltas as f64;
    println!(
        "store/size/100-one-room-revisions: one revision {one} B, 101 revisions {all} B, \
         deltas {deltas} B, bound 1.5*one+deltas {bound:.0} B, ratio {:.2}",
        all as f64 / bound
    );
}

fn main() {
    size_report();
    let mut c = Criterion::default().configure_from_args();
    import(&mut c);
    import_willow_full(&mut c);
    matching(&mut c);
    load(&mut c);
    c.final_summary();
}
