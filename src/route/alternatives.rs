//! k loopless alternative routes: Yen's algorithm (Yen 1971, via the
//! `pathfinding` crate), shortest first.

use pathfinding::directed::yen::yen;

use super::shortest_route::prepare;
use super::{Budget, Route, RouteError, RouteGraph, RouteRequest};
use crate::model::Nrg;

/// Up to `request.alternatives` loopless routes from `request.from` to
/// `request.to` avoiding `request.avoid`, in non-decreasing length. Waypoints
/// are not supported here (see [`super::shortest_route`]).
pub fn alternatives(
    graph: &RouteGraph,
    nrg: &Nrg,
    request: &RouteRequest,
    budget: &Budget,
) -> Result<Vec<Route>, RouteError> {
    if !request.via.is_empty() {
        return Err(RouteError::AlternativesWithVia);
    }
    let (stops, avoided) = prepare(graph, request)?;
    let (from, to) = (stops[0], stops[stops.len() - 1]);
    let found = yen(
        &from,
        |n| {
            let stop = budget.check();
            graph
                .edges(*n)
                .iter()
                .filter(|(m, _)| !stop && !avoided[*m as usize])
                .copied()
                .collect::<Vec<_>>()
        },
        |n| *n == to,
        request.alternatives.max(1),
    );
    if budget.is_expired() {
        return Err(RouteError::Timeout(budget.limit_ms()));
    }
    Ok(found
        .into_iter()
        .map(|(nodes, _)| {
            Route::from_path(nrg, nodes.into_iter().map(|n| graph.space(n)).collect())
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::demo;

    #[test]
    fn alternatives_are_distinct_and_sorted() {
        let nrg = demo::building(6);
        let g = RouteGraph::new(&nrg);
        let find = |l: &str| nrg.spaces().iter().find(|s| s.label() == l).unwrap().id;
        let mut req = RouteRequest::new(find("Kitchen"), find("Lounge"));
        req.alternatives = 3;
        let routes = alternatives(&g, &nrg, &req, &Budget::unlimited()).unwrap();
        assert!(routes.len() >= 2, "the demo building has a shortcut door");
        for w in routes.windows(2) {
            assert!(w[0].length_m <= w[1].length_m + 1e-9);
            assert_ne!(w[0].spaces, w[1].spaces);
        }
    }
}
