//! The route table: every endpoint once, with its method, path, summary,
//! query parameters and handler. [`super::router`] and the OpenAPI
//! document are both built from [`endpoints`], so adding a route is one
//! line here (plus its handler).

pub(crate) mod diff;
mod maps;
mod query;
mod route;
mod route_json;
mod spaces;
mod system;
mod upload;

use axum::http::Method;
use axum::routing::{MethodRouter, get, post};

use super::state::AppState;

pub use system::{fallback, method_not_allowed};

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

const REV: ParamDoc = q(
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

fn ep(
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

/// Every endpoint, in the order of the OpenAPI document. One line each;
/// `#[rustfmt::skip]` keeps it a table.
#[rustfmt::skip]
pub fn endpoints() -> Vec<Endpoint> {
    use Method as M;
    vec![
        ep(M::GET, "/health", "Liveness and database check", &[], get(system::health)),
        ep(M::GET, "/metrics", "Prometheus metrics (text format 0.0.4)", &[], get(system::metrics)),
        ep(M::GET, "/openapi.json", "This API as OpenAPI 3.1", &[], get(system::openapi)),
        ep(M::GET, "/maps", "Every map with its latest revision", &[], get(maps::list_maps)),
        ep(M::GET, "/maps/{map}", "A map and its latest revision", &[], get(maps::map)),
        ep(M::GET, "/maps/{map}/revisions", "The revisions of a map, oldest first", &[], get(maps::list_revisions)),
        Endpoint { timed: false, ..ep(M::POST, "/maps/{map}/revisions", "Upload a revision: multipart (map YAML + image, extracted; or an IndoorGML/JSON/GeoJSON file) or a raw IndoorGML/JSON body; needs the bearer token", &upload::PARAMS, post(upload::upload)) },
        ep(M::GET, "/maps/{map}/revisions/{rev}", "One revision's record (message, author, counts of changes)", &[], get(maps::revision)),
        ep(M::GET, "/maps/{map}/revisions/{rev}/indoorgml", "A revision as IndoorGML 1.0.3", &[], get(maps::indoorgml)),
        ep(M::GET, "/maps/{map}/revisions/{rev}/geojson", "A revision as a GeoJSON FeatureCollection", &[], get(maps::geojson)),
        ep(M::GET, "/maps/{map}/spaces", "Spaces of a revision, filtered by kind and name", &spaces::LIST_PARAMS, get(spaces::list_spaces)),
        ep(M::GET, "/maps/{map}/spaces/{id}", "One space with its geometry and connections", &[REV], get(spaces::space)),
        ep(M::GET, "/maps/{map}/neighbours/{id}", "Spaces within a number of navigable hops", &spaces::NEIGHBOUR_PARAMS, get(spaces::neighbours)),
        ep(M::GET, "/maps/{map}/locate", "The space containing a point (metres, map frame)", &spaces::LOCATE_PARAMS, get(spaces::locate)),
        ep(M::GET, "/maps/{map}/route", "Shortest route (or alternatives) between spaces, OSRM-shaped", &route::PARAMS, get(route::route)),
        ep(M::GET, "/maps/{map}/diff", "What changed between two revisions (spaces, connections, door widths), aligned when the frames differ", &diff::PARAMS, get(diff::diff)),
        ep(M::GET, "/", "The web viewer (one HTML page)", &[], get(crate::server::viewer::page)),
        ep(M::GET, "/maps/{map}/revisions/{rev}/svg", "A revision drawn as SVG, optionally with a route or a diff", &crate::server::viewer::SVG_PARAMS, get(crate::server::viewer::svg)),
        ep(M::POST, "/query", "Run query-language statements; JSON results", &query::PARAMS, post(query::query)),
    ]
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_is_unique_and_params_named() {
        let eps = endpoints();
        for (i, e) in eps.iter().enumerate() {
            assert!(e.path.starts_with('/'));
            assert!(
                !eps[..i]
                    .iter()
                    .any(|o| o.path == e.path && o.method == e.method),
                "{e:?} twice"
            );
        }
        assert_eq!(path_params("/maps/{map}/spaces/{id}"), vec!["map", "id"]);
    }
}
