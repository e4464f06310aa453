//! Shortest route: Dijkstra on dense arrays, leg by leg through the waypoints,
//! skipping avoided spaces.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::{Budget, Route, RouteError, RouteGraph, RouteRequest, alternatives};
use crate::model::{Nrg, SpaceId};

/// Nodes of start, waypoints and goal, and the avoided-node mask.
pub(crate) fn prepare(
    graph: &RouteGraph,
    request: &RouteRequest,
) -> Result<(Vec<u32>, Vec<bool>), RouteError> {
    let node = |id: SpaceId| graph.node(id).ok_or(RouteError::NotNavigable(id));
    let mut stops = vec![node(request.from)?];
    for via in &request.via {
        stops.push(node(*via)?);
    }
    stops.push(node(request.to)?);
    let mut avoided = vec![false; graph.len()];
    for id in &request.avoid {
        // Avoiding a space that cannot be entered anyway is harmless.
        if let Some(n) = graph.node(*id) {
            avoided[n as usize] = true;
        }
    }
    if let Some(&bad) = stops.iter().find(|n| avoided[**n as usize]) {
        return Err(RouteError::AvoidedEndpoint(graph.space(bad)));
    }
    Ok((stops, avoided))
}

/// Shortest path between two nodes avoiding the masked ones, in
/// micrometres: Dijkstra (1959) with a binary heap over dense arrays, stopping
/// when the goal is settled. `None` when unreachable or out of time.
pub(crate) fn shortest_leg(
    graph: &RouteGraph,
    avoided: &[bool],
    from: u32,
    to: u32,
    budget: &Budget,
) -> Option<(Vec<u32>, u64)> {
    let mut dist = vec![u64::MAX; graph.len()];
    let mut parent = vec![u32::MAX; graph.len()];
    let mut heap = BinaryHeap::new();
    *dist.get_mut(from as usize)? = 0;
    heap.push(Reverse((0u64, from)));
    while let Some(Reverse((d, u))) = heap.pop() {
        if budget.check() {
            return None;
        }
        if u == to {
            break;
        }
        if d > dist[u as usize] {
            continue;
        }
        for &(v, cost) in graph.edges(u) {
            let nd = d.saturating_add(cost);
            if !avoided[v as usize] && nd < dist[v as usize] {
                dist[v as usize] = nd;
                parent[v as usize] = u;
                heap.push(Reverse((nd, v)));
            }
        }
    }
    let total = *dist.get(to as usize)?;
    if total == u64::MAX {
        return None;
    }
    let mut path = vec![to];
    let mut at = to;
    while at != from {
        at = parent[at as usize];
        path.push(at);
    }
    path.reverse();
    Some((path, total))
}

/// The shortest route for `request` (or `request.alternatives` of them,
/// shortest first). An empty list means there is no route.
///
/// Errors: an endpoint or waypoint that is not a navigable space, an
/// endpoint that is also avoided, VIA with more than one alternative, or the
/// budget running out.
pub fn shortest_route(
    graph: &RouteGraph,
    nrg: &Nrg,
    request: &RouteRequest,
    budget: &Budget,
) -> Result<Vec<Route>, RouteError> {
    if request.alternatives > 1 {
        if !request.via.is_empty() {
            return Err(RouteError::AlternativesWithVia);
        }
        return alternatives(graph, nrg, request, budget);
    }
    let (stops, avoided) = prepare(graph, request)?;
    let mut path: Vec<u32> = vec![stops[0]];
    for leg in stops.windows(2) {
        let found = shortest_leg(graph, &avoided, leg[0], leg[1], budget);
        if budget.is_expired() {
            return Err(RouteError::Timeout(budget.limit_ms()));
        }
        let Some((nodes, _)) = found else {
            return Ok(Vec::new());
        };
        path.extend(nodes.into_iter().skip(1));
    }
    let ids = path.into_iter().map(|n| graph.space(n)).collect();
    Ok(vec![Route::from_path(nrg, ids)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::demo;

    fn ids(nrg: &Nrg, labels: &[&str]) -> Vec<SpaceId> {
        labels
            .iter()
            .map(|l| nrg.spaces().iter().find(|s| s.label() == *l).unwrap().id)
            .collect()
    }

    #[test]
    fn route_along_the_corridor_passes_doors() {
        let nrg = demo::building(4);
        let g = RouteGraph::new(&nrg);
        let s = ids(&nrg, &["Kitchen", "Library"]);
        let r = shortest_route(
            &g,
            &nrg,
            &RouteRequest::new(s[0], s[1]),
            &Budget::unlimited(),
        )
        .unwrap();
        assert_eq!(r.len(), 1);
        assert_eq!(r[0].spaces.first(), Some(&s[0]));
        assert_eq!(r[0].spaces.last(), Some(&s[1]));
        assert!(!r[0].doors.is_empty());
        assert_eq!(r[0].waypoints.len(), r[0].spaces.len());
    }

    #[test]
    fn avoided_endpoint_is_an_error_and_cut_graph_has_no_route() {
        let nrg = demo::building(3);
        let g = RouteGraph::new(&nrg);
        let s = ids(&nrg, &["Kitchen", "Library"]);
        let mut req = RouteRequest::new(s[0], s[1]);
        req.avoid = vec![s[1]];
        assert_eq!(
            shortest_route(&g, &nrg, &req, &Budget::unlimited()),
            Err(RouteError::AvoidedEndpoint(s[1]))
        );
        // Avoid every corridor: the kitchen's only way out is gone.
        req.avoid = nrg
            .spaces()
            .iter()
            .filter(|s| s.kind == crate::model::SpaceKind::Corridor)
            .map(|s| s.id)
            .collect();
        assert_eq!(
            shortest_route(&g, &nrg, &req, &Budget::unlimited()),
            Ok(vec![])
        );
    }
}
