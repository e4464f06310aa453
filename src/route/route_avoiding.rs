//! One route through a request's stops, avoiding a given set of spaces:
//! leg by leg through the waypoints on the navigation layer, skipping
//! avoided spaces and doors too narrow for the profile. Shared by
//! [`super::shortest_route`] and [`super::alternatives`] (which asks for it
//! once per set of passages to avoid), so neither imports the other.

use super::nav::Walk;
use super::steps::describe;
use super::{Budget, Endpoint, NavMesh, Route, RouteError, RouteRequest};
use crate::model::SpaceId;

/// Checks the request and the avoided spaces against its stops.
pub(crate) fn check_request(nav: &NavMesh, request: &RouteRequest) -> Result<(), RouteError> {
    request.profile.validate()?;
    for stop in stops(request) {
        if let Endpoint::Space(id) = stop {
            if nav.nrg().space(*id).is_none() {
                return Err(RouteError::NotNavigable(*id));
            }
            if request.avoid.contains(id) {
                return Err(RouteError::AvoidedEndpoint(*id));
            }
        }
    }
    Ok(())
}

fn stops(request: &RouteRequest) -> impl Iterator<Item = &Endpoint> {
    std::iter::once(&request.from)
        .chain(&request.via)
        .chain(std::iter::once(&request.to))
}

/// The shortest route through the request's stops avoiding `avoid`, or
/// `None` when a leg has no route.
pub(crate) fn route_avoiding(
    nav: &NavMesh,
    request: &RouteRequest,
    avoid: &[SpaceId],
    budget: &Budget,
) -> Result<Option<Route>, RouteError> {
    if nav.nrg().has_levels() {
        return super::across_levels::route_across_levels(nav, request, avoid, budget);
    }
    check_request(nav, request)?;
    let level = nav.level(&request.profile);
    let banned = nav.banned(&level, avoid, &request.profile);
    let ends = stops(request)
        .map(|s| nav.end(&level, s))
        .collect::<Result<Vec<_>, _>>()?;
    for end in &ends {
        if banned[end.space as usize] {
            let id = level.mesh.space_ids[end.space as usize];
            if avoid.contains(&id) {
                return Err(RouteError::AvoidedEndpoint(id));
            }
        }
    }
    let mut legs: Vec<Walk> = Vec::with_capacity(ends.len() - 1);
    for pair in ends.windows(2) {
        let found = nav.walk(&level, &pair[0], &pair[1], &banned, budget);
        if budget.is_expired() {
            return Err(RouteError::Timeout(budget.limit_ms()));
        }
        match found {
            Some(w) => legs.push(w),
            None => return Ok(None),
        }
    }
    Ok(Some(describe(
        nav.nrg(),
        &level.mesh,
        &legs,
        &request.profile,
    )))
}
