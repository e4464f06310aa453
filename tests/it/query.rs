//! Every statement of the query language on the demo building.

use nrgdb::model::{SpaceId, SpaceKind};
use nrgdb::query::{Cell, Format, Limits, MemorySource, QueryError, QueryResult, Session, demo};

fn session(columns: usize) -> Session<MemorySource> {
    let mut source = MemorySource::new();
    source.insert("demo", demo::building(columns));
    Session::with_default_map(source).unwrap()
}

fn one(s: &mut Session<MemorySource>, text: &str) -> Result<QueryResult, QueryError> {
    let mut all = s.execute(text)?;
    assert_eq!(all.len(), 1, "{text}");
    all.remove(0)
}

fn ids(r: &QueryResult) -> Vec<i64> {
    let QueryResult::Table(t) = r else {
        panic!("not a table: {r:?}")
    };
    t.rows
        .iter()
        .map(|row| match row[0] {
            Cell::Int(i) => i,
            _ => panic!("id column"),
        })
        .collect()
}

#[test]
fn route_between_names_passes_their_doors() {
    let mut s = session(6);
    let QueryResult::Routes(r) = one(&mut s, "ROUTE FROM \"Kitchen\" TO \"Library\"").unwrap()
    else {
        panic!()
    };
    // Kitchen 3 → door 2 → corridor 1 → door 4 → Library 5.
    assert_eq!(r[0].spaces, [3, 2, 1, 4, 5].map(SpaceId));
    assert_eq!(r[0].doors, [2, 4].map(SpaceId));
    assert_eq!(
        r[0].steps[0].instruction,
        "walk 1.9 m in Kitchen, go straight through door 2 into corridor 1"
    );
    assert_eq!(r[0].steps.last().unwrap().turn, nrgdb::route::Turn::Arrive);
    // Both doors lie on x = 2 between the two anchors: the walked path is
    // the straight line from anchor to anchor.
    assert_eq!(r[0].waypoints, vec![[2.0, 9.15], [2.0, 2.85]]);
    assert!((r[0].length_m - 6.3).abs() < 1e-9);
    let steps: f64 = r[0].steps.iter().map(|s| s.distance_m).sum();
    assert!((steps - r[0].length_m).abs() < 1e-9);
}

#[test]
fn route_via_avoid_and_alternatives() {
    let mut s = session(6);
    let QueryResult::Routes(r) = one(&mut s, "ROUTE FROM 3 TO 5 VIA room 13").unwrap() else {
        panic!()
    };
    assert!(r[0].spaces.contains(&SpaceId(13)));
    let QueryResult::Routes(r) =
        one(&mut s, "ROUTE FROM \"Kitchen\" TO \"Lounge\" AVOID door 12").unwrap()
    else {
        panic!()
    };
    assert!(!r[0].spaces.contains(&SpaceId(12)) && r[0].spaces.contains(&SpaceId(8)));
    let QueryResult::Routes(r) = one(
        &mut s,
        "ROUTE FROM \"Kitchen\" TO \"Lounge\" ALTERNATIVES 3",
    )
    .unwrap() else {
        panic!()
    };
    assert!(r.len() >= 2, "the shortcut door makes a second way");
    assert!(r[0].length_m <= r[1].length_m);
    assert_ne!(r[0].doors, r[1].doors);
    let none = one(&mut s, "ROUTE FROM \"Kitchen\" TO \"Library\" AVOID door 2").unwrap();
    assert_eq!(
        none.render(Format::Table),
        "no route: every way from Kitchen to Library passes a space in AVOID\n"
    );
}

#[test]
fn route_errors_are_clear() {
    let mut s = session(3);
    let e = one(&mut s, "ROUTE FROM \"Kitchn\" TO 5")
        .unwrap_err()
        .to_string();
    assert_eq!(e, "no space named 'Kitchn'; did you mean 'Kitchen'?");
    let e = one(&mut s, "ROUTE FROM room 2 TO 5")
        .unwrap_err()
        .to_string();
    assert_eq!(e, "space 2 is a door, not a room");
    let e = one(&mut s, "ROUTE FROM 999 TO 5").unwrap_err().to_string();
    assert!(e.contains("no space 999"), "{e}");
    let e = one(&mut s, "ROUTE FROM (-50, 0) TO 5")
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("(-50, 0) is outside every space; the nearest is space"),
        "{e}"
    );
    // The shaft has no navigable connection: no route, which is an answer.
    let r = one(&mut s, "ROUTE FROM 3 TO \"Shaft\"").unwrap();
    assert!(
        matches!(r, QueryResult::Message(ref m) if m.contains("not connected")),
        "{r:?}"
    );
}

