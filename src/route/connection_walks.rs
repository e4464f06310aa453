//! The walked path of every navigable connection: from one space's anchor
//! to the other's through their shared doorway or boundary, as IndoorGML
//! Transitions and GeoJSON connection lines carry it, and the model's
//! connection lengths set from it ([`walked_model`]).

use std::sync::Arc;

use serde::Serialize;

use super::{Budget, NavMesh, Profile};
use crate::model::{Connection, ConnectionKind, ConnectionPaths, Nrg, Point, SpaceId};

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
/// clearance, through the two spaces only; in connection order. One small
/// search per connection, with every other space closed.
pub fn connection_walks(nav: &NavMesh) -> Vec<ConnectionWalk> {
    let nrg = nav.nrg();
    let level = nav.level(&Profile::exact());
    let mut closed = vec![true; nav.space_ids(&level).len()];
    let budget = Budget::unlimited();
    nrg.connections()
        .iter()
        .filter(|c| c.kind.is_navigable())
        .map(|c| {
            let walked = nav.walk_between(&level, c.a, c.b, &mut closed, &budget);
            match walked {
                Some((length_m, points)) => ConnectionWalk {
                    a: c.a,
                    b: c.b,
                    length_m,
                    points,
                    straight: false,
                },
                None => straight(nrg, c),
            }
        })
        .collect()
}

/// The straight line between a connection's anchors (spaces that share no
/// walkable boundary).
fn straight(nrg: &Nrg, c: &Connection) -> ConnectionWalk {
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

/// The walks of a model with levels, level by level: each level's spaces
/// and connections on a navigation layer of their own (floors stacked in
/// one plane would overlap), then the vertical connections with their own
/// costs (between levels the cost is the connection's own, stairs climbed
/// or a lift ridden, not a walk in the plane).
fn walks_per_level(nav: &NavMesh) -> Vec<ConnectionWalk> {
    let nrg = nav.nrg();
    let mut walks: Vec<ConnectionWalk> = nav.floors().navs().flat_map(connection_walks).collect();
    walks.extend(
        nrg.connections()
            .iter()
            .filter(|c| c.kind == ConnectionKind::Vertical)
            .map(|c| ConnectionWalk {
                length_m: c.length_m,
                ..straight(nrg, c)
            }),
    );
    walks
}

/// A model as nrgdb stores and writes it: every navigable connection's
/// `length_m` is its walked length, and `paths` holds the walked polyline
/// of each (what IndoorGML Transitions and GeoJSON connection lines draw).
#[derive(Debug, Clone, PartialEq)]
pub struct WalkedModel {
    /// The model with walked lengths.
    pub nrg: Nrg,
    /// The walked polyline of each navigable connection, by
    /// [`Connection::key`], from the smaller id's anchor to the other's.
    pub paths: ConnectionPaths,
    /// How many lengths changed by more than a millimetre.
    pub lengths_changed: usize,
}

/// `nrg` with walked connection lengths and paths: the one function every
/// writer (IndoorGML, GeoJSON, model JSON) and every way into the store
/// goes through, so they all carry the same lengths.
///
/// ```
/// use nrgdb::route::walked_model;
/// let nrg = nrgdb::fixtures::corridor_building(2);
/// let walked = walked_model(&nrg);
/// for c in walked.nrg.connections().iter().filter(|c| c.kind.is_navigable()) {
///     let path = &walked.paths[&c.key()];
///     let own: f64 = path.windows(2).map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1])).sum();
///     assert!((own - c.length_m).abs() < 1e-9);
/// }
/// ```
pub fn walked_model(nrg: &Nrg) -> WalkedModel {
    WalkedModel::on(&NavMesh::new(Arc::new(nrg.clone())))
}

impl WalkedModel {
    /// [`walked_model`] over an already built navigation layer (a cached
    /// revision's).
    pub fn on(nav: &NavMesh) -> WalkedModel {
        let walks = if nav.nrg().has_levels() {
            walks_per_level(nav)
        } else {
            connection_walks(nav)
        };
        let mut changed = 0;
        let mut paths = ConnectionPaths::new();
        let mut walked: std::collections::HashMap<(SpaceId, SpaceId), f64> =
            std::collections::HashMap::with_capacity(walks.len());
        for w in walks {
            let key = if w.a <= w.b { (w.a, w.b) } else { (w.b, w.a) };
            let mut points = w.points;
            if key.0 != w.a {
                points.reverse();
            }
            walked.insert(key, w.length_m);
            paths.insert(key, points);
        }
        let mut connections = nav.nrg().connections().to_vec();
        for c in &mut connections {
            if let Some(&length_m) = walked.get(&c.key()) {
                if (c.length_m - length_m).abs() > 1e-3 {
                    changed += 1;
                }
                c.length_m = length_m;
            }
        }
        let nrg = Nrg::new(nav.nrg().spaces().to_vec(), connections)
            .unwrap_or_else(|_| nav.nrg().clone());
        WalkedModel {
            nrg,
            paths,
            lengths_changed: changed,
        }
    }
}

/// `nrg` with every navigable connection's `length_m` set to its walked
/// length, and how many lengths changed by more than a millimetre.
pub fn with_walked_lengths(nrg: Nrg) -> (Nrg, usize) {
    let walked = walked_model(&nrg);
    (walked.nrg, walked.lengths_changed)
}
