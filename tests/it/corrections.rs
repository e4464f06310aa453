//! Issue 22: corrections through the query language on the SQLite store,
//! kept as rules and re-applied to later imports of the map; one that no
//! longer fits is reported alone; dropped ones stop applying; refused
//! edits store nothing.

use crate::support::remapped;
use nrgdb::fixtures::corridor_building;
use nrgdb::ingest::{Ingested, ingest};
use nrgdb::model::{Nrg, SpaceId, SpaceKind, point_in_ring};
use nrgdb::query::{QueryResult, Session};
use nrgdb::store::{CorrectionState, ImportMeta, Store};

fn meta(m: &str) -> ImportMeta {
    ImportMeta::new(m, "tester")
}

/// Runs `text` on the latest revision of `map`; the message or the error.
fn run(store: &mut Store, map: &str, text: &str) -> Result<String, String> {
    let mut session = Session::new(&mut *store);
    session.use_map(map, None).map_err(|e| e.to_string())?;
    let mut results = session.execute(text).map_err(|e| e.to_string())?;
    match results.pop() {
        Some(Ok(QueryResult::Message(m))) => Ok(m),
        Some(Ok(other)) => Ok(format!("{other:?}")),
        Some(Err(e)) => Err(e.to_string()),
        None => Err("no statement".into()),
    }
}

/// `nrg` without the spaces in `gone` (and their connections).
fn without(nrg: &Nrg, gone: &[u32]) -> Nrg {
    let (spaces, connections) = nrg.clone().into_parts();
    let keep = |id: SpaceId| !gone.contains(&id.0);
    Nrg::new(
        spaces.into_iter().filter(|s| keep(s.id)).collect(),
        connections
            .into_iter()
            .filter(|c| keep(c.a) && keep(c.b))
            .collect(),
    )
    .unwrap()
}

fn containing(nrg: &Nrg, p: [f64; 2]) -> Vec<SpaceId> {
    nrg.spaces()
        .iter()
        .filter(|s| point_in_ring(p, &s.polygon))
        .map(|s| s.id)
        .collect()
}

fn corrected_store() -> Store {
    let mut store = Store::open_in_memory().unwrap();
    ingest(
        &mut store,
        "lab",
        &corridor_building(4),
        meta("mapped"),
        None,
    )
    .unwrap();
    for (text, revision) in [
        ("ADD DOOR BETWEEN 10 AND 11 AT (4, 4) WIDTH 1.0", 2),
        ("MERGE 10, 11 AS \"Lab\"", 3),
        ("SET 12 ATTRIBUTE restricted = TRUE", 4),
        ("SPLIT 1 ALONG (6.2, -1) TO (6.2, 3)", 5),
    ] {
        let m = run(&mut store, "lab", text).unwrap_or_else(|e| panic!("{text}: {e}"));
        assert!(m.contains(&format!("revision {revision}")), "{text}: {m}");
        assert!(m.contains("kept as correction"), "{m}");
    }
    store
}

#[test]
fn edits_write_revisions_and_are_kept_as_corrections() {
    let store = corrected_store();
    let latest = store.load("lab", None).unwrap();
    let lab = latest
        .spaces()
        .iter()
        .find(|s| s.name.as_deref() == Some("Lab"))
        .unwrap();
    assert!(point_in_ring([2.0, 4.0], &lab.polygon) && point_in_ring([6.0, 4.0], &lab.polygon));
    assert_eq!(
        latest.space(SpaceId(12)).unwrap().attributes["restricted"],
        serde_json::json!(true)
    );
    let corridors: Vec<f64> = latest
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Corridor)
        .map(|s| s.area_m2)
        .collect();
    assert_eq!(corridors.len(), 2, "{corridors:?}");
    let list = store.corrections("lab").unwrap();
    assert_eq!(list.len(), 4);
    assert!(list.iter().all(|c| c.state == CorrectionState::Applied));
    assert_eq!(list[1].statement, "MERGE space 10, space 11 AS \"Lab\"");
    assert_eq!((list[1].made_on, list[1].checked_on), (3, 3));
    assert_eq!(list[1].author, "nrgdb query");
    // Stored lengths are walked lengths, as for an import.
    let walked = nrgdb::route::walked_model(&latest);
    assert_eq!(walked.lengths_changed, 0);
}

fn report(done: &Ingested) -> (Vec<u32>, Vec<(u32, String)>) {
    (
        done.corrections_applied.clone(),
        done.corrections_failed
            .iter()
            .map(|(id, _, r)| (*id, r.clone()))
            .collect(),
    )
}

