//! The web viewer: `GET /` serves one page (plain HTML, CSS and JS in
//! `index.html`, compiled into the binary, no build step) and
//! `GET /maps/{map}/revisions/{rev}/svg` draws a revision with
//! [`crate::render::render_svg`], optionally with a route (`?route=FROM,TO`)
//! or the changes since another revision (`?diff=A`); a building one
//! level at a time (`?level=L`).
//!
//! Uses render, route, query's indexed revisions and the server's state,
//! params and errors; the page itself only calls the JSON API.

use axum::extract::{Path, State};
use axum::http::{HeaderValue, Uri, header};
use axum::response::{IntoResponse, Response};

use crate::diff::DiffOptions;
use crate::model::SpaceId;
use crate::query::compare_revisions;
use crate::query::{IndexedRevision, QueryError, SpaceRef};
use crate::render::{RenderOptions, RouteOverlay, Scene, diff_overlay, render_svg};
use crate::route::{Budget, RouteRequest, shortest_route};
use crate::server::endpoint::{ParamDoc, q};
use crate::server::error::{ApiError, comparing_error};
use crate::server::params::{Params, level_param, parse_rev};
use crate::server::state::AppState;
use crate::store::StoreError;

/// The page.
pub const INDEX_HTML: &str = include_str!("index.html");

/// Query parameters of the SVG endpoint.
pub const SVG_PARAMS: [ParamDoc; 4] = [
    q(
        "level",
        "string",
        false,
        "in a building with levels, the level drawn (default: the lowest); a route is drawn where it is on that level, with marks where it changes level",
    ),
    q(
        "route",
        "string",
        false,
        "draw the shortest route FROM,TO (space ids or names)",
    ),
    q(
        "diff",
        "string",
        false,
        "draw what changed since this revision number (the change set of GET /maps/{map}/diff?from=A&to=rev, aligned when the frames differ)",
    ),
    q(
        "map",
        "boolean",
        false,
        "draw the revision's occupancy map underneath when the store has it (default true)",
    ),
];

/// `GET /`: the viewer page.
pub async fn page() -> Response {
    let mut response = (
        [(header::CONTENT_TYPE, "text/html; charset=utf-8")],
        INDEX_HTML,
    )
        .into_response();
    response
        .headers_mut()
        .insert(header::CACHE_CONTROL, HeaderValue::from_static("no-cache"));
    response
}

/// A space by id or name on `rev`; unknown spaces are 404s naming `route`.
fn space(raw: &str, rev: &IndexedRevision) -> Result<SpaceId, ApiError> {
    let raw = raw.trim();
    let r = match raw.parse::<u32>() {
        Ok(id) => SpaceRef::Id {
            kind: None,
            id: SpaceId(id),
        },
        Err(_) => SpaceRef::Name(raw.to_string()),
    };
    rev.resolve(&r).map_err(|e| match e {
        QueryError::UnknownId(_) | QueryError::UnknownName { .. } => {
            ApiError::not_found("route", format!("route: {e}"))
        }
        other => ApiError::bad("route", other.to_string()),
    })
}

