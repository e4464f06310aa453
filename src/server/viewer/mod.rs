//! The web viewer: `GET /` serves one page (plain HTML, CSS and JS in
//! `index.html`, compiled into the binary, no build step) and
//! `GET /maps/{map}/revisions/{rev}/svg` draws a revision with
//! [`crate::render::render_svg`], optionally with a route (`?route=FROM,TO`)
//! or the changes since another revision (`?diff=A`).
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
use crate::server::params::{Params, parse_rev};
use crate::server::state::AppState;
use crate::store::StoreError;

/// The page.
pub const INDEX_HTML: &str = include_str!("index.html");

/// Query parameters of the SVG endpoint.
pub const SVG_PARAMS: [ParamDoc; 3] = [
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

/// `GET /maps/{map}/revisions/{rev}/svg?route=FROM,TO&diff=A`.
pub async fn svg(
    State(state): State<AppState>,
    Path((map, rev)): Path<(String, String)>,
    uri: Uri,
) -> Result<Response, ApiError> {
    let p = Params::parse(&uri, &["route", "diff", "map"])?;
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
                    routes.first().map(|x| {
                        RouteOverlay::along(&r.nrg, &x.spaces, x.waypoints.clone(), x.length_m)
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
                    Some(diff_overlay(
                        &done.comparison.changes,
                        &done.old.nrg,
                        &done.new.nrg,
                    ))
                }
            };
            let title = match diff {
                Some(a) => format!("{map}@{a} -> @{}", r.revision),
                None => format!("{map}@{}", r.revision),
            };
            let options = RenderOptions {
                title: Some(title),
                ..RenderOptions::default()
            };
            let grid = if with_map {
                let seq = u32::try_from(r.revision).map_err(|_| {
                    ApiError::Internal(format!("revision {} too large", r.revision))
                })?;
                ctx.store().grid(&map, Some(seq))?
            } else {
                None
            };
            let scene = Scene {
                nrg: &r.nrg,
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
