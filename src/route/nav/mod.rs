//! The navigation layer under the NRG: where a person or a robot can walk.
//!
//! Every space's polygon (with its holes) goes into one constrained Delaunay
//! triangulation (`spade`); each triangle is tagged with its space, and a
//! triangle edge between two spaces is a *gate* only when the model connects
//! them navigably (a door or an open boundary), else it is a wall. A walked
//! path is found over the crossing points of the openings (gates joined
//! into doorways), with the in-space lengths between them precomputed per
//! revision ([`layer`]): by a contraction hierarchy of that graph
//! ([`hierarchy`], built with the tables on the first route) or, when
//! spaces are avoided or doors too narrow, by A* ([`search`]); then it is
//! straightened through its channel of triangles by the funnel algorithm,
//! so its length is the length actually walked, exact for the channel
//! chosen. Inside a space with holes a channel of triangles is not unique,
//! so there the in-space walks come from the visibility graph of the
//! space's corners ([`visibility`]) wherever they are shorter. Clearance from
//! walls is kept by closing passages narrower than twice it and by wrapping
//! the path around obstacle corners at that distance.
//!
//! Owns [`NavMesh`], [`Profile`] and [`Endpoint`]. Uses `model`, `spade` and
//! `rstar`; knows nothing of queries, storage or HTTP.

mod clearance;
mod containment;
mod dead_ends;
mod funnel;
mod gate;
mod hierarchy;
pub(crate) mod layer;
pub(crate) mod mesh;
mod noding;
mod openings;
mod regions;
mod search;
mod visibility;

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use serde::Serialize;

pub(crate) use self::funnel::dist;
use self::layer::Layer;
use self::mesh::Mesh;
pub(crate) use self::search::Walk;
use self::search::{End, shortest_walk};
use super::{Budget, RouteError};
pub(crate) use crate::model::segment_distance;
use crate::model::{Nrg, Point, SpaceId, doorway};

/// How the walker moves: the clearance it keeps from walls and furniture,
/// the narrowest doorway it fits through, and its speed.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Profile {
    /// Distance kept from walls and obstacles, metres (a person: 0.2; a
    /// robot: its radius). Doorways narrower than twice this are closed.
    pub clearance_m: f64,
    /// Doors narrower than this are impassable (0: any door).
    pub min_door_width_m: f64,
    /// Walking speed for durations, metres per second.
    pub speed_m_s: f64,
    /// Never take stairs between levels (a wheelchair, most robots).
    #[serde(default)]
    pub no_stairs: bool,
    /// Never take a lift between levels.
    #[serde(default)]
    pub no_elevator: bool,
}

impl Default for Profile {
    fn default() -> Profile {
        Profile {
            clearance_m: 0.2,
            min_door_width_m: 0.0,
            speed_m_s: 1.4,
            no_stairs: false,
            no_elevator: false,
        }
    }
}

impl Profile {
    /// The geometric profile: zero clearance, any door (routes hug corners;
    /// their length is the free-space geodesic).
    pub fn exact() -> Profile {
        Profile {
            clearance_m: 0.0,
            ..Profile::default()
        }
    }

    /// Checks the numbers are usable.
    pub fn validate(&self) -> Result<(), RouteError> {
        let bad = |name: &'static str, value: f64| RouteError::BadProfile { name, value };
        if !(self.clearance_m.is_finite() && (0.0..=MAX_CLEARANCE_M).contains(&self.clearance_m)) {
            return Err(bad("clearance", self.clearance_m));
        }
        if !(self.min_door_width_m.is_finite() && (0.0..=100.0).contains(&self.min_door_width_m)) {
            return Err(bad("min_door_width", self.min_door_width_m));
        }
        if !(self.speed_m_s.is_finite() && self.speed_m_s > 0.0 && self.speed_m_s <= 100.0) {
            return Err(bad("speed", self.speed_m_s));
        }
        Ok(())
    }
}

/// Largest clearance accepted, metres.
pub const MAX_CLEARANCE_M: f64 = 5.0;

/// Where a route starts or ends: a space (its anchor) or a point.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Endpoint {
    /// The anchor of a space.
    Space(SpaceId),
    /// A point in metres in the map frame.
    Point(Point),
    /// A point in a given space: in a building with levels, the space
    /// says which level the point is on (make it with
    /// [`Endpoint::point_on`]).
    PointIn(Point, SpaceId),
}

