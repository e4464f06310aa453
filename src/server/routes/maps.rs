//! Maps and revisions: listings and whole-revision exports (IndoorGML,
//! GeoJSON).

use axum::Json;
use axum::extract::{Path, State};
use axum::http::{HeaderValue, Uri, header};
use axum::response::{IntoResponse, Response};
use serde_json::{Value, json};

use crate::format::{Frame, ModelFormat, frame_for, render_in};
use crate::indoorgml::IndoorGmlVersion;
use crate::server::endpoint::{ParamDoc, q};
use crate::server::error::ApiError;
use crate::server::params::{Params, parse_rev};
use crate::server::state::AppState;

/// `GET /maps`.
pub async fn list_maps(State(state): State<AppState>, uri: Uri) -> Result<Json<Value>, ApiError> {
    Params::parse(&uri, &[])?;
    let maps = state.blocking(|ctx| Ok(ctx.store().maps()?)).await?;
    Ok(Json(json!({ "maps": maps })))
}

/// `GET /maps/{map}`: the map and its latest revision.
pub async fn map(
    State(state): State<AppState>,
    Path(map): Path<String>,
    uri: Uri,
) -> Result<Json<Value>, ApiError> {
    Params::parse(&uri, &[])?;
    state
        .blocking(move |ctx| {
            let latest = ctx.store().revision(&map, None)?;
            let info = ctx.store().maps()?.into_iter().find(|m| m.name == map);
            let georef = ctx.store().georef(&map)?;
            Ok(Json(
                json!({ "map": info, "latest": latest, "georef": georef }),
            ))
        })
        .await
}

/// `GET /maps/{map}/revisions`.
pub async fn list_revisions(
    State(state): State<AppState>,
    Path(map): Path<String>,
    uri: Uri,
) -> Result<Json<Value>, ApiError> {
    Params::parse(&uri, &[])?;
    let revisions = {
        let map = map.clone();
        state
            .blocking(move |ctx| Ok(ctx.store().revisions(&map)?))
            .await?
    };
    Ok(Json(json!({ "map": map, "revisions": revisions })))
}

/// `GET /maps/{map}/revisions/{rev}`: one revision's record.
pub async fn revision(
    State(state): State<AppState>,
    Path((map, rev)): Path<(String, String)>,
    uri: Uri,
) -> Result<Json<Value>, ApiError> {
    Params::parse(&uri, &[])?;
    let rev = parse_rev("rev", &rev)?;
    state
        .blocking(move |ctx| {
            let info = ctx.store().revision(&map, rev)?;
            Ok(Json(json!({ "revision": info })))
        })
        .await
}

/// `GET /maps/{map}/levels?rev=`: a building's levels, lowest first,
/// each with its elevation and number of spaces, and the building's
/// extent (`frame_m`: x min, y min, x max, y max, metres); no levels for
/// a map without them.
pub async fn levels(
    State(state): State<AppState>,
    Path(map): Path<String>,
    uri: Uri,
) -> Result<Json<Value>, ApiError> {
    let rev = Params::parse(&uri, &["rev"])?.rev()?;
    state
        .quick(move |ctx| {
            let r = ctx.revision(&map, rev)?;
            let levels: Vec<Value> = r
                .nrg
                .levels()
                .into_iter()
                .map(|l| {
                    let n = r
                        .nrg
                        .spaces()
                        .iter()
                        .filter(|s| s.level.as_ref().is_some_and(|m| m.name == l.name))
                        .count();
                    json!({ "name": l.name, "elevation_m": l.elevation_m, "spaces": n })
                })
                .collect();
            let frame = r.nrg.extent();
            Ok(Json(json!({
                "map": r.map,
                "revision": r.revision,
                "levels": levels,
                "frame_m": frame,
            })))
        })
        .await
}

/// Cache headers: a numbered revision never changes; `latest` does.
fn with_caching(mut response: Response, numbered: bool) -> Response {
    let value = if numbered {
        "public, max-age=31536000, immutable"
    } else {
        "no-cache"
    };
    response
        .headers_mut()
        .insert(header::CACHE_CONTROL, HeaderValue::from_static(value));
    response
}

