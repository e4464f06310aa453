//! [`Nrg`] ↔ [`Document`]: how nrgdb's model is written as IndoorGML and
//! how any IndoorGML 1.0 document is read as a model.
//!
//! Writing: a space becomes a cell (room → `navi:GeneralSpace`, corridor →
//! `navi:TransitionSpace`, door → `navi:ConnectionSpace` (thick doors only),
//! other → `core:CellSpace`) with a 2D `gml:Polygon`, and a `State` at its
//! anchor, dual both ways. A navigable connection becomes a `Transition`
//! (weight = length in metres; geometry = the walked polyline from one
//! anchor to the other when the caller passes one ([`from_nrg_with_paths`]),
//! else the straight LineString between the anchors). A
//! non-navigable `adjacent` connection becomes a `core:CellSpaceBoundary`
//! without geometry or dual, referenced by both cells' `partialboundedBy`:
//! in IndoorGML a shared boundary without a Transition is exactly "adjacent
//! but not connected". Machine-readable extras (the connection kind and
//! length, a space's attributes, a door's doorway line and width under
//! `"doorway"`) go in `gml:description` as a JSON object.
//!
//! Reading: the layer whose States are dual to the most cells is the
//! navigation layer; its Transitions become connections (length = the
//! weight; a missing or 0 weight is fixed from the LineString's length and
//! counted in [`WeightFixes`]), and boundaries
//! shared by two cells without a Transition become `adjacent` connections.
//! A 3D cell's footprint is its largest floor face (the faces at the
//! solid's lowest z), else the convex hull of its vertices.

use std::collections::{HashMap, HashSet};

use geo::{ConvexHull, Coord, MultiPoint};
use serde_json::{Map, Value, json};

use super::IndoorGmlError;
use super::document::*;
use crate::model::{
    Connection, ConnectionKind, ConnectionPaths, Nrg, Point, Ring, Space, SpaceId, SpaceKind,
    polygon_area, polygon_centroid,
};

/// Describes `nrg` as an IndoorGML document (see the module docs), each
/// Transition a straight LineString between the anchors.
pub fn from_nrg(nrg: &Nrg) -> Document {
    from_nrg_with_paths(nrg, &ConnectionPaths::new())
}

