//! Shortest route: the one route of a request, or its alternatives when
//! it asks for more than one. The walking itself is [`route_avoiding`].

use super::route_avoiding::route_avoiding;
use super::{Budget, NavMesh, Route, RouteError, RouteRequest, alternatives};

/// The shortest route for `request` (or its alternatives when it asks for
/// more than one). An empty list when there is none.
pub fn shortest_route(
    nav: &NavMesh,
    request: &RouteRequest,
    budget: &Budget,
) -> Result<Vec<Route>, RouteError> {
    if request.alternatives > 1 {
        return alternatives(nav, request, budget);
    }
    Ok(route_avoiding(nav, request, &request.avoid, budget)?
        .into_iter()
        .collect())
}
