//! The types of the route table: an [`Endpoint`] (method, path, summary,
//! documented query parameters, handler) and a [`ParamDoc`]. The handlers
//! (`routes/*.rs`, the viewer) declare their parameters with [`q`]; the
//! table (`routes/mod.rs`) and the OpenAPI builder (`openapi.rs`) read
//! them. A file of its own so that none of those imports another.

use axum::http::Method;
use axum::routing::MethodRouter;

use super::state::AppState;

/// Where a parameter goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ParamIn {
    /// In the path (`{map}`).
    Path,
    /// In the query string.
    Query,
}

/// A documented parameter.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ParamDoc {
    /// Its name.
    pub name: &'static str,
    /// JSON schema type: "string", "integer", "number" or "boolean".
    pub kind: &'static str,
    /// Whether it must be given.
    pub required: bool,
    /// What it means.
    pub doc: &'static str,
}

/// A query-string parameter.
pub const fn q(
    name: &'static str,
    kind: &'static str,
    required: bool,
    doc: &'static str,
) -> ParamDoc {
    ParamDoc {
        name,
        kind,
        required,
        doc,
    }
}

/// The `rev` query parameter most read endpoints take.
pub const REV: ParamDoc = q(
    "rev",
    "string",
    false,
    "revision number, or 'latest' (default)",
);

/// One endpoint of the API.
pub struct Endpoint {
    /// The HTTP method.
    pub method: Method,
    /// The axum path pattern (`/maps/{map}`), also the OpenAPI path.
    pub path: &'static str,
    /// One line for the OpenAPI document.
    pub summary: &'static str,
    /// Query-string parameters (path parameters come from `path`).
    pub params: &'static [ParamDoc],
    /// The handler.
    pub handler: MethodRouter<AppState>,
    /// Whether the request timeout applies (uploads are bounded by size).
    pub timed: bool,
}

impl std::fmt::Debug for Endpoint {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} {}", self.method, self.path)
    }
}

/// An endpoint under the request timeout.
pub fn ep(
    method: Method,
    path: &'static str,
    summary: &'static str,
    params: &'static [ParamDoc],
    handler: MethodRouter<AppState>,
) -> Endpoint {
    Endpoint {
        method,
        path,
        summary,
        params,
        handler,
        timed: true,
    }
}

/// The path parameters of a pattern, in order (`/maps/{map}` → `map`).
pub fn path_params(path: &str) -> Vec<&str> {
    path.split('/')
        .filter_map(|seg| seg.strip_prefix('{').and_then(|s| s.strip_suffix('}')))
        .collect()
}

/// What a path parameter means.
pub fn path_param_doc(name: &str) -> &'static str {
    match name {
        "map" => "map name",
        "id" => "space id (a number)",
        "rev" => "revision number, or 'latest'",
        _ => "path parameter",
    }
}
