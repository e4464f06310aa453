//! One conformance suite for every store engine (issue 23): memory,
//! SQLite and, when a PostgreSQL server can be started, PostgreSQL. Each
//! check runs on each engine and names it when it fails: history, deltas,
//! identity, names, corrections, grids, point location, change tokens,
//! concurrent writers giving a straight history, and the same answers to
//! the same queries. Expected values come from the test's own building
//! (known ids, areas, positions), never from another engine.

use std::collections::BTreeSet;

use nrgdb::edit::Edit;
use nrgdb::grid::OccupancyGrid;
use nrgdb::model::{Georef, SpaceId, SpaceKind};
use nrgdb::query::{Format, Session};
use nrgdb::store::{CorrectionState, ImportMeta, StoreError};

use super::store_building::{building, nudge, split_room};
use super::store_engines::{EngineUnderTest, engines};

fn meta(msg: &str) -> ImportMeta {
    ImportMeta::new(msg, "conformance")
}

/// Every check below, on every engine.
fn each(mut check: impl FnMut(&EngineUnderTest)) {
    for engine in engines() {
        eprintln!("engine: {}", engine.name);
        check(&engine);
    }
}

#[test]
fn history_is_a_line_and_every_revision_reads_back() {
    each(|e| {
        let mut store = e.open();
        let inputs = [
            building(8, 0.0, 1),
            nudge(&building(8, 0.0, 1), SpaceId(3), 0.3),
            split_room(&building(8, 0.0, 1), SpaceId(2), SpaceId(900)),
        ];
        let mut stored = Vec::new();
        for (k, nrg) in inputs.iter().enumerate() {
            let mut m = meta(&format!("r{k}"));
            // A map made earlier (a recording's message time) keeps its
            // time; the others get the time they are stored.
            if k == 1 {
                m.recorded_at = Some("2020-01-02T03:04:05.678Z".into());
            }
            let done = store.import("b", nrg, m).unwrap();
            assert_eq!(done.revision.seq, k as u32 + 1, "{}", e.name);
            assert_eq!(
                done.revision.parent,
                (k > 0).then_some(k as u32),
                "{}",
                e.name
            );
            stored.push(store.load("b", None).unwrap());
        }
        let revs = store.revisions("b").unwrap();
        assert_eq!(
            revs.iter().map(|r| r.seq).collect::<Vec<_>>(),
            [1, 2, 3],
            "{}",
            e.name
        );
        assert_eq!(revs[2].message, "r2");
        assert_eq!(revs[1].created_at, "2020-01-02T03:04:05.678Z", "{}", e.name);
        assert!(
            revs[2].created_at.as_str() > "2020-01-02T03:04:05.678Z",
            "{}",
            e.name
        );
        assert_eq!(revs[2].author, "conformance");
        for (k, nrg) in stored.iter().enumerate() {
            assert_eq!(
                &store.load("b", Some(k as u32 + 1)).unwrap(),
                nrg,
                "{}",
                e.name
            );
        }
        // The first revision keeps the model's ids; it is the input exactly.
        assert_eq!(stored[0], inputs[0], "{}", e.name);
        let maps = store.maps().unwrap();
        assert_eq!(
            (maps[0].name.as_str(), maps[0].latest),
            ("b", 3),
            "{}",
            e.name
        );
        // Unknown names and numbers are clear errors.
        match store.load("bb", None) {
            Err(StoreError::NoSuchMap { suggestion, .. }) => {
                assert_eq!(suggestion.as_deref(), Some("b"), "{}", e.name)
            }
            other => panic!("{}: {other:?}", e.name),
        }
        assert!(matches!(
            store.load("b", Some(4)),
            Err(StoreError::NoSuchRevision { latest: 3, .. })
        ));
        // A fresh handle sees the same history.
        let other = e.open();
        assert_eq!(other.revisions("b").unwrap(), revs, "{}", e.name);
    });
}

