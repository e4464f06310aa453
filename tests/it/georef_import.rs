//! Placed files in and out (issue 24): a georeferenced map's IndoorGML is
//! written in the WGS84 / UTM zone of its origin with the zone as
//! `srsName`, and a file in a CRS (IndoorGML with a UTM `srsName`,
//! GeoJSON in UTM or WGS84) imports into map-frame metres, leaving its
//! georeference with a map that has none and landing in the frame of a
//! map that has one.

use std::path::Path;

use serde_json::Value;

use crate::support::{nrgdb, nrgdb_ok};

/// The positions of every `gml:posList` and `gml:pos` in a GML text.
fn gml_positions(text: &str) -> Vec<Vec<[f64; 2]>> {
    let mut lists = Vec::new();
    for part in text.split("<gml:pos").skip(1) {
        let Some(start) = part.find('>') else {
            continue;
        };
        let Some(end) = part.find("</gml:pos") else {
            continue;
        };
        let numbers: Vec<f64> = part[start + 1..end]
            .split_whitespace()
            .map(|n| n.parse().unwrap())
            .collect();
        lists.push(numbers.chunks_exact(2).map(|p| [p[0], p[1]]).collect());
    }
    lists
}

fn json(dir: &Path, file: &str) -> Value {
    serde_json::from_slice(&std::fs::read(dir.join(file)).unwrap()).unwrap()
}

/// Each space's id → its anchor, from a model JSON or a GeoJSON file.
fn anchors(doc: &Value) -> Vec<(u64, [f64; 2])> {
    let pair = |v: &Value| [v[0].as_f64().unwrap(), v[1].as_f64().unwrap()];
    match doc.get("spaces") {
        Some(spaces) => spaces
            .as_array()
            .unwrap()
            .iter()
            .map(|s| (s["id"].as_u64().unwrap(), pair(&s["anchor"])))
            .collect(),
        None => doc["features"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|f| f["properties"]["feature"] == "space")
            .map(|f| {
                let p = &f["properties"];
                (p["space_id"].as_u64().unwrap(), pair(&p["anchor"]))
            })
            .collect(),
    }
}

/// Asserts that two files hold the same spaces' anchors within
/// `tolerance`, in id order (a model placed away from a map's previous
/// revision gets new ids, in the same order).
fn same_anchors(a: &Value, b: &Value, tolerance: f64) {
    let (mut a, mut b) = (anchors(a), anchors(b));
    a.sort_by_key(|(id, _)| *id);
    b.sort_by_key(|(id, _)| *id);
    assert_eq!(a.len(), b.len());
    for ((ia, pa), (_, pb)) in a.iter().zip(&b) {
        for k in 0..2 {
            assert!(
                (pa[k] - pb[k]).abs() < tolerance,
                "space {ia}: {pa:?} vs {pb:?}"
            );
        }
    }
}

/// The database the tests use.
const DB: [&str; 2] = ["--db", "t.sqlite"];

/// The demo map in `dir`'s database, georeferenced at `origin`
/// ("LAT,LON") with +y at `heading` degrees.
fn georeferenced_demo(dir: &Path, origin: &str, heading: &str) {
    nrgdb_ok(dir, &[&["demo", "--dir", "d"][..], &DB[..]].concat());
    let georef = ["georef", "demo", "--origin", origin, "--heading", heading];
    nrgdb_ok(dir, &[&georef[..], &DB[..]].concat());
}

