//! Issue 23: a writer killed mid-commit leaves nothing half-written, on
//! every engine that outlives a process (SQLite, PostgreSQL). `nrgdb
//! import` of a large model is killed (SIGKILL) at several moments; after
//! each, every stored revision reads back whole (its row counts equal its
//! record), the history is a line, and the next writer is not blocked.

use std::process::{Command, Stdio};
use std::time::Duration;

use nrgdb::store::{ImportMeta, Store};

use super::store_engines::fresh_postgres_database;

/// A large model (3 001 spaces) as a JSON file.
fn big_model(dir: &std::path::Path, rooms: usize, dx: f64) -> std::path::PathBuf {
    let nrg = super::support::remapped(&nrgdb::fixtures::corridor_building(rooms), [dx, 0.0], 0);
    let path = dir.join(format!("big-{rooms}-{dx}.json"));
    std::fs::write(&path, serde_json::to_string(&nrg).unwrap()).unwrap();
    path
}

fn kill_imports(db: &str) {
    let dir = tempfile::tempdir().unwrap();
    // A first revision the later imports are matched against.
    let mut store = Store::open_db(db).unwrap();
    store
        .import(
            "big",
            &nrgdb::fixtures::corridor_building(1_500),
            ImportMeta::new("base", "t"),
        )
        .unwrap();
    drop(store);
    // How long one import takes here, start to end (the commit is its
    // last part): the kills are spread over it, most near the end.
    let model = big_model(dir.path(), 1_500, 0.005);
    let started = std::time::Instant::now();
    let out = Command::new(env!("CARGO_BIN_EXE_nrgdb"))
        .args(["import", "--map", "big", "--db", db])
        .arg(&model)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut whole = started.elapsed();
    eprintln!(
        "{db}: one import takes {whole:?}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    // The kills are spread over the import; an import that ends before
    // its kill (the machine got faster, other tests ended) shortens the
    // estimate, and the fractions start again until enough were killed.
    let fractions = [0.5, 0.85, 0.9, 0.93, 0.96, 0.99];
    let mut killed = 0;
    for k in 0..12 {
        if k >= fractions.len() && killed >= 2 {
            break;
        }
        let fraction = fractions[k % fractions.len()];
        let delay = whole.mul_f64(fraction);
        let model = big_model(dir.path(), 1_500, 0.01 * (k + 1) as f64);
        let spawned = std::time::Instant::now();
        let mut child = Command::new(env!("CARGO_BIN_EXE_nrgdb"))
            .args(["import", "--map", "big", "--db", db])
            .arg(&model)
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        let mut ended = None;
        while spawned.elapsed() < delay {
            if child.try_wait().unwrap().is_some() {
                ended = Some(spawned.elapsed());
                break;
            }
            std::thread::sleep(Duration::from_millis(2));
        }
        match ended.or_else(|| child.try_wait().unwrap().map(|_| spawned.elapsed())) {
            Some(took) => whole = whole.min(took),
            None => {
                child.kill().unwrap();
                killed += 1;
            }
        }
        child.wait().unwrap();
        let store = Store::open_db(db).unwrap();
        let revs = store.revisions("big").unwrap();
        for (i, r) in revs.iter().enumerate() {
            assert_eq!(r.seq, i as u32 + 1, "{db}: history is not a line");
            let nrg = store.load("big", Some(r.seq)).unwrap();
            assert_eq!(
                nrg.spaces().len(),
                r.spaces,
                "{db}: revision {} is partial",
                r.seq
            );
            assert_eq!(
                nrg.connections().len(),
                r.connections,
                "{db}: revision {}",
                r.seq
            );
        }
        assert_eq!(store.integrity_check().unwrap(), ["ok"], "{db}");
    }
    assert!(
        killed >= 2,
        "{db}: only {killed} imports were killed before they ended"
    );
    // The next writer gets the lock at once.
    let mut store = Store::open_db(db).unwrap();
    store.set_busy_timeout(Duration::from_millis(500)).unwrap();
    let before = store.revisions("big").unwrap().len();
    let done = store
        .import(
            "big",
            &nrgdb::fixtures::corridor_building(1_499),
            ImportMeta::new("after", "t"),
        )
        .unwrap();
    assert_eq!(done.revision.seq as usize, before + 1, "{db}");
}

#[test]
fn a_killed_sqlite_writer_leaves_nothing_half_written() {
    let dir = tempfile::tempdir().unwrap();
    kill_imports(&dir.path().join("killed.sqlite").display().to_string());
}

#[test]
fn a_killed_postgres_writer_leaves_nothing_half_written() {
    if let Some(url) = fresh_postgres_database() {
        kill_imports(&url);
    }
}
