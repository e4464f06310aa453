//! The metrics middleware: times each request and records it under its
//! route pattern in the shared [`Metrics`](super::metrics::Metrics). Apart
//! from `metrics.rs` so that the counters do not depend on the state that
//! holds them (state → metrics, track → state and metrics).

use std::time::Instant;

use axum::extract::{MatchedPath, Request, State};
use axum::middleware::Next;
use axum::response::Response;

use super::state::AppState;

/// Middleware: times the request and records it under its route pattern.
pub async fn track(State(state): State<AppState>, request: Request, next: Next) -> Response {
    let started = Instant::now();
    let route = request
        .extensions()
        .get::<MatchedPath>()
        .map(|p| p.as_str().to_string());
    let method = request.method().clone();
    let response = next.run(request).await;
    state.shared().metrics.record(
        route.as_deref().unwrap_or("unmatched"),
        method.as_str(),
        response.status().as_u16(),
        started.elapsed().as_secs_f64(),
    );
    response
}