/// Parameters of the IndoorGML endpoint.
pub const INDOORGML_PARAMS: [ParamDoc; 1] = [q(
    "frame",
    "string",
    false,
    "'utm' (default for a georeferenced map: metres in the WGS84 / UTM zone of its origin, the zone as srsName) or 'local' (map-frame metres)",
)];

/// `GET /maps/{map}/revisions/{rev}/indoorgml`: in the UTM zone of a
/// georeferenced map (unless `frame=local`), else map-frame metres.
pub async fn indoorgml(
    State(state): State<AppState>,
    Path((map, rev)): Path<(String, String)>,
    uri: Uri,
) -> Result<Response, ApiError> {
    let (xml, fixed) = placed_export(&state, map, rev, &uri, ModelFormat::IndoorGml).await?;
    let response = (
        [(header::CONTENT_TYPE, "application/gml+xml; charset=utf-8")],
        xml,
    )
        .into_response();
    Ok(with_caching(response, fixed))
}

/// Parameters of the GeoJSON endpoint.
pub const GEOJSON_PARAMS: [ParamDoc; 1] = [q(
    "frame",
    "string",
    false,
    "'wgs84' (default for a georeferenced map: RFC 7946 longitude and latitude), 'utm' (metres in the WGS84 / UTM zone of its origin, named in a crs member) or 'local' (map-frame metres)",
)];

/// `GET /maps/{map}/revisions/{rev}/geojson`: WGS84 when the map is
/// georeferenced (unless `frame=utm` or `frame=local`), else map-frame
/// metres.
pub async fn geojson(
    State(state): State<AppState>,
    Path((map, rev)): Path<(String, String)>,
    uri: Uri,
) -> Result<Response, ApiError> {
    let (body, fixed) = placed_export(&state, map, rev, &uri, ModelFormat::GeoJson).await?;
    let response = ([(header::CONTENT_TYPE, "application/geo+json")], body).into_response();
    Ok(with_caching(response, fixed))
}

/// A revision as `format` in the frame the `frame` parameter asks for
/// (see [`crate::format::frame_for`]), and whether the answer never
/// changes (a numbered revision in map-frame metres: a georeference can
/// be changed later).
async fn placed_export(
    state: &AppState,
    map: String,
    rev: String,
    uri: &Uri,
    format: ModelFormat,
) -> Result<(String, bool), ApiError> {
    let params = Params::parse(uri, &["frame"])?;
    let asked = match params.get("frame") {
        None => None,
        Some(name) => Some(Frame::parse(name).ok_or_else(|| {
            ApiError::bad("frame", format!("'{name}': use 'local', 'wgs84' or 'utm'"))
        })?),
    };
    let rev = parse_rev("rev", &rev)?;
    state
        .blocking(move |ctx| {
            let georef = ctx.store().georef(&map)?;
            let frame = frame_for(format, asked, georef.is_some())
                .map_err(|e| ApiError::bad("frame", e.to_string()))?;
            let r = ctx.revision(&map, rev)?;
            let walked = crate::route::WalkedModel::on(&r.nav);
            let text = render_in(
                &walked,
                format,
                IndoorGmlVersion::default(),
                frame,
                georef.as_ref(),
            );
            Ok((text, rev.is_some() && frame == Frame::Local))
        })
        .await
}

/// `GET /maps/{map}/revisions/{rev}/nav2`: the revision as a Nav2 Route
/// Server graph (GeoJSON for `nav2_route`'s GeoJsonGraphFileLoader).
pub async fn nav2(
    State(state): State<AppState>,
    Path((map, rev)): Path<(String, String)>,
    uri: Uri,
) -> Result<Response, ApiError> {
    Params::parse(&uri, &[])?;
    let rev = parse_rev("rev", &rev)?;
    let body = state
        .blocking(move |ctx| {
            let r = ctx.revision(&map, rev)?;
            Ok(crate::format::nav2::to_nav2(&r.nav))
        })
        .await?;
    if let Err(e) = crate::format::nav2::check_nav2(&body) {
        return Err(ApiError::bad(
            "map",
            format!("this revision makes no Nav2 route graph: {e}"),
        ));
    }
    let text = serde_json::to_string(&body).unwrap_or_default();
    let response = ([(header::CONTENT_TYPE, "application/geo+json")], text).into_response();
    Ok(with_caching(response, rev.is_some()))
}