/// Describes `nrg` as an IndoorGML document, each Transition's LineString
/// the connection's polyline in `paths` when it has one (oriented from the
/// Transition's first State to its second), else the straight line between
/// the anchors. Weights are the model's `length_m`: pass a model whose
/// lengths are the lengths of `paths` (`route::walked_model` gives both).
pub fn from_nrg_with_paths(nrg: &Nrg, paths: &ConnectionPaths) -> Document {
    let mut cells = Vec::with_capacity(nrg.spaces().len());
    let mut boundaries = Vec::new();
    let mut states = Vec::with_capacity(nrg.spaces().len());
    let mut transitions = Vec::new();
    let mut bounded_by: HashMap<SpaceId, Vec<String>> = HashMap::new();
    let mut state_connects: HashMap<SpaceId, Vec<String>> = HashMap::new();
    for c in nrg.connections() {
        let (Some(a), Some(b)) = (nrg.space(c.a), nrg.space(c.b)) else {
            continue;
        };
        if c.kind.is_navigable() {
            let id = format!("T{}-{}", c.a, c.b);
            state_connects.entry(c.a).or_default().push(id.clone());
            state_connects.entry(c.b).or_default().push(id.clone());
            transitions.push(Transition {
                info: FeatureInfo {
                    description: Some(json!({"connection": c.kind.as_str()}).to_string()),
                    ..FeatureInfo::new(id.clone())
                },
                weight: Some(c.length_m),
                connects: vec![state_id(c.a), state_id(c.b)],
                duality: None,
                geometry: Some(LineString {
                    id: Some(format!("{id}-g")),
                    coords: Coords {
                        dim: 2,
                        values: transition_line(paths.get(&c.key()), a.anchor, b.anchor),
                    },
                }),
            });
        } else {
            let id = format!("B{}-{}", c.a, c.b);
            bounded_by.entry(c.a).or_default().push(id.clone());
            bounded_by.entry(c.b).or_default().push(id.clone());
            boundaries.push(Boundary {
                info: FeatureInfo {
                    description: Some(
                        json!({"connection": c.kind.as_str(), "length_m": c.length_m}).to_string(),
                    ),
                    ..FeatureInfo::new(id)
                },
                class: BoundaryClass::CellSpaceBoundary,
                duality: None,
                geometry: None,
                external: Vec::new(),
            });
        }
    }
    for s in nrg.spaces() {
        let class = match s.kind {
            SpaceKind::Room => CellClass::GeneralSpace,
            SpaceKind::Corridor | SpaceKind::Stairs | SpaceKind::Elevator => {
                CellClass::TransitionSpace
            }
            SpaceKind::Door => CellClass::ConnectionSpace,
            SpaceKind::Other => CellClass::CellSpace,
        };
        let kind = s.kind.as_str().to_string();
        cells.push(Cell {
            info: FeatureInfo {
                names: s.name.iter().cloned().collect(),
                description: space_description(s),
                ..FeatureInfo::new(cell_id(s.id))
            },
            class,
            navi: NaviCodes {
                class: kind.clone(),
                function: kind.clone(),
                usage: kind,
            },
            geometry: Some(CellGeometry::Surface(Polygon {
                id: Some(format!("{}-g", cell_id(s.id))),
                exterior: closed_ring(&s.polygon, true, super::levels::elevation(s)),
                interiors: s
                    .holes
                    .iter()
                    .map(|h| closed_ring(h, false, super::levels::elevation(s)))
                    .collect(),
            })),
            duality: Some(state_id(s.id)),
            external: Vec::new(),
            bounded_by: bounded_by.remove(&s.id).unwrap_or_default(),
        });
        states.push(State {
            info: FeatureInfo::new(state_id(s.id)),
            duality: Some(cell_id(s.id)),
            connects: state_connects.remove(&s.id).unwrap_or_default(),
            point: Some(GmlPoint {
                id: Some(format!("{}-g", state_id(s.id))),
                coords: at_height(&[s.anchor], super::levels::elevation(s)),
            }),
        });
    }
    Document {
        info: FeatureInfo::new("IndoorFeatures"),
        srs_name: None,
        version: Default::default(),
        warnings: Vec::new(),
        primal: Some(PrimalSpace {
            info: FeatureInfo::new("PrimalSpaceFeatures"),
            cells,
            boundaries,
        }),
        graph: Some(LayeredGraph {
            info: FeatureInfo::new("MultiLayeredGraph"),
            layer_groups: vec![LayerGroup {
                id: "SpaceLayers".into(),
                layers: vec![Layer {
                    info: FeatureInfo::new("NavigationLayer"),
                    class: Some("TOPOGRAPHIC".into()),
                    nodes_id: "NavigationNodes".into(),
                    edges_id: "NavigationEdges".into(),
                    states,
                    transitions,
                }],
            }],
            inter_edges: Vec::new(),
        }),
    }
}

/// The flat coordinates of a Transition from anchor `a` to anchor `b`:
/// the path when it has two points or more (reversed if it runs from `b`),
/// else the straight segment.
fn transition_line(path: Option<&Vec<Point>>, a: Point, b: Point) -> Vec<f64> {
    let mut points: Vec<Point> = match path {
        Some(p) if p.len() >= 2 => p.clone(),
        _ => vec![a, b],
    };
    let (Some(&first), Some(&last)) = (points.first(), points.last()) else {
        return Vec::new();
    };
    if distance(first, a) + distance(last, b) > distance(first, b) + distance(last, a) {
        points.reverse();
    }
    points.iter().flat_map(|p| *p).collect()
}

fn cell_id(id: SpaceId) -> String {
    format!("C{id}")
}

fn state_id(id: SpaceId) -> String {
    format!("S{id}")
}

/// A closed GML ring from an open model ring, oriented counter-clockwise
/// for exteriors and clockwise for holes.
fn closed_ring(ring: &[Point], ccw: bool, z: Option<f64>) -> Coords {
    let mut pts: Vec<Point> = ring.to_vec();
    if (polygon_area(&pts) > 0.0) != ccw {
        pts.reverse();
    }
    if let Some(&first) = pts.first() {
        pts.push(first);
    }
    at_height(&pts, z)
}

/// Positions in 2D, or in 3D at height `z`.
fn at_height(points: &[Point], z: Option<f64>) -> Coords {
    match z {
        None => Coords {
            dim: 2,
            values: points.iter().flat_map(|p| *p).collect(),
        },
        Some(z) => Coords {
            dim: 3,
            values: points.iter().flat_map(|p| [p[0], p[1], z]).collect(),
        },
    }
}

