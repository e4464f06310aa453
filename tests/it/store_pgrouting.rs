//! Issue 23: the PostgreSQL engine's `nrgdb.route_edges` view is shaped
//! for pgRouting: `pgr_dijkstra` runs on it and finds the same shortest
//! path over the stored connections as a plain Dijkstra written here.

use std::collections::BTreeMap;

use nrgdb::model::{ConnectionKind, Nrg, SpaceId};
use nrgdb::store::{ImportMeta, Store};

use super::store_engines::fresh_postgres_database;

/// Shortest path length from `from` to `to` over the navigable
/// connections (a shared wall is no way through).
fn dijkstra(nrg: &Nrg, from: SpaceId, to: SpaceId) -> f64 {
    let mut dist: BTreeMap<SpaceId, f64> = BTreeMap::from([(from, 0.0)]);
    let mut done = std::collections::BTreeSet::new();
    while let Some((&u, &d)) = dist
        .iter()
        .filter(|(k, _)| !done.contains(*k))
        .min_by(|a, b| a.1.total_cmp(b.1))
    {
        if u == to {
            return d;
        }
        done.insert(u);
        for c in nrg
            .connections()
            .iter()
            .filter(|c| c.kind != ConnectionKind::Adjacent)
        {
            let v = if c.a == u {
                c.b
            } else if c.b == u {
                c.a
            } else {
                continue;
            };
            let nd = d + c.length_m;
            if dist.get(&v).is_none_or(|&old| nd < old) {
                dist.insert(v, nd);
            }
        }
    }
    f64::INFINITY
}

#[test]
fn pgr_dijkstra_runs_on_the_route_edges_view() {
    let Some(url) = fresh_postgres_database() else {
        return;
    };
    // Opening the store installs PostGIS, which pgRouting needs.
    let mut store = Store::open_db(&url).unwrap();
    let mut admin = postgres::Client::connect(&url, postgres::NoTls).unwrap();
    if let Err(e) = admin.batch_execute("CREATE EXTENSION IF NOT EXISTS pgrouting") {
        assert!(
            std::env::var("NRGDB_REQUIRE_SHARED").as_deref() != Ok("1"),
            "NRGDB_REQUIRE_SHARED=1 but pgRouting is not available (postgresql-15-pgrouting): {e:?}"
        );
        eprintln!("notice: skipping, pgRouting is not installed");
        return;
    }
    let nrg = nrgdb::fixtures::corridor_building(4);
    store.import("q", &nrg, ImportMeta::new("a", "t")).unwrap();
    let stored = store.load("q", None).unwrap();
    let rows = admin
        .query(
            "SELECT node, agg_cost FROM pgr_dijkstra(
                 'SELECT id, source, target, cost, reverse_cost FROM nrgdb.route_edges WHERE map = ''q''',
                 10, 13) ORDER BY seq",
            &[],
        )
        .unwrap();
    let nodes: Vec<i64> = rows.iter().map(|r| r.get(0)).collect();
    // Room 10 → its door → the corridor → room 13's door → room 13.
    assert_eq!(nodes, [10, 10_000, 1, 10_003, 13]);
    let cost: f64 = rows.last().unwrap().get(1);
    let expected = dijkstra(&stored, SpaceId(10), SpaceId(13));
    assert!(
        (cost - expected).abs() < 1e-9,
        "pgRouting {cost} vs {expected}"
    );
    // A second map's edges do not leak into the first's routes.
    store
        .import(
            "other",
            &nrgdb::fixtures::corridor_building(2),
            ImportMeta::new("b", "t"),
        )
        .unwrap();
    let again: f64 = admin
        .query_one(
            "SELECT agg_cost FROM pgr_dijkstra(
                 'SELECT id, source, target, cost, reverse_cost FROM nrgdb.route_edges WHERE map = ''q''',
                 10, 13) ORDER BY seq DESC LIMIT 1",
            &[],
        )
        .unwrap()
        .get(0);
    assert_eq!(again, cost);
}

/// What GIS tools (QGIS, ogr2ogr) list as layers: PostGIS registers the
/// engine's geometry columns with their type and SRID, and the polygons are
/// the building's (room 10 is 3.8 m × 4.8 m in the fixture).
#[test]
fn gis_tools_see_typed_layers_with_the_buildings_outlines() {
    let Some(url) = fresh_postgres_database() else {
        return;
    };
    let mut store = Store::open_db(&url).unwrap();
    store
        .import(
            "g",
            &nrgdb::fixtures::corridor_building(3),
            ImportMeta::new("a", "t"),
        )
        .unwrap();
    let mut admin = postgres::Client::connect(&url, postgres::NoTls).unwrap();
    let layers: Vec<(String, String, i32)> = admin
        .query(
            "SELECT f_table_name::text, type::text, srid FROM geometry_columns
             WHERE f_table_schema = 'nrgdb' ORDER BY 1",
            &[],
        )
        .unwrap()
        .iter()
        .map(|r| (r.get(0), r.get(1), r.get(2)))
        .collect();
    for (table, kind) in [
        ("connections", "LINESTRING"),
        ("latest_connections", "LINESTRING"),
        ("latest_spaces", "POLYGON"),
        ("route_edges", "LINESTRING"),
        ("spaces", "POLYGON"),
    ] {
        assert!(
            layers.contains(&(table.to_string(), kind.to_string(), 0)),
            "{table} {kind}: {layers:?}"
        );
    }
    let row = admin
        .query_one(
            "SELECT ST_Area(geom), ST_IsValid(geom) FROM nrgdb.latest_spaces
             WHERE map = 'g' AND space_id = 10",
            &[],
        )
        .unwrap();
    let (area, valid): (f64, bool) = (row.get(0), row.get(1));
    assert!((area - 3.8 * 4.8).abs() < 1e-9 && valid, "{area} {valid}");
}