#[test]
fn deltas_count_what_changed_and_nothing_changed_writes_nothing() {
    each(|e| {
        let mut store = e.open();
        let base = building(8, 0.0, 1);
        store.import("d", &base, meta("a")).unwrap();
        let moved = nudge(&base, SpaceId(3), 0.25);
        let r2 = store.import("d", &moved, meta("b")).unwrap().revision;
        assert_eq!(
            (r2.spaces_added, r2.spaces_changed, r2.spaces_removed),
            (0, 1, 0),
            "{}",
            e.name
        );
        let split = split_room(&moved, SpaceId(2), SpaceId(900));
        let r3 = store.import("d", &split, meta("c")).unwrap().revision;
        assert_eq!(r3.spaces, split.spaces().len(), "{}", e.name);
        assert_eq!(r3.spaces_added, 1, "{}", e.name);
        let again = store.import("d", &split, meta("same")).unwrap();
        assert!(again.unchanged, "{}", e.name);
        assert_eq!(again.revision.seq, 3, "{}", e.name);
        assert_eq!(store.revisions("d").unwrap().len(), 3, "{}", e.name);
    });
}

#[test]
fn identity_follows_the_building_not_the_file_ids() {
    each(|e| {
        let mut store = e.open();
        let first = building(6, 0.0, 1);
        store.import("i", &first, meta("a")).unwrap();
        store
            .rename_space("i", SpaceId(2), Some("Lab"), meta("name"))
            .unwrap();
        // The same building shifted 3 cm with every id changed: each space
        // keeps its id and the name given.
        let remapped = super::support::remapped(&first, [0.03, 0.0], 500);
        let done = store.import("i", &remapped, meta("b")).unwrap();
        for s in first.spaces() {
            assert_eq!(done.ids[&SpaceId(s.id.0 + 500)], s.id, "{}", e.name);
        }
        let now = store.load("i", None).unwrap();
        assert_eq!(
            now.space(SpaceId(2)).unwrap().name.as_deref(),
            Some("Lab"),
            "{}",
            e.name
        );
        // A new space takes an id above every id the map ever used.
        let max = first.spaces().iter().map(|s| s.id.0).max().unwrap();
        let grown = split_room(&first, SpaceId(4), SpaceId(7777));
        let done = store.import("i", &grown, meta("c")).unwrap();
        let fresh: BTreeSet<u32> = done
            .ids
            .values()
            .map(|s| s.0)
            .filter(|&v| v > max)
            .collect();
        assert_eq!(fresh.len(), 1, "{}: {:?}", e.name, done.ids);
        assert_eq!(
            store.next_space_id("i").unwrap().0,
            fresh.iter().next().unwrap() + 1
        );
        assert_eq!(
            store.next_space_id("nothing").unwrap(),
            SpaceId(1),
            "{}",
            e.name
        );
    });
}