/// A cell's description: its space's attributes and, for a door, its
/// doorway (`"doorway": {"line": [[x, y], [x, y]], "width_m": w}`; the
/// width is derived again when read).
fn space_description(s: &Space) -> Option<String> {
    let mut attrs = s.attributes.clone();
    super::levels::describe(s, &mut attrs);
    match crate::model::doorway(s) {
        Some(d) => {
            attrs.insert(
                DOORWAY_KEY.into(),
                json!({"line": d.line, "width_m": d.width_m}),
            );
            Some(Value::Object(attrs).to_string())
        }
        None => attributes_to_description(&attrs),
    }
}

/// The description key of a door's doorway extras.
pub(super) const DOORWAY_KEY: &str = "doorway";

/// Takes the doorway line nrgdb wrote out of a cell's attributes.
fn take_doorway(attributes: &mut Map<String, Value>) -> Option<[Point; 2]> {
    let line: [Point; 2] =
        serde_json::from_value(attributes.get(DOORWAY_KEY)?.get("line")?.clone()).ok()?;
    attributes.remove(DOORWAY_KEY);
    Some(line)
}

fn attributes_to_description(attrs: &Map<String, Value>) -> Option<String> {
    if attrs.is_empty() {
        return None;
    }
    if let (1, Some(Value::String(text))) = (attrs.len(), attrs.get("description")) {
        return Some(text.clone());
    }
    Some(Value::Object(attrs.clone()).to_string())
}

fn description_to_attributes(description: Option<&str>) -> Map<String, Value> {
    match description {
        None | Some("") => Map::new(),
        Some(text) => match serde_json::from_str::<Value>(text) {
            Ok(Value::Object(map)) => map,
            _ => Map::from_iter([("description".to_string(), Value::String(text.to_string()))]),
        },
    }
}

/// The connection kind and length nrgdb wrote in a description, if any.
fn described_connection(description: Option<&str>) -> (Option<ConnectionKind>, Option<f64>) {
    let Some(Ok(Value::Object(map))) = description.map(serde_json::from_str::<Value>) else {
        return (None, None);
    };
    let kind = map
        .get("connection")
        .and_then(Value::as_str)
        .and_then(|k| k.parse().ok());
    let length = map
        .get("length_m")
        .and_then(Value::as_f64)
        .filter(|l| l.is_finite() && *l >= 0.0);
    (kind, length)
}

/// Transitions read with a missing or 0 weight, and what their
/// connections' lengths were set from.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct WeightFixes {
    /// How many got their LineString's length.
    pub from_geometry: usize,
    /// The connections (`(a, b)`, `a < b`) of those without a usable
    /// LineString: their length is the straight distance between the
    /// anchors until a caller with a navigation layer sets the walked one.
    pub without_geometry: Vec<(SpaceId, SpaceId)>,
}

impl WeightFixes {
    /// How many weights were fixed in all.
    pub fn total(&self) -> usize {
        self.from_geometry + self.without_geometry.len()
    }
}

/// Reads a document as a model (see the module docs).
pub fn to_nrg(doc: &Document) -> Result<Nrg, IndoorGmlError> {
    to_nrg_fixing(doc).map(|(nrg, _)| nrg)
}

