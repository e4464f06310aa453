//! IndoorJSON2: the JSON encoding of the IndoorGML 2.0 **draft** (the
//! OGC IndoorGML SWG's `indoorjson2.schema.json`, "IndoorJSON2 v0.1",
//! repository opengeospatial/IndoorGML-SWG, `IndoorGML2/.../Part II/JSON`).
//! The draft is not an OGC standard and may change; files say
//! `"type": "IndoorJSON2", "version": "0.1"`.
//!
//! Owns the mapping between the model and that encoding, both ways. One
//! `ThematicLayer` (`"theme": "Topographic"`) holds the primal space (one
//! `CellSpace` per space, its footprint a one-surface `CompositeSurface`
//! whose rings index the shared `vertices`, z = 0) and the dual space (one
//! `Node` per space at its anchor, one `Edge` per connection with the
//! walked length as `weight` and the walked path as its `Curve`). The
//! model's words the draft has no field for travel in `attributes`: a
//! cell's `nrgdb:kind` (room, corridor, door, other) and `nrgdb:doorway`,
//! and, on the `CellBoundary` an edge is dual to, `nrgdb:connection`
//! (door, open, adjacent). Walked paths are passed in; this module knows
//! nothing of routing.

use std::collections::{BTreeMap, HashMap};

use serde_json::{Map, Value, json};

use crate::model::{
    Connection, ConnectionKind, ConnectionPaths, Nrg, Point, Ring, Space, SpaceId, SpaceKind,
    pole_of_inaccessibility,
};

/// The draft's document type.
pub const DOC_TYPE: &str = "IndoorJSON2";
/// The draft version nrgdb writes (and the major version it reads).
pub const DRAFT_VERSION: &str = "0.1";
/// The one layer nrgdb writes.
const LAYER: &str = "nrg";
const KIND: &str = "nrgdb:kind";
const DOORWAY: &str = "nrgdb:doorway";
const CONNECTION: &str = "nrgdb:connection";
/// Vertices above this count are refused (a model has far fewer).
pub const MAX_VERTICES: usize = 50_000_000;

/// Why an IndoorJSON2 text is not a model.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Json2Error {
    /// Not JSON.
    #[error("line {line}, column {column}: not JSON: {message}")]
    Syntax {
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What the parser said.
        message: String,
    },
    /// An element is missing, of the wrong type or inconsistent.
    #[error("{path}: {message}")]
    Invalid {
        /// JSON path of the element (`$.layers.nrg.dualSpace.edgeMember.E1.weight`).
        path: String,
        /// What is wrong.
        message: String,
    },
    /// The elements are readable but are no valid model.
    #[error("not a valid model: {0}")]
    Model(String),
}

fn invalid(path: &str, message: impl Into<String>) -> Json2Error {
    Json2Error::Invalid {
        path: path.to_string(),
        message: message.into(),
    }
}

fn cell_id(id: SpaceId) -> String {
    format!("C{id}")
}

fn node_id(id: SpaceId) -> String {
    format!("N{id}")
}

/// Shared vertices, each stored once (by its bits).
#[derive(Default)]
struct Vertices {
    list: Vec<Value>,
    index: HashMap<[u64; 2], usize>,
}

impl Vertices {
    fn add(&mut self, p: Point) -> usize {
        let key = [p[0].to_bits(), p[1].to_bits()];
        *self.index.entry(key).or_insert_with(|| {
            self.list.push(json!([p[0], p[1], 0.0]));
            self.list.len() - 1
        })
    }

    fn ring(&mut self, ring: &[Point]) -> Vec<usize> {
        ring.iter().map(|&p| self.add(p)).collect()
    }
}

