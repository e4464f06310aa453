//! The OpenStreetMap export (`format::osm`): the file is read back with
//! quick-xml, independently of the writer, and checked against the model
//! and the Simple Indoor Tagging rules (ids, closed ways, one area per
//! space, door nodes on both outlines, positions, areas).

use std::collections::{BTreeMap, HashSet};

use nrgdb::format::osm::to_osm_xml;
use nrgdb::model::{Georef, Nrg, Point, SpaceId, SpaceKind, doorway};
use quick_xml::Reader;
use quick_xml::events::Event;

type Tags = BTreeMap<String, String>;
/// A relation member: type, ref, role.
type Member = (String, i64, String);

/// An OSM XML file as read back.
#[derive(Default)]
struct OsmFile {
    root: Tags,
    /// Every element's attributes, for the checks on all of them.
    elements: Vec<(String, Tags)>,
    nodes: BTreeMap<i64, ([f64; 2], Tags)>,
    ways: BTreeMap<i64, (Vec<i64>, Tags)>,
    relations: BTreeMap<i64, (Vec<Member>, Tags)>,
}

fn attrs(e: &quick_xml::events::BytesStart<'_>) -> Tags {
    e.attributes()
        .map(|a| {
            let a = a.unwrap();
            let v = a
                .normalized_value(quick_xml::XmlVersion::Implicit1_0)
                .unwrap();
            (a.key.as_ref().to_string(), v.into_owned())
        })
        .collect()
}

fn num(a: &Tags, k: &str) -> f64 {
    a.get(k)
        .unwrap_or_else(|| panic!("no {k}"))
        .parse()
        .unwrap()
}

fn id(a: &Tags, k: &str) -> i64 {
    a.get(k)
        .unwrap_or_else(|| panic!("no {k}"))
        .parse()
        .unwrap()
}

fn parse(text: &str) -> OsmFile {
    let mut reader = Reader::from_str(text);
    let mut file = OsmFile::default();
    // The open node, way or relation: (kind, id).
    let mut open: Option<(String, i64)> = None;
    loop {
        let (e, empty) = match reader.read_event().unwrap() {
            Event::Eof => break,
            Event::Start(e) => (e, false),
            Event::Empty(e) => (e, true),
            Event::End(e) => {
                if matches!(e.name().as_ref(), "node" | "way" | "relation") {
                    open = None;
                }
                continue;
            }
            _ => continue,
        };
        let name = e.name().as_ref().to_string();
        let a = attrs(&e);
        file.elements.push((name.clone(), a.clone()));
        match name.as_str() {
            "osm" => file.root = a,
            "node" => {
                let i = id(&a, "id");
                let prev = file
                    .nodes
                    .insert(i, ([num(&a, "lon"), num(&a, "lat")], Tags::new()));
                assert!(prev.is_none(), "node {i} twice");
                open = (!empty).then_some((name, i));
            }
            "way" => {
                let i = id(&a, "id");
                assert!(file.ways.insert(i, (Vec::new(), Tags::new())).is_none());
                open = (!empty).then_some((name, i));
            }
            "relation" => {
                let i = id(&a, "id");
                assert!(
                    file.relations
                        .insert(i, (Vec::new(), Tags::new()))
                        .is_none()
                );
                open = (!empty).then_some((name, i));
            }
            "nd" => {
                let (_, w) = open.clone().unwrap();
                file.ways.get_mut(&w).unwrap().0.push(id(&a, "ref"));
            }
            "member" => {
                let (_, r) = open.clone().unwrap();
                let m = (a["type"].clone(), id(&a, "ref"), a["role"].clone());
                file.relations.get_mut(&r).unwrap().0.push(m);
            }
            "tag" => {
                let (kind, i) = open.clone().unwrap();
                let tags = match kind.as_str() {
                    "node" => &mut file.nodes.get_mut(&i).unwrap().1,
                    "way" => &mut file.ways.get_mut(&i).unwrap().1,
                    _ => &mut file.relations.get_mut(&i).unwrap().1,
                };
                let (k, v) = (a["k"].clone(), a["v"].clone());
                assert!(tags.insert(k.clone(), v).is_none(), "tag {k} twice");
            }
            _ => {}
        }
    }
    file
}

/// Shoelace area of a closed ring in map metres.
fn area(ring: &[Point]) -> f64 {
    ring.windows(2)
        .map(|w| w[0][0] * w[1][1] - w[1][0] * w[0][1])
        .sum::<f64>()
        .abs()
        / 2.0
}

