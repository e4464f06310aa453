//! Exports carry the walked lengths: IndoorGML Transitions are the walked
//! path through the door with its length as weight, GeoJSON connection
//! lines likewise; both read back with the same lengths. Checked against
//! the hand-made corridor building (`nrgdb::fixtures`), whose anchors and
//! doorways are known, and lengths are recomputed here from the written
//! coordinates.

use nrgdb::format::{ModelFormat, from_document, render_model};
use nrgdb::indoorgml::{self, read_str};
use nrgdb::model::{Point, SpaceId};
use nrgdb::route::walked_model;

use crate::support::{building, have_xmllint, nrgdb, nrgdb_ok, shared_dir};

fn own_length(points: &[Point]) -> f64 {
    points
        .windows(2)
        .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
        .sum()
}

fn dist(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

fn near(a: Point, b: Point) -> bool {
    dist(a, b) < 1e-9
}

/// (first State, second State, weight, LineString points) of each Transition.
fn transitions(gml: &str) -> Vec<(String, String, f64, Vec<Point>)> {
    let doc = read_str(gml).unwrap();
    doc.layers()
        .iter()
        .flat_map(|l| &l.transitions)
        .map(|t| {
            let points: Vec<Point> = t.geometry.as_ref().unwrap().coords.xy().collect();
            (
                t.connects[0].clone(),
                t.connects[1].clone(),
                t.weight.unwrap(),
                points,
            )
        })
        .collect()
}

#[test]
fn transition_is_the_walked_path_through_the_door() {
    let nrg = building(4);
    let anchor = |state: &str| {
        let id: u32 = state.trim_start_matches('S').parse().unwrap();
        nrg.space(SpaceId(id)).unwrap().anchor
    };
    let gml = render_model(&nrg, ModelFormat::IndoorGml);
    let ts = transitions(&gml);
    assert_eq!(
        ts.len(),
        nrg.connections()
            .iter()
            .filter(|c| c.kind.is_navigable())
            .count()
    );
    let mut bent = 0;
    for (a, b, weight, points) in &ts {
        assert!(near(points[0], anchor(a)), "{a}-{b} starts at {a}'s anchor");
        assert!(
            near(*points.last().unwrap(), anchor(b)),
            "{a}-{b} ends at {b}'s anchor"
        );
        let own = own_length(points);
        assert!(
            (weight - own).abs() < 1e-9,
            "{a}-{b}: weight {weight} vs line {own}"
        );
        let straight = dist(anchor(a), anchor(b));
        assert!(*weight >= straight - 1e-9, "{a}-{b}: {weight} < {straight}");
        if points.len() > 2 {
            assert!(*weight > straight, "{a}-{b}: a bent walk is longer");
            bent += 1;
        }
    }
    // Room 10 (anchor (2, 4.6)) to its door 10000 (anchor (2, 2.1)): the
    // door is straight below the room, so the walk is the 2.5 m segment.
    let (_, _, w, points) = ts.iter().find(|t| t.0 == "S10" && t.1 == "S10000").unwrap();
    assert!(near(points[0], [2.0, 4.6]) && near(*points.last().unwrap(), [2.0, 2.1]));
    assert!((w - 2.5).abs() < 1e-9, "{w}");
    // The corridor's anchor (8, 1) to door 10000 (x ∈ [1.5, 2.5] at y = 2):
    // the straight line crosses y = 2 at x ≈ 2.55, in the wall, so the
    // walk bends at the doorway's corner (2.5, 2) and is longer.
    let (_, _, w, points) = ts.iter().find(|t| t.0 == "S1" && t.1 == "S10000").unwrap();
    assert!(points.len() >= 3, "{points:?}");
    let corner = dist([8.0, 1.0], [2.5, 2.0]) + dist([2.5, 2.0], [2.0, 2.1]);
    assert!((w - corner).abs() < 1e-6, "{w} vs {corner}");
    assert!(bent >= 2, "some walks must bend ({bent})");
}

#[test]
fn weights_are_the_models_walked_lengths_and_survive_a_round_trip() {
    let nrg = building(5);
    let walked = walked_model(&nrg).nrg;
    for format in [
        ModelFormat::IndoorGml,
        ModelFormat::GeoJson,
        ModelFormat::Json,
    ] {
        let text = render_model(&nrg, format);
        let back = match format {
            ModelFormat::IndoorGml => {
                let (back, fixes) = from_document(&read_str(&text).unwrap()).unwrap();
                assert_eq!(fixes.total(), 0);
                back
            }
            ModelFormat::GeoJson => nrgdb::geojson::from_geojson(&text).unwrap(),
            _ => nrgdb::model::Nrg::from_json(&text).unwrap(),
        };
        assert_eq!(back.connections().len(), walked.connections().len());
        for (c, w) in back.connections().iter().zip(walked.connections()) {
            assert_eq!(c.key(), w.key());
            assert_eq!(c.length_m, w.length_m, "{format:?} {:?}", c.key());
        }
        // Written again, the same text: walked lengths are a fixed point.
        assert_eq!(render_model(&back, format), text, "{format:?}");
    }
}

#[test]
fn geojson_connection_line_is_the_walked_path() {
    let nrg = building(3);
    let v: serde_json::Value =
        serde_json::from_str(&render_model(&nrg, ModelFormat::GeoJson)).unwrap();
    let mut lines = 0;
    for f in v["features"].as_array().unwrap() {
        let p = &f["properties"];
        if p["feature"] != "connection" || p["kind"] == "adjacent" {
            continue;
        }
        lines += 1;
        let points: Vec<Point> =
            serde_json::from_value(f["geometry"]["coordinates"].clone()).unwrap();
        let end = |k: &str| {
            let id: u32 = serde_json::from_value(p[k].clone()).unwrap();
            nrg.space(SpaceId(id)).unwrap().anchor
        };
        assert!(near(points[0], end("a")) && near(*points.last().unwrap(), end("b")));
        let length = p["length_m"].as_f64().unwrap();
        assert!((length - own_length(&points)).abs() < 1e-9);
        assert!(length >= dist(end("a"), end("b")) - 1e-9);
    }
    assert_eq!(lines, 6);
}

#[test]
fn walked_export_is_checked_clean_and_schema_valid() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("walked.gml");
    std::fs::write(&path, render_model(&building(4), ModelFormat::IndoorGml)).unwrap();
    let doc = indoorgml::read_file(&path, indoorgml::DEFAULT_MAX_BYTES).unwrap();
    assert!(
        indoorgml::check(&doc).is_empty(),
        "{:?}",
        indoorgml::check(&doc)
    );
    let out = nrgdb(dir.path(), &["check", "--no-schema", "walked.gml"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let Some(shared) = shared_dir("indoorgml/validate.sh") else {
        return;
    };
    if !have_xmllint() && std::env::var("NRGDB_REQUIRE_SHARED").as_deref() != Ok("1") {
        eprintln!("notice: skipping, xmllint missing");
        return;
    }
    let v = std::process::Command::new(shared.join("indoorgml/validate.sh"))
        .arg(&path)
        .output()
        .unwrap();
    assert!(
        v.status.success(),
        "{}{}",
        String::from_utf8_lossy(&v.stdout),
        String::from_utf8_lossy(&v.stderr)
    );
}

#[test]
fn cli_export_and_convert_write_walked_transitions() {
    let dir = tempfile::tempdir().unwrap();
    let nrg = building(3);
    std::fs::write(dir.path().join("b.json"), nrg.to_json()).unwrap();
    let run = |args: &[&str]| {
        nrgdb_ok(dir.path(), args);
    };
    run(&["convert", "b.json", "c.gml"]);
    run(&["import", "--db", "t.db", "--map", "m", "b.json"]);
    run(&["export", "--db", "t.db", "m", "--out", "e.gml"]);
    let expected = render_model(&nrg, ModelFormat::IndoorGml);
    let converted = std::fs::read_to_string(dir.path().join("c.gml")).unwrap();
    assert_eq!(converted, expected);
    let exported = std::fs::read_to_string(dir.path().join("e.gml")).unwrap();
    assert_eq!(transitions(&exported), transitions(&expected));
}
