//! IndoorGML in a real CRS: a georeferenced map's document written in the
//! WGS84 / UTM zone of its origin with that zone as `srsName`, and a
//! document in a UTM `srsName` read back into map-frame metres.
//!
//! A document nrgdb writes this way carries its georeference in the root
//! `gml:description` (`{"nrgdb:georef": {...}}`, the same JSON as the
//! GeoJSON member), so it reads back into the frame it came from. Every
//! position moves: cell and boundary geometry, state points, transition
//! lines and the doorway lines in door cells' descriptions; heights (z)
//! stay. `srsName`s nrgdb cannot place (a local CRS such as
//! `urn:ulol:def:crs:local-m`, another projection) are read as map-frame
//! metres, as before; a geographic `srsName` is refused, because its
//! degrees read as metres would make a building a few millimetres wide.

use serde_json::{Value, json};

use super::IndoorGmlError;
use super::document::{BoundaryGeometry, CellGeometry, Coords, Document, Polygon};
use crate::model::{Georef, NamedCrs, Point, UtmZone, lowest_corner};

use super::convert::DOORWAY_KEY;
use crate::model::GEOREF_KEY;

/// Moves `doc` (in map-frame metres) into the WGS84 / UTM zone of
/// `georef`'s origin: every position, `srsName` set to the zone's URN,
/// the georeference in the root description.
pub fn into_utm(doc: &mut Document, georef: &Georef) {
    let zone = UtmZone::of([georef.lon, georef.lat]);
    map_positions(doc, &|p| zone.forward(georef.to_lon_lat(p)));
    doc.srs_name = Some(zone.urn());
    doc.info.description = Some(json!({ GEOREF_KEY: georef }).to_string());
}

/// Moves a document read from a file into map-frame metres when its
/// `srsName` names a UTM zone, into the frame of `stored` (the map's
/// georeference), else of the georeference nrgdb wrote in it, else of one
/// made at the document's lowest corner with +y along grid north (see
/// [`NamedCrs::frame`]), and returns that georeference; the `srsName` is
/// cleared. A document without a placeable `srsName` is left as it is and
/// returns None.
pub fn into_map_frame(
    doc: &mut Document,
    stored: Option<&Georef>,
) -> Result<Option<Georef>, IndoorGmlError> {
    let Some(name) = doc.srs_name.clone() else {
        return Ok(None);
    };
    let crs_error = |why: String| IndoorGmlError::Crs {
        name: name.clone(),
        why,
    };
    let zone = match NamedCrs::parse(&name) {
        None => return Ok(None),
        Some(NamedCrs::Wgs84) => {
            return Err(crs_error(
                "geographic coordinates (degrees) are not read from IndoorGML; give the positions in a projected CRS such as WGS84 / UTM (EPSG:326zz)".into(),
            ));
        }
        Some(NamedCrs::Utm(zone)) => zone,
    };
    let carried = match doc.info.description.as_deref().map(carried_georef) {
        Some(Err(why)) => return Err(crs_error(why)),
        Some(Ok(g)) => g,
        None => None,
    };
    let low = std::cell::Cell::new([f64::INFINITY; 2]);
    map_positions(doc, &|p| {
        low.set(lowest_corner([low.get(), p]));
        p
    });
    let crs = NamedCrs::Utm(zone);
    let georef = crs
        .frame(stored, carried, lowest_corner([low.get()]), "0")
        .map_err(|e| crs_error(format!("the positions are not in this zone: {e}")))?;
    map_positions(doc, &|p| georef.to_map(crs.to_lon_lat(p)));
    doc.srs_name = None;
    if doc.info.description.as_deref().is_some_and(is_georef_only) {
        doc.info.description = None;
    }
    Ok(Some(georef))
}

/// The georeference in a root description nrgdb wrote; Ok(None) for a
/// description that is not ours.
fn carried_georef(description: &str) -> Result<Option<Georef>, String> {
    let Ok(Value::Object(obj)) = serde_json::from_str::<Value>(description) else {
        return Ok(None);
    };
    let Some(g) = obj.get(GEOREF_KEY) else {
        return Ok(None);
    };
    let g: Georef = serde_json::from_value(g.clone()).map_err(|e| format!("{GEOREF_KEY}: {e}"))?;
    g.checked()
        .map(Some)
        .map_err(|e| format!("{GEOREF_KEY}: {e}"))
}

fn is_georef_only(description: &str) -> bool {
    matches!(serde_json::from_str::<Value>(description),
        Ok(Value::Object(obj)) if obj.len() == 1 && obj.contains_key(GEOREF_KEY))
}

