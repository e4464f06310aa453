//! Property tests of ROUTE on random graphs against a plain Dijkstra.

use std::collections::BTreeSet;

use nrgdb::model::{Connection, ConnectionKind, Nrg, Space, SpaceId, SpaceKind};
use nrgdb::query::{MemorySource, QueryResult, Session};
use nrgdb::route::{Budget, Route, RouteGraph, RouteRequest, shortest_route};
use proptest::prelude::*;

/// A random navigable graph: `n` spaces, edges with lengths in metres.
fn graph() -> impl Strategy<Value = Nrg> {
    (2usize..25).prop_flat_map(|n| {
        let edge = (1..=n as u32, 1..=n as u32, 1u32..10_000);
        proptest::collection::vec(edge, 0..n * 3).prop_map(move |edges| {
            let kinds = [SpaceKind::Room, SpaceKind::Corridor, SpaceKind::Door];
            let spaces = (1..=n as u32)
                .map(|i| {
                    let (x, y) = (f64::from(i) * 3.0, 0.0);
                    let square = vec![[x, y], [x + 1.0, y], [x + 1.0, y + 1.0], [x, y + 1.0]];
                    Space::new(
                        SpaceId(i),
                        kinds[i as usize % 3],
                        [x + 0.5, y + 0.5],
                        square,
                    )
                })
                .collect();
            let mut seen = BTreeSet::new();
            let connections = edges
                .into_iter()
                .filter(|(a, b, _)| a != b && seen.insert((*a.min(b), *a.max(b))))
                .map(|(a, b, mm)| Connection {
                    a: SpaceId(a),
                    b: SpaceId(b),
                    kind: ConnectionKind::Door,
                    length_m: f64::from(mm) / 1000.0,
                })
                .collect();
            Nrg::new(spaces, connections).unwrap()
        })
    })
}

/// Textbook O(n²) Dijkstra on f64 lengths, skipping `avoid`.
fn reference(nrg: &Nrg, from: SpaceId, to: SpaceId, avoid: &[SpaceId]) -> Option<f64> {
    let ids: Vec<SpaceId> = nrg.spaces().iter().map(|s| s.id).collect();
    let mut dist: Vec<f64> = vec![f64::INFINITY; ids.len()];
    let mut done = vec![false; ids.len()];
    let at = |id: SpaceId| ids.iter().position(|x| *x == id).unwrap();
    dist[at(from)] = 0.0;
    loop {
        let next = (0..ids.len())
            .filter(|i| !done[*i] && dist[*i].is_finite())
            .min_by(|a, b| dist[*a].total_cmp(&dist[*b]));
        let Some(u) = next else { break };
        done[u] = true;
        for c in nrg.connections_of(ids[u]) {
            let v = c.other(ids[u]).unwrap();
            if avoid.contains(&v) {
                continue;
            }
            let nd = dist[u] + c.length_m;
            if nd < dist[at(v)] {
                dist[at(v)] = nd;
            }
        }
    }
    let d = dist[at(to)];
    d.is_finite().then_some(d)
}

fn valid(nrg: &Nrg, r: &Route) -> bool {
    let sum: Option<f64> = r
        .spaces
        .windows(2)
        .map(|w| nrg.connection(w[0], w[1]).map(|c| c.length_m))
        .sum();
    sum.is_some_and(|s| (s - r.length_m).abs() < 1e-9)
}

const TOLERANCE: f64 = 1e-4; // costs are rounded to micrometres per edge

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn route_statement_equals_reference(nrg in graph(), a in 1u32..25, b in 1u32..25) {
        let n = nrg.spaces().len() as u32;
        let (a, b) = (SpaceId(1 + a % n), SpaceId(1 + b % n));
        let expected = reference(&nrg, a, b, &[]);
        let mut source = MemorySource::new();
        source.insert("g", nrg.clone());
        let mut session = Session::with_default_map(source).unwrap();
        let mut results = session.execute(&format!("ROUTE FROM {a} TO space {b}")).unwrap();
        let QueryResult::Routes(routes) = results.remove(0).unwrap() else { panic!() };
        match expected {
            None => prop_assert!(routes.is_empty()),
            Some(d) => {
                prop_assert_eq!(routes.len(), 1);
                prop_assert!((routes[0].length_m - d).abs() < TOLERANCE, "{} vs {}", routes[0].length_m, d);
                prop_assert!(valid(&nrg, &routes[0]));
                prop_assert_eq!(routes[0].spaces.first(), Some(&a));
                prop_assert_eq!(routes[0].spaces.last(), Some(&b));
            }
        }
    }

    #[test]
    fn via_and_avoid_are_honoured(nrg in graph(), a in 1u32..25, b in 1u32..25, c in 1u32..25, d in 1u32..25) {
        let n = nrg.spaces().len() as u32;
        let [a, b, c, d] = [a, b, c, d].map(|x| SpaceId(1 + x % n));
        let g = RouteGraph::new(&nrg);
        let mut via = RouteRequest::new(a, b);
        via.via = vec![c];
        let routes = shortest_route(&g, &nrg, &via, &Budget::unlimited()).unwrap();
        let legs = reference(&nrg, a, c, &[]).zip(reference(&nrg, c, b, &[])).map(|(x, y)| x + y);
        match legs {
            None => prop_assert!(routes.is_empty()),
            Some(len) => {
                prop_assert!((routes[0].length_m - len).abs() < TOLERANCE);
                prop_assert!(routes[0].spaces.contains(&c));
                prop_assert!(valid(&nrg, &routes[0]));
            }
        }
        let mut avoid = RouteRequest::new(a, b);
        avoid.avoid = vec![d];
        let got = shortest_route(&g, &nrg, &avoid, &Budget::unlimited());
        if d == a || d == b {
            prop_assert!(got.is_err());
        } else {
            let routes = got.unwrap();
            match reference(&nrg, a, b, &[d]) {
                None => prop_assert!(routes.is_empty()),
                Some(len) => {
                    prop_assert!((routes[0].length_m - len).abs() < TOLERANCE);
                    prop_assert!(!routes[0].spaces.contains(&d));
                }
            }
        }
    }

    #[test]
    fn alternatives_are_loopless_distinct_sorted(nrg in graph(), a in 1u32..25, b in 1u32..25, k in 1usize..6) {
        let n = nrg.spaces().len() as u32;
        let (a, b) = (SpaceId(1 + a % n), SpaceId(1 + b % n));
        let g = RouteGraph::new(&nrg);
        let mut req = RouteRequest::new(a, b);
        req.alternatives = k;
        let routes = shortest_route(&g, &nrg, &req, &Budget::unlimited()).unwrap();
        prop_assert!(routes.len() <= k);
        prop_assert_eq!(routes.is_empty(), reference(&nrg, a, b, &[]).is_none());
        if let (Some(first), Some(d)) = (routes.first(), reference(&nrg, a, b, &[])) {
            prop_assert!((first.length_m - d).abs() < TOLERANCE);
        }
        for r in &routes {
            prop_assert!(valid(&nrg, r));
            let unique: BTreeSet<_> = r.spaces.iter().collect();
            prop_assert_eq!(unique.len(), r.spaces.len(), "loop in {:?}", r.spaces);
        }
        for w in routes.windows(2) {
            prop_assert!(w[0].length_m <= w[1].length_m + TOLERANCE);
        }
        let distinct: BTreeSet<_> = routes.iter().map(|r| r.spaces.clone()).collect();
        prop_assert_eq!(distinct.len(), routes.len());
    }
}
