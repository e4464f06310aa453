//! OpenStreetMap Simple Indoor Tagging out (issue 24): the file is parsed
//! back here with quick-xml (no nrgdb code) and checked as JOSM and SIT
//! need it: ids negative and unique, every reference resolves, ways
//! closed, one `indoor=*` way per room or corridor with its level and ref,
//! one `door=yes` node per door on the outlines of both spaces it joins,
//! and the ways' areas (projected back to metres) those of the model.

use std::collections::{BTreeMap, BTreeSet};

use nrgdb::model::{Georef, SpaceKind};
use quick_xml::Reader;
use quick_xml::events::Event;

use crate::support::{nrgdb, nrgdb_ok};

#[derive(Default)]
struct Osm {
    nodes: BTreeMap<i64, ([f64; 2], BTreeMap<String, String>)>,
    ways: BTreeMap<i64, (Vec<i64>, BTreeMap<String, String>)>,
    relations: usize,
}

fn attr(e: &quick_xml::events::BytesStart<'_>, name: &str) -> Option<String> {
    e.attributes()
        .flatten()
        .find(|a| a.key.as_ref() == name)
        .map(|a| a.value.to_string())
}

fn parse(text: &str) -> Osm {
    let mut reader = Reader::from_str(text);
    let mut osm = Osm::default();
    let mut current: Option<(String, i64)> = None;
    loop {
        match reader.read_event().unwrap() {
            Event::Eof => break,
            Event::Start(e) | Event::Empty(e) => {
                let name = e.name().as_ref().to_string();
                let id = || attr(&e, "id").unwrap().parse::<i64>().unwrap();
                match name.as_str() {
                    "osm" => assert_eq!(attr(&e, "upload").as_deref(), Some("never")),
                    "node" => {
                        let (lat, lon) = (attr(&e, "lat").unwrap(), attr(&e, "lon").unwrap());
                        let i = id();
                        assert!(
                            osm.nodes
                                .insert(
                                    i,
                                    (
                                        [lon.parse().unwrap(), lat.parse().unwrap()],
                                        BTreeMap::new()
                                    )
                                )
                                .is_none()
                        );
                        current = Some(("node".into(), i));
                    }
                    "way" => {
                        let i = id();
                        assert!(osm.ways.insert(i, (Vec::new(), BTreeMap::new())).is_none());
                        current = Some(("way".into(), i));
                    }
                    "relation" => {
                        osm.relations += 1;
                        current = Some(("relation".into(), id()));
                    }
                    "nd" => {
                        let Some(("way", w)) = current.as_ref().map(|(k, i)| (k.as_str(), *i))
                        else {
                            panic!("nd outside a way")
                        };
                        osm.ways
                            .get_mut(&w)
                            .unwrap()
                            .0
                            .push(attr(&e, "ref").unwrap().parse().unwrap());
                    }
                    "tag" => {
                        let (k, v) = (attr(&e, "k").unwrap(), attr(&e, "v").unwrap());
                        match current.as_ref().map(|(k, i)| (k.as_str(), *i)) {
                            Some(("node", n)) => {
                                osm.nodes.get_mut(&n).unwrap().1.insert(k, v);
                            }
                            Some(("way", w)) => {
                                osm.ways.get_mut(&w).unwrap().1.insert(k, v);
                            }
                            _ => {}
                        }
                    }
                    _ => {}
                }
            }
            _ => {}
        }
    }
    osm
}

fn shoelace(ring: &[[f64; 2]]) -> f64 {
    let n = ring.len();
    (0..n)
        .map(|i| ring[i][0] * ring[(i + 1) % n][1] - ring[(i + 1) % n][0] * ring[i][1])
        .sum::<f64>()
        .abs()
        / 2.0
}

