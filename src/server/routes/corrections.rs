//! `GET /maps/{map}/corrections` (the corrections kept with a map and
//! their state) and `POST /maps/{map}/corrections/{id}/undo` (undo the
//! map's last edit; bearer token).

use axum::Json;
use axum::extract::{Path, State};
use axum::http::{HeaderMap, Uri};
use serde_json::{Value, json};

use crate::server::auth::require_write;
use crate::server::error::ApiError;
use crate::server::params::Params;
use crate::server::state::AppState;

/// `GET /maps/{map}/corrections`.
pub async fn list(
    State(state): State<AppState>,
    Path(map): Path<String>,
    uri: Uri,
) -> Result<Json<Value>, ApiError> {
    Params::parse(&uri, &[])?;
    let name = map.clone();
    let corrections = state
        .blocking(move |ctx| {
            ctx.store().revision(&name, None)?;
            Ok(ctx.store().corrections(&name)?)
        })
        .await?;
    Ok(Json(json!({ "map": map, "corrections": corrections })))
}

/// `POST /maps/{map}/corrections/{id}/undo` (bearer token).
pub async fn undo(
    State(state): State<AppState>,
    Path((map, id)): Path<(String, String)>,
    uri: Uri,
    headers: HeaderMap,
) -> Result<Json<Value>, ApiError> {
    require_write(state.config(), &headers)?;
    Params::parse(&uri, &[])?;
    let id: u32 = id
        .parse()
        .map_err(|_| ApiError::bad("id", format!("'{id}' is not a correction number")))?;
    let revision = state
        .blocking(move |ctx| Ok(ctx.store().undo_correction(&map, id)?))
        .await?;
    Ok(Json(json!({ "revision": revision, "undone": id })))
}
