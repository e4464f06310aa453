//! A fleet-sized database (issue 23): `--buildings` simulated buildings ×
//! `--revisions` revisions each, imported in parallel by `--writers`
//! writers (each with its own connection, as robots uploading re-mapped
//! floors), into `--db` (an SQLite file or a PostgreSQL URL). Prints the
//! time, the database's size, the errors and whether every history is a
//! straight line 1..n.
//!
//! ```sh
//! cargo run --release --example fleet_import -- --db fleet.sqlite
//! cargo run --release --example fleet_import -- --db postgres://…/fleet
//! ```
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::time::Instant;

use nrgdb::model::{Nrg, SpaceId};
use nrgdb::store::{ImportMeta, Store};

/// Building `b` as mapped the `r`-th time: a corridor building of 3–8
/// rooms, with one room moved a little more at each re-mapping.
fn building(b: usize, r: usize) -> Nrg {
    let nrg = nrgdb::fixtures::corridor_building(3 + b % 6);
    let (mut spaces, links) = nrg.into_parts();
    let moved = SpaceId(10 + (r % 3) as u32);
    let dx = 0.02 * r as f64;
    for s in spaces.iter_mut().filter(|s| s.id == moved) {
        for p in s.polygon.iter_mut().chain(std::iter::once(&mut s.anchor)) {
            p[1] += dx;
        }
    }
    Nrg::new(spaces, links).unwrap()
}

fn arg(args: &[String], name: &str, default: &str) -> String {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1))
        .cloned()
        .unwrap_or_else(|| default.to_string())
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let db = arg(&args, "--db", "fleet.sqlite");
    let buildings: usize = arg(&args, "--buildings", "1000").parse().unwrap();
    let revisions: usize = arg(&args, "--revisions", "5").parse().unwrap();
    let writers: usize = arg(&args, "--writers", "4").parse().unwrap();
    drop(Store::open_db(&db).unwrap()); // schema, once
    let started = Instant::now();
    let errors: Vec<String> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..writers)
            .map(|w| {
                let db = db.clone();
                scope.spawn(move || {
                    let mut store = Store::open_db(&db).unwrap();
                    let mut errors = Vec::new();
                    for b in (w..buildings).step_by(writers) {
                        for r in 0..revisions {
                            let meta =
                                ImportMeta::new(format!("mapping run {r}"), format!("robot-{w}"));
                            if let Err(e) =
                                store.import(&format!("building-{b:04}"), &building(b, r), meta)
                            {
                                errors.push(format!("building {b} revision {r}: {e}"));
                            }
                        }
                    }
                    errors
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect()
    });
    let took = started.elapsed();
    let store = Store::open_db(&db).unwrap();
    let maps = store.maps().unwrap();
    let mut crooked = 0;
    for m in &maps {
        let revs = store.revisions(&m.name).unwrap();
        let straight = revs.len() == revisions
            && revs
                .iter()
                .enumerate()
                .all(|(i, r)| r.seq == i as u32 + 1 && r.parent == (i > 0).then_some(i as u32));
        crooked += usize::from(!straight);
    }
    let imports = buildings * revisions;
    println!(
        "{} : {buildings} buildings × {revisions} revisions by {writers} writers: {imports} imports in {:.1} s ({:.0} imports/s); {} errors; {} maps, {crooked} histories not a straight line 1..{revisions}",
        store.location(),
        took.as_secs_f64(),
        imports as f64 / took.as_secs_f64(),
        errors.len(),
        maps.len(),
    );
    for e in errors.iter().take(5) {
        println!("  error: {e}");
    }
    if !nrgdb::store::is_postgres_url(&db) {
        let size: u64 = ["", "-wal"]
            .iter()
            .filter_map(|s| std::fs::metadata(format!("{db}{s}")).ok())
            .map(|m| m.len())
            .sum();
        println!(
            "size: {:.1} MiB (file + WAL)",
            size as f64 / (1 << 20) as f64
        );
    } else {
        let mut client = postgres::Client::connect(&db, postgres::NoTls).unwrap();
        let size: i64 = client
            .query_one("SELECT pg_database_size(current_database())", &[])
            .unwrap()
            .get(0);
        println!(
            "size: {:.1} MiB (pg_database_size)",
            size as f64 / (1 << 20) as f64
        );
    }
}