/// Checks the file written for `nrg` against the model and SIT.
fn check(nrg: &Nrg, georef: &Georef) -> OsmFile {
    let text = to_osm_xml(nrg, georef);
    let osm = parse(&text);

    // The root, no upload metadata, negative unique ids.
    assert_eq!(osm.root.get("version").map(String::as_str), Some("0.6"));
    assert_eq!(osm.root.get("generator").map(String::as_str), Some("nrgdb"));
    assert_eq!(osm.root.get("upload").map(String::as_str), Some("never"));
    let mut ids = HashSet::new();
    for (name, a) in &osm.elements {
        assert!(!a.contains_key("version") || name == "osm", "{name} {a:?}");
        assert!(!a.contains_key("changeset"), "{name} {a:?}");
        if matches!(name.as_str(), "node" | "way" | "relation") {
            let i = id(a, "id");
            assert!(i < 0, "{name} id {i}");
            assert!(ids.insert(i), "id {i} twice");
        }
    }

    // Ways resolve and are closed; relation members resolve.
    for (w, (nds, _)) in &osm.ways {
        assert!(nds.len() >= 4, "way {w}: {nds:?}");
        assert_eq!(nds.first(), nds.last(), "way {w} not closed");
        for n in nds {
            assert!(osm.nodes.contains_key(n), "way {w}: node {n} missing");
        }
    }
    for (r, (members, tags)) in &osm.relations {
        assert_eq!(tags.get("type").map(String::as_str), Some("multipolygon"));
        assert_eq!(members.iter().filter(|m| m.2 == "outer").count(), 1);
        for (kind, m, role) in members {
            assert_eq!(kind, "way");
            assert!(role == "outer" || role == "inner", "{role}");
            assert!(osm.ways.contains_key(m), "relation {r}: way {m} missing");
            assert!(osm.ways[m].1.is_empty(), "member ways carry no tags");
        }
    }

    // Positions within the model's extent, by metres per degree on a
    // sphere at the origin (the ellipsoid differs by well under 1 %).
    let (s, c) = georef.heading_deg.to_radians().sin_cos();
    let per_deg = 6_371_000.0 * std::f64::consts::PI / 180.0;
    let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
    for p in nrg.spaces().iter().flat_map(|s| &s.polygon) {
        let (east, north) = (p[0] * c + p[1] * s, -p[0] * s + p[1] * c);
        let ll = [
            georef.lon + east / (per_deg * georef.lat.to_radians().cos()),
            georef.lat + north / per_deg,
        ];
        for k in 0..2 {
            lo[k] = lo[k].min(ll[k]);
            hi[k] = hi[k].max(ll[k]);
        }
    }
    for (n, (ll, _)) in &osm.nodes {
        for k in 0..2 {
            let margin = 0.01 * (hi[k] - lo[k]) + 2e-7;
            assert!(
                ll[k] >= lo[k] - margin && ll[k] <= hi[k] + margin,
                "node {n} at {ll:?} outside {lo:?}–{hi:?}"
            );
        }
    }

    // One area per space, with its tags and its area.
    let ring = |w: i64| -> Vec<Point> {
        osm.ways[&w]
            .0
            .iter()
            .map(|n| georef.to_map(osm.nodes[n].0))
            .collect()
    };
    let mut way_nodes_of: BTreeMap<SpaceId, HashSet<i64>> = BTreeMap::new();
    for space in nrg.spaces().iter().filter(|s| s.kind != SpaceKind::Door) {
        let want = match space.kind {
            SpaceKind::Room => "room",
            SpaceKind::Corridor => "corridor",
            _ => "area",
        };
        let is_it =
            |t: &Tags| t.get("ref") == Some(&space.id.to_string()) && t.contains_key("indoor");
        let ways: Vec<i64> = osm
            .ways
            .iter()
            .filter(|(_, (_, t))| is_it(t))
            .map(|(w, _)| *w)
            .collect();
        let rels: Vec<i64> = osm
            .relations
            .iter()
            .filter(|(_, (_, t))| is_it(t))
            .map(|(r, _)| *r)
            .collect();
        assert_eq!(
            ways.len() + rels.len(),
            1,
            "space {}: {ways:?} {rels:?}",
            space.id
        );
        let (tags, members): (&Tags, Vec<(i64, bool)>) = match (ways.first(), rels.first()) {
            (Some(w), _) => (&osm.ways[w].1, vec![(*w, true)]),
            (_, Some(r)) => (
                &osm.relations[r].1,
                osm.relations[r]
                    .0
                    .iter()
                    .map(|m| (m.1, m.2 == "outer"))
                    .collect(),
            ),
            _ => unreachable!(),
        };
        assert_eq!(
            space.holes.is_empty(),
            rels.is_empty(),
            "space {}",
            space.id
        );
        assert_eq!(tags["indoor"], want, "space {}", space.id);
        assert_eq!(tags["level"], georef.level);
        assert_eq!(tags.get("name"), space.name.as_ref(), "space {}", space.id);
        let got: f64 = members
            .iter()
            .map(|&(w, outer)| {
                if outer {
                    area(&ring(w))
                } else {
                    -area(&ring(w))
                }
            })
            .sum();
        assert!(
            (got - space.area_m2).abs() <= 0.01 * space.area_m2,
            "space {}: {got} m² written, {} m² in the model",
            space.id,
            space.area_m2
        );
        let nodes = members
            .iter()
            .flat_map(|(w, _)| osm.ways[w].0.iter().copied());
        way_nodes_of.insert(space.id, nodes.collect());
    }

    // One door node per door, on the outline of every space it joins.
    let door_nodes: Vec<(&i64, &([f64; 2], Tags))> = osm
        .nodes
        .iter()
        .filter(|(_, (_, t))| t.contains_key("door"))
        .collect();
    let doors: Vec<_> = nrg
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Door)
        .collect();
    assert_eq!(door_nodes.len(), doors.len());
    for door in doors {
        let mine: Vec<_> = door_nodes
            .iter()
            .filter(|(_, (_, t))| t.get("ref") == Some(&door.id.to_string()))
            .collect();
        assert_eq!(mine.len(), 1, "door {}", door.id);
        let (n, (ll, tags)) = mine[0];
        assert_eq!(tags["door"], "yes");
        assert_eq!(tags["level"], georef.level);
        let d = doorway(door).unwrap();
        let width: f64 = tags["width"].parse().unwrap();
        assert!(
            (width - d.width_m).abs() <= 0.005 + 1e-9,
            "door {}",
            door.id
        );
        let at = georef.to_map(*ll);
        let m = d.middle();
        assert!(
            (at[0] - m[0]).hypot(at[1] - m[1]) < 0.02,
            "door {} at {at:?}",
            door.id
        );
        let sides: Vec<SpaceId> = nrg
            .connections_of(door.id)
            .map(|c| if c.a == door.id { c.b } else { c.a })
            .filter(|s| nrg.space(*s).is_some_and(|s| s.kind != SpaceKind::Door))
            .collect();
        assert!(!sides.is_empty(), "door {} joins nothing", door.id);
        for side in sides {
            assert!(
                way_nodes_of[&side].contains(n),
                "door {} is not on the outline of space {side}",
                door.id
            );
        }
    }
    osm
}