impl Endpoint {
    /// The point `p` on level `level` of `nrg`: the smallest space holding
    /// it there, or None when none does.
    ///
    /// ```
    /// use nrgdb::route::Endpoint;
    /// let nrg = nrgdb::fixtures::storeys(2, 2);
    /// let p = nrg.space(nrgdb::model::SpaceId(10)).unwrap().anchor;
    /// assert_eq!(Endpoint::point_on(&nrg, p, "1"), Some(Endpoint::PointIn(p, nrgdb::model::SpaceId(100_010))));
    /// assert_eq!(Endpoint::point_on(&nrg, [-50.0, 0.0], "1"), None);
    /// ```
    pub fn point_on(nrg: &crate::model::Nrg, p: Point, level: &str) -> Option<Endpoint> {
        nrg.spaces()
            .iter()
            .filter(|s| s.level.as_ref().is_some_and(|l| l.name == level))
            .filter(|s| {
                crate::model::point_in_ring(p, &s.polygon)
                    && !s.holes.iter().any(|h| crate::model::point_in_ring(p, h))
            })
            .min_by(|a, b| a.area_m2.total_cmp(&b.area_m2).then(a.id.cmp(&b.id)))
            .map(|s| Endpoint::PointIn(p, s.id))
    }

    /// The space of a space end, or the space a point end is known to
    /// be in ([`Endpoint::PointIn`]).
    pub fn space(&self) -> Option<SpaceId> {
        match self {
            Endpoint::Space(id) | Endpoint::PointIn(_, id) => Some(*id),
            Endpoint::Point(_) => None,
        }
    }

    /// The point of a point end.
    pub fn point(&self) -> Option<Point> {
        match self {
            Endpoint::Space(_) => None,
            Endpoint::Point(p) | Endpoint::PointIn(p, _) => Some(*p),
        }
    }
}

/// The navigation layer of one revision. Build it once ([`NavMesh::new`])
/// and share it; the layers for other clearances are built on first use
/// and kept (a few at most).
#[derive(Debug)]
pub struct NavMesh {
    nrg: Arc<Nrg>,
    exact: Arc<Level>,
    by_clearance: Mutex<HashMap<u32, Arc<Level>>>,
    /// A building's floors, each with its own layer (built on the first
    /// route of a model with levels).
    floors: std::sync::OnceLock<crate::route::across_levels::Floors>,
}

/// The mesh and tables for one clearance.
#[derive(Debug)]
pub(crate) struct Level {
    pub mesh: Arc<Mesh>,
    pub layer: Layer,
    /// Free opening of each door space (dense index), metres; infinite for
    /// other spaces.
    pub door_width: Vec<f64>,
}

/// Clearances kept in the cache at once.
const CACHED_CLEARANCES: usize = 8;

impl Level {
    fn new(nrg: &Nrg, mesh: Arc<Mesh>, clearance_m: f64) -> Level {
        let layer = Layer::new(&mesh, nrg, clearance_m);
        let door_width = door_widths(nrg, &mesh);
        Level {
            mesh,
            layer,
            door_width,
        }
    }
}

/// Each space's door width (dense index): a door's width as
/// [`doorway`] defines it, infinite for other spaces.
fn door_widths(nrg: &Nrg, mesh: &Mesh) -> Vec<f64> {
    mesh.space_ids
        .iter()
        .map(|id| {
            nrg.space(*id)
                .and_then(doorway)
                .map_or(f64::INFINITY, |d| d.width_m)
        })
        .collect()
}

impl NavMesh {
    /// Builds the navigation layer of `nrg` (at zero clearance; others on
    /// demand).
    pub fn new(nrg: Arc<Nrg>) -> NavMesh {
        let mesh = Arc::new(Mesh::new(&nrg));
        let exact = Arc::new(Level::new(&nrg, mesh, 0.0));
        NavMesh {
            nrg,
            exact,
            by_clearance: Mutex::new(HashMap::new()),
            floors: std::sync::OnceLock::new(),
        }
    }

    /// The floors of a model with levels, each on its own layer.
    pub(crate) fn floors(&self) -> &crate::route::across_levels::Floors {
        self.floors
            .get_or_init(|| crate::route::across_levels::Floors::new(&self.nrg))
    }

    /// The model this layer was built from.
    pub fn nrg(&self) -> &Nrg {
        &self.nrg
    }

    /// The level for `profile`'s clearance (rounded to the centimetre).
    pub(crate) fn level(&self, profile: &Profile) -> Arc<Level> {
        let cm = (profile.clearance_m * 100.0).round() as u32;
        if cm == 0 {
            return self.exact.clone();
        }
        if let Ok(cache) = self.by_clearance.lock()
            && let Some(level) = cache.get(&cm)
        {
            return level.clone();
        }
        let level = Arc::new(Level::new(
            &self.nrg,
            self.exact.mesh.clone(),
            f64::from(cm) / 100.0,
        ));
        if let Ok(mut cache) = self.by_clearance.lock()
            && cache.len() < CACHED_CLEARANCES
        {
            cache.insert(cm, level.clone());
        }
        level
    }

    /// The space whose walkable part contains `p` (at zero clearance).
    pub fn locate(&self, p: Point) -> Option<SpaceId> {
        let mesh = &self.exact.mesh;
        mesh.locate(p, None)
            .map(|t| mesh.space_ids[mesh.tris[t as usize].space as usize])
    }