#[test]
fn corrections_are_kept_reapplied_dropped_and_undone() {
    each(|e| {
        let mut store = e.open();
        let nrg = nrgdb::fixtures::corridor_building(3);
        nrgdb::ingest::ingest(&mut store, "c", &nrg, meta("a"), None).unwrap();
        let set = Edit::SetKind {
            space: SpaceId(11),
            kind: SpaceKind::Corridor,
        };
        let done =
            nrgdb::ingest::edit(&mut store, "c", &set, "SET 11 KIND corridor", meta("e1")).unwrap();
        assert_eq!((done.revision.seq, done.correction), (2, 1), "{}", e.name);
        // A re-mapped building: the correction is applied again.
        let again = super::support::remapped(&nrg, [0.02, 0.0], 300);
        let ing = nrgdb::ingest::ingest(&mut store, "c", &again, meta("b"), None).unwrap();
        assert_eq!(ing.corrections_applied, [1], "{}", e.name);
        let now = store.load("c", None).unwrap();
        assert_eq!(
            now.space(SpaceId(11)).unwrap().kind,
            SpaceKind::Corridor,
            "{}",
            e.name
        );
        let list = store.corrections("c").unwrap();
        assert_eq!(list[0].state, CorrectionState::Applied, "{}", e.name);
        assert_eq!(list[0].checked_on, 3, "{}", e.name);
        assert_eq!(list[0].statement, "SET 11 KIND corridor");
        // Undo is only for the last edit; this one made revision 2.
        assert!(matches!(
            store.undo_correction("c", 1),
            Err(StoreError::CannotUndo { .. })
        ));
        let attr = Edit::SetAttribute {
            space: SpaceId(12),
            key: "access".into(),
            value: serde_json::json!("staff"),
        };
        let done = nrgdb::ingest::edit(
            &mut store,
            "c",
            &attr,
            "SET 12 ATTRIBUTE access = \"staff\"",
            meta("e2"),
        )
        .unwrap();
        assert_eq!(done.correction, 2, "{}", e.name);
        let undone = store.undo_correction("c", 2).unwrap();
        assert_eq!(undone.seq, 5, "{}", e.name);
        assert_eq!(
            store.load("c", Some(5)).unwrap(),
            store.load("c", Some(3)).unwrap(),
            "{}",
            e.name
        );
        assert_eq!(
            store.corrections("c").unwrap()[1].state,
            CorrectionState::Dropped
        );
        let dropped = store.drop_correction("c", 1).unwrap();
        assert_eq!(dropped.state, CorrectionState::Dropped, "{}", e.name);
        assert!(matches!(
            store.drop_correction("c", 9),
            Err(StoreError::NoSuchCorrection { .. })
        ));
        // Dropped corrections are no longer applied.
        let ing = nrgdb::ingest::ingest(&mut store, "c", &nrg, meta("c"), None).unwrap();
        assert!(ing.corrections_applied.is_empty(), "{}", e.name);
        assert_eq!(
            store
                .load("c", None)
                .unwrap()
                .space(SpaceId(11))
                .unwrap()
                .kind,
            SpaceKind::Room
        );
    });
}

#[test]
fn grids_and_point_location() {
    each(|e| {
        let mut store = e.open();
        let grid = OccupancyGrid::from_ascii("#####\n#...#\n#.?.#\n#####", 0.05);
        let nrg = nrgdb::fixtures::corridor_building(3);
        store
            .import_with_grid("g", &nrg, meta("a"), Some(&grid))
            .unwrap();
        assert_eq!(store.grid("g", None).unwrap(), Some(grid), "{}", e.name);
        let moved = nudge(&nrg, SpaceId(10), 0.1);
        store.import("g", &moved, meta("b")).unwrap();
        assert_eq!(store.grid("g", None).unwrap(), None, "{}", e.name);
        // Room 10 spans x 0.1..3.9, y 2.2..7; its door lies in the wall
        // gap; the corridor is y 0..2; nothing at y = 9.
        assert_eq!(
            store.locate("g", Some(1), 2.0, 5.0).unwrap(),
            Some(SpaceId(10)),
            "{}",
            e.name
        );
        assert_eq!(
            store.locate("g", Some(1), 6.0, 1.0).unwrap(),
            Some(SpaceId(1)),
            "{}",
            e.name
        );
        assert_eq!(
            store.locate("g", Some(1), 6.0, 9.0).unwrap(),
            None,
            "{}",
            e.name
        );
        // Moved 0.1 m right in revision 2: x = 0.15 is outside it there.
        assert_eq!(
            store.locate("g", Some(1), 0.15, 5.0).unwrap(),
            Some(SpaceId(10))
        );
        assert_eq!(
            store.locate("g", Some(2), 0.15, 5.0).unwrap(),
            None,
            "{}",
            e.name
        );
    });
}

