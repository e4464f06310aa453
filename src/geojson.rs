//! The model as GeoJSON: a FeatureCollection that QGIS and web maps open.
//!
//! Each space is a Polygon feature (`"feature": "space"`, properties `id`,
//! `kind`, `name`, `area_m2`, `anchor`, `attributes`, and for a door
//! `width_m` and `doorway`, its doorway line `[[x, y], [x, y]]`: see
//! [`doorway`](crate::model::doorway())); each connection is a
//! LineString feature (`"feature": "connection"`, properties `a`, `b`,
//! `kind`, `length_m`) from `a`'s anchor to `b`'s: the walked polyline
//! through the doorway when the caller passes one ([`to_geojson_with_paths`],
//! with `length_m` its length), else the straight segment. Coordinates are metres in the
//! map frame, not WGS84 (GeoJSON's default CRS): load the file as a
//! projected layer in QGIS. A georeferenced map is written in WGS84
//! longitude and latitude instead ([`to_wgs84`], RFC 7946), which QGIS
//! and web maps place without hand work. Reading accepts exactly these
//! shapes back.

use serde_json::{Map, Value, json};

use crate::model::{
    Connection, ConnectionPaths, Georef, NamedCrs, Nrg, Point, Ring, Space, SpaceId, UtmZone,
    doorway, lowest_corner,
};

