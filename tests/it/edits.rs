//! Issue 22: edits on a known building (geometry and graph after each),
//! refusals with their reasons, and rules re-applied to a re-mapped model.
//! Geometry is checked against the building's drawn rectangles, not
//! against the edit code's own output.

use crate::support::remapped;
use nrgdb::edit::{Edit, EditError, NewDoor, Rule, apply};
use nrgdb::fixtures::corridor_building;
use nrgdb::model::{ConnectionKind, Nrg, SpaceId, SpaceKind, point_in_ring};

fn id(n: u32) -> SpaceId {
    SpaceId(n)
}

fn edit(nrg: &Nrg, e: Edit) -> Result<Nrg, EditError> {
    apply(nrg, &e, nrg.next_id()).map(|d| d.nrg)
}

fn checked(nrg: &Nrg) {
    let findings = nrgdb::ingest::findings(nrg);
    assert!(findings.is_empty(), "{findings:?}");
}

fn inside(nrg: &Nrg, s: SpaceId, p: [f64; 2]) -> bool {
    let space = nrg.space(s).unwrap();
    point_in_ring(p, &space.polygon) && !space.holes.iter().any(|h| point_in_ring(p, h))
}

#[test]
fn a_door_added_through_a_wall_spans_it_and_joins_both_rooms() {
    let nrg = corridor_building(3);
    // Rooms 10 (x 0.1–3.9) and 11 (x 4.1–7.9) share a 0.2 m wall at x = 4.
    let done = apply(
        &nrg,
        &Edit::AddDoor {
            a: id(10),
            b: id(11),
            at: [4.0, 4.0],
            width_m: Some(1.0),
        },
        nrg.next_id(),
    )
    .unwrap();
    let door = done.nrg.space(done.created[0]).unwrap();
    assert_eq!(door.kind, SpaceKind::Door);
    assert!((door.width_m.unwrap() - 1.0).abs() < 1e-9);
    // The doorway runs along the wall (vertical) through its middle.
    let [p, q] = door.doorway.unwrap();
    assert!(
        (p[0] - 4.0).abs() < 1e-9 && (q[0] - 4.0).abs() < 1e-9,
        "{p:?} {q:?}"
    );
    assert!(((p[1] + q[1]) / 2.0 - 4.0).abs() < 1e-9);
    // It spans the wall and 0.1 m into each room, which lose that much.
    assert!((door.area_m2 - 1.0 * 0.4).abs() < 1e-6, "{}", door.area_m2);
    for (room, before) in [(10, 3.8 * 4.8), (11, 3.8 * 4.8)] {
        let after = done.nrg.space(id(room)).unwrap().area_m2;
        assert!((before - after - 0.1).abs() < 1e-6, "{room}: {after}");
    }
    for room in [10, 11] {
        let c = done.nrg.connection(id(room), door.id).unwrap();
        assert_eq!(c.kind, ConnectionKind::Door);
    }
    assert_eq!(
        done.nrg.connection(id(10), id(11)).unwrap().kind,
        ConnectionKind::Adjacent
    );
    checked(&done.nrg);
}

#[test]
fn merging_rooms_joined_by_a_door_absorbs_the_door() {
    let nrg = corridor_building(3);
    let e = edit(
        &nrg,
        Edit::Merge {
            spaces: vec![id(10), id(11)],
            name: None,
        },
    )
    .unwrap_err();
    assert!(matches!(e, EditError::DoNotTouch { pieces: 2, .. }), "{e}");
    assert!(e.to_string().contains("do not touch"), "{e}");
    let with_door = edit(
        &nrg,
        Edit::AddDoor {
            a: id(10),
            b: id(11),
            at: [4.0, 3.0],
            width_m: None,
        },
    )
    .unwrap();
    let door = with_door
        .spaces()
        .iter()
        .find(|s| s.kind == SpaceKind::Door && s.anchor[0] == 4.0)
        .unwrap()
        .id;
    let merged = edit(
        &with_door,
        Edit::Merge {
            spaces: vec![id(11), id(10)],
            name: Some("Lab".into()),
        },
    )
    .unwrap();
    assert!(
        merged.space(door).is_none(),
        "the door between them is absorbed"
    );
    assert!(merged.space(id(10)).is_none());
    let lab = merged.space(id(11)).unwrap();
    assert_eq!(lab.name.as_deref(), Some("Lab"));
    // Both rooms (3.8 × 4.8 each) and the door through the wall.
    assert!(
        (lab.area_m2 - (2.0 * 3.8 * 4.8 + 0.9 * 0.2)).abs() < 1e-6,
        "{}",
        lab.area_m2
    );
    assert!(inside(&merged, id(11), [2.0, 4.0]) && inside(&merged, id(11), [6.0, 4.0]));
    assert!(inside(&merged, lab.id, lab.anchor));
    // Both corridor doors now lead into the lab; room 12 is still beside it.
    for d in [10_000, 10_001] {
        assert_eq!(
            merged.connection(id(d), id(11)).unwrap().kind,
            ConnectionKind::Door
        );
    }
    assert_eq!(
        merged.connection(id(11), id(12)).unwrap().kind,
        ConnectionKind::Adjacent
    );
    // Room 10's attributes came along.
    assert_eq!(lab.attributes.get("floor"), Some(&serde_json::json!(2)));
    checked(&merged);
}

