//! Georeferenced output (issue 24): `nrgdb georef` keeps a map's WGS84
//! origin, heading and level; GeoJSON of such a map is WGS84 (RFC 7946),
//! placed where an independent computation (a spherical Earth, written
//! here) puts it, and reads back to the model in metres.

use serde_json::Value;

use crate::support::{nrgdb, nrgdb_ok};

/// Mean Earth radius (IUGG), for the test's own spherical placement.
const R: f64 = 6_371_008.8;

fn demo_db(dir: &std::path::Path) {
    let out = nrgdb(dir, &["demo", "--dir", "d", "--db", "t.sqlite"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn geojson_of_a_georeferenced_map_is_wgs84_where_it_belongs() {
    let dir = tempfile::tempdir().unwrap();
    demo_db(dir.path());
    let run = |args: &[&str]| {
        let out = nrgdb(dir.path(), args);
        (
            out.status.success(),
            String::from_utf8_lossy(&out.stdout).to_string()
                + &String::from_utf8_lossy(&out.stderr),
        )
    };
    // Latitude 95: a clear error, nothing stored.
    let (ok, text) = run(&["georef", "demo", "--origin", "95,13.4", "--db", "t.sqlite"]);
    assert!(!ok && text.contains("latitude is 95"), "{text}");
    let (ok, text) = run(&["georef", "demo", "--db", "t.sqlite"]);
    assert!(ok && text.contains("no georeference"), "{text}");
    let (ok, text) = run(&[
        "georef",
        "demo",
        "--origin",
        "48.1374,11.5755",
        "--heading",
        "-30",
        "--level",
        "2",
        "--db",
        "t.sqlite",
    ]);
    assert!(
        ok && text.contains("330°") && text.contains("level 2"),
        "{text}"
    );
    // The model in metres, and the same map as WGS84 GeoJSON.
    let export = |out: &str, more: &[&str]| -> Value {
        let mut args = vec!["export", "demo", "--out", out, "--db", "t.sqlite"];
        args.extend(more);
        nrgdb_ok(dir.path(), &args);
        serde_json::from_slice(&std::fs::read(dir.path().join(out)).unwrap()).unwrap()
    };
    let model = export("m.json", &[]);
    let wgs = export("w.geojson", &[]);
    let local = export("l.geojson", &["--local-frame"]);
    assert!(wgs.get("crs").is_none(), "RFC 7946 has no crs member");
    // Each space's anchor, placed independently on a sphere: map +y at
    // 330° from north means +y points north-west.
    let (lat0, lon0, h) = (48.1374f64, 11.5755f64, 330f64.to_radians());
    let place = |x: f64, y: f64| {
        let (e, n) = (x * h.cos() + y * h.sin(), -x * h.sin() + y * h.cos());
        let lat = lat0 + (n / R).to_degrees();
        let lon = lon0 + (e / (R * lat0.to_radians().cos())).to_degrees();
        (lon, lat)
    };
    let features = wgs["features"].as_array().unwrap();
    let spaces = model["spaces"].as_array().unwrap();
    let mut compared = 0;
    for s in spaces {
        let f = features
            .iter()
            .find(|f| {
                f["properties"]["feature"] == "space" && f["properties"]["space_id"] == s["id"]
            })
            .unwrap();
        let (x, y) = (
            s["anchor"][0].as_f64().unwrap(),
            s["anchor"][1].as_f64().unwrap(),
        );
        let (lon, lat) = place(x, y);
        let got = &f["properties"]["anchor"];
        // A sphere and the ellipsoid differ by < 0.5 % of the offset
        // (tens of metres here): well under 1e-6° (0.1 m).
        assert!(
            (got[0].as_f64().unwrap() - lon).abs() < 1e-6,
            "{got} vs {lon}"
        );
        assert!(
            (got[1].as_f64().unwrap() - lat).abs() < 1e-6,
            "{got} vs {lat}"
        );
        // Every vertex is a longitude and latitude near the origin.
        for ring in f["geometry"]["coordinates"].as_array().unwrap() {
            for p in ring.as_array().unwrap() {
                let (lo, la) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
                assert!((lo - lon0).abs() < 0.01 && (la - lat0).abs() < 0.01, "{p}");
            }
        }
        // Areas and lengths stay metres.
        assert_eq!(f["properties"]["area_m2"], s["area_m2"]);
        compared += 1;
    }
    assert!(compared >= 10, "{compared} spaces");
    // The local-frame file is the metres file.
    assert!(local.get("nrgdb:georef").is_none());
    // The WGS84 file reads back to the model in metres.
    assert!(run(&["convert", "w.geojson", "back.json"]).0);
    let back: Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("back.json")).unwrap()).unwrap();
    for (a, b) in spaces.iter().zip(back["spaces"].as_array().unwrap()) {
        for k in 0..2 {
            let (p, q) = (
                a["anchor"][k].as_f64().unwrap(),
                b["anchor"][k].as_f64().unwrap(),
            );
            assert!((p - q).abs() < 1e-6, "{p} vs {q}");
        }
    }
    // Cleared: GeoJSON in metres again.
    assert!(run(&["georef", "demo", "--clear", "--db", "t.sqlite"]).0);
    assert!(export("again.geojson", &[]).get("nrgdb:georef").is_none());
}

/// `GET …/geojson` follows the map's georeference, which a writer may set
/// while the server runs; `frame=local` keeps metres.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_server_serves_wgs84_for_a_georeferenced_map() {
    let s = crate::server_client::TestServer::read_only().await;
    let local = s
        .get("/maps/building/revisions/latest/geojson")
        .await
        .json();
    assert!(local.get("nrgdb:georef").is_none());
    assert!(s.get("/maps/building").await.json()["georef"].is_null());
    {
        let mut store = nrgdb::store::Store::open(&s.db).unwrap();
        let g = nrgdb::model::Georef::new(-33.8568, 151.2153, 0.0, "0").unwrap();
        store.set_georef("building", Some(&g)).unwrap();
    }
    let wgs = s
        .get("/maps/building/revisions/latest/geojson")
        .await
        .json();
    assert_eq!(wgs["nrgdb:georef"]["lat"], -33.8568);
    assert_eq!(
        s.get("/maps/building").await.json()["georef"]["lon"],
        151.2153
    );
    let p = &wgs["features"][0]["geometry"]["coordinates"][0][0];
    let (lon, lat) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
    assert!(
        (lon - 151.2153).abs() < 0.01 && (lat + 33.8568).abs() < 0.01,
        "{p}"
    );
    // With heading 0 the model's x is east: the same vertex in metres.
    let q = &local["features"][0]["geometry"]["coordinates"][0][0];
    let x = q[0].as_f64().unwrap();
    let east = (lon - 151.2153).to_radians() * R * (-33.8568f64).to_radians().cos();
    assert!((east - x).abs() < 0.01 * x.abs().max(1.0), "{east} vs {x}");
    let again = s
        .get("/maps/building/revisions/latest/geojson?frame=local")
        .await
        .json();
    assert_eq!(again, local);
    let utm = s
        .get("/maps/building/revisions/latest/geojson?frame=utm")
        .await
        .json();
    assert_eq!(
        utm["crs"]["properties"]["name"],
        "urn:ogc:def:crs:EPSG::32756"
    );
    s.get("/maps/building/revisions/latest/geojson?frame=mercator")
        .await
        .assert_error(400, "frame");
    // IndoorGML of a georeferenced map is in its UTM zone, named.
    let gml = s.get("/maps/building/revisions/latest/indoorgml").await;
    assert!(
        gml.text()
            .contains(r#"srsName="urn:ogc:def:crs:EPSG::32756""#)
    );
    let gml = s
        .get("/maps/building/revisions/latest/indoorgml?frame=local")
        .await;
    assert!(!gml.text().contains("srsName"));
    s.get("/maps/building/revisions/latest/indoorgml?frame=wgs84")
        .await
        .assert_error(400, "frame");
    s.stop().await;
}

/// `export --crs utm`: the map's GeoJSON in its UTM zone with the CRS
/// named (checked against PROJ in `gdal_reads`); without a georeference,
/// or for a format other than GeoJSON, a clear error and no file.
#[test]
fn export_in_utm_names_its_zone_and_refuses_what_it_cannot_place() {
    let dir = tempfile::tempdir().unwrap();
    demo_db(dir.path());
    let export = |out: &str| {
        nrgdb(
            dir.path(),
            &[
                "export", "demo", "--out", out, "--crs", "utm", "--db", "t.sqlite",
            ],
        )
    };
    let err = export("u.geojson");
    assert!(!err.status.success());
    assert!(String::from_utf8_lossy(&err.stderr).contains("has no georeference"));
    assert!(!dir.path().join("u.geojson").exists());
    nrgdb_ok(
        dir.path(),
        &[
            "georef",
            "demo",
            "--origin",
            "-33.9,151.2",
            "--heading",
            "10",
            "--db",
            "t.sqlite",
        ],
    );
    let err = nrgdb(
        dir.path(),
        &[
            "export",
            "demo",
            "--out",
            "n.geojson",
            "--format",
            "nav2",
            "--crs",
            "utm",
            "--db",
            "t.sqlite",
        ],
    );
    assert!(String::from_utf8_lossy(&err.stderr).contains("--crs is for a model's GeoJSON"));
    assert!(!err.status.success() && !dir.path().join("n.geojson").exists());
    let err = nrgdb(
        dir.path(),
        &[
            "export", "demo", "--out", "w.gml", "--crs", "wgs84", "--db", "t.sqlite",
        ],
    );
    assert!(!err.status.success());
    let said = String::from_utf8_lossy(&err.stderr);
    assert!(
        said.contains("IndoorGML is written in local or utm"),
        "{said}"
    );
    assert!(!dir.path().join("w.gml").exists());
    assert!(export("u.geojson").status.success());
    let doc: Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("u.geojson")).unwrap()).unwrap();
    // Sydney lies in zone 56 south.
    assert_eq!(
        doc["crs"]["properties"]["name"],
        "urn:ogc:def:crs:EPSG::32756"
    );
    // Easting near 500 000 ± 330 km, northing near 10 000 km minus 3 750 km.
    let first = &doc["features"][0]["properties"]["anchor"];
    let (e, n) = (first[0].as_f64().unwrap(), first[1].as_f64().unwrap());
    assert!(
        (1.6e5..8.4e5).contains(&e) && (6.2e6..6.3e6).contains(&n),
        "{e} {n}"
    );
    // It reads back into the store as map-frame metres.
    let out = nrgdb(dir.path(), &["convert", "u.geojson", "back.json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
