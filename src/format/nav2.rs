//! The model as a Nav2 Route Server graph: the GeoJSON that `nav2_route`'s
//! `GeoJsonGraphFileLoader` loads (ROS 2 Navigation, Kilted and later).
//!
//! Nodes are `Point` features, one per space at its anchor (a door's is
//! the middle of its doorway: where a robot passes through), with
//! `properties.id`, `frame: "map"` and `metadata` (our space id, kind,
//! name when it has one, a door's width). Edges are `MultiLineString`
//! features along the walked path of each navigable connection, one per
//! direction (Nav2's edges are directed), and across each room or
//! corridor from one of its doors (or open neighbours) to another, so a
//! route never detours through a corridor's middle, with `id`, `startid`, `endid`,
//! `cost` (the walked length in metres) and `metadata` (both spaces,
//! the connection kind, the door's width); an edge entering a door
//! carries an `operations` entry a robot can hook (`door`, triggered
//! `ON_ENTER`, with the door's id and width). Ids are unsigned and unique
//! across nodes and edges: nodes first, then edges. Coordinates are
//! map-frame metres, as Nav2 uses them. Metadata holds no `null` (the
//! loader refuses it). [`check_nav2`] reads a graph back and checks it
//! against every rule the loader applies.

use serde_json::{Map, Value, json};

use std::collections::HashMap;

use crate::model::{ConnectionKind, Nrg, Point, Space, SpaceId, SpaceKind};
use crate::route::{Budget, Endpoint, NavMesh, Profile, RouteRequest, WalkedModel, shortest_route};

/// The Nav2 route graph of the model under `nav` (see the module docs). A
/// model without any navigable connection gives a graph Nav2 refuses (it
/// needs nodes and edges): [`check_nav2`] says so.
pub fn to_nav2(nav: &NavMesh) -> Value {
    let walked = WalkedModel::on(nav);
    let nrg = &walked.nrg;
    let index: HashMap<SpaceId, u64> = nrg
        .spaces()
        .iter()
        .enumerate()
        .map(|(i, s)| (s.id, i as u64))
        .collect();
    let node_of = |id: SpaceId| index.get(&id).copied();
    let mut features: Vec<Value> = nrg
        .spaces()
        .iter()
        .enumerate()
        .map(|(i, s)| node(i as u64, s))
        .collect();
    let mut next_id = nrg.spaces().len() as u64;
    let mut push_both = |features: &mut Vec<Value>,
                         a: &Space,
                         b: &Space,
                         kind: &str,
                         length: f64,
                         path: Vec<Point>,
                         through: Vec<SpaceId>| {
        let (Some(na), Some(nb)) = (node_of(a.id), node_of(b.id)) else {
            return;
        };
        let back: Vec<Point> = path.iter().rev().copied().collect();
        for (from, to, s, t, p) in [(na, nb, a, b, path), (nb, na, b, a, back)] {
            features.push(edge(
                next_id,
                (from, to),
                (s, t),
                kind,
                through.clone(),
                length,
                p,
            ));
            next_id += 1;
        }
    };
    // Along each navigable connection, anchor to anchor.
    for c in nrg.connections() {
        if !c.kind.is_navigable() {
            continue;
        }
        let (Some(sa), Some(sb)) = (nrg.space(c.a), nrg.space(c.b)) else {
            continue;
        };
        // The walked path runs from the smaller id's anchor to the other's.
        let path: Vec<Point> = match walked.paths.get(&c.key()) {
            Some(p) if c.a <= c.b => p.clone(),
            Some(p) => p.iter().rev().copied().collect(),
            None => vec![sa.anchor, sb.anchor],
        };
        push_both(
            &mut features,
            sa,
            sb,
            c.kind.as_str(),
            c.length_m,
            path,
            Vec::new(),
        );
    }
    // Across each region of rooms and corridors joined by open borders,
    // from one of its doors to another, without a detour through anchors
    // (a corridor's middle may be far from two doors side by side, and a
    // corridor cut in pieces has an anchor in each): the walked path when
    // it stays in the region.
    for (region, doors) in regions(nrg) {
        for (i, &a) in doors.iter().enumerate() {
            for &b in &doors[i + 1..] {
                let mut request = RouteRequest::between(Endpoint::Space(a), Endpoint::Space(b));
                request.profile = Profile::exact();
                let Ok(routes) = shortest_route(nav, &request, &Budget::unlimited()) else {
                    continue;
                };
                let Some(r) = routes.first() else {
                    continue;
                };
                let inner = &r.spaces[1..r.spaces.len().saturating_sub(1)];
                if r.spaces.len() < 3 || !inner.iter().all(|s| region.contains(s)) {
                    continue;
                }
                if let (Some(sa), Some(sb)) = (nrg.space(a), nrg.space(b)) {
                    let through = inner.to_vec();
                    push_both(
                        &mut features,
                        sa,
                        sb,
                        "across",
                        r.length_m,
                        r.waypoints.clone(),
                        through,
                    );
                }
            }
        }
    }
    json!({
        "type": "FeatureCollection",
        "name": "nrgdb route graph",
        "features": features,
    })
}

