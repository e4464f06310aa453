//! The HTTP JSON navigation backend (`nrgdb serve`): maps, revisions,
//! spaces, routes, queries and uploads over axum + tokio.
//!
//! Owns the route table ([`routes::endpoints`], one line per endpoint,
//! from which both [`router`] and the OpenAPI document are built), the
//! request state (a pool of store connections and a cache of indexed
//! revisions per (map, revision)), JSON errors, metrics, auth and
//! shutdown. Uses store, query, route, extract, indoorgml and geojson;
//! nothing below uses it. Behind the `server` feature.
//!
//! Writes need `Authorization: Bearer <token>`; a server started without
//! a token is read-only and answers writes with 403. Blocking work (SQLite,
//! routing, extraction) runs in `spawn_blocking`, each request with a store
//! connection of its own.
//!
//! ```no_run
//! # async fn run() -> Result<(), nrgdb::server::ServerError> {
//! let config = nrgdb::server::ServerConfig::new("nrgdb.sqlite");
//! nrgdb::server::serve(config).await
//! # }
//! ```

mod auth;
mod body;
mod cache;
mod config;
mod connections;
mod endpoint;
mod error;
mod metrics;
pub mod multipart;
mod openapi;
mod params;
pub mod routes;
mod shutdown;
mod state;
mod timeout;
mod track;
pub mod viewer;
mod write_timeout;

use std::future::Future;
use std::net::SocketAddr;
use std::sync::{Arc, OnceLock};

use axum::http::{HeaderValue, Method, header};
use axum::middleware::from_fn_with_state;
use axum::{Extension, Router};
use tokio::net::TcpListener;
use tower_http::cors::{AllowOrigin, CorsLayer};
use tower_http::trace::{DefaultMakeSpan, DefaultOnResponse, TraceLayer};
use tracing::Level;

pub use cache::RevisionCache;
pub use config::{DEFAULT_ADDR, ServerConfig};
pub use error::{ApiError, ServerError};
pub use metrics::Metrics;
pub use params::Params;
pub use shutdown::signal as shutdown_signal;
pub use state::{AppState, Ctx, Slot, StorePool};

/// The application: every endpoint of [`routes::endpoints`] with the
/// request timeout, metrics, tracing, JSON 404/405 answers and, when
/// configured, CORS.
pub fn router(state: AppState) -> Router {
    let mut app = Router::new();
    for e in routes::endpoints() {
        let handler = if e.timed {
            e.handler
                .layer(from_fn_with_state(state.clone(), timeout::limit))
        } else {
            e.handler
        };
        app = app.route(e.path, handler);
    }
    let doc = routes::OpenApiDocument(Arc::new(openapi_document()));
    let mut app = app
        .layer(Extension(doc))
        .route_layer(from_fn_with_state(state.clone(), track::track))
        .fallback(routes::fallback)
        .method_not_allowed_fallback(routes::method_not_allowed)
        .layer(
            // One span and one "finished processing request" event per
            // request at INFO (shown with `nrgdb -v serve`).
            TraceLayer::new_for_http()
                .make_span_with(DefaultMakeSpan::new().level(Level::INFO))
                .on_response(DefaultOnResponse::new().level(Level::INFO)),
        );
    if let Some(cors) = cors(&state.config().cors_origins) {
        app = app.layer(cors);
    }
    app.with_state(state)
}

/// The OpenAPI 3.1 document of [`routes::endpoints`] (built once).
pub fn openapi_document() -> serde_json::Value {
    static DOC: OnceLock<serde_json::Value> = OnceLock::new();
    DOC.get_or_init(|| openapi::document(&routes::endpoints()))
        .clone()
}

fn cors(origins: &[String]) -> Option<CorsLayer> {
    if origins.is_empty() {
        return None;
    }
    let allow = if origins.iter().any(|o| o == "*") {
        AllowOrigin::any()
    } else {
        AllowOrigin::list(origins.iter().filter_map(|o| HeaderValue::from_str(o).ok()))
    };
    Some(
        CorsLayer::new()
            .allow_origin(allow)
            .allow_methods([Method::GET, Method::POST])
            .allow_headers([header::AUTHORIZATION, header::CONTENT_TYPE]),
    )
}

/// Binds `addr` (port 0 picks a free one).
pub async fn bind(addr: SocketAddr) -> Result<TcpListener, ServerError> {
    TcpListener::bind(addr)
        .await
        .map_err(|source| ServerError::Bind { addr, source })
}

/// Serves `state` on `listener` until `shutdown` resolves, then lets
/// in-flight requests finish. Connections are bounded by the header
/// timeout and the connection cap of the configuration.
pub async fn serve_on(
    listener: TcpListener,
    state: AppState,
    shutdown: impl Future<Output = ()> + Send + 'static,
) -> Result<(), ServerError> {
    let config = state.config().clone();
    connections::serve_connections(listener, router(state), &config, shutdown).await;
    Ok(())
}

/// Opens the store, binds `config.addr` and serves until SIGINT/SIGTERM.
pub async fn serve(config: ServerConfig) -> Result<(), ServerError> {
    let listener = bind(config.addr).await?;
    let state = AppState::new(config)?;
    tracing::info!(addr = %listener.local_addr()?, "nrgdb serving");
    serve_on(listener, state, shutdown_signal()).await
}
