//! Errors of routing.

use crate::model::SpaceId;

/// Why a route could not be computed (a missing route is not an error).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum RouteError {
    /// The space does not exist or has no walkable area.
    #[error("space {0} does not exist or has no walkable area")]
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
    /// A point lies outside every space.
    #[error("({x}, {y}) is outside every space{}", match nearest {
        Some((id, d)) => format!("; the nearest is space {id}, {d:.2} m away"),
        None => String::new(),
    })]
    Outside {
        /// The point, metres.
        x: f64,
        /// The point, metres.
        y: f64,
        /// The nearest space and its distance in metres.
        nearest: Option<(SpaceId, f64)>,
    },
    /// A profile number out of range.
    #[error(
        "{name} {value} is out of range (clearance 0–5 m, min_door_width 0–100 m, speed > 0–100 m/s)"
    )]
    BadProfile {
        /// The parameter.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A point given as a route's stop in a building with levels.
    #[error(
        "({x}, {y}): in a building with levels a point does not say its level; give it: ({x}, {y}) ON LEVEL L (over HTTP: x,y@L)"
    )]
    PointNeedsLevel {
        /// The point's x.
        x: f64,
        /// Its y.
        y: f64,
    },
}
