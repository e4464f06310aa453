//! Nav2 Route Server graphs out (issue 24): the graph follows every rule
//! of `nav2_route`'s GeoJsonGraphFileLoader, edge costs are the lengths of
//! their own polylines, every link goes both ways, and a shortest path
//! over the graph (Dijkstra written here) walks about as far as nrgdb's
//! own route between the same rooms.

use std::collections::{BTreeMap, BinaryHeap};
use std::sync::Arc;

use nrgdb::format::nav2::{Nav2Edge, check_nav2, to_nav2};
use nrgdb::model::{SpaceId, SpaceKind};
use nrgdb::route::{Budget, NavMesh, Profile, RouteRequest, shortest_route};
use serde_json::{Value, json};

use crate::support::nrgdb_ok;

fn length(p: &[[f64; 2]]) -> f64 {
    p.windows(2)
        .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
        .sum()
}

/// Dijkstra over the graph's directed edges: (cost, node ids).
fn dijkstra(edges: &[Nav2Edge], from: u64, to: u64) -> f64 {
    let mut out: BTreeMap<u64, Vec<(u64, f64)>> = BTreeMap::new();
    for e in edges {
        out.entry(e.start)
            .or_default()
            .push((e.end, e.cost.unwrap()));
    }
    let mut best: BTreeMap<u64, f64> = BTreeMap::new();
    let mut heap = BinaryHeap::new();
    heap.push((std::cmp::Reverse(0u64), from));
    best.insert(from, 0.0);
    while let Some((std::cmp::Reverse(bits), n)) = heap.pop() {
        let d = f64::from_bits(bits);
        if n == to {
            return d;
        }
        if d > best[&n] {
            continue;
        }
        for (m, c) in out.get(&n).into_iter().flatten() {
            let nd = d + c;
            if best.get(m).is_none_or(|b| nd < *b) {
                best.insert(*m, nd);
                heap.push((std::cmp::Reverse(nd.to_bits()), *m));
            }
        }
    }
    f64::INFINITY
}

#[test]
fn the_demo_building_is_a_graph_nav2_loads() {
    let nrg = nrgdb::query::demo::building(8);
    let nav = NavMesh::new(Arc::new(nrg.clone()));
    let doc = to_nav2(&nav);
    let graph = check_nav2(&doc).unwrap();
    assert_eq!(graph.nodes.len(), nrg.spaces().len());
    // Ids unique across nodes and edges (checked by check_nav2) and every
    // edge's cost is the length of its own polyline, which starts and ends
    // at its nodes.
    let at: BTreeMap<u64, [f64; 2]> = graph.nodes.iter().copied().collect();
    for Nav2Edge {
        id,
        start: s,
        end: e,
        cost,
        path,
    } in &graph.edges
    {
        let cost = cost.unwrap();
        assert!(
            (length(path) - cost).abs() < 1e-6,
            "edge {id}: {cost} vs {}",
            length(path)
        );
        assert_eq!(path.first(), at.get(s), "edge {id}");
        assert_eq!(path.last(), at.get(e), "edge {id}");
        // Directed: the way back is another edge, of the same cost.
        assert!(
            graph
                .edges
                .iter()
                .any(|b| b.start == *e && b.end == *s && (b.cost.unwrap() - cost).abs() < 1e-9),
            "edge {id} has no way back"
        );
    }
    // Every door has an edge into it that a robot can hook.
    let features = doc["features"].as_array().unwrap();
    for d in nrg.spaces().iter().filter(|s| s.kind == SpaceKind::Door) {
        let hooked = features.iter().any(|f| {
            f["properties"]["operations"]["door"]["metadata"]["door"] == json!(d.id.0)
                && f["properties"]["operations"]["door"]["trigger"] == "ON_ENTER"
        });
        assert!(hooked, "door {}", d.id);
    }
    // Over the graph, rooms are about as far apart as nrgdb walks them
    // (the graph passes doorway middles; the route hugs corners).
    let node_of = |id: SpaceId| {
        features
            .iter()
            .find(|f| {
                f["geometry"]["type"] == "Point"
                    && f["properties"]["metadata"]["space"] == json!(id.0)
            })
            .and_then(|f| f["properties"]["id"].as_u64())
            .unwrap()
    };
    let rooms: Vec<SpaceId> = nrg
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Room)
        .map(|s| s.id)
        .collect();
    let mut compared = 0;
    let mut worst = 0f64;
    for (i, &a) in rooms.iter().enumerate() {
        for &b in rooms.iter().skip(i + 1).step_by(3) {
            let mut req = RouteRequest::new(a, b);
            req.profile = Profile::exact();
            let Some(route) = shortest_route(&nav, &req, &Budget::unlimited())
                .unwrap()
                .into_iter()
                .next()
            else {
                continue;
            };
            let over_graph = dijkstra(&graph.edges, node_of(a), node_of(b));
            let ratio = over_graph / route.length_m;
            worst = worst.max(ratio);
            assert!(
                (0.999..=1.10).contains(&ratio),
                "{a} → {b}: graph {over_graph} m, route {} m",
                route.length_m
            );
            compared += 1;
        }
    }
    assert!(compared >= 10, "{compared} pairs");
    eprintln!("{compared} room pairs, graph / route at most {worst:.3}");
}