/// A georeference is kept with the map, read by every handle, holds for
/// the revisions after it, and is removed on request.
#[test]
fn a_georeference_stays_with_its_map() {
    each(|e| {
        let mut store = e.open();
        let g = Georef::new(52.5163, 13.3777, 30.0, "1").unwrap();
        assert!(
            matches!(
                store.set_georef("nowhere", Some(&g)),
                Err(StoreError::NoSuchMap { .. })
            ),
            "{}",
            e.name
        );
        store
            .import("geo", &building(4, 0.0, 1), meta("a"))
            .unwrap();
        assert_eq!(store.georef("geo").unwrap(), None, "{}", e.name);
        store.set_georef("geo", Some(&g)).unwrap();
        store
            .import("geo", &building(5, 0.0, 1), meta("b"))
            .unwrap();
        let other = e.open();
        assert_eq!(other.georef("geo").unwrap(), Some(g.clone()), "{}", e.name);
        store.set_georef("geo", None).unwrap();
        assert_eq!(other.georef("geo").unwrap(), None, "{}", e.name);
    });
}

/// Levels (issue 25) are kept space by space; re-mapping one level makes
/// a revision in which only that level's spaces change.
#[test]
fn levels_are_kept_and_one_level_changes_alone() {
    each(|e| {
        let mut store = e.open();
        let nrg = nrgdb::fixtures::storeys(3, 4);
        store.import("tower", &nrg, meta("three floors")).unwrap();
        let back = store.load("tower", None).unwrap();
        assert_eq!(back, nrg, "{}", e.name);
        assert_eq!(back.levels().len(), 3, "{}", e.name);
        // Move one room on level 1 only.
        let (mut spaces, connections) = nrg.into_parts();
        let room = spaces
            .iter_mut()
            .find(|s| s.kind == SpaceKind::Room && s.level.as_ref().unwrap().name == "1")
            .unwrap();
        for p in &mut room.polygon {
            p[1] += 0.2;
        }
        room.anchor[1] += 0.2;
        let moved = nrgdb::model::Nrg::new(spaces, connections).unwrap();
        let done = store
            .import("tower", &moved, meta("level 1 re-mapped"))
            .unwrap();
        assert_eq!(
            (
                done.revision.spaces_changed,
                done.revision.spaces_added,
                done.revision.spaces_removed
            ),
            (1, 0, 0),
            "{}",
            e.name
        );
        assert_eq!(store.load("tower", None).unwrap(), moved, "{}", e.name);
        assert_eq!(
            store.load("tower", Some(1)).unwrap().levels().len(),
            3,
            "{}",
            e.name
        );
    });
}

#[test]
fn the_change_token_moves_when_anyone_commits() {
    each(|e| {
        let mut writer = e.open();
        let reader = e.open();
        writer.import("t", &building(4, 0.0, 1), meta("a")).unwrap();
        let before = reader.change_token().unwrap();
        let latest = reader.revision("t", None).unwrap().seq;
        writer.import("t", &building(5, 0.0, 1), meta("b")).unwrap();
        let after = reader.change_token().unwrap();
        // No token means "ask every time", which is never stale either.
        if before.is_some() {
            assert_ne!(before, after, "{}", e.name);
        }
        assert_eq!(
            reader.revision("t", None).unwrap().seq,
            latest + 1,
            "{}",
            e.name
        );
        let own = writer.change_token().unwrap();
        writer
            .rename_space("t", SpaceId(1), Some("x"), meta("n"))
            .unwrap();
        if own.is_some() {
            assert_ne!(own, writer.change_token().unwrap(), "{}", e.name);
        }
    });
}