#[test]
fn a_remapped_revision_keeps_every_correction() {
    let mut store = corrected_store();
    // Re-mapped, with a small change elsewhere: room 13's door shut.
    let fresh = without(
        &remapped(&corridor_building(4), [0.0, 0.03], 700),
        &[10_703],
    );
    let done = ingest(&mut store, "lab", &fresh, meta("re-mapped"), None).unwrap();
    assert_eq!(report(&done), (vec![1, 2, 3, 4], vec![]));
    let latest = store.load("lab", None).unwrap();
    let lab = containing(&latest, [2.0, 4.0]);
    assert_eq!(
        lab,
        containing(&latest, [6.0, 4.0]),
        "rooms 10 and 11 are one again"
    );
    let lab = latest.space(lab[0]).unwrap();
    assert_eq!(lab.name.as_deref(), Some("Lab"));
    let restricted = latest.space(containing(&latest, [10.0, 4.0])[0]).unwrap();
    assert_eq!(restricted.attributes["restricted"], serde_json::json!(true));
    assert_ne!(
        containing(&latest, [6.0, 1.0]),
        containing(&latest, [6.4, 1.0]),
        "corridor split at 6.2"
    );
    // Identity carried across: the lab keeps the id it had.
    let before = store.load("lab", Some(5)).unwrap();
    assert_eq!(
        containing(&before, [2.0, 4.0]),
        containing(&latest, [2.0, 4.0])
    );
    assert!(
        store
            .corrections("lab")
            .unwrap()
            .iter()
            .all(|c| c.checked_on == 6)
    );
}

#[test]
fn a_change_that_breaks_one_correction_reports_that_one() {
    let mut store = corrected_store();
    // Room 12 (and its door) gone from the new map: only the attribute
    // set on it no longer applies.
    let fresh = without(
        &remapped(&corridor_building(4), [0.0, 0.03], 700),
        &[712, 10_702],
    );
    let done = ingest(&mut store, "lab", &fresh, meta("room 12 walled off"), None).unwrap();
    let (applied, failed) = report(&done);
    assert_eq!(applied, vec![1, 2, 4]);
    assert_eq!(
        failed,
        vec![(3, "room 12 is no longer in the map".to_string())]
    );
    assert!(
        done.corrections_failed[0]
            .1
            .contains("SET space 12 ATTRIBUTE restricted = TRUE")
    );
    let list = store.corrections("lab").unwrap();
    assert_eq!(list[2].state, CorrectionState::Failed);
    assert_eq!(
        list[2].reason.as_deref(),
        Some("room 12 is no longer in the map")
    );
    // Dropped, it is no longer tried.
    let dropped = store.drop_correction("lab", 3).unwrap();
    assert_eq!(dropped.state, CorrectionState::Dropped);
    let done = ingest(&mut store, "lab", &fresh, meta("again"), None).unwrap();
    assert_eq!(report(&done), (vec![1, 2, 4], vec![]));
    assert!(store.drop_correction("lab", 9).is_err());
}

#[test]
fn refused_edits_store_nothing_and_say_why() {
    let mut store = corrected_store();
    let revisions = store.revisions("lab").unwrap().len();
    for (text, reason) in [
        ("MERGE 12, 13", "do not touch"),
        ("MERGE 12, 99", "99"),
        ("REMOVE DOOR 12", "not a door"),
        (
            "ADD DOOR BETWEEN 12 AND 13 AT (12, 4) WIDTH 90",
            "doors are 0.3 to 5 m wide",
        ),
        ("SPLIT 13 ALONG (13, 4) TO (14, 4)", "does not cut"),
        ("SET 13 KIND door", "a door stays a door"),
        ("UNSET 13 ATTRIBUTE nothing", "no such attribute"),
        ("SET 13 ATTRIBUTE x = NULL", "UNSET"),
    ] {
        let e = run(&mut store, "lab", text).expect_err(text);
        assert!(e.contains(reason), "{text}: {e}");
    }
    // An edit on an older revision is refused, not written over history.
    let mut session = Session::new(&mut store);
    session.use_map("lab", Some(2)).unwrap();
    let r = session.execute("SET 13 KIND corridor").unwrap();
    let e = r[0].as_ref().unwrap_err().to_string();
    assert!(e.contains("not the latest"), "{e}");
    assert_eq!(store.revisions("lab").unwrap().len(), revisions);
    assert_eq!(store.corrections("lab").unwrap().len(), 4);
}
