//! The per-request time bound as a middleware: past it the client gets a
//! 503 JSON error. Searches also carry the bound themselves
//! ([`crate::route::Budget`]), so their blocking work stops too.

use axum::extract::{Request, State};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};

use super::error::ApiError;
use super::state::AppState;

/// Runs the request within `config.timeout`.
pub async fn limit(State(state): State<AppState>, request: Request, next: Next) -> Response {
    let bound = state.config().timeout;
    match tokio::time::timeout(bound, next.run(request)).await {
        Ok(response) => response,
        Err(_) => ApiError::Timeout(bound.as_millis()).into_response(),
    }
}
