//! Issue 19: a door's doorway line and width are first-class: they survive
//! model JSON, GeoJSON, IndoorGML and the store, and FIND and NEIGHBOURS
//! show the width.

use nrgdb::model::{Connection, ConnectionKind, Nrg, Point, Space, SpaceId, SpaceKind, doorway};
use nrgdb::query::{Format, MemorySource, Session};
use nrgdb::store::{ImportMeta, Store};

/// Two rooms joined through a 0.6 m thick wall by a 0.4 m doorway: the
/// door's polygon is taller (0.6 m, the wall) than wide (0.4 m, the
/// opening), so its rectangle's long side is the wall's depth and only the
/// stored line says where the opening is.
fn two_rooms() -> Nrg {
    let rect = |x0: f64, y0: f64, x1: f64, y1: f64| -> Vec<Point> {
        vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
    };
    let room = |id: u32, y0: f64, y1: f64| {
        Space::new(
            SpaceId(id),
            SpaceKind::Room,
            [2.0, (y0 + y1) / 2.0],
            rect(0.0, y0, 4.0, y1),
        )
    };
    let mut door = Space::new(
        SpaceId(3),
        SpaceKind::Door,
        [2.0, 3.3],
        rect(1.8, 3.0, 2.2, 3.6),
    );
    door.doorway = Some([[1.8, 3.3], [2.2, 3.3]]);
    let link = |a: u32, b: u32| Connection {
        a: SpaceId(a),
        b: SpaceId(b),
        kind: ConnectionKind::Door,
        length_m: 1.5,
    };
    Nrg::new(
        vec![room(1, 0.0, 3.0), room(2, 3.6, 6.6), door],
        vec![link(1, 3), link(2, 3)],
    )
    .unwrap()
}

fn door_of(nrg: &Nrg) -> ([Point; 2], f64) {
    let door = nrg
        .spaces()
        .iter()
        .find(|s| s.kind == SpaceKind::Door)
        .unwrap();
    let d = doorway(door).unwrap();
    assert_eq!(door.width_m, Some(d.width_m));
    (d.line, d.width_m)
}

#[test]
fn issue_19_a_doors_line_and_width_survive_every_format() {
    let nrg = two_rooms();
    let (line, width) = door_of(&nrg);
    assert!((width - 0.4).abs() < 1e-12, "{width}");

    let json = nrg.to_json();
    assert!(
        json.contains("\"width_m\": 0.4") && json.contains("\"doorway\""),
        "{json}"
    );
    assert_eq!(door_of(&Nrg::from_json(&json).unwrap()), (line, width));

    let geojson = nrgdb::geojson::to_geojson(&nrg).to_string();
    let back = nrgdb::geojson::from_geojson(&geojson).unwrap();
    assert_eq!(door_of(&back), (line, width));

    let gml = nrgdb::indoorgml::write_string(&nrgdb::indoorgml::from_nrg(&nrg));
    let doc = nrgdb::indoorgml::read_str(&gml).unwrap();
    let back = nrgdb::indoorgml::to_nrg(&doc).unwrap();
    assert_eq!(door_of(&back), (line, width));
    // The extras do not leak into the attributes.
    assert!(back.spaces().iter().all(|s| s.attributes.is_empty()));

    let mut store = Store::open_in_memory().unwrap();
    store
        .import("m", &nrg, ImportMeta::new("first", "tester"))
        .unwrap();
    assert_eq!(door_of(&store.load("m", None).unwrap()), (line, width));
}

#[test]
fn issue_19_find_and_neighbours_show_the_width() {
    let mut source = MemorySource::new();
    source.insert_with_note("m", two_rooms(), "two rooms");
    let mut session = Session::with_default_map(source).unwrap();
    let found = session
        .run(
            "FIND doors WHERE width >= 0.4 ORDER BY width DESC",
            Format::Csv,
        )
        .unwrap();
    assert!(found.contains("width_m,doorway"), "{found}");
    assert!(found.contains(",0.40,"), "{found}");
    let none = session
        .run("FIND doors WHERE width > 0.5", Format::Csv)
        .unwrap();
    assert_eq!(none.lines().count(), 1, "{none}");
    let near = session.run("NEIGHBOURS OF 1", Format::Csv).unwrap();
    assert!(near.contains("width_m") && near.contains(",0.40"), "{near}");
}
