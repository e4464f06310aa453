//! Issue 24: our GeoJSON and OpenStreetMap files as GDAL reads them (GDAL
//! is what QGIS opens vector files with; `ogrinfo` from Debian's
//! `gdal-bin`). Checked against the model, not against our own reader:
//! GDAL must read every feature without a warning, give each its fields
//! with one type, place a georeferenced file where the georeference says,
//! and find every space and door of the OpenStreetMap file by its tags.
//! Skips with a notice when `ogrinfo` is missing, unless
//! `NRGDB_REQUIRE_SHARED=1` (CI installs it).

use std::collections::BTreeSet;
use std::path::Path;
use std::process::Command;

use nrgdb::format::osm::to_osm_xml;
use nrgdb::format::{ModelFormat, render, render_geojson_wgs84};
use nrgdb::model::{Georef, Nrg, SpaceKind};
use nrgdb::route::walked_model;

/// `ogrinfo ARGS…` (stdout, stderr), or None when GDAL is not here.
fn ogrinfo(args: &[&str]) -> Option<(String, String)> {
    match Command::new("ogrinfo").args(args).output() {
        Ok(out) => {
            assert!(
                out.status.success(),
                "ogrinfo {args:?}: {}",
                String::from_utf8_lossy(&out.stderr)
            );
            Some((
                String::from_utf8_lossy(&out.stdout).into_owned(),
                String::from_utf8_lossy(&out.stderr).into_owned(),
            ))
        }
        Err(_) if std::env::var("NRGDB_REQUIRE_SHARED").as_deref() == Ok("1") => {
            panic!("NRGDB_REQUIRE_SHARED=1 but ogrinfo (gdal-bin) is missing")
        }
        Err(_) => {
            eprintln!("notice: skipping, ogrinfo (gdal-bin) not found");
            None
        }
    }
}

fn model() -> Nrg {
    nrgdb::fixtures::corridor_building(6)
}

/// `[min x, min y, max x, max y]` of every space's outline, in metres.
fn bounds(nrg: &Nrg) -> [f64; 4] {
    let points = nrg.spaces().iter().flat_map(|s| s.polygon.iter());
    points.fold([f64::MAX, f64::MAX, f64::MIN, f64::MIN], |b, p| {
        [
            b[0].min(p[0]),
            b[1].min(p[1]),
            b[2].max(p[0]),
            b[3].max(p[1]),
        ]
    })
}

/// The `name (Type)` lines of `ogrinfo -so`'s field list.
fn fields(summary: &str) -> BTreeSet<String> {
    summary
        .lines()
        .filter_map(|l| l.split_once(": "))
        .filter(|(name, ty)| !name.starts_with(' ') && ty.contains("(0.0)"))
        .map(|(name, ty)| format!("{name}: {}", ty.trim_end_matches(" (0.0)")))
        .collect()
}

