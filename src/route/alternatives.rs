//! k alternative routes, distinct by the doors they use (and in a
//! building, the stairs and lifts): Yen's idea on those passages (Yen
//! 1971) — each next route is the shortest that avoids one more passage
//! of a route already found, shortest first.

use std::collections::HashSet;

use super::route_avoiding::{check_request, route_avoiding};
use super::{Budget, NavMesh, Route, RouteError, RouteRequest};
use crate::model::SpaceId;

/// Most routes returned.
pub const MAX_ALTERNATIVES: usize = 10;

/// Up to `request.alternatives` (at most 10) routes from `request.from` to
/// `request.to` avoiding `request.avoid`, each through a different sequence
/// of doors (and in a building, stairs and lifts), in non-decreasing
/// length. Waypoints are not supported here.
pub fn alternatives(
    nav: &NavMesh,
    request: &RouteRequest,
    budget: &Budget,
) -> Result<Vec<Route>, RouteError> {
    if !request.via.is_empty() {
        return Err(RouteError::AlternativesWithVia);
    }
    check_request(nav, request)?;
    let k = request.alternatives.clamp(1, MAX_ALTERNATIVES);
    let ends: Vec<SpaceId> = [&request.from, &request.to]
        .iter()
        .filter_map(|e| e.space())
        .collect();
    let nrg = nav.nrg();
    let mut base = request.avoid.clone();
    base.sort_unstable();
    let Some(best) = route_avoiding(nav, request, &base, budget)? else {
        return Ok(Vec::new());
    };
    let mut seen: HashSet<Vec<SpaceId>> = HashSet::from([passages(nrg, &best)]);
    let mut tried: HashSet<Vec<SpaceId>> = HashSet::from([base.clone()]);
    let mut found = vec![(best, base)];
    let mut candidates: Vec<(Route, Vec<SpaceId>)> = Vec::new();
    while found.len() < k {
        let (last, last_avoid) = &found[found.len() - 1];
        for door in &passages(nrg, last) {
            if ends.contains(door) || last_avoid.contains(door) {
                continue;
            }
            let mut avoid = last_avoid.clone();
            avoid.push(*door);
            avoid.sort_unstable();
            if !tried.insert(avoid.clone()) {
                continue;
            }
            if let Some(route) = route_avoiding(nav, request, &avoid, budget)?
                && seen.insert(passages(nrg, &route))
            {
                candidates.push((route, avoid));
            }
        }
        let Some(next) = candidates
            .iter()
            .enumerate()
            .min_by(|a, b| a.1.0.length_m.total_cmp(&b.1.0.length_m))
            .map(|(i, _)| i)
        else {
            break;
        };
        found.push(candidates.swap_remove(next));
    }
    // The search crosses gates at sampled points, so a route found later
    // can be a little shorter than an earlier one: sort by walked length.
    let mut routes: Vec<Route> = found.into_iter().map(|(r, _)| r).collect();
    routes.sort_by(|a, b| a.length_m.total_cmp(&b.length_m));
    Ok(routes)
}

/// The doors a route passes and, in a building, the stairs and lifts it
/// takes, in order: what makes two routes different.
fn passages(nrg: &crate::model::Nrg, route: &Route) -> Vec<SpaceId> {
    use crate::model::SpaceKind;
    route
        .spaces
        .iter()
        .copied()
        .filter(|id| {
            nrg.space(*id).is_some_and(|s| {
                matches!(
                    s.kind,
                    SpaceKind::Door | SpaceKind::Stairs | SpaceKind::Elevator
                )
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use super::*;
    use crate::query::demo;

    #[test]
    fn alternatives_are_distinct_and_sorted() {
        let nrg = demo::building(6);
        let find = |l: &str| nrg.spaces().iter().find(|s| s.label() == l).unwrap().id;
        let mut req = RouteRequest::new(find("Kitchen"), find("Lounge"));
        req.alternatives = 3;
        let nav = NavMesh::new(Arc::new(nrg.clone()));
        let routes = alternatives(&nav, &req, &Budget::unlimited()).unwrap();
        assert!(routes.len() >= 2, "the demo building has a shortcut door");
        for w in routes.windows(2) {
            assert!(w[0].length_m <= w[1].length_m + 1e-9);
            assert_ne!(w[0].doors, w[1].doors);
        }
    }
}