fn space_metadata(s: &Space) -> Map<String, Value> {
    let mut m = Map::new();
    m.insert("space".into(), json!(s.id.0));
    m.insert("kind".into(), json!(s.kind.to_string()));
    if let Some(name) = &s.name {
        m.insert("name".into(), json!(name));
    }
    if s.kind == SpaceKind::Door
        && let Some(d) = crate::model::doorway(s)
    {
        m.insert("width_m".into(), json!(round_mm(d.width_m)));
    }
    m
}

fn round_mm(v: f64) -> f64 {
    (v * 1000.0).round() / 1000.0
}

fn node(id: u64, s: &Space) -> Value {
    json!({
        "type": "Feature",
        "geometry": {"type": "Point", "coordinates": s.anchor},
        "properties": {
            "id": id,
            "frame": "map",
            "metadata": Value::Object(space_metadata(s)),
        },
    })
}

fn edge(
    id: u64,
    (from, to): (u64, u64),
    (s, t): (&Space, &Space),
    kind: &str,
    through: Vec<SpaceId>,
    length_m: f64,
    path: Vec<Point>,
) -> Value {
    let mut metadata = Map::new();
    metadata.insert("from_space".into(), json!(s.id.0));
    metadata.insert("to_space".into(), json!(t.id.0));
    metadata.insert("connection".into(), json!(kind));
    if !through.is_empty() {
        let ids: Vec<u32> = through.iter().map(|x| x.0).collect();
        metadata.insert("through_spaces".into(), json!(ids));
    }
    let width = |x: &Space| crate::model::doorway(x).map(|d| round_mm(d.width_m));
    if let Some(w) = width(t).or_else(|| width(s)) {
        metadata.insert("door_width_m".into(), json!(w));
    }
    let mut properties = json!({
        "id": id,
        "startid": from,
        "endid": to,
        "cost": length_m,
        "overridable": true,
        "metadata": Value::Object(metadata),
    });
    // Entering a door: an operation a robot can hook (open it, slow down).
    if t.kind == SpaceKind::Door {
        let mut op = Map::new();
        op.insert("door".into(), json!(t.id.0));
        if let Some(w) = width(t) {
            op.insert("width_m".into(), json!(w));
        }
        properties["operations"] = json!({
            "door": {"type": "door", "trigger": "ON_ENTER", "metadata": Value::Object(op)}
        });
    }
    json!({
        "type": "Feature",
        "geometry": {"type": "MultiLineString", "coordinates": [path]},
        "properties": properties,
    })
}

