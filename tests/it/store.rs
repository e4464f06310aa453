//! The versioned store through its library API (issue 4): exact round
//! trips, stable identity, schema guard, no partial revisions, growth with
//! changes, concurrent writers.

use std::collections::BTreeMap;

use nrgdb::model::{Nrg, SpaceId, SpaceKind};
use nrgdb::store::{ImportMeta, Store, StoreError};

use super::store_building::{building, nudge, split_room};

fn meta(msg: &str) -> ImportMeta {
    ImportMeta::new(msg, "tester")
}

/// `nrg` with every space id replaced by `1000 - id`, so a re-import must
/// find identities by geometry, not by the file's ids.
fn renumber(nrg: &Nrg) -> Nrg {
    let (mut spaces, mut links) = nrg.clone().into_parts();
    for s in &mut spaces {
        s.id = SpaceId(1000 - s.id.0);
    }
    for c in &mut links {
        c.a = SpaceId(1000 - c.a.0);
        c.b = SpaceId(1000 - c.b.0);
    }
    Nrg::new(spaces, links).unwrap()
}

#[test]
fn issue_4_every_revision_reads_back_exactly() {
    let mut store = Store::open_in_memory().unwrap();
    let first = building(10, 0.0, 1);
    let done = store.import("b", &first, meta("first")).unwrap();
    assert_eq!(done.revision.seq, 1);
    assert_eq!(done.revision.parent, None);
    assert_eq!(store.load("b", None).unwrap(), first);

    let mut snapshots = vec![first.clone()];
    let inputs = [
        renumber(&building(10, 0.03, 2)),
        split_room(&building(10, 0.0, 1), SpaceId(2), SpaceId(900)),
        nudge(&building(10, 0.0, 1), SpaceId(7), 0.25),
    ];
    for (k, input) in inputs.iter().enumerate() {
        let done = store.import("b", input, meta("again")).unwrap();
        assert_eq!(done.revision.seq, k as u32 + 2);
        assert_eq!(done.revision.parent, Some(k as u32 + 1));
        let stored = store.load("b", None).unwrap();
        // The stored revision is the input with stable ids.
        assert_eq!(stored.spaces().len(), input.spaces().len());
        for s in input.spaces() {
            let got = stored.space(done.ids[&s.id]).unwrap();
            assert_eq!(
                (got.kind, &got.polygon, got.anchor),
                (s.kind, &s.polygon, s.anchor)
            );
        }
        snapshots.push(stored);
    }
    store
        .rename_space("b", SpaceId(2), Some("Kitchen"), meta("name"))
        .unwrap();
    snapshots.push(store.load("b", None).unwrap());
    for (k, snap) in snapshots.iter().enumerate() {
        let rev = k as u32 + 1;
        assert_eq!(&store.load("b", Some(rev)).unwrap(), snap, "revision {rev}");
    }
    let revs = store.revisions("b").unwrap();
    assert_eq!(revs.len(), 5);
    assert_eq!(store.log("b").unwrap()[0].message, "name");
}