#[test]
fn neighbours_by_depth() {
    let mut s = session(4);
    assert_eq!(ids(&one(&mut s, "NEIGHBOURS OF \"Kitchen\"").unwrap()), [2]);
    assert_eq!(ids(&one(&mut s, "neighbors of 3 depth 2").unwrap()), [2, 1]);
    let three = ids(&one(&mut s, "NEIGHBOURS OF 3 DEPTH 3").unwrap());
    assert_eq!(three, [2, 1, 4, 6]);
}

#[test]
fn find_filters_sorts_and_limits() {
    let mut s = session(4);
    let rooms = ids(&one(&mut s, "FIND rooms").unwrap());
    assert_eq!(rooms.len(), 8);
    let named = ids(&one(&mut s, "FIND rooms WHERE name LIKE 'L%' ORDER BY id DESC").unwrap());
    assert_eq!(named, [13, 5]);
    let limited = ids(&one(
        &mut s,
        "FIND spaces WHERE kind != room ORDER BY area DESC, id LIMIT 2",
    )
    .unwrap());
    assert_eq!(limited, [1, 6]);
    // Lower doors are 1.2 m openings (4 and 14 also declare 1.2 m), upper
    // ones 1.0 m (2 and 12 declare 0.9 m): the width is the opening, the
    // long side of a door's rectangle, not the wall's 0.3 m depth.
    let wide = ids(&one(&mut s, "FIND doors WHERE width > 1").unwrap());
    assert_eq!(wide, [4, 9, 14, 19]);
    let seats = ids(&one(&mut s, "FIND rooms WHERE attr.seats = 4").unwrap());
    assert_eq!(seats, [10, 13]);
    let missing = ids(&one(&mut s, "FIND doors WHERE attr.width_m = NULL").unwrap());
    assert_eq!(missing, [7, 9, 17, 19, 21]);
    let hub = ids(&one(&mut s, "FIND corridors WHERE degree >= 4 AND NOT id = 1").unwrap());
    assert_eq!(hub, [6, 11]);
    let e = one(&mut s, "FIND rooms WHERE area = \"big\"")
        .unwrap_err()
        .to_string();
    assert!(e.contains("cannot compare area"), "{e}");
    let others = ids(&one(&mut s, "FIND others").unwrap());
    assert_eq!(others, [22]);
}

#[test]
fn locate_and_reachable() {
    let mut s = session(3);
    assert_eq!(ids(&one(&mut s, "LOCATE (2.0, 9.0)").unwrap()), [3]);
    assert_eq!(ids(&one(&mut s, "LOCATE (2.0, 7.1)").unwrap()), [2]);
    assert!(ids(&one(&mut s, "LOCATE (99, 99)").unwrap()).is_empty());
    let QueryResult::Table(t) = one(&mut s, "REACHABLE FROM \"Kitchen\" WITHIN 3.2").unwrap()
    else {
        panic!()
    };
    assert_eq!(t.columns.last().unwrap(), "distance_m");
    assert_eq!(ids(&QueryResult::Table(t.clone())), [3, 2, 1]);
}

/// `(x, y) ON LEVEL l` as a route's stop in a building: the route starts
/// and ends at the points, on their levels; a level the map has not, or
/// a point outside every space of its level, is a clear error.
#[test]
fn routes_from_points_on_levels() {
    let mut source = MemorySource::new();
    let tower = nrgdb::fixtures::storeys(3, 3);
    let a = tower.space(nrgdb::model::SpaceId(10)).unwrap().anchor;
    let b = tower.space(nrgdb::model::SpaceId(200_012)).unwrap().anchor;
    source.insert("tower", tower);
    let mut s = Session::with_default_map(source).unwrap();
    let text = format!(
        "ROUTE FROM ({}, {}) ON LEVEL 0 TO ({}, {}) ON LEVEL 2",
        a[0] + 0.25,
        a[1],
        b[0],
        b[1] - 0.25
    );
    let QueryResult::Routes(routes) = one(&mut s, &text).unwrap() else {
        panic!("not a route")
    };
    let r = &routes[0];
    assert_eq!(r.waypoints.first(), Some(&[a[0] + 0.25, a[1]]));
    assert_eq!(r.waypoints.last(), Some(&[b[0], b[1] - 0.25]));
    assert_eq!(r.levels.last().unwrap().level, "2");
    let e = one(
        &mut s,
        &format!("ROUTE FROM ({}, {}) ON LEVEL 7 TO 10", a[0], a[1]),
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("no level 7 (it has 0, 1, 2)"), "{e}");
    let e = one(&mut s, "ROUTE FROM (-40, -40) ON LEVEL 1 TO 10")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("no space on level 1 contains the point (-40, -40)"),
        "{e}"
    );
    let e = one(&mut s, &format!("ROUTE FROM ({}, {}) TO 10", a[0], a[1]))
        .unwrap_err()
        .to_string();
    assert!(e.contains("ON LEVEL"), "{e}");
}