/// The regions of rooms and corridors joined by open borders (each a
/// sorted list of spaces), each with the doors that lead into it.
fn regions(nrg: &Nrg) -> Vec<(Vec<SpaceId>, Vec<SpaceId>)> {
    let ids: Vec<SpaceId> = nrg.spaces().iter().map(|s| s.id).collect();
    let at: HashMap<SpaceId, usize> = ids.iter().enumerate().map(|(i, id)| (*id, i)).collect();
    let mut parent: Vec<usize> = (0..ids.len()).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let door = |id: SpaceId| nrg.space(id).is_some_and(|s| s.kind == SpaceKind::Door);
    for c in nrg.connections() {
        if c.kind != ConnectionKind::Open || door(c.a) || door(c.b) {
            continue;
        }
        if let (Some(&i), Some(&j)) = (at.get(&c.a), at.get(&c.b)) {
            let (ri, rj) = (root(&mut parent, i), root(&mut parent, j));
            parent[ri] = rj;
        }
    }
    let mut by_root: std::collections::BTreeMap<usize, (Vec<SpaceId>, Vec<SpaceId>)> =
        std::collections::BTreeMap::new();
    for (i, id) in ids.iter().enumerate() {
        if !door(*id) {
            let r = root(&mut parent, i);
            by_root.entry(r).or_default().0.push(*id);
        }
    }
    for c in nrg.connections() {
        if !c.kind.is_navigable() {
            continue;
        }
        for (d, s) in [(c.a, c.b), (c.b, c.a)] {
            if door(d)
                && !door(s)
                && let Some(&i) = at.get(&s)
            {
                let r = root(&mut parent, i);
                if let Some(entry) = by_root.get_mut(&r) {
                    entry.1.push(d);
                }
            }
        }
    }
    by_root
        .into_values()
        .map(|(spaces, mut doors)| {
            doors.sort_unstable();
            doors.dedup();
            (spaces, doors)
        })
        .collect()
}

/// Why a document is not a graph Nav2's GeoJSON loader takes.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("feature {feature}: {message}")]
pub struct Nav2Error {
    /// Position of the feature in `features` (0 for the document).
    pub feature: usize,
    /// What is wrong.
    pub message: String,
}

/// A graph read back: nodes (id, position) and edges (id, start, end,
/// cost, path).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Nav2Graph {
    /// Node id and position.
    pub nodes: Vec<(u64, [f64; 2])>,
    /// The edges.
    pub edges: Vec<Nav2Edge>,
}

/// One directed edge of a graph read back.
#[derive(Debug, Clone, PartialEq)]
pub struct Nav2Edge {
    /// Its id.
    pub id: u64,
    /// The node it starts at.
    pub start: u64,
    /// The node it ends at.
    pub end: u64,
    /// Its cost, when given.
    pub cost: Option<f64>,
    /// Its polyline.
    pub path: Vec<[f64; 2]>,
}

/// Reads a Nav2 route graph and checks it as `GeoJsonGraphFileLoader`
/// does: `Point` features are nodes and `LineString`/`MultiLineString`
/// ones edges; there are both; every id, `startid` and `endid` is an
/// unsigned integer; ids are unique across nodes and edges; every edge's
/// ends are nodes; a node's coordinates are two numbers; `cost` is a
/// number and `overridable` a boolean when present; `metadata` holds only
/// numbers, booleans, strings, arrays of them and objects of them;
/// `operations` have a string `type` and a `trigger` of `NODE`,
/// `ON_ENTER` or `ON_EXIT`.
pub fn check_nav2(doc: &Value) -> Result<Nav2Graph, Nav2Error> {
    let err = |feature: usize, message: String| Nav2Error { feature, message };
    let features = doc
        .get("features")
        .and_then(Value::as_array)
        .ok_or_else(|| err(0, "no \"features\" array".into()))?;
    let mut graph = Nav2Graph::default();
    let mut ids = std::collections::BTreeSet::new();
    let uint = |f: usize, p: &Value, key: &str| -> Result<u64, Nav2Error> {
        p.get(key)
            .and_then(Value::as_u64)
            .ok_or_else(|| err(f, format!("properties.{key} is not an unsigned integer")))
    };
    for (f, feature) in features.iter().enumerate() {
        let kind = feature.pointer("/geometry/type").and_then(Value::as_str);
        let p = feature.get("properties").cloned().unwrap_or(Value::Null);
        let is_edge = matches!(kind, Some("LineString" | "MultiLineString"));
        if kind != Some("Point") && !is_edge {
            continue;
        }
        let id = uint(f, &p, "id")?;
        if !ids.insert(id) {
            return Err(err(f, format!("id {id} is used twice")));
        }
        if let Some(m) = p.get("metadata") {
            check_metadata(m).map_err(|m| err(f, format!("metadata: {m}")))?;
        }
        check_operations(&p).map_err(|m| err(f, m))?;
        let coords = feature.pointer("/geometry/coordinates");
        if !is_edge {
            let xy = coords
                .and_then(Value::as_array)
                .and_then(|a| Some([a.first()?.as_f64()?, a.get(1)?.as_f64()?]))
                .ok_or_else(|| err(f, "a node's coordinates are not two numbers".into()))?;
            graph.nodes.push((id, xy));
            continue;
        }
        let cost = match p.get("cost") {
            None => None,
            Some(c) => Some(
                c.as_f64()
                    .ok_or_else(|| err(f, "properties.cost is not a number".into()))?,
            ),
        };
        if p.get("overridable").is_some_and(|o| !o.is_boolean()) {
            return Err(err(f, "properties.overridable is not a boolean".into()));
        }
        let path = polyline(kind, coords);
        graph.edges.push(Nav2Edge {
            id,
            start: uint(f, &p, "startid")?,
            end: uint(f, &p, "endid")?,
            cost,
            path,
        });
    }
    if graph.nodes.is_empty() || graph.edges.is_empty() {
        return Err(err(0, "a graph needs nodes and edges".into()));
    }
    let nodes: std::collections::BTreeSet<u64> = graph.nodes.iter().map(|n| n.0).collect();
    for e in &graph.edges {
        let id = e.id;
        for (which, n) in [("start", &e.start), ("end", &e.end)] {
            if !nodes.contains(n) {
                return Err(err(
                    0,
                    format!("edge {id}: {which} node {n} does not exist"),
                ));
            }
        }
    }
    Ok(graph)
}