#[test]
fn issue_4_stable_ids_survive_shift_and_split() {
    let mut store = Store::open_in_memory().unwrap();
    let first = building(10, 0.0, 1);
    store.import("b", &first, meta("first")).unwrap();
    let info = store
        .rename_space("b", SpaceId(2), Some("Kitchen"), meta("name"))
        .unwrap();
    assert_eq!(info.spaces_changed, 1);
    assert_eq!(info.spaces_added + info.spaces_removed, 0);
    let mut room = store
        .load("b", None)
        .unwrap()
        .space(SpaceId(2))
        .unwrap()
        .clone();
    assert_eq!(room.name.as_deref(), Some("Kitchen"));
    room.attributes.insert("floor".into(), serde_json::json!(0));

    // Re-mapped: every vertex moved a little, room 2 split, ids renumbered.
    let remapped = renumber(&split_room(&building(10, 0.05, 9), SpaceId(2), SpaceId(77)));
    let done = store.import("b", &remapped, meta("remapped")).unwrap();
    let stored = store.load("b", None).unwrap();
    // Every space of the first revision is continued under its own id.
    for s in first.spaces() {
        assert_eq!(done.ids[&SpaceId(1000 - s.id.0)], s.id, "space {}", s.id);
    }
    // The smaller part of the split room is new, above every id used.
    assert_eq!(done.ids[&SpaceId(1000 - 77)], SpaceId(51));
    let kitchen = stored.space(SpaceId(2)).unwrap();
    assert_eq!(
        kitchen.name.as_deref(),
        Some("Kitchen"),
        "name survives re-mapping"
    );
    assert_eq!(kitchen.attributes.get("floor"), Some(&serde_json::json!(0)));
    assert_eq!(stored.space(SpaceId(51)).unwrap().name, None);
    assert_eq!(done.revision.spaces_added, 1);
    assert_eq!(done.revision.spaces_removed, 0);
    // The name also survives a second re-mapping.
    store
        .import("b", &renumber(&building(10, 0.02, 3)), meta("again"))
        .unwrap();
    let again = store.load("b", None).unwrap();
    assert_eq!(
        again.space(SpaceId(2)).unwrap().name.as_deref(),
        Some("Kitchen")
    );
}

#[test]
fn issue_4_new_name_in_the_model_wins() {
    let mut store = Store::open_in_memory().unwrap();
    store
        .import("b", &building(3, 0.0, 1), meta("first"))
        .unwrap();
    store
        .rename_space("b", SpaceId(2), Some("Kitchen"), meta("name"))
        .unwrap();
    let (mut spaces, links) = building(3, 0.01, 2).into_parts();
    spaces[1].name = Some("Pantry".into());
    spaces[1]
        .attributes
        .insert("floor".into(), serde_json::json!(1));
    let nrg = Nrg::new(spaces, links).unwrap();
    store
        .import("b", &nrg, meta("renamed in the file"))
        .unwrap();
    let s = store
        .load("b", None)
        .unwrap()
        .space(SpaceId(2))
        .unwrap()
        .clone();
    assert_eq!(s.name.as_deref(), Some("Pantry"));
    assert_eq!(s.attributes["floor"], serde_json::json!(1));
}

#[test]
fn issue_4_storage_grows_with_changes_only() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("g.sqlite");
    let mut store = Store::open(&path).unwrap();
    let base = building(10, 0.0, 1);
    store.import("b", &base, meta("first")).unwrap();
    for k in 0..20u32 {
        // Each revision moves one room a little; the rest is unchanged.
        let room = SpaceId(2 + 5 * (k % 10));
        let current = store.load("b", None).unwrap();
        store
            .import("b", &nudge(&current, room, 0.01), meta("nudge"))
            .unwrap();
    }
    let raw = rusqlite::Connection::open(&path).unwrap();
    let rows: i64 = raw
        .query_row("SELECT COUNT(*) FROM spaces", [], |r| r.get(0))
        .unwrap();
    let links: i64 = raw
        .query_row("SELECT COUNT(*) FROM connections", [], |r| r.get(0))
        .unwrap();
    assert_eq!(rows, 50 + 20, "one row per changed space");
    assert_eq!(
        links as usize,
        base.connections().len(),
        "connections unchanged"
    );
    let first = store.load("b", Some(1)).unwrap();
    assert_eq!(first, base);
}

#[test]
fn issue_4_newer_schema_is_refused_and_untouched() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("future.sqlite");
    {
        let mut store = Store::open(&path).unwrap();
        store
            .import("b", &building(2, 0.0, 1), meta("first"))
            .unwrap();
    }
    {
        let raw = rusqlite::Connection::open(&path).unwrap();
        raw.pragma_update(None, "user_version", 99).unwrap();
        raw.pragma_update(None, "journal_mode", "delete").unwrap();
    }
    let before = std::fs::read(&path).unwrap();
    let err = Store::open(&path).unwrap_err();
    assert!(matches!(err, StoreError::TooNew { found: 99, .. }), "{err}");
    let msg = err.to_string();
    assert!(
        msg.contains("schema version 99") && msg.contains("untouched"),
        "{msg}"
    );
    assert_eq!(std::fs::read(&path).unwrap(), before, "file modified");
}