#[test]
fn a_split_cuts_exactly_along_the_line_and_shares_the_cut() {
    let nrg = corridor_building(3);
    // The corridor (x 0–12, y 0–2) cut at x = 5: pieces 10 and 14 m².
    let done = apply(
        &nrg,
        &Edit::Split {
            space: id(1),
            line: [[5.0, -1.0], [5.0, 3.0]],
            door: None,
        },
        nrg.next_id(),
    )
    .unwrap();
    let other = done.created[0];
    let (big, small) = (
        done.nrg.space(id(1)).unwrap(),
        done.nrg.space(other).unwrap(),
    );
    assert!((big.area_m2 - 14.0).abs() < 1e-9 && (small.area_m2 - 10.0).abs() < 1e-9);
    assert_eq!(big.name.as_deref(), Some("Main corridor"));
    assert_eq!(small.kind, SpaceKind::Corridor);
    for x in [0.5, 4.9, 5.1, 11.5] {
        let (in_big, in_small) = (
            inside(&done.nrg, id(1), [x, 1.0]),
            inside(&done.nrg, other, [x, 1.0]),
        );
        assert!(in_big != in_small && in_big == (x > 5.0), "x = {x}");
    }
    assert_eq!(
        done.nrg.connection(id(1), other).unwrap().kind,
        ConnectionKind::Open
    );
    // Each room's door joins the piece it opens on.
    assert!(done.nrg.connection(id(10_000), other).is_some());
    assert!(done.nrg.connection(id(10_002), id(1)).is_some());
    assert!(done.nrg.connection(id(10_000), id(1)).is_none());
    checked(&done.nrg);
}

#[test]
fn a_split_line_drawn_short_of_the_walls_still_cuts_wall_to_wall() {
    let nrg = corridor_building(3);
    // Drawn from 0.3 m inside the corridor's bottom to 0.4 m below its top.
    let done = apply(
        &nrg,
        &Edit::Split {
            space: id(1),
            line: [[5.0, 0.3], [5.0, 1.6]],
            door: None,
        },
        nrg.next_id(),
    )
    .unwrap();
    let (big, small) = (
        done.nrg.space(id(1)).unwrap(),
        done.nrg.space(done.created[0]).unwrap(),
    );
    assert!((big.area_m2 - 14.0).abs() < 1e-9 && (small.area_m2 - 10.0).abs() < 1e-9);
    checked(&done.nrg);
}

#[test]
fn a_split_with_a_door_makes_a_wall_with_that_doorway() {
    let nrg = corridor_building(2);
    // Room 10 (x 0.1–3.9, y 2.2–7) cut at y = 5 with a 0.8 m door at x = 2.
    let done = apply(
        &nrg,
        &Edit::Split {
            space: id(10),
            line: [[-0.5, 5.0], [4.0, 5.0]],
            door: Some(NewDoor {
                at: [2.0, 5.1],
                width_m: Some(0.8),
            }),
        },
        nrg.next_id(),
    )
    .unwrap();
    let (piece, door) = (done.created[0], done.created[1]);
    let d = done.nrg.space(door).unwrap();
    assert!((d.width_m.unwrap() - 0.8).abs() < 1e-9);
    let [p, q] = d.doorway.unwrap();
    assert!(
        (p[1] - 5.0).abs() < 1e-9
            && (q[1] - 5.0).abs() < 1e-9
            && ((p[0] + q[0]) / 2.0 - 2.0).abs() < 1e-9
    );
    assert_eq!(
        done.nrg.connection(id(10), piece).unwrap().kind,
        ConnectionKind::Adjacent
    );
    assert_eq!(
        done.nrg.connection(id(10), door).unwrap().kind,
        ConnectionKind::Door
    );
    assert_eq!(
        done.nrg.connection(piece, door).unwrap().kind,
        ConnectionKind::Door
    );
    // The lower piece (2.8 m deep) keeps the id and the corridor door.
    assert!(inside(&done.nrg, id(10), [2.0, 3.0]) && inside(&done.nrg, piece, [1.0, 6.0]));
    assert!(done.nrg.connection(id(10_000), id(10)).is_some());
    checked(&done.nrg);
}