/// Applies `f` to the x and y of every position in `doc` (see the module
/// docs for which).
fn map_positions(doc: &mut Document, f: &dyn Fn(Point) -> Point) {
    let coords = |c: &mut Coords| {
        let dim = c.dim.max(2);
        for p in c.values.chunks_exact_mut(dim) {
            let [x, y] = f([p[0], p[1]]);
            p[0] = x;
            p[1] = y;
        }
    };
    let polygon = |p: &mut Polygon| {
        coords(&mut p.exterior);
        p.interiors.iter_mut().for_each(coords);
    };
    if let Some(primal) = &mut doc.primal {
        for cell in &mut primal.cells {
            match &mut cell.geometry {
                Some(CellGeometry::Surface(p)) => polygon(p),
                Some(CellGeometry::Solid(s)) => {
                    s.exterior.iter_mut().for_each(polygon);
                    s.interiors.iter_mut().flatten().for_each(polygon);
                }
                None => {}
            }
            if let Some(d) = &mut cell.info.description {
                map_doorway_line(d, f);
            }
        }
        for b in &mut primal.boundaries {
            match &mut b.geometry {
                Some(BoundaryGeometry::Curve(l)) => coords(&mut l.coords),
                Some(BoundaryGeometry::Surface(p)) => polygon(p),
                None => {}
            }
        }
    }
    if let Some(graph) = &mut doc.graph {
        for layer in graph.layer_groups.iter_mut().flat_map(|g| &mut g.layers) {
            for s in &mut layer.states {
                if let Some(p) = &mut s.point {
                    coords(&mut p.coords);
                }
            }
            for t in &mut layer.transitions {
                if let Some(l) = &mut t.geometry {
                    coords(&mut l.coords);
                }
            }
        }
    }
}

/// Moves the doorway line in a door cell's description, when it has one.
fn map_doorway_line(description: &mut String, f: &dyn Fn(Point) -> Point) {
    let Ok(Value::Object(mut obj)) = serde_json::from_str::<Value>(description) else {
        return;
    };
    let Some(line) = obj.get_mut(DOORWAY_KEY).and_then(|d| d.get_mut("line")) else {
        return;
    };
    let Ok(points) = serde_json::from_value::<[Point; 2]>(line.clone()) else {
        return;
    };
    *line = json!(points.map(f));
    *description = Value::Object(obj).to_string();
}

#[cfg(test)]
mod tests {
    use super::*;

    fn office() -> Document {
        super::super::from_nrg(&crate::fixtures::corridor_building(3))
    }

    #[test]
    fn a_document_goes_to_utm_and_back_within_a_micrometre() {
        let g = Georef::new(48.137, 11.575, 25.0, "2").unwrap();
        let original = office();
        let mut doc = original.clone();
        into_utm(&mut doc, &g);
        assert_eq!(doc.srs_name.as_deref(), Some("urn:ogc:def:crs:EPSG::32632"));
        let cell = |d: &Document| match &d.cells()[0].geometry {
            Some(CellGeometry::Surface(p)) => p.exterior.xy().collect::<Vec<_>>(),
            other => panic!("{other:?}"),
        };
        // Munich is about 691 km east and 5 334 km north in zone 32.
        let [e, n] = cell(&doc)[0];
        assert!((690_000.0..693_000.0).contains(&e) && (5_333_000.0..5_336_000.0).contains(&n));
        let got = into_map_frame(&mut doc, None).unwrap();
        assert_eq!(got, Some(g));
        assert_eq!(doc.srs_name, None);
        for (a, b) in cell(&doc).iter().zip(cell(&original)) {
            assert!(
                (a[0] - b[0]).abs() < 1e-6 && (a[1] - b[1]).abs() < 1e-6,
                "{a:?} {b:?}"
            );
        }
        assert_eq!(doc.info.description, original.info.description);
    }

    #[test]
    fn a_local_srs_name_is_left_alone_and_degrees_are_refused() {
        let mut doc = office();
        doc.srs_name = Some("urn:ulol:def:crs:local-m".into());
        let before = doc.clone();
        assert_eq!(into_map_frame(&mut doc, None).unwrap(), None);
        assert_eq!(doc, before);
        doc.srs_name = Some("EPSG:4326".into());
        let err = into_map_frame(&mut doc, None).unwrap_err().to_string();
        assert!(
            err.contains("EPSG:4326") && err.contains("projected"),
            "{err}"
        );
    }
}
