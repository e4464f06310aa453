//! `GET /maps/{map}/route`: shortest route or alternatives between spaces
//! given by id, name or point, through waypoints, around avoided spaces.

use axum::extract::{Path, State};
use axum::http::{Uri, header};
use axum::response::{IntoResponse, Response};

use super::route_json::route_response;
use crate::model::SpaceId;
use crate::query::{IndexedRevision, QueryError, SpaceRef};
use crate::route::{Budget, Endpoint, Profile, RouteRequest, no_route_reason, shortest_route};
use crate::server::endpoint::{ParamDoc, REV, q};
use crate::server::error::ApiError;
use crate::server::params::{Params, parse_value};
use crate::server::state::{AppState, Ctx};

use crate::route::MAX_ALTERNATIVES;

/// Query parameters of the route endpoint.
pub const PARAMS: [ParamDoc; 12] = [
    q(
        "from",
        "string",
        true,
        "start: space id, name, or point 'x,y' in metres ('x,y@L' on level L of a building)",
    ),
    q(
        "to",
        "string",
        true,
        "goal: space id, name, or point 'x,y' in metres ('x,y@L' on level L of a building)",
    ),
    q(
        "via",
        "string",
        false,
        "waypoints in order: comma-separated ids or names; with points ('x,y', 'x,y@L'), ';'-separated",
    ),
    q(
        "avoid",
        "string",
        false,
        "spaces not to enter: comma-separated ids or names",
    ),
    q(
        "avoid_where",
        "string",
        false,
        "spaces not to enter: a FIND condition, e.g. attr.restricted = TRUE (the route's ends excepted)",
    ),
    q(
        "alternatives",
        "string",
        false,
        "true (3 routes), false, or a number of routes 1 to 10",
    ),
    q(
        "clearance",
        "number",
        false,
        "distance kept from walls, metres (default 0.2; a robot: its radius; 0 to 5)",
    ),
    q(
        "min_door_width",
        "number",
        false,
        "doors narrower than this are impassable, metres (default 0)",
    ),
    q(
        "speed",
        "number",
        false,
        "walking speed for durations, m/s (default 1.4)",
    ),
    q(
        "no_stairs",
        "boolean",
        false,
        "true: never take stairs between levels (a wheelchair, most robots)",
    ),
    q(
        "no_elevator",
        "boolean",
        false,
        "true: never take a lift between levels",
    ),
    REV,
];

/// A space reference: an id, a point `x,y`, or a name.
fn reference(raw: &str) -> SpaceRef {
    let raw = raw.trim();
    if let Ok(id) = raw.parse::<u32>() {
        return SpaceRef::Id {
            kind: None,
            id: SpaceId(id),
        };
    }
    // `x,y@L`: the point on level L of a building.
    let (point, level) = match raw.rsplit_once('@') {
        Some((p, l)) if !l.trim().is_empty() => (p, Some(l.trim())),
        _ => (raw, None),
    };
    if let Some((x, y)) = point.split_once(',')
        && let (Ok(x), Ok(y)) = (x.trim().parse::<f64>(), y.trim().parse::<f64>())
        && x.is_finite()
        && y.is_finite()
    {
        return match level {
            Some(l) => SpaceRef::PointOn {
                at: [x, y],
                level: l.to_string(),
            },
            None => SpaceRef::Point([x, y]),
        };
    }
    SpaceRef::Name(raw.to_string())
}

/// Resolves parameter `name`'s value on `rev`; unknown spaces are 404s
/// naming the parameter.
fn resolve(name: &str, raw: &str, rev: &IndexedRevision) -> Result<SpaceId, ApiError> {
    rev.resolve(&reference(raw)).map_err(|e| match e {
        QueryError::UnknownId(_)
        | QueryError::UnknownName { .. }
        | QueryError::NoSpaceAt { .. }
        | QueryError::NoSpaceOnLevel { .. } => ApiError::not_found(name, format!("{name}: {e}")),
        other => ApiError::bad(name, other.to_string()),
    })
}

/// A route end: a point `x,y` is the point itself (it must lie in a
/// space; `x,y@L` in a space on level L); anything else is a space (its
/// anchor).
fn endpoint(name: &str, raw: &str, rev: &IndexedRevision) -> Result<Endpoint, ApiError> {
    match reference(raw) {
        SpaceRef::PointOn { at, level } => rev
            .point_on(at, &level)
            .map_err(|e| ApiError::not_found(name, format!("{name}: {e}"))),
        SpaceRef::Point(p) => match rev.nav.locate(p) {
            Some(_) => Ok(Endpoint::Point(p)),
            None => Err(ApiError::not_found(
                name,
                format!("{name}: {}", rev.outside(p)),
            )),
        },
        _ => Ok(Endpoint::Space(resolve(name, raw, rev)?)),
    }
}

/// `via`: waypoints separated by `;` when any is a point, else by `,`.
fn endpoints(
    name: &str,
    raw: Option<&str>,
    rev: &IndexedRevision,
) -> Result<Vec<Endpoint>, ApiError> {
    let Some(raw) = raw else {
        return Ok(Vec::new());
    };
    // One point alone (`x,y` or `x,y@L`) is one waypoint.
    let one_point = matches!(
        reference(raw),
        SpaceRef::Point(_) | SpaceRef::PointOn { .. }
    );
    let parts: Vec<&str> = if raw.contains(';') {
        raw.split(';').collect()
    } else if one_point {
        vec![raw]
    } else {
        raw.split(',').collect()
    };
    parts
        .into_iter()
        .filter(|s| !s.trim().is_empty())
        .map(|s| endpoint(name, s, rev))
        .collect()
}