/// The model as IndoorJSON2 text; `paths` are the walked polylines of the
/// connections by [`Connection::key`] (a connection without one gets the
/// straight line between the anchors).
pub fn write_string(nrg: &Nrg, paths: &ConnectionPaths) -> String {
    let mut v = Vertices::default();
    let mut cells = Map::new();
    let mut nodes = Map::new();
    let mut edges_of: BTreeMap<SpaceId, Vec<Value>> = BTreeMap::new();
    let mut edges = Map::new();
    let mut boundaries = Map::new();
    for c in nrg.connections() {
        let (a, b) = c.key();
        let edge = format!("E{a}-{b}");
        let boundary = format!("B{a}-{b}");
        let line = match paths.get(&(a, b)) {
            Some(p) if p.len() >= 2 => v.ring(p),
            _ => {
                let ends = [nrg.space(a), nrg.space(b)];
                ends.iter().flatten().map(|s| v.add(s.anchor)).collect()
            }
        };
        edges.insert(
            edge.clone(),
            json!({
                "type": "Edge",
                "duality": boundary,
                "weight": c.length_m,
                "geometry": {"type": "Curve", "boundaries": line},
                "connects": [node_id(a), node_id(b)],
            }),
        );
        boundaries.insert(
            boundary,
            json!({
                "type": "CellBoundary",
                "isVirtual": c.kind != ConnectionKind::Door,
                "duality": edge,
                "attributes": {CONNECTION: c.kind.as_str()},
            }),
        );
        edges_of.entry(a).or_default().push(json!(edge));
        edges_of.entry(b).or_default().push(json!(edge));
    }
    for s in nrg.spaces() {
        let mut rings = vec![json!(v.ring(&s.polygon))];
        rings.extend(s.holes.iter().map(|h| json!(v.ring(h))));
        let mut attributes = s.attributes.clone();
        let level = attributes.remove("level");
        attributes.insert(KIND.into(), json!(s.kind.as_str()));
        if let Some(d) = s.doorway {
            attributes.insert(DOORWAY.into(), json!(d));
        }
        let mut cell = json!({
            "type": "CellSpace",
            "poi": false,
            "duality": node_id(s.id),
            "cellSpaceGeom": {"type": "CompositeSurface", "boundaries": [rings]},
            "attributes": attributes,
        });
        if let Some(obj) = cell.as_object_mut() {
            if let Some(name) = &s.name {
                obj.insert("name".into(), json!(name));
            }
            match level {
                Some(Value::String(l)) => {
                    obj.insert("level".into(), json!(l));
                }
                Some(other) => {
                    if let Some(Value::Object(a)) = obj.get_mut("attributes") {
                        a.insert("level".into(), other);
                    }
                }
                None => {}
            }
        }
        cells.insert(cell_id(s.id), cell);
        nodes.insert(
            node_id(s.id),
            json!({
                "type": "Node",
                "duality": cell_id(s.id),
                "geometry": {"type": "Point", "boundaries": v.add(s.anchor)},
                "connects": edges_of.remove(&s.id).unwrap_or_default(),
            }),
        );
    }
    let doc = json!({
        "type": DOC_TYPE,
        "version": DRAFT_VERSION,
        "layers": {
            LAYER: {
                "type": "ThematicLayer",
                "semanticExtension": false,
                "theme": "Topographic",
                "primalSpace": {"cellSpaceMember": cells, "cellBoundaryMember": boundaries},
                "dualSpace": {"isLogical": false, "nodeMember": nodes, "edgeMember": edges},
            }
        },
        "layerConnections": [],
        "vertices": v.list,
    });
    serde_json::to_string_pretty(&doc).unwrap_or_default() + "\n"
}

/// Whether JSON text declares itself IndoorJSON2 (its top-level `type`).
pub fn is_indoorjson2_type(value: Option<&str>) -> bool {
    value == Some(DOC_TYPE)
}

/// Reads IndoorJSON2 text into a model. Nodes without a point get the
/// pole of inaccessibility of their cell; edges may name their nodes or
/// (as the draft's example does) their cells in `connects`.
pub fn read_str(text: &str) -> Result<Nrg, Json2Error> {
    let root: Value = serde_json::from_str(text).map_err(|e| Json2Error::Syntax {
        line: e.line(),
        column: e.column(),
        message: e.to_string(),
    })?;
    let root = object(&root, "$")?;
    match root.get("type").and_then(Value::as_str) {
        Some(DOC_TYPE) => {}
        other => {
            return Err(invalid(
                "$.type",
                format!("expected \"{DOC_TYPE}\", found {}", shown(other)),
            ));
        }
    }
    let version = root.get("version").and_then(Value::as_str);
    if !version.is_some_and(|v| v.starts_with("0.")) {
        return Err(invalid(
            "$.version",
            format!(
                "expected a 0.x draft version (nrgdb reads draft {DRAFT_VERSION}), found {}",
                shown(version)
            ),
        ));
    }
    let vertices = vertices(root.get("vertices"))?;
    let layers = object(root.get("layers").unwrap_or(&Value::Null), "$.layers")?;
    let with_cells: Vec<_> = layers
        .iter()
        .filter(|(_, l)| l.get("primalSpace").is_some())
        .collect();
    let (name, layer) = match with_cells.as_slice() {
        [one] => *one,
        [] => return Err(invalid("$.layers", "no layer has a primalSpace")),
        many => {
            let names: Vec<_> = many.iter().map(|(n, _)| n.as_str()).collect();
            return Err(invalid(
                "$.layers",
                format!(
                    "{} layers have cells ({}); nrgdb reads a one-layer model",
                    names.len(),
                    names.join(", ")
                ),
            ));
        }
    };
    Reader {
        vertices: &vertices,
        layer: format!("$.layers.{name}"),
    }
    .model(layer)
}

