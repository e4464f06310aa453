//! `nrgdb eval --doors` and `eval::door_report`: the door scores item by
//! item, on a hand-drawn map whose ground truth marks one doorway the map
//! has, leaves one out and draws one line across open floor; places are
//! checked against where this test drew them.

use nrgdb::eval::{GroundTruth, door_report};
use nrgdb::extract::{ExtractParams, extract};
use nrgdb::grid::{Cell, OccupancyGrid};
use serde_json::Value;

use crate::diff_support::write_map;
use crate::support::nrgdb_ok;

const RES: f64 = 0.05;
const W: usize = 160;
const H: usize = 60;
/// Walls between the rooms: columns `[x, x + 3)`.
const WALLS: [usize; 2] = [50, 100];
/// Both doorways: rows `[20, 38)`, 0.9 m.
const DOOR_ROWS: (usize, usize) = (20, 38);
/// The GT's line across room A's open floor.
const LINE_COL: usize = 25;

fn is_wall(x: usize, y: usize) -> bool {
    let border = x < 2 || y < 2 || x >= W - 2 || y >= H - 2;
    let door = (DOOR_ROWS.0..DOOR_ROWS.1).contains(&y);
    border || WALLS.iter().any(|&c| (c..c + 3).contains(&x) && !door)
}

fn grid() -> OccupancyGrid {
    let cells = (0..W * H)
        .map(|i| {
            if is_wall(i % W, i / W) {
                Cell::Occupied
            } else {
                Cell::Free
            }
        })
        .collect();
    OccupancyGrid::from_cells(W as u32, H as u32, RES, [1.0, 2.0, 0.0], cells)
}

/// GT grey: rooms white; the first doorway and the line at `LINE_COL`
/// dark; the second doorway white (the GT calls the two right rooms one).
fn gt_grey() -> Vec<u8> {
    (0..W * H)
        .map(|i| {
            let (x, y) = (i % W, i / W);
            let first_doorway = (WALLS[0]..WALLS[0] + 3).contains(&x);
            if is_wall(x, y) || first_doorway || x == LINE_COL {
                0
            } else {
                255
            }
        })
        .collect()
}

/// Metres of pixel column/row centres, map frame (origin [1, 2], y up).
fn metres(col: f64, row: f64) -> [f64; 2] {
    [1.0 + (col + 0.5) * RES, 2.0 + (H as f64 - row - 0.5) * RES]
}

fn near(a: [f64; 2], b: [f64; 2], tol: f64) -> bool {
    (a[0] - b[0]).hypot(a[1] - b[1]) <= tol
}

#[test]
fn each_line_and_door_is_reported_where_it_is() {
    let g = grid();
    let map: Vec<u8> = g
        .cells
        .iter()
        .map(|c| if *c == Cell::Free { 255 } else { 0 })
        .collect();
    let gt = GroundTruth::from_grey(W as u32, H as u32, &gt_grey(), &map);
    assert_eq!(gt.doors.len(), 2, "the doorway and the line across room A");
    let x = extract(&g, &ExtractParams::default()).unwrap();
    let r = door_report(&gt, &x, &g);
    let door_middle_rows = (DOOR_ROWS.0 + DOOR_ROWS.1) as f64 / 2.0 - 0.5;
    let first_door = metres(WALLS[0] as f64 + 1.0, door_middle_rows);
    let second_door = metres(WALLS[1] as f64 + 1.0, door_middle_rows);

    let missed: Vec<_> = r.missed().collect();
    assert_eq!(missed.len(), 1, "{r:#?}");
    let line_middle = metres(LINE_COL as f64, (H as f64 - 1.0) / 2.0);
    assert!(near(missed[0].middle, line_middle, 0.05), "{missed:?}");
    // From wall to wall: the free rows 2..H-2.
    assert!(
        (missed[0].length_m - (H - 4) as f64 * RES).abs() <= 0.05,
        "{missed:?}"
    );

    let found: Vec<_> = r.lines.iter().filter(|l| l.found).collect();
    assert_eq!(found.len(), 1, "{r:#?}");
    assert!(near(found[0].middle, first_door, 0.05), "{found:?}");

    let right: Vec<_> = r.doors.iter().filter(|d| d.matched.is_some()).collect();
    assert_eq!(right.len(), 1, "{r:#?}");
    assert!(near(right[0].middle, first_door, 0.1), "{right:?}");
    let width = right[0].width_m.unwrap();
    assert!(
        (width - 0.9).abs() <= 0.05,
        "reported {width} m for a 0.9 m doorway"
    );

    let wrong: Vec<_> = r.wrong().collect();
    assert_eq!(wrong.len(), 1, "{r:#?}");
    assert!(near(wrong[0].middle, second_door, 0.1), "{wrong:?}");
}

#[test]
fn eval_doors_lists_them_as_text_and_json() {
    let dir = tempfile::tempdir().unwrap();
    write_map(dir.path(), "m", &grid());
    let gt = image::GrayImage::from_raw(W as u32, H as u32, gt_grey()).unwrap();
    gt.save(dir.path().join("m_gt.png")).unwrap();
    let out = nrgdb_ok(dir.path(), &["eval", "m.yaml", "--doors"]);
    let text = String::from_utf8_lossy(&out.stdout);
    let kinds: Vec<&str> = text
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .filter(|w| ["missed", "wrong", "right"].contains(w))
        .collect();
    assert_eq!(kinds, ["missed", "wrong", "right"], "{text}");
    let line_x = metres(LINE_COL as f64, 0.0)[0];
    assert!(text.contains(&format!("({line_x:.2}, ")), "{text}");

    let out = nrgdb_ok(dir.path(), &["eval", "m.yaml", "--doors", "--json"]);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let lines = v["door_report"]["lines"].as_array().unwrap();
    let doors = v["door_report"]["doors"].as_array().unwrap();
    assert_eq!(lines.len(), 2);
    assert_eq!(doors.len(), 2);
    assert_eq!(v["doors"]["gt"], 2);

    // One map only.
    let many = crate::support::nrgdb(dir.path(), &["eval", ".", "--doors"]);
    assert!(!many.status.success());
    assert!(String::from_utf8_lossy(&many.stderr).contains("--doors"));
}