/// `GET /maps/{map}/revisions/{rev}/svg?route=FROM,TO&diff=A&level=L&map=false`.
pub async fn svg(
    State(state): State<AppState>,
    Path((map, rev)): Path<(String, String)>,
    uri: Uri,
) -> Result<Response, ApiError> {
    let p = Params::parse(&uri, &["route", "diff", "map", "level"])?;
    let level = p.get("level").map(str::to_string);
    let rev = parse_rev("rev", &rev)?;
    let route = p.get("route").map(str::to_string);
    let diff: Option<u32> = p.opt("diff", "a revision number")?;
    let with_map = p.opt::<bool>("map", "true or false")?.unwrap_or(true);
    let timeout = state.config().timeout;
    // The search stops when the client gets its 503, even when it started
    // late (waiting for a blocking thread).
    let deadline = std::time::Instant::now().checked_add(timeout);
    let body = state
        .blocking(move |ctx| {
            let r = ctx.revision(&map, rev)?;
            // The level drawn: asked for, else the lowest.
            let level = match level_param(level.as_deref(), &r)? {
                Some(l) => Some(l),
                None => r.nrg.levels().into_iter().next().map(|l| l.name),
            };
            let overlay = match &route {
                None => None,
                Some(pair) => {
                    let (from, to) = pair.split_once(',').ok_or_else(|| {
                        ApiError::bad(
                            "route",
                            format!("'{pair}': expected FROM,TO (two space ids or names)"),
                        )
                    })?;
                    let request = RouteRequest::new(space(from, &r)?, space(to, &r)?);
                    let routes =
                        shortest_route(&r.nav, &request, &Budget::within(timeout, deadline))?;
                    routes.first().and_then(|x| match &level {
                        Some(l) => RouteOverlay::on_level(&r.nrg, x, l),
                        None => Some(RouteOverlay::of_route(&r.nrg, x)),
                    })
                }
            };
            // The change set of `GET /diff?from=A&to=rev`, drawn over rev.
            let changes = match diff {
                None => None,
                Some(a) => {
                    let a = ctx
                        .store()
                        .revision(&map, Some(a))
                        .map_err(|e| match e {
                            StoreError::NoSuchRevision { .. } => {
                                ApiError::not_found("diff", e.to_string())
                            }
                            other => other.into(),
                        })?
                        .seq;
                    let done = compare_revisions(
                        &*ctx.store(),
                        &map,
                        u64::from(a),
                        r.revision,
                        &DiffOptions {
                            deadline,
                            ..DiffOptions::default()
                        },
                    )
                    .map_err(|e| {
                        comparing_error(
                            e,
                            "diff",
                            "GET /maps/{map}/diff?align=never compares them as they are",
                            timeout.as_millis(),
                        )
                    })?;
                    let all = diff_overlay(&done.comparison.changes, &done.old.nrg, &done.new.nrg);
                    Some(match &level {
                        Some(l) => all.on_level(&done.old.nrg, &done.new.nrg, l),
                        None => all,
                    })
                }
            };
            let mut title = match diff {
                Some(a) => format!("{map}@{a} -> @{}", r.revision),
                None => format!("{map}@{}", r.revision),
            };
            // A level is drawn alone, in the whole building's frame so
            // that switching levels keeps the picture in place.
            let (floor, frame_m) = match &level {
                Some(l) => {
                    title.push_str(&format!(" level {l}"));
                    let floor = r.nrg.level_model(l).ok_or_else(|| {
                        ApiError::not_found("level", format!("no spaces on level {l}"))
                    })?;
                    (Some(floor), r.nrg.extent())
                }
                None => (None, None),
            };
            let options = RenderOptions {
                title: Some(title),
                frame_m,
                ..RenderOptions::default()
            };
            // Buildings with levels keep no single occupancy map.
            let grid = if with_map && level.is_none() {
                let seq = u32::try_from(r.revision).map_err(|_| {
                    ApiError::Internal(format!("revision {} too large", r.revision))
                })?;
                ctx.store().grid(&map, Some(seq))?
            } else {
                None
            };
            let scene = Scene {
                nrg: floor.as_ref().unwrap_or(&r.nrg),
                map: grid.as_ref(),
                route: overlay.as_ref(),
                diff: changes.as_ref(),
                options: &options,
            };
            render_svg(&scene).map_err(|e| ApiError::Internal(format!("drawing {map}: {e}")))
        })
        .await?;
    let mut response = ([(header::CONTENT_TYPE, "image/svg+xml")], body).into_response();
    let caching = if rev.is_some() {
        "public, max-age=3600"
    } else {
        "no-cache"
    };
    response
        .headers_mut()
        .insert(header::CACHE_CONTROL, HeaderValue::from_static(caching));
    Ok(response)
}