    /// Resolves an end point on `level`.
    pub(crate) fn end(&self, level: &Level, at: &Endpoint) -> Result<End, RouteError> {
        let mesh = &level.mesh;
        match at {
            Endpoint::Space(id) => {
                let s = mesh.space(*id).ok_or(RouteError::NotNavigable(*id))?;
                if mesh.space_tris[s as usize].is_empty() {
                    return Err(RouteError::NotNavigable(*id));
                }
                End::anchor(&level.mesh, &level.layer, s).ok_or(RouteError::NotNavigable(*id))
            }
            Endpoint::Point(p) | Endpoint::PointIn(p, _) => match mesh.locate(*p, None) {
                Some(t) => Ok(End::point(mesh, &level.layer, *p, t)),
                None => Err(self.outside(*p)),
            },
        }
    }

    /// The error for a point outside every space, naming the nearest.
    pub fn outside(&self, p: Point) -> RouteError {
        let nearest = self
            .nrg
            .spaces()
            .iter()
            .filter(|s| !s.polygon.is_empty())
            .map(|s| (s.id, distance_to_space(p, s)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        RouteError::Outside {
            x: p[0],
            y: p[1],
            nearest,
        }
    }

    /// The shortest walk between two end points avoiding `banned` spaces
    /// (and doors narrower than the profile allows), or `None`.
    pub(crate) fn walk(
        &self,
        level: &Level,
        from: &End,
        to: &End,
        banned: &[bool],
        budget: &Budget,
    ) -> Option<Walk> {
        shortest_walk(&level.mesh, &level.layer, from, to, banned, budget)
    }

    /// The dense "banned" mask of a level: `avoid` plus doors narrower than
    /// the profile's minimum.
    pub(crate) fn banned(&self, level: &Level, avoid: &[SpaceId], profile: &Profile) -> Vec<bool> {
        let mesh = &level.mesh;
        let mut banned: Vec<bool> = level
            .door_width
            .iter()
            .map(|w| *w < profile.min_door_width_m)
            .collect();
        for id in avoid {
            if let Some(s) = mesh.space(*id) {
                banned[s as usize] = true;
            }
        }
        banned
    }
}

/// Distance from `p` to the space's area (0 inside).
pub(crate) fn distance_to_space(p: Point, s: &crate::model::Space) -> f64 {
    let inside = crate::model::point_in_ring(p, &s.polygon)
        && !s.holes.iter().any(|h| crate::model::point_in_ring(p, h));
    if inside {
        return 0.0;
    }
    std::iter::once(&s.polygon)
        .chain(&s.holes)
        .flat_map(|r| (0..r.len()).map(move |i| (r[i], r[(i + 1) % r.len()])))
        .map(|(a, b)| segment_distance(p, a, b))
        .fold(f64::INFINITY, f64::min)
}

impl NavMesh {
    /// Walked length from `from` to every space's anchor on `level` (dense
    /// order, infinite beyond `bound_m`), or `None` out of time.
    pub(crate) fn distances(
        &self,
        level: &Level,
        from: &End,
        banned: &[bool],
        bound_m: f64,
        budget: &Budget,
    ) -> Option<Vec<f64>> {
        search::anchor_distances(&level.mesh, &level.layer, from, banned, bound_m, budget)
    }

    /// The space ids of a level in dense order.
    pub(crate) fn space_ids<'a>(&self, level: &'a Level) -> &'a [SpaceId] {
        &level.mesh.space_ids
    }
}

impl NavMesh {
    /// The width of a door space as routing sees it: its width as
    /// [`doorway`] defines it (infinite for other kinds).
    pub fn door_width(&self, id: SpaceId) -> f64 {
        self.exact
            .mesh
            .space(id)
            .and_then(|s| self.exact.door_width.get(s as usize).copied())
            .unwrap_or(f64::INFINITY)
    }
}

impl NavMesh {
    /// The walk from `a`'s anchor to `b`'s through those two spaces only
    /// on `level`: `closed` must mark every space closed on entry and is
    /// left so. Length and polyline, or `None`.
    pub(crate) fn walk_between(
        &self,
        level: &Level,
        a: SpaceId,
        b: SpaceId,
        closed: &mut [bool],
        budget: &Budget,
    ) -> Option<(f64, Vec<Point>)> {
        let mesh = &level.mesh;
        let (sa, sb) = (mesh.space(a)?, mesh.space(b)?);
        let from = self.end(level, &Endpoint::Space(a)).ok()?;
        let to = self.end(level, &Endpoint::Space(b)).ok()?;
        closed[sa as usize] = false;
        closed[sb as usize] = false;
        let walked = self.walk(level, &from, &to, closed, budget);
        closed[sa as usize] = true;
        closed[sb as usize] = true;
        walked.map(|w| (w.length_m, w.points))
    }
}
