//! Errors of the server: [`ServerError`] stops it from starting,
//! [`ApiError`] answers one request as JSON with an HTTP status.

use std::net::SocketAddr;

use axum::Json;
use axum::http::{HeaderValue, StatusCode, header};
use axum::response::{IntoResponse, Response};
use serde_json::json;

use crate::diff::DiffError;
use crate::query::{QueryError, SourceError};
use crate::route::RouteError;
use crate::store::StoreError;

/// Why the server could not start or stopped with an error.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ServerError {
    /// The database could not be opened.
    #[error("cannot open the database: {0}")]
    Store(#[from] StoreError),
    /// The address could not be bound.
    #[error("cannot listen on {addr}: {source} (is another server running there? try --addr)")]
    Bind {
        /// The address asked for.
        addr: SocketAddr,
        /// What the OS said.
        source: std::io::Error,
    },
    /// Serving failed.
    #[error("server failed: {0}")]
    Io(#[from] std::io::Error),
}

/// One request's failure; becomes `{"code", "message", "parameter"?}` with
/// the matching status. Server faults (5xx) are logged and answered without
/// their details.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ApiError {
    /// A parameter is missing, unknown or malformed (400).
    #[error("parameter '{name}': {message}")]
    BadParameter {
        /// The parameter.
        name: String,
        /// What is wrong and what would work.
        message: String,
    },
    /// A map, revision or space that does not exist (404).
    #[error("{message}")]
    NotFound {
        /// The parameter that named it.
        name: String,
        /// What was not found.
        message: String,
    },
    /// No route matches the method and path (404).
    #[error("no endpoint {method} {path} (GET /openapi.json lists them)")]
    NoEndpoint {
        /// The method.
        method: String,
        /// The path.
        path: String,
    },
    /// The path exists but not with this method (405).
    #[error("method {0} is not allowed here (GET /openapi.json lists the endpoints)")]
    MethodNotAllowed(String),
    /// A write without (or with a wrong) bearer token (401).
    #[error("this write needs 'Authorization: Bearer <token>' (the token given to nrgdb serve)")]
    Unauthorized,
    /// A write on a server started without a token (403).
    #[error("the server is read-only: start it with --token or NRGDB_TOKEN to accept writes")]
    ReadOnly,
    /// The body is larger than allowed (413).
    #[error("request body exceeds the limit of {limit} bytes (raise --max-upload-mb)")]
    TooLarge {
        /// The limit in bytes.
        limit: usize,
    },
    /// An upload that cannot be read as a model or a map; nothing was stored (400).
    #[error("upload refused, nothing stored: {0}")]
    BadUpload(String),
    /// A query that does not parse (400), with its position.
    #[error("query: {0}")]
    BadQuery(String),
    /// The request ran out of time (503).
    #[error("request exceeded its time bound of {0} ms (narrow the request or raise --timeout-ms)")]
    Timeout(u128),
    /// The request body did not arrive in time (408).
    #[error(
        "the request body did not arrive within {0} ms (a slow connection? raise --body-timeout-ms)"
    )]
    BodyTimeout(u128),
    /// The database is locked by another writer (503).
    #[error("database is busy (another writer holds it); retry")]
    Busy,
    /// Anything else (500); the details go to the log only.
    #[error("internal error: {0}")]
    Internal(String),
}

impl ApiError {
    /// A 400 naming `name`.
    pub fn bad(name: &str, message: impl Into<String>) -> ApiError {
        ApiError::BadParameter {
            name: name.to_string(),
            message: message.into(),
        }
    }

    /// A 404 naming `name`.
    pub fn not_found(name: &str, message: impl Into<String>) -> ApiError {
        ApiError::NotFound {
            name: name.to_string(),
            message: message.into(),
        }
    }

    /// The HTTP status.
    pub fn status(&self) -> StatusCode {
        match self {
            ApiError::BadParameter { .. } | ApiError::BadUpload(_) | ApiError::BadQuery(_) => {
                StatusCode::BAD_REQUEST
            }
            ApiError::NotFound { .. } | ApiError::NoEndpoint { .. } => StatusCode::NOT_FOUND,
            ApiError::MethodNotAllowed(_) => StatusCode::METHOD_NOT_ALLOWED,
            ApiError::Unauthorized => StatusCode::UNAUTHORIZED,
            ApiError::ReadOnly => StatusCode::FORBIDDEN,
            ApiError::TooLarge { .. } => StatusCode::PAYLOAD_TOO_LARGE,
            ApiError::BodyTimeout(_) => StatusCode::REQUEST_TIMEOUT,
            ApiError::Timeout(_) | ApiError::Busy => StatusCode::SERVICE_UNAVAILABLE,
            ApiError::Internal(_) => StatusCode::INTERNAL_SERVER_ERROR,
        }
    }

