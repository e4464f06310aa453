//! Routes in a building with levels (issue 25). Each level is walked on a
//! navigation layer of its own (floors stacked in one plane would
//! overlap); levels are joined by the vertical connections (stairs, lifts)
//! with their own costs. The route is the shortest over a small graph
//! whose nodes are the route's stops (spaces, or points on a level) and
//! the ends of the vertical
//! connections the profile allows (`NO STAIRS`, `NO ELEVATOR`), whose
//! edges are the walked routes between two nodes on one level and the
//! vertical connections. Steps say where a level changes: "take Lift A
//! from level 3 to level 0", "walk up the East stairs to level 1".

use std::collections::{BinaryHeap, HashMap};
use std::sync::Arc;

use super::route_avoiding::route_avoiding;
use super::steps::{Step, Turn};
use super::{Budget, Endpoint, LevelSpan, NavMesh, Route, RouteError, RouteRequest};
use crate::model::{ConnectionKind, Level, Nrg, SpaceId, SpaceKind};

/// The floors of a building, each with its own navigation layer.
#[derive(Debug)]
pub(crate) struct Floors {
    by_level: HashMap<String, NavMesh>,
}

impl Floors {
    /// Splits `nrg` by level and builds each level's layer.
    pub(crate) fn new(nrg: &Nrg) -> Floors {
        let mut by_level = HashMap::new();
        for level in nrg.levels() {
            let Some(floor) = nrg.level_model(&level.name) else {
                continue;
            };
            // Each floor alone is a plain one-level model.
            let (spaces, connections) = floor.into_parts();
            let spaces = spaces
                .into_iter()
                .map(|s| crate::model::Space { level: None, ..s })
                .collect();
            if let Ok(floor) = Nrg::new(spaces, connections) {
                by_level.insert(level.name.clone(), NavMesh::new(Arc::new(floor)));
            }
        }
        Floors { by_level }
    }

    /// Each floor's layer.
    pub(crate) fn navs(&self) -> impl Iterator<Item = &NavMesh> {
        self.by_level.values()
    }
}

fn level_of(nrg: &Nrg, id: SpaceId) -> Option<&Level> {
    nrg.space(id).and_then(|s| s.level.as_ref())
}

/// A stop of a route across levels: where it is, and the space that
/// says its level.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Stop {
    at: Endpoint,
    space: SpaceId,
}

/// The shortest route through the request's stops across levels, or
/// `None` when a leg has none. Stops are spaces, or points in a known
/// space ([`Endpoint::PointIn`]; a bare point does not say its level).
pub(crate) fn route_across_levels(
    nav: &NavMesh,
    request: &RouteRequest,
    avoid: &[SpaceId],
    budget: &Budget,
) -> Result<Option<Route>, RouteError> {
    let nrg = nav.nrg();
    request.profile.validate()?;
    let floors = nav.floors();
    let stops: Vec<Stop> = std::iter::once(&request.from)
        .chain(&request.via)
        .chain(std::iter::once(&request.to))
        .map(|e| match *e {
            Endpoint::Space(id) => Ok(Stop { at: *e, space: id }),
            Endpoint::PointIn(_, id) => Ok(Stop { at: *e, space: id }),
            Endpoint::Point(p) => Err(RouteError::PointNeedsLevel { x: p[0], y: p[1] }),
        })
        .collect::<Result<_, _>>()?;
    let mut parts: Vec<Part> = Vec::new();
    let mut leg_lengths = Vec::new();
    for pair in stops.windows(2) {
        for stop in pair {
            if nrg.space(stop.space).is_none() {
                return Err(RouteError::NotNavigable(stop.space));
            }
            if avoid.contains(&stop.space) {
                return Err(RouteError::AvoidedEndpoint(stop.space));
            }
        }
        let Some(leg) = shortest_leg(nrg, floors, pair[0], pair[1], request, avoid, budget)? else {
            return Ok(None);
        };
        leg_lengths.push(leg.iter().map(Part::length).sum());
        parts.extend(leg);
    }
    Ok(Some(joined(nrg, parts, leg_lengths, request)))
}

