//! Spaces reachable within a walking distance: Dijkstra bounded by distance.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::graph::to_micrometres;
use super::{Budget, RouteError, RouteGraph};
use crate::model::SpaceId;

/// Every navigable space whose shortest walking distance from `from` is at
/// most `within_m` metres, with that distance, nearest first (then by id).
/// `from` itself is included at distance 0.
pub fn reachable_within(
    graph: &RouteGraph,
    from: SpaceId,
    within_m: f64,
    budget: &Budget,
) -> Result<Vec<(SpaceId, f64)>, RouteError> {
    let start = graph.node(from).ok_or(RouteError::NotNavigable(from))?;
    let bound = to_micrometres(within_m);
    let mut dist = vec![u64::MAX; graph.len()];
    let mut heap = BinaryHeap::new();
    dist[start as usize] = 0;
    heap.push(Reverse((0u64, start)));
    while let Some(Reverse((d, n))) = heap.pop() {
        if budget.check() {
            return Err(RouteError::Timeout(budget.limit_ms()));
        }
        if d > dist[n as usize] {
            continue;
        }
        for &(m, cost) in graph.edges(n) {
            let nd = d.saturating_add(cost);
            if nd <= bound && nd < dist[m as usize] {
                dist[m as usize] = nd;
                heap.push(Reverse((nd, m)));
            }
        }
    }
    let mut out: Vec<(SpaceId, f64)> = dist
        .iter()
        .enumerate()
        .filter(|(_, d)| **d != u64::MAX)
        .map(|(n, d)| (graph.space(n as u32), *d as f64 / 1e6))
        .collect();
    out.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::demo;

    #[test]
    fn reach_grows_with_distance() {
        let nrg = demo::building(5);
        let g = RouteGraph::new(&nrg);
        let from = nrg.spaces()[0].id;
        let near = reachable_within(&g, from, 3.0, &Budget::unlimited()).unwrap();
        let far = reachable_within(&g, from, 1000.0, &Budget::unlimited()).unwrap();
        assert_eq!(near[0], (from, 0.0));
        assert!(near.len() < far.len());
        assert!(near.iter().all(|(_, d)| *d <= 3.0));
        // Every space is a node; spaces without a navigable connection
        // (the demo's storage room) are never reached.
        let isolated = nrg
            .spaces()
            .iter()
            .filter(|s| nrg.connections_of(s.id).all(|c| !c.kind.is_navigable()))
            .count();
        assert_eq!(far.len(), g.len() - isolated);
    }
}
