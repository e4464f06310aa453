//! Errors of routing.

use crate::model::SpaceId;

/// Why a route could not be computed (a missing route is not an error).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RouteError {
    /// The space does not exist or cannot be walked through.
    #[error("space {0} does not exist")]
    NotNavigable(SpaceId),
    /// Start, goal or a waypoint is also in AVOID.
    #[error("space {0} is both on the route and in AVOID (remove it from one of them)")]
    AvoidedEndpoint(SpaceId),
    /// VIA combined with ALTERNATIVES.
    #[error("alternatives are not computed for routes with waypoints (drop VIA or ALTERNATIVES)")]
    AlternativesWithVia,
    /// The time bound ran out.
    #[error(
        "route search exceeded its time bound of {0} ms (raise the timeout or narrow the query)"
    )]
    Timeout(u128),
}