#[test]
fn the_demo_building_in_simple_indoor_tagging() {
    let nrg = nrgdb::query::demo::building(6);
    let g = Georef::new(47.3769, 8.5417, 25.0, "3").unwrap();
    let osm = parse(&nrgdb::format::osm::to_osm(&nrg, &g));
    // Ids negative; every way closed and its nodes present.
    assert!(osm.nodes.keys().chain(osm.ways.keys()).all(|id| *id < 0));
    for (id, (refs, _)) in &osm.ways {
        assert!(
            refs.len() >= 4 && refs.first() == refs.last(),
            "way {id} not closed"
        );
        assert!(
            refs.iter().all(|r| osm.nodes.contains_key(r)),
            "way {id}: unknown node"
        );
    }
    let way_of = |space: u32| {
        let found: Vec<_> = osm
            .ways
            .iter()
            .filter(|(_, (_, t))| {
                t.get("ref") == Some(&space.to_string()) && t.contains_key("indoor")
            })
            .collect();
        assert_eq!(found.len(), 1, "space {space}: {} ways", found.len());
        found[0].1.clone()
    };
    for s in nrg.spaces() {
        match s.kind {
            SpaceKind::Door => {
                let doors: Vec<_> = osm
                    .nodes
                    .iter()
                    .filter(|(_, (_, t))| {
                        t.get("door").map(String::as_str) == Some("yes")
                            && t.get("ref") == Some(&s.id.0.to_string())
                    })
                    .collect();
                assert_eq!(doors.len(), 1, "door {}", s.id);
                let (node, (_, tags)) = doors[0];
                assert_eq!(tags["level"], "3");
                let width: f64 = tags["width"].parse().unwrap();
                assert!((width - nrgdb::model::doorway(s).unwrap().width_m).abs() < 0.006);
                // On the outline of each space the door joins.
                for c in nrg.connections().iter().filter(|c| c.kind.is_navigable()) {
                    if let Some(other) = c.other(s.id) {
                        let (refs, _) = way_of(other.0);
                        assert!(
                            refs.contains(node),
                            "door {} not on the outline of {other}",
                            s.id
                        );
                    }
                }
            }
            kind => {
                let (refs, tags) = way_of(s.id.0);
                let want = if kind == SpaceKind::Room {
                    "room"
                } else if kind == SpaceKind::Corridor {
                    "corridor"
                } else {
                    "area"
                };
                assert_eq!(tags["indoor"], want);
                assert_eq!(tags["level"], "3");
                if let Some(name) = &s.name {
                    assert_eq!(&tags["name"], name);
                }
                // The outline back in metres: the space's area plus a notch
                // per door, a triangle as wide as the doorway reaching half
                // the wall's depth into it: a quarter of the door's area.
                let ring: Vec<[f64; 2]> = refs[..refs.len() - 1]
                    .iter()
                    .map(|r| g.to_map(osm.nodes[r].0))
                    .collect();
                let notches: f64 = nrg
                    .connections()
                    .iter()
                    .filter(|c| c.kind.is_navigable())
                    .filter_map(|c| c.other(s.id))
                    .filter_map(|o| nrg.space(o))
                    .filter(|o| o.kind == SpaceKind::Door)
                    .map(|d| d.area_m2 / 4.0)
                    .sum();
                let area = shoelace(&ring);
                if s.holes.is_empty() {
                    let want = s.area_m2 + notches;
                    assert!(
                        (area - want).abs() < 0.01 * want,
                        "space {}: {area} vs {want}",
                        s.id
                    );
                }
            }
        }
    }
    let unique: BTreeSet<_> = osm
        .nodes
        .values()
        .map(|(p, _)| ((p[0] * 1e7).round() as i64, (p[1] * 1e7).round() as i64))
        .collect();
    assert_eq!(unique.len(), osm.nodes.len(), "two nodes at one position");
}

#[test]
fn the_cli_needs_a_georeference() {
    let dir = tempfile::tempdir().unwrap();
    nrgdb_ok(dir.path(), &["demo", "--dir", "d", "--db", "t.sqlite"]);
    let out = nrgdb(
        dir.path(),
        &[
            "export", "demo", "--format", "osm", "--out", "b.osm", "--db", "t.sqlite",
        ],
    );
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
    nrgdb_ok(
        dir.path(),
        &[
            "export", "demo", "--format", "osm", "--out", "b.osm", "--db", "t.sqlite",
        ],
    );
    let osm = parse(&std::fs::read_to_string(dir.path().join("b.osm")).unwrap());
    assert!(
        osm.ways
            .values()
            .any(|(_, t)| t.get("indoor").map(String::as_str) == Some("room"))
    );
}