#[test]
fn the_demo_building_is_tagged_by_simple_indoor_tagging() {
    let nrg = nrgdb::query::demo::building(8);
    let georef = Georef::new(48.137, 11.575, 30.0, "2").unwrap();
    let osm = check(&nrg, &georef);
    assert!(osm.relations.is_empty());
    // Corridor segments meet end to end: their common corners are one node.
    let corridors: Vec<&Vec<i64>> = osm
        .ways
        .values()
        .filter(|(_, t)| t.get("indoor").map(String::as_str) == Some("corridor"))
        .map(|(n, _)| n)
        .collect();
    assert_eq!(corridors.len(), 8);
    for pair in corridors.windows(2) {
        let a: HashSet<_> = pair[0].iter().collect();
        assert!(pair[1].iter().filter(|n| a.contains(n)).count() >= 2);
    }
}

#[test]
fn holes_become_multipolygons_and_names_are_escaped() {
    let (mut spaces, connections) = nrgdb::fixtures::corridor_building(4).into_parts();
    for s in &mut spaces {
        if s.kind == SpaceKind::Corridor {
            s.holes = vec![vec![[5.0, 0.8], [5.0, 1.2], [5.4, 1.2], [5.4, 0.8]]];
            s.name = Some("Hall \"A\" & <B>".into());
            s.update_area();
        }
    }
    let nrg = Nrg::new(spaces, connections).unwrap();
    let georef = Georef::new(-33.9, 151.2, 270.0, "-1").unwrap();
    let osm = check(&nrg, &georef);
    assert_eq!(osm.relations.len(), 1);
}

#[test]
fn a_model_without_spaces_is_a_valid_empty_file() {
    let georef = Georef::new(0.0, 0.0, 0.0, "0").unwrap();
    let osm = check(&Nrg::default(), &georef);
    assert!(osm.nodes.is_empty() && osm.ways.is_empty() && osm.relations.is_empty());
}

/// `nrgdb export --format osm` refuses a map without a georeference
/// (writing nothing) and writes the file once it has one.
#[test]
fn the_cli_needs_a_georeference() {
    use crate::support::{nrgdb, nrgdb_ok};
    let dir = tempfile::tempdir().unwrap();
    nrgdb_ok(dir.path(), &["demo", "--dir", "d", "--db", "t.sqlite"]);
    let args = [
        "export", "demo", "--format", "osm", "--out", "b.osm", "--db", "t.sqlite",
    ];
    let out = nrgdb(dir.path(), &args);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("no georeference"));
    assert!(!dir.path().join("b.osm").exists());
    nrgdb_ok(
        dir.path(),
        &[
            "georef",
            "demo",
            "--origin",
            "52.52,13.405",
            "--db",
            "t.sqlite",
        ],
    );
    nrgdb_ok(dir.path(), &args);
    let text = std::fs::read_to_string(dir.path().join("b.osm")).unwrap();
    parse(&text);
    assert!(
        text.contains(r#"<tag k="indoor" v="room"/>"#)
            && text.contains(r#"<tag k="door" v="yes"/>"#)
    );
}