/// Reads a document as a model, saying which Transitions had a missing or
/// 0 weight and how their lengths were set (see [`WeightFixes`]).
pub fn to_nrg_fixing(doc: &Document) -> Result<(Nrg, WeightFixes), IndoorGmlError> {
    let mut fixes = WeightFixes::default();
    let cells = doc.cells();
    let ids = space_ids(cells);
    let cell_index: HashMap<&str, usize> = cells
        .iter()
        .enumerate()
        .map(|(i, c)| (c.info.id.as_str(), i))
        .collect();
    let layer = navigation_layer(doc, &cell_index);
    // State id → cell index, for the navigation layer.
    let mut state_cell: HashMap<&str, usize> = HashMap::new();
    let mut state_of_cell: HashMap<usize, &State> = HashMap::new();
    if let Some(layer) = layer {
        for s in &layer.states {
            if let Some(&ci) = s.duality.as_deref().and_then(|d| cell_index.get(d)) {
                state_cell.insert(s.info.id.as_str(), ci);
                state_of_cell.entry(ci).or_insert(s);
            }
        }
    }
    let mut spaces = Vec::with_capacity(cells.len());
    for (i, cell) in cells.iter().enumerate() {
        let state = state_of_cell.get(&i).copied();
        spaces.push(space(cell, ids[i], state)?);
    }
    super::levels::assign(cells, &mut spaces);
    let anchor = |ci: usize| spaces.get(ci).map_or([0.0, 0.0], |s: &Space| s.anchor);
    let mut seen = HashSet::new();
    let mut connections = Vec::new();
    if let Some(layer) = layer {
        for t in &layer.transitions {
            let [a, b] = match t.connects.as_slice() {
                [a, b] => [a.as_str(), b.as_str()],
                _ => continue,
            };
            let (Some(&ca), Some(&cb)) = (state_cell.get(a), state_cell.get(b)) else {
                continue;
            };
            if ca == cb || !seen.insert(ordered(ca, cb)) {
                continue;
            }
            let (described, _) = described_connection(t.info.description.as_deref());
            let is_door = |ci: usize| {
                spaces
                    .get(ci)
                    .is_some_and(|s: &Space| s.kind == SpaceKind::Door)
            };
            let kind =
                described
                    .filter(|k| k.is_navigable())
                    .unwrap_or(if is_door(ca) || is_door(cb) {
                        ConnectionKind::Door
                    } else {
                        ConnectionKind::Open
                    });
            let weight = t.weight.filter(|w| w.is_finite() && *w > 0.0);
            let length_m = match weight {
                Some(w) => w,
                None => {
                    let line = t
                        .geometry
                        .as_ref()
                        .map(|g| polyline_length(&g.coords))
                        .filter(|l| l.is_finite() && *l > 0.0);
                    match line {
                        Some(l) => {
                            fixes.from_geometry += 1;
                            l
                        }
                        None => {
                            let (x, y) = (ids[ca], ids[cb]);
                            fixes
                                .without_geometry
                                .push(if x <= y { (x, y) } else { (y, x) });
                            distance(anchor(ca), anchor(cb))
                        }
                    }
                }
            };
            connections.push(Connection {
                a: ids[ca],
                b: ids[cb],
                kind,
                length_m,
            });
        }
    }
    // Boundaries shared by two cells and not crossed by a Transition.
    let mut sharing: HashMap<&str, Vec<usize>> = HashMap::new();
    for (i, cell) in cells.iter().enumerate() {
        for b in &cell.bounded_by {
            sharing.entry(b.as_str()).or_default().push(i);
        }
    }
    for b in doc.boundaries() {
        let Some(users) = sharing.get(b.info.id.as_str()) else {
            continue;
        };
        let (described, length) = described_connection(b.info.description.as_deref());
        if let ([ca, cb], None) = (users.as_slice(), &b.duality) {
            let (ca, cb) = (*ca, *cb);
            if ca == cb
                || described.is_some_and(|k| k.is_navigable())
                || !seen.insert(ordered(ca, cb))
            {
                continue;
            }
            let length_m = length.unwrap_or_else(|| distance(anchor(ca), anchor(cb)));
            connections.push(Connection {
                a: ids[ca],
                b: ids[cb],
                kind: ConnectionKind::Adjacent,
                length_m,
            });
        }
    }
    super::levels::fit_connections(&spaces, &mut connections);
    let nrg = Nrg::new(spaces, connections).map_err(|e| IndoorGmlError::Model(e.to_string()))?;
    Ok((nrg, fixes))
}

fn ordered(a: usize, b: usize) -> (usize, usize) {
    if a <= b { (a, b) } else { (b, a) }
}

/// Space ids: `C<n>` cell ids give n; otherwise cells are numbered from 1
/// in document order.
fn space_ids(cells: &[Cell]) -> Vec<SpaceId> {
    let parsed: Vec<Option<u32>> = cells
        .iter()
        .map(|c| {
            c.info
                .id
                .strip_prefix('C')
                .and_then(|n| n.parse::<u32>().ok())
                .filter(|n| *n > 0)
        })
        .collect();
    let unique: HashSet<u32> = parsed.iter().flatten().copied().collect();
    if parsed.iter().all(Option::is_some) && unique.len() == cells.len() {
        parsed
            .into_iter()
            .map(|n| SpaceId(n.unwrap_or(0)))
            .collect()
    } else {
        (1..=cells.len() as u32).map(SpaceId).collect()
    }
}

