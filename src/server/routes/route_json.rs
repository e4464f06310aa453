//! The route answer, shaped like the routing engines people know (OSRM,
//! GraphHopper): `code`, the snapped `waypoints`, and `routes` with
//! distance (metres), duration (seconds at walking speed), `legs` between
//! waypoints with readable steps, the path as a GeoJSON LineString through
//! the spaces' anchors (map frame), and the spaces and doors passed.

use serde::Serialize;

use crate::model::{Nrg, Point, SpaceId};
use crate::query::IndexedRevision;
use crate::route::{Route, describe_steps};

/// Walking speed used for `duration`, in metres per second.
pub const WALKING_SPEED_M_S: f64 = 1.4;

/// The whole answer of `GET /maps/{map}/route`.
#[derive(Debug, Serialize)]
pub struct RouteResponse<'a> {
    /// "Ok", or "NoRoute" when the spaces are not connected.
    pub code: &'static str,
    /// The map.
    pub map: &'a str,
    /// The revision routed on.
    pub revision: u64,
    /// Start, waypoints and goal as resolved.
    pub waypoints: Vec<Waypoint<'a>>,
    /// Routes, shortest first (empty with "NoRoute").
    pub routes: Vec<RouteJson<'a>>,
}

/// A resolved stop.
#[derive(Debug, Serialize)]
pub struct Waypoint<'a> {
    /// The space.
    pub space: SpaceId,
    /// Its name, if any.
    pub name: Option<&'a str>,
    /// Its anchor in metres.
    pub location: Point,
}

/// One route.
#[derive(Debug, Serialize)]
pub struct RouteJson<'a> {
    /// Length in metres.
    pub distance: f64,
    /// Seconds at [`WALKING_SPEED_M_S`].
    pub duration: f64,
    /// One leg per pair of consecutive waypoints.
    pub legs: Vec<Leg>,
    /// The path through the anchors.
    pub geometry: LineString<'a>,
    /// Every space entered, in order.
    pub spaces: Vec<SpaceJson<'a>>,
    /// The door spaces passed, in order.
    pub doors: Vec<SpaceId>,
}

/// The part of a route between two waypoints.
#[derive(Debug, Serialize)]
pub struct Leg {
    /// Length in metres.
    pub distance: f64,
    /// Seconds at walking speed.
    pub duration: f64,
    /// Where it starts.
    pub from: SpaceId,
    /// Where it ends.
    pub to: SpaceId,
    /// Readable steps.
    pub steps: Vec<Step>,
}

/// A readable step.
#[derive(Debug, Serialize)]
pub struct Step {
    /// "leave Kitchen through door 7 into corridor 3".
    pub instruction: String,
}

/// A GeoJSON LineString.
#[derive(Debug, Serialize)]
pub struct LineString<'a> {
    /// Always "LineString".
    #[serde(rename = "type")]
    pub kind: &'static str,
    /// `[x, y]` in metres.
    pub coordinates: &'a [Point],
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
}

fn millimetres(m: f64) -> f64 {
    (m * 1000.0).round() / 1000.0
}

fn seconds(m: f64) -> f64 {
    (m / WALKING_SPEED_M_S * 10.0).round() / 10.0
}

fn path_length(nrg: &Nrg, path: &[SpaceId]) -> f64 {
    path.windows(2)
        .filter_map(|w| nrg.connection(w[0], w[1]))
        .map(|c| c.length_m)
        .sum()
}

/// Splits `route` into legs at the `stops` (start, waypoints, goal), in order.
fn legs(nrg: &Nrg, route: &Route, stops: &[SpaceId]) -> Vec<Leg> {
    let path = &route.spaces;
    if stops.len() <= 2 {
        let (from, to) = (path.first().copied(), path.last().copied());
        return vec![Leg {
            distance: millimetres(route.length_m),
            duration: seconds(route.length_m),
            from: from.unwrap_or(SpaceId(0)),
            to: to.unwrap_or(SpaceId(0)),
            steps: route
                .steps
                .iter()
                .map(|s| Step {
                    instruction: s.clone(),
                })
                .collect(),
        }];
    }
    let mut out = Vec::new();
    let mut start = 0;
    for stop in stops.iter().skip(1) {
        let end = path
            .iter()
            .enumerate()
            .skip(start + 1)
            .find(|(_, id)| *id == stop)
            .map_or(path.len().saturating_sub(1), |(i, _)| i);
        let piece = path.get(start..=end).unwrap_or(&[]);
        let length = path_length(nrg, piece);
        out.push(Leg {
            distance: millimetres(length),
            duration: seconds(length),
            from: path.get(start).copied().unwrap_or(SpaceId(0)),
            to: *stop,
            steps: describe_steps(nrg, piece)
                .into_iter()
                .map(|instruction| Step { instruction })
                .collect(),
        });
        start = end;
    }
    out
}

/// Builds the answer for `routes` found between `stops` on `rev`.
pub fn route_response<'a>(
    rev: &'a IndexedRevision,
    stops: &[SpaceId],
    routes: &'a [Route],
) -> RouteResponse<'a> {
    let nrg = &rev.nrg;
    let waypoints = stops
        .iter()
        .filter_map(|id| nrg.space(*id))
        .map(|s| Waypoint {
            space: s.id,
            name: s.name.as_deref(),
            location: s.anchor,
        })
        .collect();
    let routes_json = routes
        .iter()
        .map(|r| RouteJson {
            distance: millimetres(r.length_m),
            duration: seconds(r.length_m),
            legs: legs(nrg, r, stops),
            geometry: LineString {
                kind: "LineString",
                coordinates: &r.waypoints,
            },
            spaces: r
                .spaces
                .iter()
                .filter_map(|id| nrg.space(*id))
                .map(|s| SpaceJson {
                    id: s.id,
                    kind: s.kind.as_str(),
                    name: s.name.as_deref(),
                })
                .collect(),
            doors: r.doors.clone(),
        })
        .collect::<Vec<_>>();
    RouteResponse {
        code: if routes_json.is_empty() {
            "NoRoute"
        } else {
            "Ok"
        },
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
        req.via = vec![SpaceId(11)];
        let routes = shortest_route(&rev.graph, &rev.nrg, &req, &Budget::unlimited()).unwrap();
        let stops = [SpaceId(10), SpaceId(11), SpaceId(13)];
        let answer = route_response(&rev, &stops, &routes);
        assert_eq!(answer.code, "Ok");
        let r = &answer.routes[0];
        assert_eq!(r.legs.len(), 2);
        assert_eq!((r.legs[0].to, r.legs[1].from), (SpaceId(11), SpaceId(11)));
        let sum: f64 = r.legs.iter().map(|l| l.distance).sum();
        assert!((sum - r.distance).abs() < 0.01);
        assert_eq!(r.geometry.coordinates.len(), r.spaces.len());
        assert_eq!(
            r.doors.len(),
            4,
            "in and out of rooms 11 and back out, into 13"
        );
    }
}
