//! IndoorJSON2 (the IndoorGML 2.0 draft's JSON encoding): a model written
//! and read back keeps its spaces, kinds, polygons, connections and walked
//! weights; what is written has the members the draft schema requires, and
//! each edge's weight is the length of its own curve (recomputed here from
//! the vertices); bad input is an error naming the element, never a panic.

use nrgdb::format::{Declared, FileKind, ModelFormat, detect, model_from_bytes, render};
use nrgdb::indoorgml::json2;
use nrgdb::model::{Point, SpaceId};
use nrgdb::route::walked_model;
use serde_json::{Value, json};

use crate::support::{building, nrgdb_ok};

fn written() -> (nrgdb::model::Nrg, Value) {
    let walked = walked_model(&building(4));
    let text = render(&walked, ModelFormat::IndoorJson);
    (walked.nrg, serde_json::from_str(&text).unwrap())
}

fn layer(doc: &Value) -> &Value {
    &doc["layers"]["nrg"]
}

#[test]
fn written_documents_carry_what_the_draft_schema_requires() {
    let (nrg, doc) = written();
    for key in ["type", "version", "layers", "vertices"] {
        assert!(doc.get(key).is_some(), "{key}");
    }
    assert_eq!(doc["type"], "IndoorJSON2");
    let l = layer(&doc);
    assert_eq!(l["type"], "ThematicLayer");
    assert!(l["theme"].is_string());
    let cells = l["primalSpace"]["cellSpaceMember"].as_object().unwrap();
    assert_eq!(cells.len(), nrg.spaces().len());
    assert!(
        cells
            .values()
            .all(|c| c["poi"].is_boolean() && c["type"] == "CellSpace")
    );
    assert!(l["dualSpace"]["isLogical"].is_boolean());
    let edges = l["dualSpace"]["edgeMember"].as_object().unwrap();
    assert_eq!(edges.len(), nrg.connections().len());
    for e in edges.values() {
        assert_eq!(e["type"], "Edge");
        assert!(e["weight"].is_number());
        assert_eq!(e["connects"].as_array().unwrap().len(), 2);
    }
    let vertices = doc["vertices"].as_array().unwrap();
    assert!(vertices.iter().all(|v| v.as_array().unwrap().len() == 3));
}