/// Four writers import into one map at once: every import is stored (or
/// refused with a clear "retry"), and the history stays a line.
#[test]
fn concurrent_writers_give_a_straight_history() {
    each(|e| {
        let mut first = e.open();
        first
            .import("w", &building(6, 0.0, 1), meta("start"))
            .unwrap();
        let stored = std::thread::scope(|scope| {
            let handles: Vec<_> = (0..4u64)
                .map(|w| {
                    let mut store = e.open();
                    scope.spawn(move || {
                        let mut ok = 0;
                        for k in 0..4u64 {
                            let nrg = nudge(
                                &building(6, 0.0, 1),
                                SpaceId(1 + (w as u32 % 3)),
                                0.01 * (1 + w * 4 + k) as f64,
                            );
                            match store.import("w", &nrg, meta(&format!("w{w}k{k}"))) {
                                Ok(done) if !done.unchanged => ok += 1,
                                Ok(_) => {}
                                Err(StoreError::MapChanged { .. } | StoreError::Busy) => {}
                                Err(other) => panic!("{other:?}"),
                            }
                        }
                        ok
                    })
                })
                .collect();
            handles.into_iter().map(|h| h.join().unwrap()).sum::<u32>()
        });
        let revs = first.revisions("w").unwrap();
        assert_eq!(revs.len() as u32, 1 + stored, "{}", e.name);
        assert!(
            stored >= 4,
            "{}: only {stored} of 16 imports stored",
            e.name
        );
        for (k, r) in revs.iter().enumerate() {
            assert_eq!(r.seq, k as u32 + 1, "{}", e.name);
            assert_eq!(r.parent, (k > 0).then_some(k as u32), "{}", e.name);
            first.load("w", Some(r.seq)).unwrap();
        }
    });
}

/// The same statements give the same answers on every engine; the
/// expected facts come from the building itself.
#[test]
fn the_same_queries_give_the_same_answers() {
    let mut answers: Vec<(String, String)> = Vec::new();
    each(|e| {
        let mut store = e.open();
        store
            .import("q", &nrgdb::fixtures::corridor_building(4), meta("a"))
            .unwrap();
        let mut session = Session::with_default_map(&mut store).unwrap();
        let script = "FIND rooms ORDER BY area DESC LIMIT 2; NEIGHBOURS OF 10; \
                      ROUTE FROM 10 TO 13; LOCATE (6.0, 1.0); SHOW REVISIONS; \
                      NAME 11 AS \"Kitchen\"; FIND rooms WHERE name = \"Kitchen\"";
        let text = session.run(script, Format::Csv).unwrap();
        assert!(text.contains("Kitchen"), "{}: {text}", e.name);
        assert!(text.contains("route,length_m"), "{}: {text}", e.name);
        drop(session);
        assert_eq!(store.revisions("q").unwrap().len(), 2, "{}", e.name);
        answers.push((e.name.to_string(), text.replace(e.name, "")));
    });
    let reference = &answers[0];
    for (name, text) in &answers[1..] {
        assert_eq!(
            text, &reference.1,
            "{name} answers differently from {}",
            reference.0
        );
    }
}

/// Renaming through a session works at the latest revision only, on every
/// source (issue 23: the memory source renamed at any revision).
#[test]
fn name_needs_the_latest_revision_everywhere() {
    each(|e| {
        let mut store = e.open();
        store.import("n", &building(4, 0.0, 1), meta("a")).unwrap();
        store.import("n", &building(5, 0.0, 1), meta("b")).unwrap();
        let mut session = Session::new(&mut store);
        session.run("USE n AT REVISION 1", Format::Table).unwrap();
        let e1 = session.run("NAME 1 AS \"x\"", Format::Table).unwrap();
        assert!(
            e1.starts_with("error") && e1.contains("latest"),
            "{}: {e1}",
            e.name
        );
    });
    let mut memory = nrgdb::query::MemorySource::new();
    memory.insert("n", building(4, 0.0, 1));
    memory.insert("n", building(5, 0.0, 1));
    let mut session = Session::new(memory);
    session.run("USE n AT REVISION 1", Format::Table).unwrap();
    let e2 = session.run("NAME 1 AS \"x\"", Format::Table).unwrap();
    assert!(
        e2.starts_with("error") && e2.contains("latest"),
        "memory source: {e2}"
    );
}
