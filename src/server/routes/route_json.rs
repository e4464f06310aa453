//! The route answer, shaped like the routing engines people know (OSRM,
//! GraphHopper): `code`, the snapped `waypoints`, and `routes` with the
//! walked distance (metres), duration (seconds at the profile's speed),
//! `legs` between waypoints with steps (distance, turn, door), the whole
//! walked path as a GeoJSON LineString (map frame), and the spaces and
//! doors passed. With no route, `code` is "NoRoute" and `message` says why.

use serde::Serialize;

use crate::model::{Nrg, Point, SpaceId};
use crate::query::IndexedRevision;
use crate::route::{Endpoint, LevelSpan, Route, Step, Turn};

/// The whole answer of `GET /maps/{map}/route`.
#[derive(Debug, Serialize)]
pub struct RouteResponse<'a> {
    /// "Ok", or "NoRoute" when there is none.
    pub code: &'static str,
    /// Why there is no route ("every doorway into Office 27 is narrower
    /// than 0.9 m"); absent with "Ok".
    #[serde(skip_serializing_if = "Option::is_none")]
    pub message: Option<String>,
    /// The map.
    pub map: &'a str,
    /// The revision routed on.
    pub revision: u64,
    /// Start, waypoints and goal as resolved.
    pub waypoints: Vec<Waypoint<'a>>,
    /// Routes, shortest first (empty with "NoRoute").
    pub routes: Vec<RouteJson<'a>>,
}

/// A resolved stop: a space (at its anchor) or a point.
#[derive(Debug, Serialize)]
pub struct Waypoint<'a> {
    /// The space (the one containing the point, for a point).
    pub space: Option<SpaceId>,
    /// Its name, if any.
    pub name: Option<&'a str>,
    /// Where the route starts, passes or ends, metres.
    #[serde(serialize_with = "point_mm")]
    pub location: Point,
}

/// One route.
#[derive(Debug, Serialize)]
pub struct RouteJson<'a> {
    /// Walked length in metres.
    pub distance: f64,
    /// Seconds at the profile's speed.
    pub duration: f64,
    /// One leg per pair of consecutive waypoints.
    pub legs: Vec<Leg<'a>>,
    /// The walked path.
    pub geometry: LineString<'a>,
    /// Every space entered, in order.
    pub spaces: Vec<SpaceJson<'a>>,
    /// The door spaces passed, in order.
    pub doors: Vec<SpaceId>,
    /// In a building with levels: the level of each stretch of the
    /// geometry (`from_waypoint` indexes its positions).
    #[serde(skip_serializing_if = "<[LevelSpan]>::is_empty")]
    pub levels: &'a [LevelSpan],
}

/// The part of a route between two waypoints.
#[derive(Debug, Serialize)]
pub struct Leg<'a> {
    /// Walked length in metres.
    pub distance: f64,
    /// Seconds at the profile's speed.
    pub duration: f64,
    /// The steps that end in this leg.
    pub steps: Vec<StepJson<'a>>,
}

/// A step: walk a distance, then turn (through a door) into a space.
#[derive(Debug, Serialize)]
pub struct StepJson<'a> {
    /// "walk 12 m along corridor 2, turn left through door 31 into Office 27".
    pub instruction: &'a str,
    /// Metres walked in this step.
    pub distance: f64,
    /// The manoeuvre at its end: straight, left, right, sharp_left,
    /// sharp_right, u_turn or arrive.
    pub turn: Turn,
    /// The space walked in.
    pub space: SpaceId,
    /// The door passed at its end.
    pub door: Option<SpaceId>,
    /// The space entered at its end.
    pub into: Option<SpaceId>,
    /// Where the manoeuvre happens, metres.
    #[serde(serialize_with = "point_mm")]
    pub location: Point,
    /// The level of the space walked in, in a building with levels.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub level: Option<&'a str>,
}

/// A GeoJSON LineString.
#[derive(Debug, Serialize)]
pub struct LineString<'a> {
    /// Always "LineString".
    #[serde(rename = "type")]
    pub kind: &'static str,
    /// `[x, y]` in metres, or `[x, y, z]` (z the level's elevation) in a
    /// building with levels.
    pub coordinates: Coordinates<'a>,
}

/// A LineString's positions.
#[derive(Debug, Serialize)]
#[serde(untagged)]
pub enum Coordinates<'a> {
    /// `[x, y]`, to the millimetre.
    Flat(#[serde(serialize_with = "points_mm")] &'a [Point]),
    /// `[x, y, z]`, to the millimetre.
    WithZ(Vec<[f64; 3]>),
}

impl<'a> Coordinates<'a> {
    /// The route's positions, with z when it has levels.
    fn of(route: &'a Route) -> Coordinates<'a> {
        if route.levels.is_empty() {
            return Coordinates::Flat(&route.waypoints);
        }
        let z = route.waypoint_elevations();
        Coordinates::WithZ(
            route
                .waypoints
                .iter()
                .zip(z)
                .map(|(p, z)| [millimetres(p[0]), millimetres(p[1]), millimetres(z)])
                .collect(),
        )
    }
}

/// A space passed.
#[derive(Debug, Serialize)]
pub struct SpaceJson<'a> {
    /// Its id.
    pub id: SpaceId,
    /// room, corridor, door or other.
    pub kind: &'static str,
    /// Its name, if any.
    pub name: Option<&'a str>,
    /// Its level, in a building with levels.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub level: Option<&'a str>,
}

/// The name of a space's level in `nrg`, if it has one.
fn level_of(nrg: &Nrg, id: SpaceId) -> Option<&str> {
    nrg.space(id)
        .and_then(|s| s.level.as_ref())
        .map(|l| l.name.as_str())
}

fn millimetres(m: f64) -> f64 {
    (m * 1000.0).round() / 1000.0
}

