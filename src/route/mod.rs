//! Routing over an [`Nrg`]: walked paths through free space. The
//! navigation layer ([`NavMesh`]) triangulates the spaces; a route is the
//! shortest walkable polyline between two end points (spaces' anchors or
//! points) through doorways and open boundaries, keeping a clearance from
//! walls, with ordered waypoints (VIA), excluded spaces (AVOID), k
//! alternatives distinct by the doors they use, a distance-bounded reach,
//! and readable steps with distances and turns.
//!
//! Owns [`NavMesh`], [`RouteRequest`], [`Route`], [`Step`], the algorithms
//! (a file each) and [`RouteGraph`] (the topological adjacency NEIGHBOURS
//! walks). Uses `model`, `spade` and `pathfinding`. Must not use store,
//! query, server or the terminal. "No route" is an answer (an empty list)
//! with a reason ([`no_route_reason`]), not an error.
//!
//! ```
//! use std::sync::Arc;
//! use nrgdb::model::SpaceId;
//! use nrgdb::query::demo;
//! use nrgdb::route::{Budget, NavMesh, RouteRequest, shortest_route};
//! let nav = NavMesh::new(Arc::new(demo::building(4)));
//! // From the Kitchen (3) to the lower room of the last segment (20).
//! let request = RouteRequest::new(SpaceId(3), SpaceId(20));
//! let routes = shortest_route(&nav, &request, &Budget::unlimited()).unwrap();
//! assert_eq!(routes.len(), 1);
//! assert!(routes[0].length_m > 0.0);
//! ```

mod across_levels;
mod alternatives;
mod budget;
mod connection_walks;
mod error;
mod graph;
mod nav;
mod no_route;
mod reachable;
mod route_avoiding;
mod shortest_route;
mod steps;

pub use alternatives::{MAX_ALTERNATIVES, alternatives};
pub use budget::Budget;
pub use connection_walks::{
    ConnectionWalk, WalkedModel, connection_walks, walked_model, with_walked_lengths,
};
pub use error::RouteError;
pub use graph::RouteGraph;
pub use nav::{Endpoint, MAX_CLEARANCE_M, NavMesh, Profile};
pub use no_route::no_route_reason;
pub use reachable::reachable_within;
pub use shortest_route::shortest_route;
pub use steps::{Step, Turn};

use serde::Serialize;

use crate::model::{Point, SpaceId};

/// What to route: from, to, ordered waypoints, excluded spaces, how many
/// alternatives (1 = just the shortest) and the walker's profile.
#[derive(Debug, Clone, PartialEq)]
pub struct RouteRequest {
    /// Start.
    pub from: Endpoint,
    /// Goal.
    pub to: Endpoint,
    /// Places to pass through, in order.
    pub via: Vec<Endpoint>,
    /// Spaces the route must not enter.
    pub avoid: Vec<SpaceId>,
    /// Number of routes wanted (at least 1).
    pub alternatives: usize,
    /// Clearance, narrowest door and speed.
    pub profile: Profile,
}

impl RouteRequest {
    /// The plain shortest route between the anchors of two spaces, with
    /// the default profile.
    pub fn new(from: SpaceId, to: SpaceId) -> RouteRequest {
        RouteRequest::between(Endpoint::Space(from), Endpoint::Space(to))
    }

    /// The plain shortest route between two end points, default profile.
    pub fn between(from: Endpoint, to: Endpoint) -> RouteRequest {
        RouteRequest {
            from,
            to,
            via: Vec::new(),
            avoid: Vec::new(),
            alternatives: 1,
            profile: Profile::default(),
        }
    }
}

/// One route: the spaces passed in order, the doors among them, the walked
/// length and polyline in metres (map frame), duration, and readable steps.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Route {
    /// Every space entered, start and goal included.
    pub spaces: Vec<SpaceId>,
    /// The door spaces passed, in order.
    pub doors: Vec<SpaceId>,
    /// Walked length in metres (the length of `waypoints`; in a building
    /// with levels, plus the costs of the stairs and lifts taken).
    pub length_m: f64,
    /// Walked length of each leg between consecutive stops (one leg
    /// without VIA).
    pub leg_lengths_m: Vec<f64>,
    /// Walking time at the profile's speed, seconds.
    pub duration_s: f64,
    /// The whole walked polyline, start and goal included.
    pub waypoints: Vec<Point>,
    /// Steps: distance walked in a space, then the turn into the next.
    pub steps: Vec<Step>,
    /// In a building with levels, the level of each stretch of
    /// `waypoints`, in order (empty without levels).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub levels: Vec<LevelSpan>,
}

/// A stretch of a route on one level: from waypoint `from_waypoint` on,
/// until the next span starts.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LevelSpan {
    /// Index in the route's `waypoints` of the first point on this level.
    pub from_waypoint: usize,
    /// The level's name.
    pub level: String,
    /// Its elevation, metres.
    pub elevation_m: f64,
}

impl Route {
    /// Each waypoint's elevation (0 without levels): the z of the route's
    /// 3D geometry.
    pub fn waypoint_elevations(&self) -> Vec<f64> {
        let mut z = vec![0.0; self.waypoints.len()];
        for (k, span) in self.levels.iter().enumerate() {
            let end = self
                .levels
                .get(k + 1)
                .map_or(z.len(), |n| n.from_waypoint.min(z.len()));
            for v in z.iter_mut().take(end).skip(span.from_waypoint) {
                *v = span.elevation_m;
            }
        }
        z
    }
}