/// The layer whose States are dual to the most cells.
fn navigation_layer<'a>(doc: &'a Document, cells: &HashMap<&str, usize>) -> Option<&'a Layer> {
    let graph = doc.graph.as_ref()?;
    graph
        .layers()
        .enumerate()
        .max_by_key(|(i, l)| {
            let dual = l
                .states
                .iter()
                .filter(|s| s.duality.as_deref().is_some_and(|d| cells.contains_key(d)))
                .count();
            (dual, std::cmp::Reverse(*i))
        })
        .map(|(_, l)| l)
}

/// Stairs or a lift, when a cell's navi class or function says so (ours
/// write `stairs` / `elevator`; other files "Stair", "Staircase", "Lift",
/// "Elevator").
fn vertical_kind(navi: &NaviCodes) -> Option<SpaceKind> {
    [&navi.class, &navi.function].into_iter().find_map(|code| {
        let code = code.to_ascii_lowercase();
        if code.contains("stair") {
            Some(SpaceKind::Stairs)
        } else if code.contains("elevator") || code.contains("lift") {
            Some(SpaceKind::Elevator)
        } else {
            None
        }
    })
}

fn space(cell: &Cell, id: SpaceId, state: Option<&State>) -> Result<Space, IndoorGmlError> {
    let kind = match cell.class {
        CellClass::GeneralSpace => SpaceKind::Room,
        CellClass::TransitionSpace => vertical_kind(&cell.navi).unwrap_or(SpaceKind::Corridor),
        CellClass::ConnectionSpace | CellClass::AnchorSpace => SpaceKind::Door,
        _ => vertical_kind(&cell.navi).unwrap_or(SpaceKind::Other),
    };
    let (polygon, holes) = footprint(cell)?;
    // The State's point when it lies in the cell; else (no State, or a
    // point outside, as some files have) the cell's pole of
    // inaccessibility, an interior point routes can start from.
    let inside = |p: &[f64; 2]| {
        crate::model::point_in_ring(*p, &polygon)
            && !holes.iter().any(|h| crate::model::point_in_ring(*p, h))
    };
    let anchor = state
        .and_then(|s| s.point.as_ref())
        .and_then(|p| p.coords.xy().next())
        .filter(inside)
        .or_else(|| crate::model::pole_of_inaccessibility(&polygon, &holes, 0.01).map(|(p, _)| p))
        .or_else(|| polygon_centroid(&polygon))
        .unwrap_or([0.0, 0.0]);
    let mut attributes = description_to_attributes(cell.info.description.as_deref());
    let doorway = take_doorway(&mut attributes);
    if cell.info.id != cell_id(id) {
        attributes.insert("gml_id".into(), Value::String(cell.info.id.clone()));
    }
    let name = cell
        .info
        .names
        .first()
        .or_else(|| state.and_then(|s| s.info.names.first()))
        .filter(|n| !n.is_empty())
        .cloned();
    let mut space = Space::new(id, kind, anchor, polygon);
    space.name = name;
    space.holes = holes;
    space.attributes = attributes;
    if kind == SpaceKind::Door && doorway.is_some() {
        space.doorway = doorway;
    }
    space.update_area();
    space.update_doorway();
    Ok(space)
}

/// The 2D footprint of a cell: exterior ring (CCW) and holes (CW).
pub(super) fn footprint(cell: &Cell) -> Result<(Ring, Vec<Ring>), IndoorGmlError> {
    let degenerate = || {
        IndoorGmlError::Model(format!(
            "line {}: cell {} has no usable 2D footprint (fewer than 3 distinct points)",
            cell.info.line, cell.info.id
        ))
    };
    let (exterior, holes) = match &cell.geometry {
        None => {
            return Err(IndoorGmlError::Model(format!(
                "line {}: cell {} has no geometry",
                cell.info.line, cell.info.id
            )));
        }
        Some(CellGeometry::Surface(p)) => (
            open_ring(&p.exterior),
            p.interiors
                .iter()
                .map(open_ring)
                .filter(|r| r.len() >= 3)
                .collect(),
        ),
        Some(CellGeometry::Solid(s)) => (solid_footprint(s), Vec::new()),
    };
    let exterior = if exterior.len() >= 3 && polygon_area(&exterior).abs() > 1e-12 {
        exterior
    } else {
        let all: Vec<Coord> = match &cell.geometry {
            Some(CellGeometry::Surface(p)) => {
                p.exterior.xy().map(|[x, y]| Coord { x, y }).collect()
            }
            Some(CellGeometry::Solid(s)) => s
                .exterior
                .iter()
                .flat_map(|p| p.exterior.xy())
                .map(|[x, y]| Coord { x, y })
                .collect(),
            None => Vec::new(),
        };
        hull(all)
    };
    if exterior.len() < 3 {
        return Err(degenerate());
    }
    Ok((
        orient(exterior, true),
        holes.into_iter().map(|h| orient(h, false)).collect(),
    ))
}