#[test]
fn refused_edits_say_why_and_change_nothing() {
    let nrg = corridor_building(3);
    let cases: Vec<(Edit, &str)> = vec![
        (
            Edit::Merge {
                spaces: vec![id(10)],
                name: None,
            },
            "at least two",
        ),
        (
            Edit::Merge {
                spaces: vec![id(10), id(99)],
                name: None,
            },
            "no space 99",
        ),
        (
            Edit::Merge {
                spaces: vec![id(10), id(10)],
                name: None,
            },
            "named twice",
        ),
        // Inside room 10, more than 1 m from its walls at both ends.
        (
            Edit::Split {
                space: id(10),
                line: [[2.0, 4.0], [2.0, 5.0]],
                door: None,
            },
            "crosses its outline 0 times",
        ),
        (
            Edit::Split {
                space: id(1),
                line: [[5.0, -3.0], [5.0, 0.5]],
                door: None,
            },
            "crosses its outline 1 times",
        ),
        // Across the corridor and on through the wall into room 11.
        (
            Edit::Split {
                space: id(1),
                line: [[5.0, -1.0], [5.0, 9.0]],
                door: None,
            },
            "crosses its outline 2 times",
        ),
        (
            Edit::Split {
                space: id(1),
                line: [[-1.0, 0.0], [13.0, 0.0]],
                door: None,
            },
            "runs along the outline",
        ),
        (
            Edit::Split {
                space: id(1),
                line: [[5.0, f64::NAN], [5.0, 3.0]],
                door: None,
            },
            "not a finite number",
        ),
        (
            Edit::Split {
                space: id(1),
                line: [[5.0, 1.0], [5.0, 1.01]],
                door: None,
            },
            "0.010 m long",
        ),
        (
            Edit::Split {
                space: id(10_000),
                line: [[2.0, 1.0], [2.0, 3.0]],
                door: None,
            },
            "a door stays a door",
        ),
        (
            Edit::Split {
                space: id(1),
                line: [[5.0, -1.0], [5.0, 3.0]],
                door: Some(NewDoor {
                    at: [7.0, 1.0],
                    width_m: None,
                }),
            },
            "from the split line",
        ),
        (
            Edit::AddDoor {
                a: id(10),
                b: id(12),
                at: [6.0, 4.0],
                width_m: None,
            },
            "apart near",
        ),
        (
            Edit::AddDoor {
                a: id(10),
                b: id(11),
                at: [4.0, 4.0],
                width_m: Some(100.0),
            },
            "doors are 0.3 to 5 m wide",
        ),
        (
            Edit::AddDoor {
                a: id(10),
                b: id(11),
                at: [4.0, 4.0],
                width_m: Some(f64::INFINITY),
            },
            "not a finite number",
        ),
        (
            Edit::AddDoor {
                a: id(10),
                b: id(10),
                at: [4.0, 4.0],
                width_m: None,
            },
            "both sides",
        ),
        (
            Edit::AddDoor {
                a: id(10),
                b: id(10_000),
                at: [2.0, 2.2],
                width_m: None,
            },
            "is a door",
        ),
        // Beside the corridor door of room 10: the new door would overlap it.
        (
            Edit::AddDoor {
                a: id(1),
                b: id(10),
                at: [2.2, 2.1],
                width_m: None,
            },
            "would overlap",
        ),
        (Edit::RemoveDoor { door: id(10) }, "not a door"),
        (
            Edit::SetKind {
                space: id(10),
                kind: SpaceKind::Door,
            },
            "a door stays a door",
        ),
        (
            Edit::UnsetAttribute {
                space: id(11),
                key: "floor".into(),
            },
            "no such attribute",
        ),
        (
            Edit::SetAttribute {
                space: id(11),
                key: "".into(),
                value: serde_json::json!(1),
            },
            "empty",
        ),
        (
            Edit::SetAttribute {
                space: id(11),
                key: "note".into(),
                value: serde_json::json!("x".repeat(5000)),
            },
            "at most 4096",
        ),
    ];
    for (e, reason) in cases {
        let err = edit(&nrg, e.clone()).expect_err(&format!("{e:?} was accepted"));
        assert!(err.to_string().contains(reason), "{e:?}: {err}");
    }
}