/// A point in metres, said to the millimetre (map cells are centimetres wide:
/// more digits would be noise, and they are most of the answer's bytes).
fn point_mm<S: serde::Serializer>(p: &Point, s: S) -> Result<S::Ok, S::Error> {
    p.map(millimetres).serialize(s)
}

/// Points as [`point_mm`] says each.
fn points_mm<S: serde::Serializer>(points: &&[Point], s: S) -> Result<S::Ok, S::Error> {
    s.collect_seq(points.iter().map(|p| p.map(millimetres)))
}

fn tenths(s: f64) -> f64 {
    (s * 10.0).round() / 10.0
}

fn step_json<'a>(s: &'a Step, nrg: &'a Nrg) -> StepJson<'a> {
    StepJson {
        level: level_of(nrg, s.space),
        instruction: &s.instruction,
        distance: millimetres(s.distance_m),
        turn: s.turn,
        space: s.space,
        door: s.door,
        into: s.into,
        location: s.at,
    }
}

/// Splits `route`'s steps into its legs by where each step ends.
fn legs<'a>(route: &'a Route, nrg: &'a Nrg) -> Vec<Leg<'a>> {
    let speed = if route.length_m > 0.0 && route.duration_s > 0.0 {
        route.length_m / route.duration_s
    } else {
        1.4
    };
    let mut out: Vec<Leg<'_>> = Vec::new();
    let mut ends = Vec::new();
    let mut acc = 0.0;
    for l in &route.leg_lengths_m {
        acc += l;
        ends.push(acc);
    }
    let mut walked = 0.0;
    let mut leg = 0;
    for l in &route.leg_lengths_m {
        out.push(Leg {
            distance: millimetres(*l),
            duration: tenths(l / speed),
            steps: Vec::new(),
        });
    }
    for s in &route.steps {
        walked += s.distance_m;
        while leg + 1 < ends.len() && walked > ends[leg] + 1e-6 {
            leg += 1;
        }
        if let Some(l) = out.get_mut(leg) {
            l.steps.push(step_json(s, nrg));
        }
    }
    out
}

/// Builds the answer for `routes` found between `stops` on `rev`; `reason`
/// says why there is none.
pub fn route_response<'a>(
    rev: &'a IndexedRevision,
    stops: &[Endpoint],
    routes: &'a [Route],
    reason: Option<String>,
) -> RouteResponse<'a> {
    let nrg = &rev.nrg;
    let waypoints = stops
        .iter()
        .map(|e| match e {
            Endpoint::Space(id) => {
                let s = nrg.space(*id);
                Waypoint {
                    space: Some(*id),
                    name: s.and_then(|s| s.name.as_deref()),
                    location: s.map_or([0.0, 0.0], |s| s.anchor),
                }
            }
            Endpoint::Point(_) | Endpoint::PointIn(..) => {
                let (p, id) = match e {
                    Endpoint::PointIn(p, id) => (*p, Some(*id)),
                    _ => (
                        e.point().unwrap_or_default(),
                        e.point().and_then(|p| rev.nav.locate(p)),
                    ),
                };
                Waypoint {
                    space: id,
                    name: id
                        .and_then(|id| nrg.space(id))
                        .and_then(|s| s.name.as_deref()),
                    location: p,
                }
            }
        })
        .collect();
    let routes_json = routes
        .iter()
        .map(|r| RouteJson {
            distance: millimetres(r.length_m),
            duration: tenths(r.duration_s),
            legs: legs(r, nrg),
            geometry: LineString {
                kind: "LineString",
                coordinates: Coordinates::of(r),
            },
            levels: &r.levels,
            spaces: r
                .spaces
                .iter()
                .filter_map(|id| nrg.space(*id))
                .map(|s| SpaceJson {
                    id: s.id,
                    kind: s.kind.as_str(),
                    name: s.name.as_deref(),
                    level: s.level.as_ref().map(|l| l.name.as_str()),
                })
                .collect(),
            doors: r.doors.clone(),
        })
        .collect::<Vec<_>>();
    let ok = !routes_json.is_empty();
    RouteResponse {
        code: if ok { "Ok" } else { "NoRoute" },
        message: if ok { None } else { reason },
        map: &rev.map,
        revision: rev.revision,
        waypoints,
        routes: routes_json,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::corridor_building;
    use crate::route::{Budget, RouteRequest, shortest_route};

    #[test]
    fn legs_split_at_waypoints_and_add_up() {
        let rev = IndexedRevision::new("m", 1, corridor_building(4));
        let mut req = RouteRequest::new(SpaceId(10), SpaceId(13));
        req.via = vec![Endpoint::Space(SpaceId(11))];
        let routes = shortest_route(&rev.nav, &req, &Budget::unlimited()).unwrap();
        let stops = [
            Endpoint::Space(SpaceId(10)),
            Endpoint::Space(SpaceId(11)),
            Endpoint::Space(SpaceId(13)),
        ];
        let answer = route_response(&rev, &stops, &routes, None);
        assert_eq!(answer.code, "Ok");
        let r = &answer.routes[0];
        assert_eq!(r.legs.len(), 2);
        let sum: f64 = r.legs.iter().map(|l| l.distance).sum();
        assert!((sum - r.distance).abs() < 0.01);
        let steps: f64 = r
            .legs
            .iter()
            .flat_map(|l| &l.steps)
            .map(|s| s.distance)
            .sum();
        assert!(
            (steps - r.distance).abs() < 0.01,
            "{steps} vs {}",
            r.distance
        );
        assert!(matches!(r.geometry.coordinates, Coordinates::Flat(c) if c.len() >= 2));
        assert_eq!(
            r.doors.len(),
            4,
            "in and out of rooms 11 and back out, into 13"
        );
    }
}