fn hull(points: Vec<Coord>) -> Ring {
    let mp = MultiPoint::from(points);
    let h = mp.convex_hull();
    open_points(h.exterior().coords().map(|c| [c.x, c.y]))
}

/// The largest face at the solid's lowest z, projected to xy.
fn solid_footprint(s: &Solid) -> Ring {
    let min_z = s
        .exterior
        .iter()
        .flat_map(|p| p.exterior.z())
        .fold(f64::INFINITY, f64::min);
    s.exterior
        .iter()
        .filter(|p| p.exterior.z().all(|z| (z - min_z).abs() < 1e-6))
        .map(|p| open_ring(&p.exterior))
        .max_by(|a, b| polygon_area(a).abs().total_cmp(&polygon_area(b).abs()))
        .unwrap_or_default()
}

fn open_ring(coords: &Coords) -> Ring {
    open_points(coords.xy())
}

/// Drops repeated consecutive points and the closing point.
fn open_points(points: impl Iterator<Item = Point>) -> Ring {
    let mut ring: Ring = Vec::new();
    for p in points {
        if ring.last() != Some(&p) {
            ring.push(p);
        }
    }
    while ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
    ring
}

fn orient(mut ring: Ring, ccw: bool) -> Ring {
    if (polygon_area(&ring) > 0.0) != ccw {
        ring.reverse();
    }
    ring
}

fn polyline_length(coords: &Coords) -> f64 {
    let pts: Vec<Point> = coords.xy().collect();
    pts.windows(2).map(|w| distance(w[0], w[1])).sum()
}