/// Why a GeoJSON document is not an nrgdb model.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum GeoJsonError {
    /// Not JSON at all.
    #[error("not JSON: {0}")]
    Json(#[from] serde_json::Error),
    /// A feature lacks something or has the wrong shape.
    #[error("feature {index}: {message}")]
    Feature {
        /// Position in `features`.
        index: usize,
        /// What is wrong.
        message: String,
    },
    /// The features do not form a valid model.
    #[error("{0}")]
    Model(#[from] crate::model::ModelError),
}

/// The model as a GeoJSON FeatureCollection, connections as straight
/// lines between the anchors.
pub fn to_geojson(nrg: &Nrg) -> Value {
    to_geojson_with_paths(nrg, &ConnectionPaths::new())
}

/// The model as a GeoJSON FeatureCollection, each connection drawn as its
/// polyline in `paths` when it has one (from `a`'s anchor to `b`'s). The
/// `length_m` property is the model's: pass a model whose lengths are the
/// paths' (`route::walked_model` gives both).
pub fn to_geojson_with_paths(nrg: &Nrg, paths: &ConnectionPaths) -> Value {
    let mut features = Vec::with_capacity(nrg.spaces().len() + nrg.connections().len());
    for s in nrg.spaces() {
        let rings: Vec<Value> = std::iter::once(&s.polygon)
            .chain(&s.holes)
            .map(|r| closed(r))
            .collect();
        let mut properties = json!({
            "feature": "space",
            "space_id": s.id,
            "kind": s.kind,
            "name": s.name,
            "area_m2": s.area_m2,
            "anchor": s.anchor,
            "attributes": s.attributes,
        });
        if let (Some(d), Some(p)) = (doorway(s), properties.as_object_mut()) {
            p.insert("width_m".into(), json!(d.width_m));
            p.insert("doorway".into(), json!(d.line));
        }
        features.push(json!({
            "type": "Feature",
            "id": format!("space-{}", s.id),
            "geometry": {"type": "Polygon", "coordinates": rings},
            "properties": properties,
        }));
    }
    for c in nrg.connections() {
        let (Some(a), Some(b)) = (nrg.space(c.a), nrg.space(c.b)) else {
            continue;
        };
        features.push(json!({
            "type": "Feature",
            "id": format!("connection-{}-{}", c.a, c.b),
            "geometry": {"type": "LineString", "coordinates": line(paths.get(&c.key()), c, a.anchor, b.anchor)},
            "properties": {"feature": "connection", "a": c.a, "b": c.b, "kind": c.kind, "length_m": c.length_m}
        }));
    }
    json!({"type": "FeatureCollection", "features": features})
}

/// A connection's line from `a`'s anchor to `b`'s: its path (stored from
/// the smaller id) when it has two points or more, else the segment.
fn line(path: Option<&Vec<Point>>, c: &Connection, a: Point, b: Point) -> Value {
    match path {
        Some(p) if p.len() >= 2 => {
            let mut pts = p.clone();
            if c.key().0 != c.a {
                pts.reverse();
            }
            json!(pts)
        }
        _ => json!([a, b]),
    }
}

fn closed(ring: &[Point]) -> Value {
    let mut pts: Vec<Point> = ring.to_vec();
    if let Some(&first) = pts.first() {
        pts.push(first);
    }
    json!(pts)
}

/// The member a WGS84 document carries its georeference in, so that it
/// reads back into map-frame metres.
pub const GEOREF_MEMBER: &str = crate::model::GEOREF_KEY;

/// `doc` (as [`to_geojson_with_paths`] writes it) in WGS84 longitude and
/// latitude (RFC 7946), placed by `georef`: every geometry's coordinates
/// and the `anchor` and `doorway` properties. Lengths and areas stay
/// metres. The georeference is kept in the member [`GEOREF_MEMBER`].
pub fn to_wgs84(mut doc: Value, georef: &Georef) -> Value {
    map_positions(&mut doc, &|p| georef.to_lon_lat(p));
    if let Some(obj) = doc.as_object_mut() {
        obj.insert(GEOREF_MEMBER.into(), json!(georef));
    }
    doc
}

/// `doc` (as [`to_geojson_with_paths`] writes it) in the WGS84 / UTM zone
/// of `georef`'s origin (see [`UtmZone`]), in metres, with the CRS named
/// in a `crs` member (`urn:ogc:def:crs:EPSG::326zz`), which GDAL and so
/// QGIS read: every geometry's coordinates and the `anchor` and `doorway`
/// properties. The georeference rides along in [`GEOREF_MEMBER`], so the
/// file reads back to map-frame metres. Not RFC 7946 (which allows WGS84
/// only): the older GeoJSON 2008 `crs` member.
pub fn to_utm(mut doc: Value, georef: &Georef) -> Value {
    let zone = UtmZone::of([georef.lon, georef.lat]);
    map_positions(&mut doc, &|p| zone.forward(georef.to_lon_lat(p)));
    if let Some(obj) = doc.as_object_mut() {
        obj.insert(
            "crs".into(),
            json!({"type": "name", "properties": {"name": zone.urn()}}),
        );
        obj.insert(GEOREF_MEMBER.into(), json!(georef));
    }
    doc
}

/// The CRS a `crs` member names (None without one), or an error naming a
/// CRS this reader cannot place.
fn named_crs(doc: &Value) -> Result<Option<NamedCrs>, GeoJsonError> {
    let Some(crs) = doc.get("crs") else {
        return Ok(None);
    };
    let name = crs
        .pointer("/properties/name")
        .and_then(Value::as_str)
        .unwrap_or("");
    match NamedCrs::parse(name) {
        Some(c) => Ok(Some(c)),
        None => Err(GeoJsonError::Feature {
            index: 0,
            message: format!(
                "crs {name:?}: only WGS84 (CRS84, EPSG:4326) and WGS84 / UTM (EPSG:326zz, 327zz) are read"
            ),
        }),
    }
}

/// Applies `f` to every position of every feature: geometry coordinates
/// (any nesting) and the `anchor` and `doorway` properties.
fn map_positions(doc: &mut Value, f: &dyn Fn(Point) -> Point) {
    fn walk(v: &mut Value, f: &dyn Fn(Point) -> Point) {
        let Some(items) = v.as_array_mut() else {
            return;
        };
        if let [Value::Number(x), Value::Number(y)] = items.as_slice()
            && let (Some(x), Some(y)) = (x.as_f64(), y.as_f64())
        {
            let [a, b] = f([x, y]);
            *v = json!([a, b]);
            return;
        }
        for item in items {
            walk(item, f);
        }
    }
    let Some(features) = doc.get_mut("features").and_then(Value::as_array_mut) else {
        return;
    };
    for feature in features {
        if let Some(c) = feature.pointer_mut("/geometry/coordinates") {
            walk(c, f);
        }
        for key in ["/properties/anchor", "/properties/doorway"] {
            if let Some(p) = feature.pointer_mut(key) {
                walk(p, f);
            }
        }
    }
}

/// Reads a FeatureCollection written by [`to_geojson`] (or in WGS84 by
/// [`to_wgs84`], or in UTM by [`to_utm`]: its positions are taken back to
/// map-frame metres). See [`from_geojson_in`] for files in a CRS.
pub fn from_geojson(text: &str) -> Result<Nrg, GeoJsonError> {
    from_geojson_in(text, None).map(|(nrg, _)| nrg)
}

/// Reads a FeatureCollection as [`from_geojson`] does, into the frame of
/// the map it goes to, and says which georeference placed it.
///
/// A file in a CRS (a `crs` member naming WGS84 or a UTM zone, or the
/// [`GEOREF_MEMBER`] that [`to_wgs84`] writes) is read into the frame of
/// `stored` (the map's georeference, so that revisions share one frame),
/// else of the georeference the file carries, else of one made at the
/// file's lowest corner with +y along the CRS's north (see
/// [`NamedCrs::frame`]); that georeference is returned. A file without a
/// CRS is map-frame metres and returns None.
pub fn from_geojson_in(
    text: &str,
    stored: Option<&Georef>,
) -> Result<(Nrg, Option<Georef>), GeoJsonError> {
    let mut value: Value = serde_json::from_str(text)?;
    let at_member = |e: String| GeoJsonError::Feature {
        index: 0,
        message: format!("{GEOREF_MEMBER}: {e}"),
    };
    let carried = match value.get(GEOREF_MEMBER) {
        Some(g) => {
            let g: Georef =
                serde_json::from_value(g.clone()).map_err(|e| at_member(e.to_string()))?;
            Some(g.checked().map_err(|e| at_member(e.to_string()))?)
        }
        None => None,
    };
    // `to_wgs84` writes no `crs` member (RFC 7946 has none).
    let crs = named_crs(&value)?.or(carried.as_ref().map(|_| NamedCrs::Wgs84));
    let mut placed = None;
    if let Some(crs) = crs {
        let low = std::cell::Cell::new([f64::INFINITY; 2]);
        map_positions(&mut value, &|p| {
            low.set(lowest_corner([low.get(), p]));
            p
        });
        let corner = lowest_corner([low.get()]);
        let g = crs
            .frame(stored, carried, corner, "0")
            .map_err(|e| GeoJsonError::Feature {
                index: 0,
                message: format!("placing the file's positions: {e}"),
            })?;
        map_positions(&mut value, &|p| g.to_map(crs.to_lon_lat(p)));
        placed = Some(g);
    }
    let features =
        value
            .get("features")
            .and_then(Value::as_array)
            .ok_or(GeoJsonError::Feature {
                index: 0,
                message: "not a FeatureCollection (no \"features\" array)".into(),
            })?;
    let mut spaces = Vec::new();
    let mut connections = Vec::new();
    for (index, f) in features.iter().enumerate() {
        let err = |message: String| GeoJsonError::Feature { index, message };
        let props = f
            .get("properties")
            .and_then(Value::as_object)
            .ok_or_else(|| err("has no properties".into()))?;
        match props.get("feature").and_then(Value::as_str) {
            Some("space") => spaces.push(space(f, props).map_err(err)?),
            Some("connection") => {
                let c: Connection = serde_json::from_value(Value::Object(props.clone()))
                    .map_err(|e| err(e.to_string()))?;
                connections.push(c);
            }
            other => {
                return Err(err(format!(
                    "property \"feature\" is {other:?}, expected \"space\" or \"connection\""
                )));
            }
        }
    }
    Ok((Nrg::new(spaces, connections)?, placed))
}

fn space(f: &Value, props: &Map<String, Value>) -> Result<Space, String> {
    let field = |k: &str| {
        props
            .get(k)
            .cloned()
            .ok_or_else(|| format!("has no property \"{k}\""))
    };
    // `space_id`; files written before it was named so say `id`.
    let (key, value) = ["space_id", "id"]
        .into_iter()
        .find_map(|k| props.get(k).map(|v| (k, v)))
        .ok_or("has no property \"space_id\"")?;
    let id: SpaceId = serde_json::from_value(value.clone()).map_err(|e| format!("{key}: {e}"))?;
    let kind = serde_json::from_value(field("kind")?).map_err(|e| format!("kind: {e}"))?;
    let anchor: Point =
        serde_json::from_value(field("anchor")?).map_err(|e| format!("anchor: {e}"))?;
    let geometry = f.get("geometry").ok_or("has no geometry")?;
    if geometry.get("type").and_then(Value::as_str) != Some("Polygon") {
        return Err("a space's geometry must be a Polygon".into());
    }
    let rings: Vec<Ring> =
        serde_json::from_value(geometry.get("coordinates").cloned().unwrap_or(Value::Null))
            .map_err(|e| format!("coordinates: {e}"))?;
    let mut rings = rings.into_iter().map(|mut r| {
        if r.len() > 1 && r.first() == r.last() {
            r.pop();
        }
        r
    });
    let polygon = rings.next().ok_or("polygon has no rings")?;
    let mut s = Space::new(id, kind, anchor, polygon);
    s.holes = rings.collect();
    s.name = props
        .get("name")
        .and_then(Value::as_str)
        .map(str::to_string);
    if let Some(Value::Object(a)) = props.get("attributes") {
        s.attributes = a.clone();
    }
    if let Some(line) = props.get("doorway").filter(|v| !v.is_null()) {
        let line: [Point; 2] =
            serde_json::from_value(line.clone()).map_err(|e| format!("doorway: {e}"))?;
        s.doorway = Some(line);
    }
    s.update_area();
    s.update_doorway();
    Ok(s)
}