#[test]
fn issue_4_failed_import_leaves_no_partial_revision() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("p.sqlite");
    let mut store = Store::open(&path).unwrap();
    let first = building(5, 0.0, 1);
    store.import("b", &first, meta("first")).unwrap();
    // Fail at the very end of any import, after all its rows are written.
    let raw = rusqlite::Connection::open(&path).unwrap();
    raw.execute_batch(
        "CREATE TRIGGER fail_late BEFORE INSERT ON revisions
         BEGIN SELECT RAISE(ABORT, 'injected failure'); END;",
    )
    .unwrap();
    let moved = renumber(&building(5, 0.05, 4));
    let err = store.import("b", &moved, meta("doomed")).unwrap_err();
    assert!(err.to_string().contains("injected failure"), "{err}");
    // A new map whose first import fails is not left behind either.
    assert!(store.import("other", &moved, meta("doomed")).is_err());
    raw.execute_batch("DROP TRIGGER fail_late").unwrap();
    assert_eq!(store.revisions("b").unwrap().len(), 1);
    assert_eq!(store.load("b", None).unwrap(), first);
    let rows: i64 = raw
        .query_row(
            "SELECT COUNT(*) FROM spaces WHERE valid_to IS NOT NULL",
            [],
            |r| r.get(0),
        )
        .unwrap();
    assert_eq!(rows, 0, "no row was closed");
    assert_eq!(store.integrity_check().unwrap(), vec!["ok".to_string()]);
    // A bad map name stores nothing either.
    assert!(matches!(
        store.import("a@b", &first, meta("x")),
        Err(StoreError::BadMapName { .. })
    ));
    let names: Vec<String> = store.maps().unwrap().into_iter().map(|m| m.name).collect();
    assert_eq!(names, vec!["b".to_string()]);
    let total: i64 = raw
        .query_row("SELECT COUNT(*) FROM spaces", [], |r| r.get(0))
        .unwrap();
    assert_eq!(total as usize, first.spaces().len());
}

#[test]
fn issue_4_errors_name_what_exists() {
    let mut store = Store::open_in_memory().unwrap();
    let err = store.load("x", None).unwrap_err().to_string();
    assert_eq!(err, "no map named 'x'; maps are: (none) (see `nrgdb maps`)");
    store.import("a", &building(1, 0.0, 1), meta("1")).unwrap();
    store.import("b", &building(1, 0.0, 1), meta("1")).unwrap();
    let err = store.load("x", None).unwrap_err().to_string();
    assert!(err.starts_with("no map named 'x'; maps are: a, b"), "{err}");
    let err = store.load("a", Some(7)).unwrap_err().to_string();
    assert_eq!(err, "revision 7 of map 'a' does not exist (latest is 1)");
    let err = store
        .rename_space("a", SpaceId(99), Some("n"), meta("n"))
        .unwrap_err();
    assert!(matches!(err, StoreError::NoSuchSpace { .. }), "{err}");
}

#[test]
fn issue_4_locate_finds_the_space_under_a_point() {
    let mut store = Store::open_in_memory().unwrap();
    store.import("b", &building(4, 0.0, 1), meta("1")).unwrap();
    // Corridor of segment 1 spans x 4..8, y 0..2; its upper room is 2.2..6.2.
    assert_eq!(store.locate("b", None, 5.0, 1.0).unwrap(), Some(SpaceId(6)));
    assert_eq!(store.locate("b", None, 5.0, 4.0).unwrap(), Some(SpaceId(7)));
    assert_eq!(store.locate("b", None, 5.0, 20.0).unwrap(), None);
    // Door of segment 0's upper room: x 1.5..2.5, y 2.0..2.2.
    assert_eq!(store.locate("b", None, 2.0, 2.1).unwrap(), Some(SpaceId(3)));
    // After the room moves away in revision 2, revision 1 still has it.
    let moved = nudge(&building(4, 0.0, 1), SpaceId(7), 100.0);
    store.import("b", &moved, meta("moved")).unwrap();
    assert_ne!(store.locate("b", None, 5.0, 4.0).unwrap(), Some(SpaceId(7)));
    assert_eq!(
        store.locate("b", Some(1), 5.0, 4.0).unwrap(),
        Some(SpaceId(7))
    );
    let kinds: BTreeMap<SpaceId, SpaceKind> = store
        .load("b", Some(1))
        .unwrap()
        .spaces()
        .iter()
        .map(|s| (s.id, s.kind))
        .collect();
    assert_eq!(kinds[&SpaceId(6)], SpaceKind::Corridor);
}