    /// A short machine-readable code ("BadParameter", "NotFound", …).
    pub fn code(&self) -> &'static str {
        match self {
            ApiError::BadParameter { .. } => "BadParameter",
            ApiError::NotFound { .. } => "NotFound",
            ApiError::NoEndpoint { .. } => "NoEndpoint",
            ApiError::MethodNotAllowed(_) => "MethodNotAllowed",
            ApiError::Unauthorized => "Unauthorized",
            ApiError::ReadOnly => "ReadOnly",
            ApiError::TooLarge { .. } => "TooLarge",
            ApiError::BadUpload(_) => "BadUpload",
            ApiError::BadQuery(_) => "BadQuery",
            ApiError::Timeout(_) => "Timeout",
            ApiError::BodyTimeout(_) => "BodyTimeout",
            ApiError::Busy => "Busy",
            ApiError::Internal(_) => "Internal",
        }
    }

    /// The parameter at fault, if any.
    pub fn parameter(&self) -> Option<&str> {
        match self {
            ApiError::BadParameter { name, .. } | ApiError::NotFound { name, .. } => Some(name),
            ApiError::BadQuery(_) => Some("query"),
            _ => None,
        }
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        let status = self.status();
        let message = if let ApiError::Internal(detail) = &self {
            tracing::error!(%detail, "internal error");
            "internal error (see the server log)".to_string()
        } else {
            self.to_string()
        };
        let mut body = json!({"code": self.code(), "message": message});
        if let Some(p) = self.parameter() {
            body["parameter"] = p.into();
        }
        let mut response = (status, Json(body)).into_response();
        if matches!(self, ApiError::Unauthorized) {
            response.headers_mut().insert(
                header::WWW_AUTHENTICATE,
                HeaderValue::from_static("Bearer realm=\"nrgdb\""),
            );
        }
        response
    }
}

impl From<StoreError> for ApiError {
    fn from(e: StoreError) -> ApiError {
        match e {
            StoreError::NoSuchMap { .. } => ApiError::not_found("map", e.to_string()),
            StoreError::NoSuchRevision { .. } => ApiError::not_found("rev", e.to_string()),
            StoreError::NoSuchSpace { .. } => ApiError::not_found("id", e.to_string()),
            StoreError::BadMapName { .. } => ApiError::bad("map", e.to_string()),
            StoreError::TooLong { field, .. } => ApiError::bad(field, e.to_string()),
            StoreError::Model(m) => ApiError::BadUpload(m.to_string()),
            StoreError::TooManyOverlaps { .. } => ApiError::BadUpload(e.to_string()),
            // Another writer kept adding revisions while this import was
            // matched: retrying later is the answer, as for a held lock.
            StoreError::NoSuchCorrection { .. } => ApiError::not_found("id", e.to_string()),
            StoreError::CannotUndo { .. } => ApiError::bad("id", e.to_string()),
            StoreError::Busy | StoreError::MapChanged { .. } | StoreError::Stale { .. } => {
                ApiError::Busy
            }
            other => ApiError::Internal(other.to_string()),
        }
    }
}

impl From<RouteError> for ApiError {
    fn from(e: RouteError) -> ApiError {
        match e {
            RouteError::Timeout(ms) => ApiError::Timeout(ms),
            RouteError::NotNavigable(id) => ApiError::not_found(
                "from",
                format!("space {id} does not exist in this revision"),
            ),
            RouteError::AvoidedEndpoint(_) => ApiError::bad("avoid", e.to_string()),
            RouteError::AlternativesWithVia => ApiError::bad("alternatives", e.to_string()),
            RouteError::Outside { .. } => ApiError::not_found("from", e.to_string()),
            RouteError::BadProfile { name, .. } => ApiError::bad(name, e.to_string()),
            RouteError::PointNeedsLevel { .. } => ApiError::bad("from", e.to_string()),
        }
    }
}

impl From<QueryError> for ApiError {
    fn from(e: QueryError) -> ApiError {
        match e {
            QueryError::Syntax { .. } => ApiError::BadQuery(e.to_string()),
            QueryError::Timeout(ms) => ApiError::Timeout(ms),
            QueryError::Route(r) => r.into(),
            QueryError::UnknownId(_) | QueryError::UnknownName { .. } => {
                ApiError::not_found("id", e.to_string())
            }
            // A storage fault during a query is the server's, not the
            // client's: 500/503 with the details logged.
            QueryError::Source(SourceError::Backend(e)) => match e.downcast::<StoreError>() {
                Ok(store) => ApiError::from(*store),
                Err(other) => ApiError::Internal(other.to_string()),
            },
            other => ApiError::bad("query", other.to_string()),
        }
    }
}

/// A failed comparison as an API error: no reliable alignment, or models
/// too piled to match, is the caller's to fix (a 400 naming `parameter`,
/// with `hint`), a busy store or running past the time bound
/// (`timeout_ms`) a 503, anything else ours. Shared by `GET /diff` and the viewer's
/// `?diff=` (here, so that neither imports the other).
pub fn comparing_error(
    e: QueryError,
    parameter: &'static str,
    hint: &str,
    timeout_ms: u128,
) -> ApiError {
    match e {
        QueryError::Diff(DiffError::TimedOut) => ApiError::Timeout(timeout_ms),
        QueryError::Diff(
            e @ (DiffError::Unreliable { .. }
            | DiffError::TooFewWalls { .. }
            | DiffError::TooManyOverlaps { .. }),
        ) => ApiError::bad(parameter, format!("{e} ({hint})")),
        QueryError::Source(SourceError::Backend(e)) => match e.downcast::<StoreError>() {
            Ok(e) => (*e).into(),
            Err(e) => ApiError::Internal(format!("loading a revision: {e}")),
        },
        other => ApiError::Internal(other.to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statuses_and_parameters() {
        let e = ApiError::bad("depth", "must be 1..=100");
        assert_eq!(e.status(), StatusCode::BAD_REQUEST);
        assert_eq!(e.parameter(), Some("depth"));
        assert_eq!(ApiError::Unauthorized.status(), StatusCode::UNAUTHORIZED);
        assert_eq!(ApiError::ReadOnly.status(), StatusCode::FORBIDDEN);
        let e: ApiError = StoreError::NoSuchMap {
            name: "x".into(),
            known: "(none)".into(),
            suggestion: None,
        }
        .into();
        assert_eq!(
            (e.status(), e.parameter()),
            (StatusCode::NOT_FOUND, Some("map"))
        );
    }
}
