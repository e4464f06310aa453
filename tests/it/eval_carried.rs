//! `nrgdb eval MAP --gt-map REF`: a ground truth drawn on one map of a
//! building, scored on another map of it in another frame (turned a quarter
//! turn and moved). The GT's rooms, doorways and connections are known from
//! how the test drew the floor, so the carried GT is checked against them,
//! and the scores against those of the map the GT was drawn on.

use std::path::Path;

use nrgdb::grid::{Cell, OccupancyGrid};
use serde_json::Value;

use crate::diff_support::{Floor, Rect, floor, turned, write_map};
use crate::support::{nrgdb, nrgdb_ok};

/// The floor's GT image: every free pixel white but the door gaps, which
/// the GT closes with black (IPA style): 5 rooms, 4 doorway lines.
fn gt_image(grid: &OccupancyGrid, doors: &[Rect]) -> image::GrayImage {
    let in_door = |col: u32, row: u32| {
        doors
            .iter()
            .any(|d| (d.0..d.2).contains(&col) && (d.1..d.3).contains(&row))
    };
    image::GrayImage::from_fn(grid.width, grid.height, |col, row| {
        let free = grid.cells[(row * grid.width + col) as usize] == Cell::Free;
        image::Luma([if free && !in_door(col, row) { 255 } else { 0 }])
    })
}

/// A temporary folder holding the floor as `drawn.yaml` with its GT
/// `drawn_gt.png`, and the floor.
fn drawn_floor() -> (tempfile::TempDir, Floor) {
    let dir = tempfile::tempdir().unwrap();
    let f = floor();
    write_map(dir.path(), "drawn", &f.grid);
    gt_image(&f.grid, &f.doors)
        .save(dir.path().join("drawn_gt.png"))
        .unwrap();
    (dir, f)
}

fn json(dir: &Path, args: &[&str]) -> Value {
    let out = nrgdb_ok(dir, args);
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn a_ground_truth_carried_onto_a_turned_and_moved_map_scores_as_on_its_own() {
    let (dir, f) = drawn_floor();
    // Another run's map: turned, padded, another origin.
    write_map(dir.path(), "run", &turned(&f.grid, 9, [4.0, -7.0, 0.0]));

    let own = json(dir.path(), &["eval", "drawn.yaml", "--json"]);
    let carried = json(
        dir.path(),
        &["eval", "run.yaml", "--gt-map", "drawn.yaml", "--json"],
    );
    // What the test drew: 5 rooms, 4 doorways, 4 connections.
    for v in [&own, &carried] {
        assert_eq!(v["rooms"]["gt_rooms"], 5, "{v:#}");
        assert_eq!(v["doors"]["gt"], 4, "{v:#}");
        assert_eq!(v["connections"]["gt"], 4, "{v:#}");
        assert_eq!(v["doors"]["recall"], 1.0, "{v:#}");
        assert_eq!(v["connections"]["recall"], 1.0, "{v:#}");
    }
    for key in ["recall_micro", "precision_micro"] {
        let (a, b) = (
            own["rooms"][key].as_f64().unwrap(),
            carried["rooms"][key].as_f64().unwrap(),
        );
        assert!(
            (a - b).abs() < 0.005,
            "rooms {key}: {a} on its own, {b} carried"
        );
        assert!(b > 0.9, "rooms {key} {b}");
    }
    let width = |v: &Value| v["widths"]["median_m"].as_f64().unwrap();
    assert!((width(&own) - width(&carried)).abs() < 0.03);
    // The alignment found the quarter turn back (the run's map is the drawn
    // one turned counter-clockwise), and the walls agree both ways.
    let a = &carried["gt_alignment"];
    let turn = a["alignment"]["transform"]["rotation_rad"]
        .as_f64()
        .unwrap();
    assert!(turn.cos().abs() < 0.01 && turn.sin() < -0.99, "{a:#}");
    assert!(a["alignment"]["inliers"].as_f64().unwrap() > 0.95, "{a:#}");
    assert!(a["walls_found"].as_f64().unwrap() > 0.95, "{a:#}");

    // As text: the alignment is said first.
    let out = nrgdb_ok(dir.path(), &["eval", "run.yaml", "--gt-map", "drawn.yaml"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.starts_with("ground truth carried from drawn.yaml: turned"),
        "{text}"
    );
}

#[test]
fn a_map_of_another_building_is_refused_by_name() {
    let (dir, _) = drawn_floor();
    // A plain square room: no fit puts half its walls on the floor's.
    let (w, h) = (200u32, 200u32);
    let cells = (0..w * h)
        .map(|i| {
            let (c, r) = (i % w, i / w);
            if (10..190).contains(&c) && (10..190).contains(&r) {
                Cell::Free
            } else {
                Cell::Occupied
            }
        })
        .collect();
    write_map(
        dir.path(),
        "other",
        &OccupancyGrid::from_cells(w, h, 0.05, [0.0, 0.0, 0.0], cells),
    );
    let out = nrgdb(
        dir.path(),
        &["eval", "other.yaml", "--gt-map", "drawn.yaml"],
    );
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("cannot carry the ground truth of drawn.yaml onto other.yaml"),
        "{err}"
    );
    // One map only.
    let many = nrgdb(dir.path(), &["eval", ".", "--gt-map", "drawn.yaml"]);
    assert!(!many.status.success());
    assert!(String::from_utf8_lossy(&many.stderr).contains("--gt-map"));
}