#[test]
fn kinds_and_attributes_change_and_a_removed_door_leaves_a_wall() {
    let nrg = corridor_building(2);
    let nrg = edit(
        &nrg,
        Edit::SetKind {
            space: id(10),
            kind: SpaceKind::Corridor,
        },
    )
    .unwrap();
    assert_eq!(nrg.space(id(10)).unwrap().kind, SpaceKind::Corridor);
    let nrg = edit(
        &nrg,
        Edit::SetAttribute {
            space: id(11),
            key: "restricted".into(),
            value: serde_json::json!(true),
        },
    )
    .unwrap();
    assert_eq!(
        nrg.space(id(11)).unwrap().attributes["restricted"],
        serde_json::json!(true)
    );
    let nrg = edit(
        &nrg,
        Edit::UnsetAttribute {
            space: id(11),
            key: "restricted".into(),
        },
    )
    .unwrap();
    assert!(nrg.space(id(11)).unwrap().attributes.is_empty());
    let nrg = edit(&nrg, Edit::RemoveDoor { door: id(10_001) }).unwrap();
    assert!(nrg.space(id(10_001)).is_none());
    assert_eq!(
        nrg.connection(id(1), id(11)).unwrap().kind,
        ConnectionKind::Adjacent
    );
    // No way into room 11 is left.
    let graph = nrgdb::model::ConnectivityGraph::new(&nrg);
    assert!(
        graph.neighbours(id(11)).is_empty(),
        "{:?}",
        graph.neighbours(id(11))
    );
}

#[test]
fn rules_find_their_spaces_again_by_overlap_or_say_what_happened() {
    let nrg = corridor_building(3);
    let add = Edit::AddDoor {
        a: id(10),
        b: id(11),
        at: [4.0, 4.0],
        width_m: None,
    };
    let with_door = edit(&nrg, add.clone()).unwrap();
    let door = with_door.spaces().iter().map(|s| s.id).max().unwrap();
    let merge = Edit::Merge {
        spaces: vec![id(10), id(11)],
        name: Some("Lab".into()),
    };
    let rules = [
        Rule::record(&nrg, &add).unwrap(),
        Rule::record(&with_door, &merge).unwrap(),
        Rule::record(
            &nrg,
            &Edit::Split {
                space: id(1),
                line: [[5.0, -1.0], [5.0, 3.0]],
                door: None,
            },
        )
        .unwrap(),
    ];
    // Re-mapped 5 cm off with other ids: every rule applies again.
    let mut model = remapped(&nrg, [0.05, 0.0], 500);
    for rule in &rules {
        let done = rule
            .reapply(&model, model.next_id())
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(done.note, None);
        model = done.edited.nrg;
    }
    let lab = model
        .spaces()
        .iter()
        .find(|s| s.name.as_deref() == Some("Lab"))
        .unwrap();
    assert!(inside(&model, lab.id, [2.0, 4.0]) && inside(&model, lab.id, [6.0, 4.0]));
    // The corridor, 5 cm to the right now, cut at x = 5 as before.
    assert!(
        model
            .spaces()
            .iter()
            .any(|s| s.kind == SpaceKind::Corridor && (s.area_m2 - 2.0 * 4.95).abs() < 1e-6)
    );
    checked(&model);
    // The same door applied twice is already there.
    let again = rules[0].reapply(&model, model.next_id());
    assert!(again.is_err() || again.unwrap().note.is_some());
    // A map where room 11 was cut in two: the merge no longer applies.
    let fresh = remapped(&nrg, [0.0, 0.0], 500);
    // Cut in three strips, none holding half of it.
    let fresh = edit(
        &fresh,
        Edit::Split {
            space: id(511),
            line: [[5.5, 2.0], [5.5, 7.5]],
            door: None,
        },
    )
    .unwrap();
    let fresh = edit(
        &fresh,
        Edit::Split {
            space: id(511),
            line: [[6.5, 2.0], [6.5, 7.5]],
            door: None,
        },
    )
    .unwrap();
    let fresh = rules[0].reapply(&fresh, fresh.next_id());
    let reason = match fresh {
        Ok(done) => rules[1]
            .reapply(&done.edited.nrg, done.edited.nrg.next_id())
            .unwrap_err(),
        Err(reason) => reason,
    };
    assert!(reason.contains("room 11 was split"), "{reason}");
    let _ = door;
}
