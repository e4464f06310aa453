//! `/health`, `/metrics`, `/openapi.json` and the JSON answers for unknown
//! paths and methods.

use std::sync::Arc;

use axum::extract::{Request, State};
use axum::http::header;
use axum::response::{IntoResponse, Response};
use axum::{Extension, Json};
use serde_json::{Value, json};

use crate::server::error::ApiError;
use crate::server::state::AppState;

/// `GET /health`: `{"status":"ok"}` when a database query succeeds.
pub async fn health(State(state): State<AppState>) -> Result<Json<Value>, ApiError> {
    let maps = state.blocking(|ctx| Ok(ctx.store().maps()?.len())).await?;
    Ok(Json(json!({
        "status": "ok",
        "version": env!("CARGO_PKG_VERSION"),
        "maps": maps,
        "writable": state.config().writable(),
    })))
}

/// `GET /metrics`: Prometheus text.
pub async fn metrics(State(state): State<AppState>) -> Response {
    let shared = state.shared();
    let text = shared.metrics.render(&shared.cache);
    (
        [(
            header::CONTENT_TYPE,
            "text/plain; version=0.0.4; charset=utf-8",
        )],
        text,
    )
        .into_response()
}

/// The OpenAPI document, handed to [`openapi`] by the router (an
/// extension), so this file does not build it from the table it is in.
#[derive(Debug, Clone)]
pub struct OpenApiDocument(pub Arc<Value>);

/// `GET /openapi.json`: the document built from the route table.
pub async fn openapi(Extension(doc): Extension<OpenApiDocument>) -> Json<Value> {
    Json(Value::clone(&doc.0))
}

/// Any path no route matches: 404 JSON (counted as route "unmatched").
pub async fn fallback(State(state): State<AppState>, request: Request) -> Response {
    let e = ApiError::NoEndpoint {
        method: request.method().to_string(),
        path: request.uri().path().to_string(),
    };
    let response = e.into_response();
    state.shared().metrics.record(
        "unmatched",
        request.method().as_str(),
        response.status().as_u16(),
        0.0,
    );
    response
}

/// A known path with a method it does not take: 405 JSON.
pub async fn method_not_allowed(request: Request) -> Response {
    ApiError::MethodNotAllowed(request.method().to_string()).into_response()
}