fn shown(v: Option<&str>) -> String {
    v.map_or_else(|| "nothing".to_string(), |s| format!("\"{s}\""))
}

fn object<'v>(v: &'v Value, path: &str) -> Result<&'v Map<String, Value>, Json2Error> {
    v.as_object()
        .ok_or_else(|| invalid(path, format!("expected an object, found {}", type_name(v))))
}

fn array<'v>(v: &'v Value, path: &str) -> Result<&'v Vec<Value>, Json2Error> {
    v.as_array()
        .ok_or_else(|| invalid(path, format!("expected an array, found {}", type_name(v))))
}

fn type_name(v: &Value) -> &'static str {
    match v {
        Value::Null => "nothing",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

fn vertices(v: Option<&Value>) -> Result<Vec<Point>, Json2Error> {
    let list = array(v.unwrap_or(&Value::Null), "$.vertices")?;
    if list.len() > MAX_VERTICES {
        return Err(invalid(
            "$.vertices",
            format!("{} vertices, above the limit of {MAX_VERTICES}", list.len()),
        ));
    }
    list.iter()
        .enumerate()
        .map(|(i, p)| {
            let path = format!("$.vertices[{i}]");
            let xyz = array(p, &path)?;
            let n: Vec<f64> = xyz.iter().filter_map(Value::as_f64).collect();
            match n.as_slice() {
                [x, y, z] if n.len() == xyz.len() && [x, y, z].iter().all(|c| c.is_finite()) => {
                    Ok([*x, *y])
                }
                _ => Err(invalid(&path, "expected [x, y, z], three finite numbers")),
            }
        })
        .collect()
}

struct Reader<'a> {
    vertices: &'a [Point],
    layer: String,
}

