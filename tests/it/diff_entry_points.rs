//! Issue 19: one change set wherever it is asked for. A simulated building
//! is mapped, a door on it is shut, and the re-mapped grid is turned a
//! quarter turn plus 30° and moved (another mapping run, another frame).
//! Both are imported as revisions 1 and 2 of one map, and every entry
//! point is asked what changed: `nrgdb diff`, the query language's `DIFF`
//! (in a session and through `POST /query`), `GET /diff`, and the
//! pictures (`nrgdb render --diff` and the viewer's `?diff=`). They must
//! all report the one change set, aligned on the stored grids.

use std::path::Path;

use nrgdb::diff::ChangeSet;
use nrgdb::extract::{ExtractParams, extract};
use nrgdb::grid::{Cell, LoadOptions, OccupancyGrid, load_map};
use nrgdb::model::SpaceKind;
use nrgdb::query::{Cell as QueryCell, QueryResult, Session, compare_revisions};
use nrgdb::sim::{SimParams, simulate, write_simulation};
use nrgdb::store::Store;
use serde_json::Value;

use super::diff_support::{turned, write_map};
use super::server_client::TestServer;
use super::support::nrgdb;

/// Revision 1: the simulated building as mapped; revision 2: one of its
/// doors shut, turned and moved. Both written as map files in `dir`.
fn revision_pair(dir: &Path) -> (OccupancyGrid, OccupancyGrid) {
    let sim = simulate(&SimParams::new(11)).unwrap();
    let files = write_simulation(&dir.join("sim"), &sim).unwrap();
    let a = load_map(&files.yaml, &LoadOptions::default()).unwrap();
    let first = extract(&a, &ExtractParams::default()).unwrap();
    // The door with the most pixels: shut it as a wall.
    let door = first
        .nrg
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Door)
        .max_by_key(|s| first.labels.data.iter().filter(|&&l| l == s.id.0).count())
        .expect("a door")
        .id;
    let mut shut = a.clone();
    for (i, label) in first.labels.data.iter().enumerate() {
        if *label == door.0 {
            shut.cells[i] = Cell::Occupied;
            shut.grey[i] = 0;
        }
    }
    let b = turned(&shut, 12, [2.5, -1.5, 30f64.to_radians()]);
    write_map(dir, "a", &a);
    write_map(dir, "b", &b);
    (a, b)
}

/// `(class, space id)` of every diff outline in an SVG, sorted.
fn diff_items(svg: &str) -> Vec<(String, u32)> {
    let mut out = Vec::new();
    for piece in svg.split("class=\"diff ").skip(1) {
        let class = piece.split('"').next().unwrap_or_default().to_string();
        let id = piece
            .split("data-space=\"")
            .nth(1)
            .and_then(|r| r.split('"').next())
            .and_then(|n| n.parse().ok())
            .expect("a diff outline names its space");
        out.push((class, id));
    }
    out.sort();
    out
}

/// The rows `DIFF` gives for a change set: the alignment, then a row per
/// change.
fn diff_rows(cs: &ChangeSet) -> Vec<Vec<String>> {
    let mut rows = Vec::new();
    if let Some(t) = cs.alignment {
        rows.push(vec![
            "aligned".to_string(),
            String::new(),
            String::new(),
            String::new(),
            format!(
                "rotation {:.2}°, translation ({:.3}, {:.3}) m",
                t.rotation_deg(),
                t.tx_m,
                t.ty_m
            ),
        ]);
    }
    rows.extend(
        cs.rows()
            .into_iter()
            .map(|r| vec![r.change, r.old, r.new, r.space, r.detail]),
    );
    rows
}

