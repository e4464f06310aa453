//! Routing over an [`Nrg`]: shortest routes by metric length through the
//! anchors of the spaces (door spaces included) on the navigable graph, with
//! ordered waypoints (VIA), excluded spaces (AVOID), k loopless alternatives
//! (Yen) and a distance-bounded reach.
//!
//! Owns [`RouteGraph`], [`RouteRequest`], [`Route`] and the algorithms, a file
//! each. Uses `model` and `pathfinding`. Must not use store, query, server
//! or the terminal. "No route" is an answer (an empty list), not an error.
//!
//! ```
//! use nrgdb::model::SpaceId;
//! use nrgdb::query::demo;
//! use nrgdb::route::{Budget, RouteGraph, RouteRequest, shortest_route};
//! let nrg = demo::building(4);
//! let graph = RouteGraph::new(&nrg);
//! // From the Kitchen (3) to the lower room of the last segment (20).
//! let request = RouteRequest::new(SpaceId(3), SpaceId(20));
//! let routes = shortest_route(&graph, &nrg, &request, &Budget::unlimited()).unwrap();
//! assert_eq!(routes.len(), 1);
//! assert!(routes[0].length_m > 0.0);
//! ```

mod alternatives;
mod budget;
mod error;
mod graph;
mod reachable;
mod shortest_route;
mod steps;

pub use alternatives::alternatives;
pub use budget::Budget;
pub use error::RouteError;
pub use graph::RouteGraph;
pub use reachable::reachable_within;
pub use shortest_route::shortest_route;
pub use steps::describe_steps;

use serde::Serialize;

use crate::model::{Nrg, Point, SpaceId, SpaceKind};

/// What to route: from, to, ordered waypoints, excluded spaces and how many
/// alternatives (1 = just the shortest).
#[derive(Debug, Clone, PartialEq)]
pub struct RouteRequest {
    /// Start space.
    pub from: SpaceId,
    /// Goal space.
    pub to: SpaceId,
    /// Spaces to pass through, in order.
    pub via: Vec<SpaceId>,
    /// Spaces the route must not enter.
    pub avoid: Vec<SpaceId>,
    /// Number of routes wanted (at least 1).
    pub alternatives: usize,
}

impl RouteRequest {
    /// The plain shortest route from `from` to `to`.
    pub fn new(from: SpaceId, to: SpaceId) -> RouteRequest {
        RouteRequest {
            from,
            to,
            via: Vec::new(),
            avoid: Vec::new(),
            alternatives: 1,
        }
    }
}

/// One route: the spaces passed in order, the doors among them, its length
/// and waypoints in metres (map frame), and readable steps.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Route {
    /// Every space entered, start and goal included.
    pub spaces: Vec<SpaceId>,
    /// The door spaces passed, in order.
    pub doors: Vec<SpaceId>,
    /// Total length in metres (sum of the connections' `length_m`).
    pub length_m: f64,
    /// The anchors of `spaces`, in metres.
    pub waypoints: Vec<Point>,
    /// Human-readable steps ("leave Kitchen through door 7 into corridor 3").
    pub steps: Vec<String>,
}

impl Route {
    /// Builds a route from a path of spaces: doors, length, waypoints, steps.
    pub fn from_path(nrg: &Nrg, path: Vec<SpaceId>) -> Route {
        let doors = path
            .iter()
            .filter(|id| nrg.space(**id).is_some_and(|s| s.kind == SpaceKind::Door))
            .copied()
            .collect();
        let length_m = path
            .windows(2)
            .filter_map(|w| nrg.connection(w[0], w[1]))
            .map(|c| c.length_m)
            .sum();
        let waypoints = path
            .iter()
            .filter_map(|id| nrg.space(*id).map(|s| s.anchor))
            .collect();
        let steps = describe_steps(nrg, &path);
        Route {
            spaces: path,
            doors,
            length_m,
            waypoints,
            steps,
        }
    }
}