fn polyline(kind: Option<&str>, coords: Option<&Value>) -> Vec<[f64; 2]> {
    let point = |v: &Value| Some([v.get(0)?.as_f64()?, v.get(1)?.as_f64()?]);
    let line = |v: &Value| -> Vec<[f64; 2]> {
        v.as_array()
            .map(|a| a.iter().filter_map(point).collect())
            .unwrap_or_default()
    };
    match (kind, coords) {
        (Some("LineString"), Some(c)) => line(c),
        (Some("MultiLineString"), Some(c)) => c
            .as_array()
            .map(|parts| parts.iter().flat_map(line).collect())
            .unwrap_or_default(),
        _ => Vec::new(),
    }
}

fn check_metadata(m: &Value) -> Result<(), String> {
    let Some(obj) = m.as_object() else {
        return Err("is not an object".into());
    };
    let primitive = |v: &Value| v.is_number() || v.is_boolean() || v.is_string();
    for (k, v) in obj {
        let ok = match v {
            Value::Object(_) => check_metadata(v).is_ok(),
            Value::Array(items) => items.iter().all(primitive),
            _ => primitive(v),
        };
        if !ok {
            return Err(format!(
                "{k} is {v}: not a number, boolean, string, array or object of them"
            ));
        }
    }
    Ok(())
}

fn check_operations(p: &Value) -> Result<(), String> {
    let Some(ops) = p.get("operations") else {
        return Ok(());
    };
    let list: Vec<&Value> = match ops {
        Value::Object(o) => o.values().collect(),
        Value::Array(a) => a.iter().collect(),
        _ => return Err("operations is neither an object nor an array".into()),
    };
    for op in list {
        if !op.get("type").is_some_and(Value::is_string) {
            return Err("an operation has no string \"type\"".into());
        }
        let trigger = op.get("trigger").and_then(Value::as_str);
        if !matches!(trigger, Some("NODE" | "ON_ENTER" | "ON_EXIT")) {
            return Err(format!(
                "an operation's trigger is {trigger:?}, not NODE, ON_ENTER or ON_EXIT"
            ));
        }
        if let Some(m) = op.get("metadata") {
            check_metadata(m).map_err(|m| format!("operation metadata: {m}"))?;
        }
    }
    Ok(())
}

/// Whether `nrg` has what a Nav2 graph needs (a navigable connection).
pub fn has_route_graph(nrg: &Nrg) -> bool {
    nrg.connections().iter().any(|c| c.kind.is_navigable())
}
