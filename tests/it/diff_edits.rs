//! Issue 6: change detection on edited occupancy grids, with no shared
//! data: a generated floor (tests/it/diff_support.rs) is extracted, edited
//! (a door painted shut, a wall removed, a wall added, the whole map
//! turned and moved) and extracted again; the diff must report exactly
//! the edit.

use nrgdb::diff::{DiffOptions, Revision, compare};
use nrgdb::grid::Cell;
use nrgdb::model::SpaceKind;

use super::diff_support::{checked_diff, extracted, floor, kinds, paint, turned};

#[test]
fn floor_extracts_as_designed() {
    let a = extracted(&floor().grid);
    let count = |k| a.spaces().iter().filter(|s| s.kind == k).count();
    assert_eq!(
        (
            count(SpaceKind::Room),
            count(SpaceKind::Corridor),
            count(SpaceKind::Door)
        ),
        (4, 1, 4),
        "{}",
        kinds(&a)
    );
}

#[test]
fn self_diff_reports_nothing() {
    let a = extracted(&floor().grid);
    let cs = checked_diff(&a, &a);
    assert!(cs.is_empty(), "{}", cs.table());
    assert_eq!(cs.summary.unchanged, a.spaces().len());
}

/// The one door space of `nrg` whose polygon contains the pixel rectangle's
/// centre.
fn door_at(
    f: &super::diff_support::Floor,
    nrg: &nrgdb::model::Nrg,
    r: super::diff_support::Rect,
) -> nrgdb::model::SpaceId {
    let p = f
        .grid
        .pixel_to_metres(f64::from(r.0 + r.2) / 2.0, f64::from(r.1 + r.3) / 2.0);
    nrg.spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Door)
        .min_by(|x, y| {
            let d = |s: &nrgdb::model::Space| (s.anchor[0] - p[0]).hypot(s.anchor[1] - p[1]);
            d(x).total_cmp(&d(y))
        })
        .unwrap()
        .id
}

#[test]
fn door_painted_shut_removes_the_door_and_its_links() {
    let f = floor();
    let a = extracted(&f.grid);
    let mut g = f.grid.clone();
    paint(&mut g, f.doors[1], Cell::Occupied);
    let b = extracted(&g);
    let cs = checked_diff(&a, &b);
    let door = door_at(&f, &a, f.doors[1]);
    let s = &cs.summary;
    assert_eq!((s.removed, s.connections_removed), (1, 2), "{}", cs.table());
    assert_eq!(s.unchanged, a.spaces().len() - 1, "{}", cs.table());
    let removed: Vec<_> = cs.changed_spaces().filter_map(|e| e.old).collect();
    assert_eq!(removed, vec![door]);
    assert!(
        cs.changed_connections()
            .all(|c| c.old.as_ref().is_some_and(|o| o.a == door || o.b == door))
    );
    assert_eq!(cs.rows().len(), 3, "{}", cs.table());
}

#[test]
fn wall_removed_merges_two_rooms() {
    let f = floor();
    let a = extracted(&f.grid);
    let mut g = f.grid.clone();
    paint(&mut g, f.wall_0_1, Cell::Free);
    let b = extracted(&g);
    let cs = checked_diff(&a, &b);
    let s = &cs.summary;
    assert_eq!(
        (s.merged, s.added, s.removed, s.split, s.resized, s.rekinded),
        (1, 0, 0, 0, 0, 0),
        "{}",
        cs.table()
    );
    // Both rooms and the door between them went into the merged room,
    // which keeps the larger room's identity.
    let mut parts: Vec<_> = cs.merges[0]
        .parts
        .iter()
        .map(|p| a.space(p.id).unwrap().kind)
        .collect();
    parts.sort();
    assert_eq!(
        parts,
        [SpaceKind::Room, SpaceKind::Room, SpaceKind::Door],
        "{}",
        cs.table()
    );
    // The door's two links went with it; nothing else changed.
    assert_eq!(
        (s.connections_removed, s.connections_added),
        (2, 0),
        "{}",
        cs.table()
    );
    assert_eq!(s.unchanged, a.spaces().len() - 3, "{}", cs.table());
}

#[test]
fn wall_added_splits_a_room() {
    let f = floor();
    let a = extracted(&f.grid);
    let mut g = f.grid.clone();
    paint(&mut g, f.split_3, Cell::Occupied);
    let b = extracted(&g);
    let cs = checked_diff(&a, &b);
    let s = &cs.summary;
    assert_eq!(
        (s.split, s.added, s.removed, s.merged, s.resized, s.rekinded),
        (1, 0, 0, 0, 0, 0),
        "{}",
        cs.table()
    );
    assert_eq!(cs.splits[0].parts.len(), 2);
    // The part without the door has no links: nothing else changes.
    assert_eq!(cs.changed_connections().count(), 0, "{}", cs.table());
    assert_eq!(s.unchanged, a.spaces().len() - 1, "{}", cs.table());
}

#[test]
fn turned_and_moved_map_aligns_and_reports_nothing() {
    let f = floor();
    let a = extracted(&f.grid);
    // A quarter turn of the pixels plus a 20° yaw and a shift of the
    // origin: the building seen from another run.
    let g = turned(&f.grid, 15, [3.0, -4.0, 20f64.to_radians()]);
    let b = extracted(&g);
    let side = |nrg, grid| Revision::new(nrg).with_grid(Some(grid));
    let done = compare(side(&a, &f.grid), side(&b, &g), &DiffOptions::default()).unwrap();
    let al = done
        .alignment
        .expect("frames differ, so the maps are aligned");
    assert!(done.identity_inliers.unwrap() < 0.5);
    assert!(al.inliers > 0.9, "{al:?}");
    // b → a undoes 90° + 20°.
    let deg = al.transform.rotation_deg();
    assert!((deg + 110.0).abs() < 0.5, "{al:?}");
    assert!(done.changes.is_empty(), "{}", done.changes.table());
    assert_eq!(done.changes.summary.unchanged, a.spaces().len());
    assert_eq!(nrgdb::diff::apply(&a, &done.changes).unwrap(), done.moved);
}