/// A piece of a route: a walk on one level or a ride between two.
enum Part {
    Walk(Route),
    Vertical {
        from: SpaceId,
        to: SpaceId,
        length_m: f64,
    },
}

impl Part {
    fn length(&self) -> f64 {
        match self {
            Part::Walk(r) => r.length_m,
            Part::Vertical { length_m, .. } => *length_m,
        }
    }
}

/// Dijkstra over the stops and the allowed connector ends; walks between
/// two nodes on one level are asked of that level's layer when first
/// needed.
fn shortest_leg(
    nrg: &Nrg,
    floors: &Floors,
    from: Stop,
    to: Stop,
    request: &RouteRequest,
    avoid: &[SpaceId],
    budget: &Budget,
) -> Result<Option<Vec<Part>>, RouteError> {
    let allowed = |id: SpaceId| {
        let refused = match nrg.space(id).map(|s| s.kind) {
            Some(SpaceKind::Stairs) => request.profile.no_stairs,
            Some(SpaceKind::Elevator) => request.profile.no_elevator,
            _ => false,
        };
        !refused && !avoid.contains(&id)
    };
    if from == to {
        return Ok(Some(Vec::new()));
    }
    // Nodes: the two stops (0 and 1), then each allowed connector end
    // once (a stop that is a connector's space is that connector's node).
    let mut nodes: Vec<Stop> = vec![from, to];
    let node_of = |id: SpaceId, nodes: &mut Vec<Stop>| -> usize {
        let stop = Stop {
            at: Endpoint::Space(id),
            space: id,
        };
        match nodes.iter().position(|n| *n == stop) {
            Some(k) => k,
            None => {
                nodes.push(stop);
                nodes.len() - 1
            }
        }
    };
    // Rides between connector ends: (node, node, cost).
    let vertical: Vec<(usize, usize, f64)> = nrg
        .connections()
        .iter()
        .filter(|c| c.kind == ConnectionKind::Vertical && allowed(c.a) && allowed(c.b))
        .map(|c| {
            (
                node_of(c.a, &mut nodes),
                node_of(c.b, &mut nodes),
                c.length_m,
            )
        })
        .collect();
    let node_level: Vec<Option<&str>> = nodes
        .iter()
        .map(|n| level_of(nrg, n.space).map(|l| l.name.as_str()))
        .collect();
    let mut walks: HashMap<(usize, usize), Option<Route>> = HashMap::new();
    let mut dist: HashMap<usize, f64> = HashMap::from([(0, 0.0)]);
    let mut came: HashMap<usize, (usize, bool)> = HashMap::new();
    let mut heap = BinaryHeap::from([Entry(0.0, 0)]);
    while let Some(Entry(d, u)) = heap.pop() {
        if d > dist.get(&u).copied().unwrap_or(f64::INFINITY) {
            continue;
        }
        if u == 1 {
            break;
        }
        if budget.is_expired() {
            return Err(RouteError::Timeout(budget.limit_ms()));
        }
        let level = node_level[u];
        let mut relax = |v: usize, w: f64, ride: bool, heap: &mut BinaryHeap<Entry>| {
            let nd = d + w;
            if nd < dist.get(&v).copied().unwrap_or(f64::INFINITY) {
                dist.insert(v, nd);
                came.insert(v, (u, ride));
                heap.push(Entry(nd, v));
            }
        };
        for v in 0..nodes.len() {
            if v == u || node_level[v] != level {
                continue;
            }
            let walk = walks.entry((u, v)).or_insert_with(|| {
                walk_on(
                    floors,
                    level,
                    nodes[u].at,
                    nodes[v].at,
                    request,
                    avoid,
                    budget,
                )
            });
            if let Some(r) = walk {
                let w = r.length_m;
                relax(v, w, false, &mut heap);
            }
        }
        for &(a, b, w) in &vertical {
            if a == u {
                relax(b, w, true, &mut heap);
            } else if b == u {
                relax(a, w, true, &mut heap);
            }
        }
    }
    if !came.contains_key(&1) {
        return Ok(None);
    }
    let mut parts = Vec::new();
    let mut at = 1;
    while at != 0 {
        let Some(&(prev, ride)) = came.get(&at) else {
            return Ok(None);
        };
        if ride {
            let length_m = vertical
                .iter()
                .find(|&&(a, b, _)| (a, b) == (prev, at) || (b, a) == (prev, at))
                .map_or(0.0, |v| v.2);
            parts.push(Part::Vertical {
                from: nodes[prev].space,
                to: nodes[at].space,
                length_m,
            });
        } else if let Some(Some(r)) = walks.remove(&(prev, at)) {
            parts.push(Part::Walk(r));
        }
        at = prev;
    }
    parts.reverse();
    Ok(Some(parts))
}

