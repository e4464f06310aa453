//! Spaces reachable within a walking distance: Dijkstra over the gates of
//! the navigation layer, bounded by the walked length to each anchor, each
//! space found then measured by the walk a route to it takes.

use super::{Budget, Endpoint, NavMesh, Profile, RouteError};
use crate::model::SpaceId;

/// Every space whose anchor is at most `within_m` metres walked from
/// `from` (with `profile`), with that distance, nearest first (then by id).
/// A space `from` is included at distance 0.
pub fn reachable_within(
    nav: &NavMesh,
    from: &Endpoint,
    within_m: f64,
    profile: &Profile,
    budget: &Budget,
) -> Result<Vec<(SpaceId, f64)>, RouteError> {
    profile.validate()?;
    let level = nav.level(profile);
    let start = nav.end(&level, from)?;
    let banned = nav.banned(&level, &[], profile);
    // The search sums lengths through the doorways' crossing points, a few
    // centimetres over the straightened walk: search a little further,
    // then measure each space found by the walk ROUTE would answer.
    let slack = (0.05 * within_m).clamp(0.5, 5.0);
    let dist = nav
        .distances(&level, &start, &banned, within_m + slack, budget)
        .ok_or(RouteError::Timeout(budget.limit_ms()))?;
    let ids = nav.space_ids(&level);
    let mut out: Vec<(SpaceId, f64)> = Vec::new();
    for (s, d) in dist.iter().enumerate() {
        if !d.is_finite() {
            continue;
        }
        if s == start.space as usize {
            // Its own space: the search measured the walk to its anchor.
            if *d <= within_m {
                out.push((ids[s], *d));
            }
            continue;
        }
        let to = nav.end(&level, &Endpoint::Space(ids[s]))?;
        let walked = nav
            .walk(&level, &start, &to, &banned, budget)
            .map_or(*d, |w| w.length_m);
        if budget.is_expired() {
            return Err(RouteError::Timeout(budget.limit_ms()));
        }
        if walked <= within_m {
            out.push((ids[s], walked));
        }
    }
    out.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
    Ok(out)
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use super::*;
    use crate::query::demo;
    use crate::route::{RouteRequest, shortest_route};

    #[test]
    fn reach_grows_with_distance() {
        let nrg = demo::building(5);
        let nav = NavMesh::new(Arc::new(nrg.clone()));
        let from = Endpoint::Space(nrg.spaces()[0].id);
        let p = Profile::default();
        let b = Budget::unlimited();
        let near = reachable_within(&nav, &from, 3.0, &p, &b).unwrap();
        let far = reachable_within(&nav, &from, 1000.0, &p, &b).unwrap();
        assert_eq!(near[0], (nrg.spaces()[0].id, 0.0));
        assert!(near.len() < far.len());
        assert!(near.iter().all(|(_, d)| *d <= 3.0));
        // Each distance is the length of the route to that space.
        for (id, d) in &far {
            let request = RouteRequest::between(from, Endpoint::Space(*id));
            let routes = shortest_route(&nav, &request, &b).unwrap();
            assert!((routes[0].length_m - d).abs() < 1e-9, "{id:?}: {d} m");
        }
        // Spaces without a navigable connection (the demo's storage room)
        // are never reached.
        let isolated = nrg
            .spaces()
            .iter()
            .filter(|s| nrg.connections_of(s.id).all(|c| !c.kind.is_navigable()))
            .count();
        assert_eq!(far.len(), nrg.spaces().len() - isolated);
    }
}
