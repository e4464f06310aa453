//! Issue 20, failure mode 4: a cluster of chairs round a table standing in
//! a room cuts it into pieces with doors between them, unless
//! `clutter_max_m` tells the cluster from a wall. The truth is the plan
//! drawn here: one 10 m × 5 m room.

use nrgdb::extract::{ExtractParams, extract};
use nrgdb::grid::OccupancyGrid;

/// The room at 0.05 m/px, walls 0.1 m thick, with a cluster in its
/// middle (2.4 m × 2.2 m): a table drawn as its outline (a scan sees its edge), eight
/// 0.3 m chairs round it, each tied to the table by a one-pixel line (the
/// scan's hits between them).
fn room_with_cluster() -> OccupancyGrid {
    let (w, h) = (204usize, 104usize);
    let mut cells = vec![vec!['.'; w]; h];
    for (y, row) in cells.iter_mut().enumerate() {
        for (x, c) in row.iter_mut().enumerate() {
            if x < 2 || y < 2 || x >= w - 2 || y >= h - 2 {
                *c = '#';
            }
        }
    }
    let mut put = |x: usize, y: usize| cells[y][x] = '#';
    // The table's outline: 1.2 m × 0.8 m, centred at (102, 52).
    let (tx0, tx1, ty0, ty1) = (90, 114, 44, 60);
    for x in tx0..=tx1 {
        put(x, ty0);
        put(x, ty1);
    }
    for y in ty0..=ty1 {
        put(tx0, y);
        put(tx1, y);
    }
    // Chairs (6 × 6 px) 0.4 m off the table, each with a line to it.
    let chairs = [
        (84, 30),
        (96, 30),
        (108, 30),
        (84, 68),
        (96, 68),
        (108, 68),
        (78, 49),
        (120, 49),
    ];
    for &(cx, cy) in &chairs {
        for y in cy..cy + 6 {
            for x in cx..cx + 6 {
                put(x, y);
            }
        }
        let (mx, my) = (cx + 3, cy + 3);
        let (x_end, y_end) = (mx.clamp(tx0, tx1), my.clamp(ty0, ty1));
        for x in mx.min(x_end)..=mx.max(x_end) {
            put(x, my);
        }
        for y in my.min(y_end)..=my.max(y_end) {
            put(x_end, y);
        }
    }
    let text: Vec<String> = cells.iter().map(|r| r.iter().collect()).collect();
    OccupancyGrid::from_ascii(&text.join("\n"), 0.05)
}

/// Rooms and corridors, and doors, of the extraction with `clutter_max_m`.
fn spaces_and_doors(clutter_max_m: f64) -> (usize, usize) {
    let mut p = ExtractParams::default();
    p.building.clutter_max_m = clutter_max_m;
    let x = extract(&room_with_cluster(), &p).expect("the room extracts");
    let doors = x
        .nrg
        .spaces()
        .iter()
        .filter(|s| s.kind.as_str() == "door")
        .count();
    (x.nrg.spaces().len() - doors, doors)
}

#[test]
fn a_chair_cluster_cuts_the_room_unless_told_from_walls() {
    let (spaces, doors) = spaces_and_doors(0.0);
    assert!(
        spaces >= 2 && doors >= 1,
        "without the clutter rule the cluster is a wall: {spaces} spaces, {doors} doors"
    );
    let with = spaces_and_doors(2.5);
    assert_eq!(with, (1, 0), "with it, the room is one space: {with:?}");
}