/// The walked route between two ends on one level, on its own layer.
fn walk_on(
    floors: &Floors,
    level: Option<&str>,
    a: Endpoint,
    b: Endpoint,
    request: &RouteRequest,
    avoid: &[SpaceId],
    budget: &Budget,
) -> Option<Route> {
    let nav = floors.by_level.get(level?)?;
    // A point in a space is a plain point on its floor's own layer.
    let plain = |e: Endpoint| match e {
        Endpoint::PointIn(p, _) => Endpoint::Point(p),
        other => other,
    };
    let ends = [a, b].map(|e| match e {
        Endpoint::Space(id) => Some(id),
        _ => None,
    });
    let leg = RouteRequest {
        from: plain(a),
        to: plain(b),
        via: Vec::new(),
        avoid: avoid
            .iter()
            .copied()
            .filter(|s| !ends.contains(&Some(*s)))
            .collect(),
        alternatives: 1,
        profile: request.profile,
    };
    route_avoiding(nav, &leg, &leg.avoid, budget).ok().flatten()
}

/// One route from its parts: spaces, doors, lengths and waypoints in
/// order, and a step for each change of level.
fn joined(nrg: &Nrg, parts: Vec<Part>, leg_lengths_m: Vec<f64>, request: &RouteRequest) -> Route {
    let mut route = Route {
        spaces: Vec::new(),
        doors: Vec::new(),
        length_m: 0.0,
        leg_lengths_m,
        duration_s: 0.0,
        waypoints: Vec::new(),
        steps: Vec::new(),
        levels: Vec::new(),
    };
    for part in parts {
        route.length_m += part.length();
        match part {
            Part::Walk(r) => {
                if let Some(&first) = r.spaces.first() {
                    enter_level(nrg, &mut route, first);
                }
                // A walk from stairs or a lift starts where the ride ended.
                let mut waypoints = r.waypoints.as_slice();
                if route.waypoints.last() == waypoints.first() {
                    waypoints = &waypoints[1..];
                }
                route.waypoints.extend_from_slice(waypoints);
                for id in r.spaces {
                    if route.spaces.last() != Some(&id) {
                        route.spaces.push(id);
                    }
                }
                route.doors.extend(r.doors);
                // The arrival of a walk that ends at stairs or a lift is
                // not the route's arrival.
                let mut steps = r.steps;
                if let Some(last) = steps.last()
                    && last.turn == Turn::Arrive
                {
                    steps.pop();
                }
                route.steps.extend(steps);
            }
            Part::Vertical { from, to, length_m } => {
                // A route that starts on the stairs or in the lift starts
                // at their anchor on its own level.
                if route.waypoints.is_empty() {
                    enter_level(nrg, &mut route, from);
                    if let Some(s) = nrg.space(from) {
                        route.waypoints.push(s.anchor);
                    }
                }
                if route.spaces.last() != Some(&from) {
                    route.spaces.push(from);
                }
                route.spaces.push(to);
                route.steps.push(level_step(nrg, from, to, length_m));
                // The ride in 3D: from the anchor on one level to the
                // anchor on the other.
                enter_level(nrg, &mut route, to);
                if let Some(s) = nrg.space(to) {
                    route.waypoints.push(s.anchor);
                }
            }
        }
    }
    // From a stop to itself: there already, at the stop.
    if route.waypoints.is_empty()
        && let Some(id) = request.to.space()
    {
        enter_level(nrg, &mut route, id);
        route.spaces.push(id);
        let at = request
            .to
            .point()
            .or_else(|| nrg.space(id).map(|s| s.anchor));
        route.waypoints.extend(at);
    }
    let end = route.waypoints.last().copied().unwrap_or_default();
    let goal = request
        .to
        .space()
        .or(route.spaces.last().copied())
        .unwrap_or(SpaceId(0));
    route.steps.push(Step {
        instruction: format!(
            "arrive at {}",
            nrg.space(goal)
                .map_or_else(|| goal.to_string(), |s| s.label())
        ),
        distance_m: 0.0,
        space: goal,
        turn: Turn::Arrive,
        door: None,
        into: None,
        at: end,
    });
    route.duration_s = route.length_m / request.profile.speed_m_s;
    route
}