fn distance(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cell(id: u32, x0: f64, y0: f64) -> String {
        let (x1, y1) = (x0 + 2.0, y0 + 2.0);
        format!(
            r##"<core:cellSpaceMember><core:CellSpace gml:id="C{id}"><core:cellSpaceGeometry><core:Geometry2D>
<gml:Polygon gml:id="C{id}-g"><gml:exterior><gml:LinearRing><gml:posList srsDimension="2">{x0} {y0} {x1} {y0} {x1} {y1} {x0} {y1} {x0} {y0}</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon>
</core:Geometry2D></core:cellSpaceGeometry><core:duality xlink:href="#S{id}"/></core:CellSpace></core:cellSpaceMember>"##
        )
    }

    fn state(id: u32, x: f64, y: f64, connects: &[&str]) -> String {
        let connects: String = connects
            .iter()
            .map(|t| format!(r##"<core:connects xlink:href="#{t}"/>"##))
            .collect();
        format!(
            r##"<core:stateMember><core:State gml:id="S{id}"><core:duality xlink:href="#C{id}"/>{connects}
<core:geometry><gml:Point gml:id="S{id}-g"><gml:pos srsDimension="2">{x} {y}</gml:pos></gml:Point></core:geometry></core:State></core:stateMember>"##
        )
    }

    fn transition(id: &str, a: u32, b: u32, weight: Option<&str>, line: Option<&str>) -> String {
        let weight = weight.map_or(String::new(), |w| format!("<core:weight>{w}</core:weight>"));
        let line = line.map_or(String::new(), |l| {
            format!(
                r#"<core:geometry><gml:LineString gml:id="{id}-g"><gml:posList srsDimension="2">{l}</gml:posList></gml:LineString></core:geometry>"#
            )
        });
        format!(
            r##"<core:transitionMember><core:Transition gml:id="{id}">{weight}<core:connects xlink:href="#S{a}"/><core:connects xlink:href="#S{b}"/>{line}</core:Transition></core:transitionMember>"##
        )
    }

    /// Four 2 m squares: 1 | 2 | 3 in a row, 4 above 1. Transitions:
    /// 1-2 weight 0 with a bent line, 2-3 no weight with a straight line,
    /// 1-4 weight 0 and no line, 2-4 weight 7.5.
    fn hand_made() -> String {
        let cells: String = [(1, 0.0, 0.0), (2, 2.0, 0.0), (3, 4.0, 0.0), (4, 0.0, 2.0)]
            .iter()
            .map(|&(id, x, y)| cell(id, x, y))
            .collect();
        let states = [
            state(1, 1.0, 1.0, &["T1", "T3"]),
            state(2, 3.0, 1.0, &["T1", "T2", "T4"]),
            state(3, 5.0, 1.0, &["T2"]),
            state(4, 1.0, 3.0, &["T3", "T4"]),
        ]
        .concat();
        let transitions = [
            transition("T1", 1, 2, Some(" 0.0 "), Some("1 1 2 1.5 3 1")),
            transition("T2", 2, 3, None, Some("3 1 5 1")),
            transition("T3", 1, 4, Some("0"), None),
            transition("T4", 2, 4, Some("7.5"), Some("3 1 1 3")),
        ]
        .concat();
        format!(
            r#"<?xml version="1.0" encoding="UTF-8"?>
<core:IndoorFeatures gml:id="F" xmlns:core="http://www.opengis.net/indoorgml/1.0/core" xmlns:gml="http://www.opengis.net/gml/3.2" xmlns:xlink="http://www.w3.org/1999/xlink">
<core:primalSpaceFeatures><core:PrimalSpaceFeatures gml:id="P">{cells}</core:PrimalSpaceFeatures></core:primalSpaceFeatures>
<core:multiLayeredGraph><core:MultiLayeredGraph gml:id="G"><core:spaceLayers gml:id="SL"><core:spaceLayerMember><core:SpaceLayer gml:id="L">
<core:nodes gml:id="N">{states}</core:nodes><core:edges gml:id="E">{transitions}</core:edges>
</core:SpaceLayer></core:spaceLayerMember></core:spaceLayers></core:MultiLayeredGraph></core:multiLayeredGraph>
</core:IndoorFeatures>"#
        )
    }

    #[test]
    fn missing_or_zero_weights_are_fixed_from_the_line_and_counted() {
        let doc = crate::indoorgml::read_str(&hand_made()).unwrap();
        let (nrg, fixes) = to_nrg_fixing(&doc).unwrap();
        assert_eq!(fixes.from_geometry, 2);
        assert_eq!(fixes.without_geometry, vec![(SpaceId(1), SpaceId(4))]);
        assert_eq!(fixes.total(), 3);
        let length = |a, b| nrg.connection(SpaceId(a), SpaceId(b)).unwrap().length_m;
        // 1-2: two legs of √(1² + 0.5²).
        assert!((length(1, 2) - 2.0 * 1.25f64.sqrt()).abs() < 1e-12);
        assert!((length(2, 3) - 2.0).abs() < 1e-12);
        // No line: the straight distance until a caller walks it.
        assert!((length(1, 4) - 2.0).abs() < 1e-12);
        // A positive weight is kept, whatever the line says.
        assert_eq!(length(2, 4), 7.5);
        assert_eq!(to_nrg(&doc).unwrap(), nrg);
    }

    #[test]
    fn transitions_draw_the_given_path_from_their_first_state() {
        let doc = crate::indoorgml::read_str(&hand_made()).unwrap();
        let nrg = to_nrg(&doc).unwrap();
        let mut paths = ConnectionPaths::new();
        // Given from 2's side: written reversed, from S1 to S2.
        paths.insert(
            (SpaceId(1), SpaceId(2)),
            vec![[3.0, 1.0], [2.0, 0.5], [1.0, 1.0]],
        );
        let out = from_nrg_with_paths(&nrg, &paths);
        let ts = &out.layers()[0].transitions;
        let line = |id: &str| -> Vec<f64> {
            let t = ts.iter().find(|t| t.info.id == id).unwrap();
            t.geometry.as_ref().unwrap().coords.values.clone()
        };
        assert_eq!(line("T1-2"), vec![1.0, 1.0, 2.0, 0.5, 3.0, 1.0]);
        assert_eq!(line("T2-3"), vec![3.0, 1.0, 5.0, 1.0]);
        let t = ts.iter().find(|t| t.info.id == "T1-2").unwrap();
        assert_eq!(
            t.weight,
            Some(nrg.connection(SpaceId(1), SpaceId(2)).unwrap().length_m)
        );
    }
}