#[test]
fn issue_4_concurrent_importers_keep_a_straight_history() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("c.sqlite");
    Store::open(&path).unwrap();
    let workers: Vec<_> = (0..2u64)
        .map(|w| {
            let path = path.clone();
            std::thread::spawn(move || {
                let mut store = Store::open(&path).unwrap();
                let (mut landed, mut busy) = (0, 0);
                for k in 0..6u64 {
                    let nrg = building(8, 0.02, w * 100 + k);
                    match store.import("shared", &nrg, meta(&format!("w{w} k{k}"))) {
                        Ok(_) => landed += 1,
                        // Both say another writer got in first: retry.
                        Err(StoreError::Busy | StoreError::MapChanged { .. }) => busy += 1,
                        Err(e) => panic!("unexpected error: {e}"),
                    }
                }
                (landed, busy)
            })
        })
        .collect();
    let mut landed = 0;
    for w in workers {
        let (l, b) = w.join().unwrap();
        assert_eq!(l + b, 6);
        landed += l;
    }
    let store = Store::open(&path).unwrap();
    let revs = store.revisions("shared").unwrap();
    assert_eq!(revs.len(), landed);
    for (k, r) in revs.iter().enumerate() {
        assert_eq!(r.seq as usize, k + 1);
        assert_eq!(r.parent, (k > 0).then_some(k as u32));
        assert_eq!(
            store.load("shared", Some(r.seq)).unwrap().spaces().len(),
            40
        );
    }
    assert_eq!(store.integrity_check().unwrap(), vec!["ok".to_string()]);
}

#[test]
fn issue_4_readers_are_not_blocked_and_writers_get_a_clear_busy() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("w.sqlite");
    let mut store = Store::open(&path).unwrap();
    let first = building(3, 0.0, 1);
    store.import("b", &first, meta("first")).unwrap();
    // Another process holds the write lock with an open transaction.
    let raw = rusqlite::Connection::open(&path).unwrap();
    raw.execute_batch("BEGIN IMMEDIATE; UPDATE maps SET created_at = created_at;")
        .unwrap();
    let started = std::time::Instant::now();
    assert_eq!(store.load("b", None).unwrap(), first);
    assert!(store.locate("b", None, 1.0, 1.0).unwrap().is_some());
    assert!(
        started.elapsed() < std::time::Duration::from_secs(2),
        "reader waited"
    );
    store
        .set_busy_timeout(std::time::Duration::from_millis(50))
        .unwrap();
    let err = store
        .import("b", &building(3, 0.01, 2), meta("second"))
        .unwrap_err();
    assert_eq!(
        err.to_string(),
        "database is busy (another nrgdb is writing); retry"
    );
    raw.execute_batch("COMMIT").unwrap();
    store
        .import("b", &building(3, 0.01, 2), meta("second"))
        .unwrap();
    assert_eq!(store.revisions("b").unwrap().len(), 2);
}

#[test]
fn issue_4_a_file_that_is_not_a_database_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("notes.txt");
    std::fs::write(
        &path,
        "hello, this is not sqlite at all, just some text".repeat(40),
    )
    .unwrap();
    let before = std::fs::read(&path).unwrap();
    let err = Store::open(&path).unwrap_err().to_string();
    assert!(err.contains("is it an nrgdb database?"), "{err}");
    assert_eq!(std::fs::read(&path).unwrap(), before);
}