/// Starts a new level span at the next waypoint when `space` is on
/// another level than the last span.
fn enter_level(nrg: &Nrg, route: &mut Route, space: SpaceId) {
    let Some(level) = level_of(nrg, space) else {
        return;
    };
    if route.levels.last().is_some_and(|l| l.level == level.name) {
        return;
    }
    route.levels.push(LevelSpan {
        from_waypoint: route.waypoints.len(),
        level: level.name.clone(),
        elevation_m: level.elevation_m,
    });
}

/// "take Lift A from level 3 to level 0" / "walk up the Stairs to level 1".
fn level_step(nrg: &Nrg, from: SpaceId, to: SpaceId, length_m: f64) -> Step {
    let (a, b) = (nrg.space(from), nrg.space(to));
    let name = |id: SpaceId| {
        nrg.space(id)
            .and_then(|s| s.name.clone())
            .unwrap_or_else(|| id.to_string())
    };
    let level = |s: Option<&crate::model::Space>| s.and_then(|s| s.level.clone());
    let (la, lb) = (level(a), level(b));
    let (la_name, lb_name) = (
        la.as_ref().map_or("?", |l| l.name.as_str()).to_string(),
        lb.as_ref().map_or("?", |l| l.name.as_str()).to_string(),
    );
    let up = match (&la, &lb) {
        (Some(x), Some(y)) => y.elevation_m > x.elevation_m,
        _ => true,
    };
    let instruction = match a.map(|s| s.kind) {
        Some(SpaceKind::Elevator) => {
            format!(
                "take {} from level {la_name} to level {lb_name}",
                name(from)
            )
        }
        Some(SpaceKind::Stairs) => format!(
            "walk {} the {} to level {lb_name}",
            if up { "up" } else { "down" },
            name(from)
        ),
        _ => format!("go {} to level {lb_name}", if up { "up" } else { "down" }),
    };
    Step {
        instruction,
        distance_m: length_m,
        space: from,
        turn: Turn::Straight,
        door: None,
        into: Some(to),
        at: b.map_or([0.0, 0.0], |s| s.anchor),
    }
}

/// A heap entry: distance (smallest first), node.
struct Entry(f64, usize);

impl PartialEq for Entry {
    fn eq(&self, other: &Self) -> bool {
        self.0.total_cmp(&other.0).is_eq() && self.1 == other.1
    }
}
impl Eq for Entry {}
impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Entry {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        other.0.total_cmp(&self.0).then(other.1.cmp(&self.1))
    }
}
