//! The walked path of every navigable connection: from one space's anchor
//! to the other's through their shared doorway or boundary, as IndoorGML
//! Transitions and GeoJSON connection lines carry it, and the model's
//! connection lengths set from it.

use std::sync::Arc;

use serde::Serialize;

use super::nav::Endpoint;
use super::{Budget, NavMesh, Profile, RouteRequest};
use crate::model::{Connection, Nrg, Point, SpaceId};

/// The walked path of one connection.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConnectionWalk {
    /// One end (the smaller id).
    pub a: SpaceId,
    /// The other end.
    pub b: SpaceId,
    /// Walked length, metres.
    pub length_m: f64,
    /// The polyline from `a`'s anchor to `b`'s.
    pub points: Vec<Point>,
    /// Whether the two spaces share no walkable boundary, so the path is
    /// the straight line between the anchors.
    pub straight: bool,
}

/// The walked path of each navigable connection of `nav`'s model, at zero
/// clearance, through the two spaces only; in connection order.
pub fn connection_walks(nav: &NavMesh) -> Vec<ConnectionWalk> {
    let nrg = nav.nrg();
    let all: Vec<SpaceId> = nrg.spaces().iter().map(|s| s.id).collect();
    nrg.connections()
        .iter()
        .filter(|c| c.kind.is_navigable())
        .map(|c| walk_one(nav, c, &all))
        .collect()
}

fn walk_one(nav: &NavMesh, c: &Connection, all: &[SpaceId]) -> ConnectionWalk {
    let nrg = nav.nrg();
    let avoid: Vec<SpaceId> = all
        .iter()
        .copied()
        .filter(|s| *s != c.a && *s != c.b)
        .collect();
    let mut request = RouteRequest::between(Endpoint::Space(c.a), Endpoint::Space(c.b));
    request.profile = Profile::exact();
    let walked = super::shortest_route::route_avoiding(nav, &request, &avoid, &Budget::unlimited())
        .ok()
        .flatten();
    match walked {
        Some(route) => ConnectionWalk {
            a: c.a,
            b: c.b,
            length_m: route.length_m,
            points: route.waypoints,
            straight: false,
        },
        None => {
            let anchor = |id| nrg.space(id).map_or([0.0, 0.0], |s| s.anchor);
            let (p, q) = (anchor(c.a), anchor(c.b));
            ConnectionWalk {
                a: c.a,
                b: c.b,
                length_m: (p[0] - q[0]).hypot(p[1] - q[1]),
                points: vec![p, q],
                straight: true,
            }
        }
    }
}

/// `nrg` with every navigable connection's `length_m` set to its walked
/// length, and how many lengths changed by more than a millimetre.
pub fn with_walked_lengths(nrg: Nrg) -> (Nrg, usize) {
    let nav = NavMesh::new(Arc::new(nrg));
    let walks = connection_walks(&nav);
    let mut nrg = (*nav.nrg()).clone();
    let mut changed = 0;
    let mut connections = nrg.connections().to_vec();
    for c in &mut connections {
        if let Some(w) = walks.iter().find(|w| w.a == c.a && w.b == c.b) {
            if (c.length_m - w.length_m).abs() > 1e-3 {
                changed += 1;
            }
            c.length_m = w.length_m;
        }
    }
    let spaces = nrg.spaces().to_vec();
    if let Ok(updated) = Nrg::new(spaces, connections) {
        nrg = updated;
    }
    (nrg, changed)
}