/// `Extent: (x0, y0) - (x1, y1)` of `ogrinfo -so`.
fn extent(summary: &str) -> [f64; 4] {
    let line = summary
        .lines()
        .find_map(|l| l.strip_prefix("Extent: "))
        .expect("an extent");
    let n: Vec<f64> = line
        .split(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-'))
        .filter(|s| !s.is_empty() && *s != "-")
        .map(|s| s.parse().unwrap())
        .collect();
    [n[0], n[1], n[2], n[3]]
}

fn feature_count(summary: &str) -> usize {
    summary
        .lines()
        .find_map(|l| l.strip_prefix("Feature Count: "))
        .expect("a feature count")
        .trim()
        .parse()
        .unwrap()
}

fn geojson_summary(dir: &Path, name: &str, text: &str) -> Option<String> {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    let path = path.display().to_string();
    let layer = name.trim_end_matches(".geojson");
    let (out, err) = ogrinfo(&["-so", &path, layer])?;
    assert!(
        !err.contains("Warning") && !err.contains("ERROR"),
        "{name}: {err}"
    );
    Some(out)
}

#[test]
fn gdal_reads_our_geojson_with_one_type_per_field_and_every_feature() {
    let dir = tempfile::tempdir().unwrap();
    let nrg = model();
    let walked = walked_model(&nrg);
    let text = render(&walked, ModelFormat::GeoJson);
    let Some(summary) = geojson_summary(dir.path(), "local.geojson", &text) else {
        return;
    };
    assert_eq!(
        feature_count(&summary),
        nrg.spaces().len() + nrg.connections().len()
    );
    let f = fields(&summary);
    for want in [
        "id: String",
        "space_id: Integer",
        "a: Integer",
        "b: Integer",
        "kind: String",
        "length_m: Real",
        "width_m: Real",
    ] {
        assert!(f.contains(want), "{want} not in {f:?}");
    }
    // The extent is the model's, in metres.
    let [x0, y0, x1, y1] = bounds(&nrg);
    let e = extent(&summary);
    for (got, want) in e.iter().zip([x0, y0, x1, y1]) {
        assert!(
            (got - want).abs() < 1e-6,
            "extent {e:?}, model [{x0}, {y0}, {x1}, {y1}]"
        );
    }
}

#[test]
fn gdal_places_a_georeferenced_geojson_at_its_origin() {
    let dir = tempfile::tempdir().unwrap();
    let nrg = model();
    // Heading 0: +x east, +y north.
    let georef = Georef::new(48.137, 11.575, 0.0, "0").unwrap();
    let text = render_geojson_wgs84(&walked_model(&nrg), &georef);
    let Some(summary) = geojson_summary(dir.path(), "wgs84.geojson", &text) else {
        return;
    };
    assert!(summary.contains("ID[\"EPSG\",4326]"), "{summary}");
    let [lon0, lat0, lon1, lat1] = extent(&summary);
    // Metres per degree at 48.137° N on WGS84 (meridian and parallel
    // radii of curvature), computed here.
    let (a, e2) = (6_378_137.0_f64, 0.006_694_379_990_14_f64);
    let phi = 48.137_f64.to_radians();
    let w = (1.0 - e2 * phi.sin().powi(2)).sqrt();
    let m_lat = a * (1.0 - e2) / w.powi(3) * std::f64::consts::PI / 180.0;
    let m_lon = a / w * phi.cos() * std::f64::consts::PI / 180.0;
    let [x0, y0, x1, y1] = bounds(&nrg);
    // ogrinfo prints the extent to 1e-6°: up to 0.056 m of rounding.
    let edges = [
        ("west", lon0 - 11.575, x0, m_lon),
        ("east", lon1 - 11.575, x1, m_lon),
        ("south", lat0 - 48.137, y0, m_lat),
        ("north", lat1 - 48.137, y1, m_lat),
    ];
    for (edge, deg, metres, per) in edges {
        assert!(
            (deg * per - metres).abs() < 0.06,
            "{edge} edge {deg}° from the origin, model {metres} m"
        );
    }
}

#[test]
fn gdal_finds_every_space_and_door_of_our_openstreetmap_file() {
    let dir = tempfile::tempdir().unwrap();
    let nrg = model();
    let georef = Georef::new(48.137, 11.575, 30.0, "2").unwrap();
    let path = dir.path().join("building.osm");
    std::fs::write(&path, to_osm_xml(&nrg, &georef)).unwrap();
    let path = path.display().to_string();
    // New objects have negative ids (as JOSM writes them); GDAL's default
    // node index takes only positive ones.
    let read = |layer: &str| {
        ogrinfo(&[
            "--config",
            "OSM_USE_CUSTOM_INDEXING",
            "NO",
            "-q",
            &path,
            layer,
        ])
        .map(|(out, err)| {
            assert!(
                !err.contains("ERROR") && !err.contains("Warning"),
                "{layer}: {err}"
            );
            out
        })
    };
    let Some(points) = read("points") else {
        return;
    };
    let areas = read("lines").unwrap() + &read("multipolygons").unwrap();
    // `"nrgdb:id"=>"7"` in each feature's other_tags.
    let ids = |text: &str, tag: &str| -> BTreeSet<u32> {
        text.lines()
            .filter(|l| l.contains(tag))
            .filter_map(|l| l.split("\"nrgdb:id\"=>\"").nth(1))
            .filter_map(|rest| rest.split('"').next()?.parse().ok())
            .collect()
    };
    let doors: BTreeSet<u32> = nrg
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Door)
        .map(|s| s.id.0)
        .collect();
    let others: BTreeSet<u32> = nrg
        .spaces()
        .iter()
        .filter(|s| s.kind != SpaceKind::Door)
        .map(|s| s.id.0)
        .collect();
    assert!(!doors.is_empty());
    assert_eq!(ids(&points, "\"door\"=>"), doors);
    assert_eq!(ids(&areas, "\"indoor\"=>"), others);
    assert!(
        areas
            .lines()
            .filter(|l| l.contains("\"indoor\"=>"))
            .all(|l| l.contains("\"level\"=>\"2\""))
    );
}