#[test]
fn broken_graphs_are_refused_as_nav2_would() {
    let nav = NavMesh::new(Arc::new(nrgdb::query::demo::building(2)));
    let good = to_nav2(&nav);
    let with = |f: &dyn Fn(&mut Value)| {
        let mut doc = good.clone();
        f(&mut doc);
        check_nav2(&doc).unwrap_err().to_string()
    };
    let edge_at = good["features"]
        .as_array()
        .unwrap()
        .iter()
        .position(|f| f["geometry"]["type"] == "MultiLineString")
        .unwrap();
    let e = format!("/features/{edge_at}/properties");
    assert!(
        with(&|d| d.pointer_mut(&e).unwrap()["endid"] = json!(99_999))
            .contains("end node 99999 does not exist")
    );
    assert!(with(&|d| d.pointer_mut(&e).unwrap()["id"] = json!(0)).contains("id 0 is used twice"));
    assert!(
        with(&|d| d.pointer_mut(&e).unwrap()["startid"] = json!(-1))
            .contains("startid is not an unsigned")
    );
    assert!(
        with(&|d| d.pointer_mut(&e).unwrap()["metadata"]["x"] = Value::Null).contains("metadata")
    );
    assert!(
        with(&|d| d.pointer_mut(&e).unwrap()["operations"] =
            json!({"a": {"type": "a", "trigger": "SOMETIMES"}}))
        .contains("SOMETIMES")
    );
    assert!(with(&|d| d["features"] = json!([])).contains("needs nodes and edges"));
    let nodes_only = with(&|d| {
        let keep: Vec<Value> = d["features"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|f| f["geometry"]["type"] == "Point")
            .cloned()
            .collect();
        d["features"] = Value::Array(keep);
    });
    assert!(nodes_only.contains("needs nodes and edges"), "{nodes_only}");
}

#[test]
fn the_cli_and_the_server_write_it() {
    let dir = tempfile::tempdir().unwrap();
    nrgdb_ok(dir.path(), &["demo", "--dir", "d", "--db", "t.sqlite"]);
    nrgdb_ok(
        dir.path(),
        &[
            "export",
            "demo",
            "--format",
            "nav2",
            "--out",
            "graph.geojson",
            "--db",
            "t.sqlite",
        ],
    );
    let doc: Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("graph.geojson")).unwrap()).unwrap();
    let graph = check_nav2(&doc).unwrap();
    assert!(graph.edges.len() > graph.nodes.len());
    let rt = tokio::runtime::Runtime::new().unwrap();
    rt.block_on(async {
        let s = crate::server_client::TestServer::read_only().await;
        let reply = s.get("/maps/building/revisions/latest/nav2").await;
        assert_eq!(reply.status, 200);
        let served = reply.json();
        let g = check_nav2(&served).unwrap();
        assert_eq!(g.nodes.len(), 13);
        s.get("/maps/nowhere/revisions/latest/nav2")
            .await
            .assert_error(404, "map");
        s.stop().await;
    });
}