#[test]
fn indoorgml_of_a_georeferenced_map_is_in_its_utm_zone_and_imports_back() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let run = |args: &[&str]| nrgdb_ok(d, &[args, &DB[..]].concat());
    georeferenced_demo(d, "48.1374,11.5755", "-30");
    run(&["export", "demo", "--out", "g.gml"]);
    run(&["export", "demo", "--out", "local.gml", "--local-frame"]);
    run(&["export", "demo", "--out", "m.json"]);
    run(&["export", "demo", "--out", "w.geojson"]);
    let text = std::fs::read_to_string(d.join("g.gml")).unwrap();
    assert!(text.contains(r#"srsName="urn:ogc:def:crs:EPSG::32632""#));
    let local = std::fs::read_to_string(d.join("local.gml")).unwrap();
    assert!(!local.contains("srsName"));
    // Distances in UTM are true distances times the point scale
    // k = k0 (1 + x² / 2ρν) at x metres from the central meridian (9° E),
    // ρ and ν the radii of curvature: Munich lies about 191 km east of
    // it, k ≈ 1.000 05. The map frame's own placement (metres per degree
    // taken at the origin) is true to about 1e-5 over the building.
    let (a, e2, phi) = (6_378_137.0f64, 6.694_38e-3, 48.1374f64.to_radians());
    let w = 1.0 - e2 * phi.sin().powi(2);
    let rho_nu = a * (1.0 - e2) / w.powf(1.5) * a / w.sqrt();
    let (placed, metres) = (gml_positions(&text), gml_positions(&local));
    assert_eq!(placed.len(), metres.len());
    let mut compared = 0;
    for (p, m) in placed.iter().zip(&metres).take(200) {
        for (a, b) in p.windows(2).zip(m.windows(2)) {
            let d_map = (b[1][0] - b[0][0]).hypot(b[1][1] - b[0][1]);
            if d_map < 1.0 {
                continue;
            }
            let d_utm = (a[1][0] - a[0][0]).hypot(a[1][1] - a[0][1]);
            let x = (a[0][0] + a[1][0]) / 2.0 - 500_000.0;
            let k = 0.9996 * (1.0 + x * x / (2.0 * rho_nu));
            assert!(
                (d_utm / d_map - k).abs() < 1.5e-5,
                "{d_utm} / {d_map} vs k {k}"
            );
            compared += 1;
        }
    }
    assert!(compared > 100, "{compared} edges");
    // Our checker and, where present, the OGC schema accept the file.
    nrgdb_ok(d, &["check", "g.gml"]);
    crate::support::schema_valid_if_shared(&d.join("g.gml"));
    // Into a new map: the same model in metres, and the georeference with it.
    let out = run(&["import", "g.gml", "--map", "copy"]);
    let said = String::from_utf8_lossy(&out.stdout);
    assert!(said.contains("georeferenced from the file's CRS"), "{said}");
    run(&["export", "copy", "--out", "copy.json"]);
    same_anchors(&json(d, "m.json"), &json(d, "copy.json"), 1e-6);
    let shown = String::from_utf8_lossy(&run(&["georef", "copy"]).stdout).to_string();
    assert!(
        shown.contains("48.1374") && shown.contains("330°"),
        "{shown}"
    );
    // Into a map with its own georeference (40 m away, turned): the
    // positions land in that map's frame, the same places on the Earth.
    run(&["import", "m.json", "--map", "other"]);
    run(&[
        "georef",
        "other",
        "--origin",
        "48.13776,11.57551",
        "--heading",
        "75",
    ]);
    let out = run(&["import", "g.gml", "--map", "other"]);
    assert!(!String::from_utf8_lossy(&out.stdout).contains("georeferenced from"));
    run(&["export", "other", "--out", "other.json"]);
    run(&["export", "other", "--out", "other.geojson"]);
    let moved = anchors(&json(d, "other.json"));
    let kept = anchors(&json(d, "m.json"));
    let shift = (moved[0].1[0] - kept[0].1[0]).hypot(moved[0].1[1] - kept[0].1[1]);
    assert!(shift > 10.0, "the frame moved the model by {shift} m");
    same_anchors(&json(d, "w.geojson"), &json(d, "other.geojson"), 2e-8);
}

#[test]
fn a_utm_file_from_elsewhere_imports_at_its_corner_in_true_metres() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let run = |args: &[&str]| nrgdb_ok(d, &[args, &DB[..]].concat());
    georeferenced_demo(d, "-33.9,151.2", "10");
    run(&["export", "demo", "--out", "u.geojson", "--crs", "utm"]);
    run(&["export", "demo", "--out", "w.geojson"]);
    run(&["export", "demo", "--out", "m.json"]);
    // As another program writes it: the zone named, no georeference member.
    let mut doc = json(d, "u.geojson");
    doc.as_object_mut().unwrap().remove("nrgdb:georef");
    std::fs::write(d.join("plain.geojson"), doc.to_string()).unwrap();
    let out = run(&["import", "plain.geojson", "--map", "third"]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("georeferenced from the file's CRS"));
    run(&["export", "third", "--out", "third.json"]);
    run(&["export", "third", "--out", "third.geojson"]);
    // The same places on the Earth (to 2 mm), areas in true square metres.
    same_anchors(&json(d, "w.geojson"), &json(d, "third.geojson"), 2e-8);
    let area = |v: &Value| -> Vec<f64> {
        v["spaces"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s["area_m2"].as_f64().unwrap())
            .collect()
    };
    for (a, b) in area(&json(d, "m.json"))
        .iter()
        .zip(area(&json(d, "third.json")))
    {
        assert!((a - b).abs() <= 1e-4 * a.max(1.0), "{a} vs {b}");
    }
    // The frame starts at the file's lowest corner: every anchor is at
    // positive x and y, the lowest within the model's extent of 0.
    let third = anchors(&json(d, "third.json"));
    assert!(third.iter().all(|(_, p)| p[0] > 0.0 && p[1] > 0.0));
    // Degrees in a GML srsName are refused with the reason, nothing stored.
    run(&["export", "demo", "--out", "g.gml"]);
    let text = std::fs::read_to_string(d.join("g.gml")).unwrap();
    let bad = text.replace("urn:ogc:def:crs:EPSG::32756", "EPSG:4326");
    std::fs::write(d.join("deg.gml"), bad).unwrap();
    let out = nrgdb(
        d,
        &["import", "deg.gml", "--map", "deg", "--db", "t.sqlite"],
    );
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("deg.gml") && err.contains("EPSG:4326"),
        "{err}"
    );
    let maps = String::from_utf8_lossy(&run(&["maps"]).stdout).to_string();
    assert!(!maps.contains("deg"), "{maps}");
}