/// Every coordinate of a file, in order.
fn coordinates(doc: &serde_json::Value) -> Vec<[f64; 2]> {
    fn walk(v: &serde_json::Value, out: &mut Vec<[f64; 2]>) {
        match v.as_array().map(Vec::as_slice) {
            Some([x, y]) if x.is_number() && y.is_number() => {
                out.push([x.as_f64().unwrap(), y.as_f64().unwrap()])
            }
            Some(items) => items.iter().for_each(|i| walk(i, out)),
            None => {}
        }
    }
    let mut out = Vec::new();
    for f in doc["features"].as_array().unwrap() {
        walk(&f["geometry"]["coordinates"], &mut out);
    }
    out
}

/// UTM output (`export --crs utm`): GDAL names its CRS EPSG:32632, and
/// PROJ (through `ogr2ogr`), projecting our WGS84 file into that zone,
/// finds every coordinate within a millimetre of ours. The file reads back
/// to the model's map-frame metres.
#[test]
fn gdal_reads_our_utm_geojson_where_proj_puts_it() {
    let dir = tempfile::tempdir().unwrap();
    let nrg = model();
    let georef = Georef::new(48.137, 11.575, 30.0, "0").unwrap();
    let walked = walked_model(&nrg);
    let utm = nrgdb::format::render_geojson_utm(&walked, &georef);
    let Some(summary) = geojson_summary(dir.path(), "utm.geojson", &utm) else {
        return;
    };
    assert!(summary.contains("ID[\"EPSG\",32632]"), "{summary}");
    let wgs = dir.path().join("wgs.geojson");
    std::fs::write(&wgs, render_geojson_wgs84(&walked, &georef)).unwrap();
    let projected = dir.path().join("projected.geojson");
    let out = Command::new("ogr2ogr")
        .args([
            "-f",
            "GeoJSON",
            "-t_srs",
            "EPSG:32632",
            "-lco",
            "COORDINATE_PRECISION=6",
        ])
        .arg(&projected)
        .arg(&wgs)
        .output()
        .expect("ogr2ogr comes with ogrinfo");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let theirs: serde_json::Value =
        serde_json::from_slice(&std::fs::read(&projected).unwrap()).unwrap();
    let ours: serde_json::Value = serde_json::from_str(&utm).unwrap();
    let (a, b) = (coordinates(&ours), coordinates(&theirs));
    assert_eq!(a.len(), b.len());
    let worst = a
        .iter()
        .zip(&b)
        .map(|(p, q)| (p[0] - q[0]).hypot(p[1] - q[1]))
        .fold(0.0, f64::max);
    eprintln!(
        "{} coordinates: ours and PROJ's differ by up to {worst} m",
        a.len()
    );
    assert!(worst < 1e-3, "ours and PROJ's differ by up to {worst} m");
    // Back to map-frame metres.
    let back = nrgdb::geojson::from_geojson(&utm).unwrap();
    for (s, t) in nrg.spaces().iter().zip(back.spaces()) {
        for (p, q) in s.polygon.iter().zip(&t.polygon) {
            assert!(
                (p[0] - q[0]).hypot(p[1] - q[1]) < 1e-3,
                "{p:?} read back as {q:?}"
            );
        }
    }
}