/// The walker from `clearance`, `min_door_width` and `speed`.
fn profile(p: &Params) -> Result<Profile, ApiError> {
    let d = Profile::default();
    let number = |name: &str, default: f64| -> Result<f64, ApiError> {
        p.get(name).map_or(Ok(default), |raw| {
            parse_value(name, raw.trim(), "a number of metres")
        })
    };
    let flag = |name: &str| -> Result<bool, ApiError> {
        match p.get(name).map(str::trim) {
            None | Some("false") => Ok(false),
            Some("true") => Ok(true),
            Some(other) => Err(ApiError::bad(name, format!("'{other}': use true or false"))),
        }
    };
    let profile = Profile {
        clearance_m: number("clearance", d.clearance_m)?,
        min_door_width_m: number("min_door_width", d.min_door_width_m)?,
        speed_m_s: number("speed", d.speed_m_s)?,
        no_stairs: flag("no_stairs")?,
        no_elevator: flag("no_elevator")?,
    };
    profile.validate().map_err(ApiError::from)?;
    Ok(profile)
}

fn list(name: &str, raw: Option<&str>, rev: &IndexedRevision) -> Result<Vec<SpaceId>, ApiError> {
    raw.map_or(Ok(Vec::new()), |raw| {
        raw.split(',')
            .filter(|s| !s.trim().is_empty())
            .map(|s| resolve(name, s, rev))
            .collect()
    })
}

fn alternatives(raw: Option<&str>) -> Result<usize, ApiError> {
    match raw.map(str::trim) {
        None | Some("false") => Ok(1),
        Some("true") => Ok(3),
        Some(n) => {
            let k: usize = parse_value("alternatives", n, "true, false or a number of routes")?;
            if (1..=MAX_ALTERNATIVES).contains(&k) {
                Ok(k)
            } else {
                Err(ApiError::bad(
                    "alternatives",
                    format!("{k} is out of range (1 to {MAX_ALTERNATIVES})"),
                ))
            }
        }
    }
}

/// `GET /maps/{map}/route?from=&to=&via=&avoid=&avoid_where=&alternatives=&clearance=&min_door_width=&speed=&rev=`.
pub async fn route(
    State(state): State<AppState>,
    Path(map): Path<String>,
    uri: Uri,
) -> Result<Response, ApiError> {
    let p = Params::parse(
        &uri,
        &[
            "from",
            "to",
            "via",
            "avoid",
            "avoid_where",
            "alternatives",
            "clearance",
            "min_door_width",
            "speed",
            "no_stairs",
            "no_elevator",
            "rev",
        ],
    )?;
    let walker = profile(&p)?;
    let from = p.required("from")?.to_string();
    let to = p.required("to")?.to_string();
    let via = p.get("via").map(str::to_string);
    let avoid = p.get("avoid").map(str::to_string);
    let avoid_where = p
        .get("avoid_where")
        .map(crate::query::parse_condition)
        .transpose()
        .map_err(|e| ApiError::bad("avoid_where", e.to_string()))?;
    let k = alternatives(p.get("alternatives"))?;
    if k > 1 && via.is_some() {
        return Err(ApiError::bad(
            "alternatives",
            "alternatives are not computed for routes with waypoints (drop via or alternatives)",
        ));
    }
    let rev = p.rev()?;
    let timeout = state.config().timeout;
    // The search stops when the client gets its 503, even when it started
    // late (waiting for a blocking thread).
    let deadline = std::time::Instant::now().checked_add(timeout);
    let work = move |ctx: &mut Ctx<'_>| {
        let r = ctx.revision(&map, rev)?;
        let (from, to) = (endpoint("from", &from, &r)?, endpoint("to", &to, &r)?);
        let mut avoided = list("avoid", avoid.as_deref(), &r)?;
        if let Some(cond) = &avoid_where {
            let ends: Vec<SpaceId> = [&from, &to]
                .into_iter()
                .filter_map(Endpoint::space)
                .collect();
            avoided.extend(
                crate::query::matching_spaces(cond, &r, &ends)
                    .map_err(|e| ApiError::bad("avoid_where", e.to_string()))?,
            );
        }
        let request = RouteRequest {
            from,
            to,
            via: endpoints("via", via.as_deref(), &r)?,
            avoid: avoided,
            alternatives: k,
            profile: walker,
        };
        let routes = shortest_route(&r.nav, &request, &Budget::within(timeout, deadline))?;
        let reason = routes.is_empty().then(|| no_route_reason(&r.nav, &request));
        let mut stops = vec![request.from];
        stops.extend(&request.via);
        stops.push(request.to);
        serde_json::to_vec(&route_response(&r, &stops, &routes, reason))
            .map_err(|e| ApiError::Internal(e.to_string()))
    };
    // One shortest route is a Dijkstra: cheap enough for the async worker
    // when the revision is cached. Alternatives (Yen) go to the blocking pool.
    let body = if k == 1 {
        state.quick(work).await?
    } else {
        state.blocking(work).await?
    };
    Ok(([(header::CONTENT_TYPE, "application/json")], body).into_response())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn references_and_alternatives() {
        assert_eq!(
            reference("12"),
            SpaceRef::Id {
                kind: None,
                id: SpaceId(12)
            }
        );
        assert_eq!(reference("1.5, 2"), SpaceRef::Point([1.5, 2.0]));
        assert_eq!(reference("Kitchen"), SpaceRef::Name("Kitchen".into()));
        assert_eq!(alternatives(Some("true")).unwrap(), 3);
        assert_eq!(alternatives(None).unwrap(), 1);
        assert!(alternatives(Some("11")).is_err());
        assert!(alternatives(Some("x")).is_err());
    }
}