#[test]
fn edge_weights_are_the_walked_curves() {
    let (nrg, doc) = written();
    let vertices: Vec<Point> = doc["vertices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()])
        .collect();
    let nodes = &layer(&doc)["dualSpace"]["nodeMember"];
    for e in layer(&doc)["dualSpace"]["edgeMember"]
        .as_object()
        .unwrap()
        .values()
    {
        let line: Vec<Point> = e["geometry"]["boundaries"]
            .as_array()
            .unwrap()
            .iter()
            .map(|i| vertices[i.as_u64().unwrap() as usize])
            .collect();
        let own: f64 = line
            .windows(2)
            .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
            .sum();
        assert!((e["weight"].as_f64().unwrap() - own).abs() < 1e-9, "{e}");
        let anchor = |n: &Value| {
            let i = nodes[n.as_str().unwrap()]["geometry"]["boundaries"]
                .as_u64()
                .unwrap();
            vertices[i as usize]
        };
        assert_eq!(line[0], anchor(&e["connects"][0]));
        assert_eq!(*line.last().unwrap(), anchor(&e["connects"][1]));
        // At least the straight line, as a walk must be.
        let (a, b) = (line[0], *line.last().unwrap());
        assert!(own >= (a[0] - b[0]).hypot(a[1] - b[1]) - 1e-9);
    }
    assert!(nrg.connections().iter().any(|c| c.length_m > 0.0));
}

#[test]
fn a_model_round_trips() {
    let walked = walked_model(&building(4));
    let text = render(&walked, ModelFormat::IndoorJson);
    let kind = detect(&Declared::name("m.indoor.json"), text.as_bytes()).unwrap();
    assert_eq!(kind, FileKind::Model(ModelFormat::IndoorJson));
    let (back, _) =
        model_from_bytes(text.as_bytes(), ModelFormat::IndoorJson, "m".as_ref()).unwrap();
    let nrg = &walked.nrg;
    assert_eq!(back.spaces().len(), nrg.spaces().len());
    for (a, b) in back.spaces().iter().zip(nrg.spaces()) {
        assert_eq!(
            (
                a.id, a.kind, &a.name, &a.polygon, &a.holes, a.anchor, a.doorway
            ),
            (
                b.id, b.kind, &b.name, &b.polygon, &b.holes, b.anchor, b.doorway
            )
        );
        assert_eq!(a.attributes, b.attributes);
    }
    assert_eq!(back.connections(), nrg.connections());
    // Written again: the same text.
    assert_eq!(render(&walked_model(&back), ModelFormat::IndoorJson), text);
}

#[test]
fn cli_converts_to_and_from_indoorjson2_and_checks_it() {
    let dir = tempfile::tempdir().unwrap();
    let nrg = building(3);
    std::fs::write(dir.path().join("b.json"), nrg.to_json()).unwrap();
    let ok = |args: &[&str]| {
        nrgdb_ok(dir.path(), args);
    };
    ok(&["convert", "b.json", "b.indoor.json"]);
    ok(&["convert", "b.indoor.json", "c.json"]);
    // What came out of IndoorJSON2 is a model the IndoorGML checker passes.
    ok(&["convert", "b.indoor.json", "c.gml"]);
    ok(&["check", "--no-schema", "c.gml"]);
    let back =
        nrgdb::model::Nrg::from_json(&std::fs::read_to_string(dir.path().join("c.json")).unwrap())
            .unwrap();
    let walked = walked_model(&nrg).nrg;
    assert_eq!(back.connections(), walked.connections());
    assert_eq!(back.spaces().len(), nrg.spaces().len());
}

/// A small document written here by hand, with cells named as other
/// tools name them and edges connecting cells (as the draft's own example
/// does) and nodes.
fn hand() -> Value {
    json!({
        "type": "IndoorJSON2", "version": "0.1",
        "layers": {"L": {
            "type": "ThematicLayer", "semanticExtension": false, "theme": "Topographic",
            "primalSpace": {"cellSpaceMember": {
                "room-a": {"type": "CellSpace", "poi": false, "name": "A", "level": "2",
                    "cellSpaceGeom": {"type": "CompositeSurface", "boundaries": [[[0, 1, 2, 3]]]}},
                "room-b": {"type": "CellSpace", "poi": false,
                    "cellSpaceGeom": {"type": "Surface", "boundaries": [[1, 4, 5, 2]]}}
            }},
            "dualSpace": {"isLogical": false,
                "nodeMember": {"n-a": {"type": "Node", "duality": "room-a", "geometry": {"type": "Point", "boundaries": 6}}},
                "edgeMember": {"e": {"type": "Edge", "weight": 4.5, "connects": ["n-a", "room-b"]}}}
        }},
        "vertices": [[0,0,0],[4,0,0],[4,3,0],[0,3,0],[8,0,0],[8,3,0],[1,1,0]]
    })
}

#[test]
fn a_hand_written_document_is_read() {
    let nrg = json2::read_str(&hand().to_string()).unwrap();
    let a = nrg.space(SpaceId(1)).unwrap();
    assert_eq!((a.name.as_deref(), a.anchor), (Some("A"), [1.0, 1.0]));
    assert_eq!(a.attributes.get("level"), Some(&json!("2")));
    let b = nrg.space(SpaceId(2)).unwrap();
    // No node: an inside point.
    assert!(b.anchor[0] > 4.0 && b.anchor[0] < 8.0 && b.anchor[1] > 0.0 && b.anchor[1] < 3.0);
    assert_eq!(nrg.connections().len(), 1);
    assert_eq!(nrg.connections()[0].length_m, 4.5);
}

#[test]
fn bad_input_names_the_element() {
    type Edit = fn(&mut Value);
    let cases: &[(&str, Edit)] = &[
        ("$.type", |d| d["type"] = json!("CityJSON")),
        ("$.version", |d| d["version"] = json!("2.0")),
        ("$.vertices[2]", |d| d["vertices"][2] = json!([1, "x", 0])),
        ("$.vertices", |d| d["vertices"] = json!({})),
        (
            "$.layers.L.primalSpace.cellSpaceMember.room-a.cellSpaceGeom.boundaries[0][0][3]",
            |d| {
                d["layers"]["L"]["primalSpace"]["cellSpaceMember"]["room-a"]["cellSpaceGeom"]["boundaries"]
                    [0][0][3] = json!(99)
            },
        ),
        (
            "$.layers.L.primalSpace.cellSpaceMember.room-b.cellSpaceGeom",
            |d| {
                d["layers"]["L"]["primalSpace"]["cellSpaceMember"]["room-b"]["cellSpaceGeom"]["type"] =
                    json!("Solid")
            },
        ),
        ("$.layers.L.primalSpace.cellSpaceMember.room-b", |d| {
            d["layers"]["L"]["primalSpace"]["cellSpaceMember"]["room-b"]
                .as_object_mut()
                .unwrap()
                .remove("cellSpaceGeom");
        }),
        ("$.layers.L.dualSpace.edgeMember.e.weight", |d| {
            d["layers"]["L"]["dualSpace"]["edgeMember"]["e"]
                .as_object_mut()
                .unwrap()
                .remove("weight");
        }),
        ("$.layers.L.dualSpace.edgeMember.e.weight", |d| {
            d["layers"]["L"]["dualSpace"]["edgeMember"]["e"]["weight"] = json!(-1)
        }),
        ("$.layers.L.dualSpace.edgeMember.e.connects[1]", |d| {
            d["layers"]["L"]["dualSpace"]["edgeMember"]["e"]["connects"][1] = json!("nowhere")
        }),
        ("$.layers.L.dualSpace.edgeMember.e.connects", |d| {
            d["layers"]["L"]["dualSpace"]["edgeMember"]["e"]["connects"] = json!(["n-a"])
        }),
        ("$.layers.L.dualSpace.nodeMember.n-a.duality", |d| {
            d["layers"]["L"]["dualSpace"]["nodeMember"]["n-a"]["duality"] = json!("room-z")
        }),
        ("$.layers", |d| {
            let l = d["layers"]["L"].clone();
            d["layers"]["M"] = l;
        }),
    ];
    for (path, edit) in cases {
        let mut doc = hand();
        edit(&mut doc);
        let err = json2::read_str(&doc.to_string()).unwrap_err().to_string();
        assert!(
            err.starts_with(&format!("{path}:")),
            "want {path}, got: {err}"
        );
    }
    let err = json2::read_str("{\"type\": ").unwrap_err().to_string();
    assert!(err.starts_with("line 1, column"), "{err}");
}

#[test]
fn truncated_or_odd_documents_never_panic() {
    let text = render(&walked_model(&building(2)), ModelFormat::IndoorJson);
    for cut in (0..text.len()).step_by(97) {
        if text.is_char_boundary(cut) {
            assert!(json2::read_str(&text[..cut]).is_err());
        }
    }
    for odd in [
        "null",
        "[]",
        "{}",
        "{\"type\":\"IndoorJSON2\",\"version\":\"0.1\"}",
        "{\"type\":\"IndoorJSON2\",\"version\":\"0.1\",\"vertices\":[],\"layers\":{\"x\":{\"primalSpace\":[]}}}",
    ] {
        assert!(json2::read_str(odd).is_err(), "{odd}");
    }
}