impl Reader<'_> {
    fn vertex(&self, v: &Value, path: &str) -> Result<Point, Json2Error> {
        let i = v.as_u64().ok_or_else(|| {
            invalid(
                path,
                format!("expected a vertex index, found {}", type_name(v)),
            )
        })?;
        usize::try_from(i)
            .ok()
            .and_then(|i| self.vertices.get(i))
            .copied()
            .ok_or_else(|| {
                invalid(
                    path,
                    format!(
                        "vertex index {i} is out of range ({} vertices)",
                        self.vertices.len()
                    ),
                )
            })
    }

    fn ring(&self, v: &Value, path: &str) -> Result<Ring, Json2Error> {
        let ring = array(v, path)?
            .iter()
            .enumerate()
            .map(|(i, x)| self.vertex(x, &format!("{path}[{i}]")))
            .collect::<Result<Ring, _>>()?;
        if ring.len() < 3 {
            return Err(invalid(path, "a ring needs at least 3 vertices"));
        }
        Ok(ring)
    }

    /// The footprint: a `CompositeSurface` of one surface or a `Surface`.
    fn footprint(&self, geom: &Value, path: &str) -> Result<(Ring, Vec<Ring>), Json2Error> {
        let geom = object(geom, path)?;
        let b = format!("{path}.boundaries");
        let boundaries = array(geom.get("boundaries").unwrap_or(&Value::Null), &b)?;
        let (rings, rpath) = match geom.get("type").and_then(Value::as_str) {
            Some("CompositeSurface") => match boundaries.as_slice() {
                [one] => (array(one, &format!("{b}[0]"))?, format!("{b}[0]")),
                _ => {
                    return Err(invalid(
                        &b,
                        format!(
                            "{} surfaces; nrgdb reads a cell's footprint as one surface",
                            boundaries.len()
                        ),
                    ));
                }
            },
            Some("Surface") => (boundaries, b.clone()),
            Some(t @ ("Solid" | "CompositeSolid")) => {
                return Err(invalid(
                    path,
                    format!("a {t}: nrgdb reads 2D footprints (CompositeSurface or Surface)"),
                ));
            }
            other => {
                return Err(invalid(
                    &format!("{path}.type"),
                    format!(
                        "expected CompositeSurface or Surface, found {}",
                        shown(other)
                    ),
                ));
            }
        };
        let mut rings = rings
            .iter()
            .enumerate()
            .map(|(i, r)| self.ring(r, &format!("{rpath}[{i}]")));
        let exterior = rings
            .next()
            .ok_or_else(|| invalid(&rpath, "a surface needs an exterior ring"))??;
        Ok((exterior, rings.collect::<Result<_, _>>()?))
    }

    fn model(&self, layer: &Value) -> Result<Nrg, Json2Error> {
        let lp = &self.layer;
        let layer = object(layer, lp)?;
        let primal = object(
            layer.get("primalSpace").unwrap_or(&Value::Null),
            &format!("{lp}.primalSpace"),
        )?;
        let cp = format!("{lp}.primalSpace.cellSpaceMember");
        let cells = object(primal.get("cellSpaceMember").unwrap_or(&Value::Null), &cp)?;
        let empty = Map::new();
        let dual = match layer.get("dualSpace") {
            Some(d) => object(d, &format!("{lp}.dualSpace"))?,
            None => &empty,
        };
        let np = format!("{lp}.dualSpace.nodeMember");
        let nodes = match dual.get("nodeMember") {
            Some(n) => object(n, &np)?,
            None => &empty,
        };
        let ids = space_ids(cells.keys());
        // Node id → cell id, and each cell's anchor.
        let mut node_cell: HashMap<&str, &str> = HashMap::new();
        let mut anchors: HashMap<&str, Point> = HashMap::new();
        for (nid, node) in nodes {
            let path = format!("{np}.{nid}");
            let node = object(node, &path)?;
            let Some(cell) = node.get("duality").and_then(Value::as_str) else {
                continue;
            };
            if !cells.contains_key(cell) {
                return Err(invalid(
                    &format!("{path}.duality"),
                    format!("names cell \"{cell}\", which is not in {cp}"),
                ));
            }
            node_cell.insert(nid, cell);
            if let Some(g) = node.get("geometry") {
                let gp = format!("{path}.geometry.boundaries");
                let p = self.vertex(g.get("boundaries").unwrap_or(&Value::Null), &gp)?;
                anchors.insert(cell, p);
            }
        }
        let mut spaces = Vec::with_capacity(cells.len());
        for ((cid, cell), id) in cells.iter().zip(&ids) {
            spaces.push(self.space(cid, cell, *id, anchors.get(cid.as_str()), &cp)?);
        }
        let boundaries = match primal.get("cellBoundaryMember") {
            Some(b) => object(b, &format!("{lp}.primalSpace.cellBoundaryMember"))?,
            None => &empty,
        };
        let by_cell: HashMap<&str, SpaceId> = cells
            .keys()
            .map(String::as_str)
            .zip(ids.iter().copied())
            .collect();
        let kinds: HashMap<SpaceId, SpaceKind> = spaces.iter().map(|s| (s.id, s.kind)).collect();
        let ep = format!("{lp}.dualSpace.edgeMember");
        let edges = match dual.get("edgeMember") {
            Some(e) => object(e, &ep)?,
            None => &empty,
        };
        let mut connections = Vec::with_capacity(edges.len());
        for (eid, edge) in edges {
            let path = format!("{ep}.{eid}");
            let edge = object(edge, &path)?;
            let end = |i: usize, v: &Value| -> Result<SpaceId, Json2Error> {
                let p = format!("{path}.connects[{i}]");
                let name = v.as_str().ok_or_else(|| invalid(&p, "expected an id"))?;
                let cell = node_cell.get(name).copied().unwrap_or(name);
                by_cell
                    .get(cell)
                    .copied()
                    .ok_or_else(|| invalid(&p, format!("\"{name}\" is neither a node nor a cell")))
            };
            let cp = format!("{path}.connects");
            let (a, b) = match array(edge.get("connects").unwrap_or(&Value::Null), &cp)?.as_slice()
            {
                [a, b] => (end(0, a)?, end(1, b)?),
                other => {
                    return Err(invalid(
                        &cp,
                        format!("an edge connects 2 nodes, found {}", other.len()),
                    ));
                }
            };
            let wp = format!("{path}.weight");
            let length_m = edge
                .get("weight")
                .and_then(Value::as_f64)
                .filter(|w| w.is_finite() && *w >= 0.0)
                .ok_or_else(|| invalid(&wp, "expected a weight: a finite number ≥ 0 (metres)"))?;
            let kind = self.connection_kind(edge, boundaries, &path)?.unwrap_or(
                if [a, b]
                    .iter()
                    .any(|s| kinds.get(s) == Some(&SpaceKind::Door))
                {
                    ConnectionKind::Door
                } else {
                    ConnectionKind::Open
                },
            );
            connections.push(Connection {
                a,
                b,
                kind,
                length_m,
            });
        }
        Nrg::new(spaces, connections).map_err(|e| Json2Error::Model(e.to_string()))
    }

    fn space(
        &self,
        cid: &str,
        cell: &Value,
        id: SpaceId,
        anchor: Option<&Point>,
        cp: &str,
    ) -> Result<Space, Json2Error> {
        let path = format!("{cp}.{cid}");
        let cell = object(cell, &path)?;
        let gp = format!("{path}.cellSpaceGeom");
        let geom = cell
            .get("cellSpaceGeom")
            .ok_or_else(|| invalid(&path, "no cellSpaceGeom: nrgdb needs each cell's footprint"))?;
        let (polygon, holes) = self.footprint(geom, &gp)?;
        let mut attributes = match cell.get("attributes") {
            Some(a) => object(a, &format!("{path}.attributes"))?.clone(),
            None => Map::new(),
        };
        let kind = match attributes.remove(KIND) {
            Some(Value::String(k)) => k
                .parse()
                .map_err(|e: String| invalid(&format!("{path}.attributes.{KIND}"), e))?,
            Some(_) => {
                return Err(invalid(
                    &format!("{path}.attributes.{KIND}"),
                    "expected a string",
                ));
            }
            None => SpaceKind::Other,
        };
        let doorway = match attributes.remove(DOORWAY) {
            Some(d) => Some(
                serde_json::from_value::<[Point; 2]>(d)
                    .ok()
                    .filter(|d| d.iter().flatten().all(|c| c.is_finite()))
                    .ok_or_else(|| {
                        invalid(
                            &format!("{path}.attributes.{DOORWAY}"),
                            "expected [[x, y], [x, y]]",
                        )
                    })?,
            ),
            None => None,
        };
        if let Some(level) = cell.get("level") {
            attributes.insert("level".into(), level.clone());
        }
        let anchor = match anchor {
            Some(a) => *a,
            None => pole_of_inaccessibility(&polygon, &holes, 0.01)
                .map(|(p, _)| p)
                .ok_or_else(|| invalid(&gp, "the footprint has no inside point"))?,
        };
        let mut space = Space::new(id, kind, anchor, polygon);
        space.name = cell.get("name").and_then(Value::as_str).map(str::to_string);
        space.holes = holes;
        space.attributes = attributes;
        space.doorway = doorway;
        space.update_area();
        space.update_doorway();
        Ok(space)
    }

    /// The kind the edge's dual boundary declares, if it declares one.
    fn connection_kind(
        &self,
        edge: &Map<String, Value>,
        boundaries: &Map<String, Value>,
        path: &str,
    ) -> Result<Option<ConnectionKind>, Json2Error> {
        let Some(b) = edge.get("duality").and_then(Value::as_str) else {
            return Ok(None);
        };
        let declared = boundaries
            .get(b)
            .and_then(|b| b.get("attributes"))
            .and_then(|a| a.get(CONNECTION));
        match declared {
            None => Ok(None),
            Some(Value::String(k)) => k.parse().map(Some).map_err(|e: String| {
                invalid(
                    &format!(
                        "{}.primalSpace.cellBoundaryMember.{b}.attributes.{CONNECTION}",
                        self.layer
                    ),
                    e,
                )
            }),
            Some(_) => Err(invalid(
                &format!("{path}.duality"),
                format!("boundary \"{b}\" has a {CONNECTION} that is not a string"),
            )),
        }
    }
}

/// Space ids for the cells: the numbers of `C<n>` ids when every id is
/// one and they are distinct, else 1, 2, 3… in document order.
fn space_ids<'a>(keys: impl Iterator<Item = &'a String> + Clone) -> Vec<SpaceId> {
    let parsed: Option<Vec<u32>> = keys
        .clone()
        .map(|k| k.strip_prefix('C').and_then(|n| n.parse().ok()))
        .collect();
    if let Some(ns) = parsed {
        let mut sorted = ns.clone();
        sorted.sort_unstable();
        sorted.dedup();
        if sorted.len() == ns.len() {
            return ns.into_iter().map(SpaceId).collect();
        }
    }
    (1..).take(keys.count()).map(SpaceId).collect()
}