fn cell_text(c: &QueryCell) -> String {
    match c {
        QueryCell::Text(t) => t.clone(),
        QueryCell::Null => String::new(),
        other => format!("{other:?}"),
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue_19_every_entry_point_reports_one_change_set() {
    let s = TestServer::read_only().await;
    let dir = s.db.parent().unwrap().to_path_buf();
    let db = s.db.to_str().unwrap().to_string();
    let (grid_a, grid_b) = revision_pair(&dir);
    for (file, message) in [("a.yaml", "as mapped"), ("b.yaml", "door shut, remapped")] {
        let out = nrgdb(
            &dir,
            &["import", file, "--map", "m", "-m", message, "--db", &db],
        );
        assert!(out.status.success(), "{out:?}");
    }

    // 1. `nrgdb diff`.
    let out = nrgdb(&dir, &["diff", "m", "1", "2", "--json", "--db", &db]);
    assert_eq!(out.status.code(), Some(1), "{out:?}");
    let cs = ChangeSet::from_json(&String::from_utf8_lossy(&out.stdout)).unwrap();
    // Aligned on the stored grids: b → a undoes the quarter turn and 30°.
    let t = cs.alignment.expect("frames differ: aligned");
    let turn = (t.rotation_deg() + 120.0 + 540.0).rem_euclid(360.0) - 180.0;
    assert!(turn.abs() < 1.0, "{t:?}");
    // What changed is the door (and what its closing re-cut), not the
    // whole building (unaligned, every space would be removed and added).
    let s_ = &cs.summary;
    assert!(
        s_.removed >= 1 && s_.unchanged > 3 * (s_.added + s_.removed),
        "{}",
        cs.table()
    );
    assert!(
        cs.changed_spaces()
            .any(|e| e.new.is_none() && e.kind == SpaceKind::Door),
        "{}",
        cs.table()
    );
    assert_eq!(
        (cs.from.as_deref(), cs.to.as_deref()),
        (Some("m@1"), Some("m@2"))
    );

    // The library, with the grids it was given, agrees.
    let store = Store::open(&s.db).unwrap();
    for (rev, grid) in [(1, &grid_a), (2, &grid_b)] {
        let kept = store
            .grid("m", Some(rev))
            .unwrap()
            .expect("imported from a map: grid kept");
        assert_eq!((&kept.cells, kept.origin), (&grid.cells, grid.origin));
    }
    let lib = compare_revisions(&store, "m", 1, 2, &Default::default()).unwrap();
    assert_eq!(lib.comparison.changes, cs);

    // 2. `DIFF` in a session over the store, and through `POST /query`.
    let mut session = Session::new(store);
    session.use_map("m", None).unwrap();
    let QueryResult::Table(table) = session.execute("DIFF 1 2;").unwrap().remove(0).unwrap() else {
        panic!("DIFF gives a table");
    };
    let got: Vec<Vec<String>> = table
        .rows
        .iter()
        .map(|r| r.iter().map(cell_text).collect())
        .collect();
    assert_eq!(got, diff_rows(&cs));
    let q = s.post("/query?map=m", &[], b"DIFF 1 2;").await;
    assert_eq!(q.status, 200, "{}", q.text());
    let rows: Vec<Vec<String>> = q.json()["results"][0]["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            ["change", "old", "new", "space", "detail"]
                .iter()
                .map(|k| r[k].as_str().unwrap_or_default().to_string())
                .collect()
        })
        .collect();
    assert_eq!(rows, diff_rows(&cs));

    // 3. `GET /diff`.
    let d = s.get("/maps/m/diff?from=1&to=2").await;
    assert_eq!(d.status, 200, "{}", d.text());
    let v: Value = d.json();
    let served = ChangeSet::from_json(&v["changes"].to_string()).unwrap();
    assert_eq!(served, cs);
    assert!(v["alignment"]["inliers"].as_f64().unwrap() > 0.9, "{v}");

    // 4. The pictures draw that change set over revision 2.
    let (old, new) = (&lib.old.nrg, &lib.new.nrg);
    let overlay = nrgdb::render::diff_overlay(&cs, old, new);
    let mut want: Vec<(String, u32)> = [
        ("added", &overlay.added),
        ("removed", &overlay.removed),
        ("changed", &overlay.changed),
        ("split", &overlay.split),
        ("merged", &overlay.merged),
    ]
    .iter()
    .flat_map(|(class, list)| list.iter().map(|o| (class.to_string(), o.id.0)))
    .collect();
    want.sort();
    assert!(want.iter().any(|(c, _)| c == "removed"), "{want:?}");
    let out = nrgdb(
        &dir,
        &[
            "render", "m@2", "--diff", "1", "2", "--out", "d.svg", "--db", &db,
        ],
    );
    assert!(out.status.success(), "{out:?}");
    let svg = std::fs::read_to_string(dir.join("d.svg")).unwrap();
    assert_eq!(diff_items(&svg), want, "render --diff");
    let viewer = s.get("/maps/m/revisions/2/svg?diff=1").await;
    assert_eq!(viewer.status, 200, "{}", viewer.text());
    assert_eq!(diff_items(&viewer.text()), want, "viewer ?diff=");
    s.stop().await;
}