#[test]
fn show_use_name_diff_explain() {
    let mut s = session(2);
    assert!(
        one(&mut s, "SHOW MAPS")
            .unwrap()
            .render(Format::Csv)
            .starts_with("map,revisions,latest\ndemo,1,1\n")
    );
    let QueryResult::Message(m) = one(&mut s, "NAME room 8 AS \"Meeting Room\"").unwrap() else {
        panic!()
    };
    assert!(m.contains("revision 2"), "{m}");
    assert_eq!(s.current().unwrap().revision, 2);
    assert_eq!(
        ids(&one(&mut s, "FIND rooms WHERE name = 'meeting room'").unwrap()),
        [8]
    );
    assert_eq!(ids(&one(&mut s, "SHOW REVISIONS OF demo").unwrap()), [1, 2]);
    one(&mut s, "USE demo AT REVISION 1").unwrap();
    assert!(ids(&one(&mut s, "FIND rooms WHERE name = 'meeting room'").unwrap()).is_empty());
    let e = one(&mut s, "USE dmeo").unwrap_err().to_string();
    assert_eq!(
        e,
        "no map named 'dmeo'; did you mean 'demo'? (see SHOW MAPS)"
    );
    // Revision 2 only named space 8 (issue 6: DIFF answers).
    let QueryResult::Table(t) = one(&mut s, "DIFF 1 2").unwrap() else {
        panic!()
    };
    assert_eq!(t.rows.len(), 1, "{t:?}");
    assert_eq!(t.rows[0][0], Cell::Text("renamed".into()));
    assert_eq!(t.rows[0][2], Cell::Text("8".into()));
    let QueryResult::Plan(p) = one(&mut s, "EXPLAIN FIND rooms WHERE area > 3 LIMIT 2").unwrap()
    else {
        panic!()
    };
    assert_eq!(
        p,
        "Limit 2\n  Filter area > 3.0\n    Scan spaces kind = room"
    );
}

#[test]
fn limits_bound_rows_and_time() {
    let mut s = session(4);
    s.set_limits(Limits {
        max_rows: 3,
        ..Limits::default()
    });
    let e = one(&mut s, "FIND spaces").unwrap_err();
    assert!(matches!(e, QueryError::TooManyRows(3)));
    assert!(one(&mut s, "FIND spaces LIMIT 3").is_ok());
    let mut big = session(2000);
    big.set_limits(Limits {
        timeout: std::time::Duration::ZERO,
        ..Limits::default()
    });
    let e = one(&mut big, "REACHABLE FROM 3 WITHIN 100000").unwrap_err();
    assert!(matches!(e, QueryError::Timeout(0)), "{e}");
}

#[test]
fn no_map_selected_and_renderings() {
    let mut s = Session::new(MemorySource::new());
    let e = one(&mut s, "FIND rooms").unwrap_err().to_string();
    assert!(e.contains("no map selected"), "{e}");
    let mut s = session(2);
    let json = one(&mut s, "ROUTE FROM 3 TO 5")
        .unwrap()
        .render(Format::Json);
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(v["routes"][0]["spaces"], serde_json::json!([3, 2, 1, 4, 5]));
    let csv = one(&mut s, "ROUTE FROM 3 TO 5")
        .unwrap()
        .render(Format::Csv);
    assert!(csv.starts_with("route,length_m,point,x_m,y_m\n1,"), "{csv}");
    // A header and one row per point of the walked polyline.
    let points = v["routes"][0]["waypoints"].as_array().unwrap().len();
    assert!(points >= 2);
    assert_eq!(csv.lines().count(), 1 + points);
    assert_eq!(kind_of(&s, 2), SpaceKind::Door);
}

fn kind_of(s: &Session<MemorySource>, id: u32) -> SpaceKind {
    s.current().unwrap().nrg.space(SpaceId(id)).unwrap().kind
}

#[test]
fn parse_errors_point_at_the_token() {
    let mut s = session(2);
    let e = s.execute("FIND rooms ORDRE BY area").unwrap_err();
    assert!(
        e.to_string()
            .contains("found 'ORDRE' (did you mean ORDER?)"),
        "{e}"
    );
    assert_eq!(e.span().unwrap().column, 12);
}

/// Issue 21: a LIKE pattern is matched against every row's name in
/// O(name × pattern); one longer than any name is refused, naming its size.
#[test]
fn issue_21_a_like_pattern_longer_than_any_name_is_refused() {
    let mut s = session(3);
    let long = format!("FIND spaces WHERE name LIKE \"{}\";", "%a".repeat(600));
    match one(&mut s, &long) {
        Err(QueryError::PatternTooLong { chars, limit }) => {
            assert_eq!((chars, limit), (1200, nrgdb::model::MAX_NAME_CHARS));
        }
        other => panic!("{other:?}"),
    }
    let fine = format!("FIND spaces WHERE name LIKE \"{}\";", "%".repeat(1000));
    assert!(one(&mut s, &fine).is_ok());
}
