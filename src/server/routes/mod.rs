//! The route table: every endpoint once, with its method, path, summary,
//! query parameters and handler. [`super::router`] and the OpenAPI
//! document are both built from [`endpoints`], so adding a route is one
//! line here (plus its handler). The types of the table ([`Endpoint`],
//! [`ParamDoc`]) live in `server/endpoint.rs`, which the handlers and the
//! OpenAPI builder import; nothing here is imported back by them.

mod corrections;
mod diff;
mod maps;
mod query;
mod route;
mod route_json;
mod spaces;
mod system;
mod upload;

use axum::http::Method;
use axum::routing::{get, post};

pub use super::endpoint::{Endpoint, ParamDoc, ParamIn, path_param_doc, path_params, q};
use super::endpoint::{REV, ep};

pub use system::{OpenApiDocument, fallback, method_not_allowed};

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
        ep(M::GET, "/maps/{map}", "A map, its latest revision and its georeference (null when it has none)", &[], get(maps::map)),
        ep(M::GET, "/maps/{map}/revisions", "The revisions of a map, oldest first", &[], get(maps::list_revisions)),
        Endpoint { timed: false, ..ep(M::POST, "/maps/{map}/revisions", "Upload a revision: multipart (map YAML + image, extracted; or an IndoorGML/JSON/GeoJSON file) or a raw IndoorGML/JSON body; needs the bearer token", &upload::PARAMS, post(upload::upload)) },
        ep(M::GET, "/maps/{map}/revisions/{rev}", "One revision's record (message, author, counts of changes)", &[], get(maps::revision)),
        ep(M::GET, "/maps/{map}/revisions/{rev}/indoorgml", "A revision as IndoorGML 1.0.3 (in its UTM zone, named as srsName, when the map is georeferenced)", &maps::INDOORGML_PARAMS, get(maps::indoorgml)),
        ep(M::GET, "/maps/{map}/revisions/{rev}/geojson", "A revision as a GeoJSON FeatureCollection (WGS84 when the map is georeferenced)", &maps::GEOJSON_PARAMS, get(maps::geojson)),
        ep(M::GET, "/maps/{map}/revisions/{rev}/nav2", "A revision as a Nav2 Route Server graph (GeoJSON, directed edges along the walked paths)", &[], get(maps::nav2)),
        ep(M::GET, "/maps/{map}/levels", "The levels of a building (name, elevation, spaces), lowest first, and its extent", &[REV], get(maps::levels)),
        ep(M::GET, "/maps/{map}/spaces", "Spaces of a revision, filtered by kind, level and name", &spaces::LIST_PARAMS, get(spaces::list_spaces)),
        ep(M::GET, "/maps/{map}/spaces/{id}", "One space with its geometry and connections", &[REV], get(spaces::space)),
        ep(M::GET, "/maps/{map}/neighbours/{id}", "Spaces within a number of navigable hops", &spaces::NEIGHBOUR_PARAMS, get(spaces::neighbours)),
        ep(M::GET, "/maps/{map}/locate", "The space containing a point (metres, map frame), on a level or on each", &spaces::LOCATE_PARAMS, get(spaces::locate)),
        ep(M::GET, "/maps/{map}/route", "Shortest route (or alternatives) between spaces, OSRM-shaped", &route::PARAMS, get(route::route)),
        ep(M::GET, "/maps/{map}/diff", "What changed between two revisions (spaces, connections, door widths), aligned when the frames differ", &diff::PARAMS, get(diff::diff)),
        ep(M::GET, "/", "The web viewer (one HTML page)", &[], get(crate::server::viewer::page)),
        ep(M::GET, "/maps/{map}/revisions/{rev}/svg", "A revision drawn as SVG, optionally with a route or a diff", &crate::server::viewer::SVG_PARAMS, get(crate::server::viewer::svg)),
        ep(M::GET, "/maps/{map}/corrections", "The corrections kept with a map (MERGE, SPLIT, ADD DOOR, …) and their state at the last import", &[], get(corrections::list)),
        ep(M::POST, "/maps/{map}/corrections/{id}/undo", "Undo the map's last edit: a revision restoring the model before it; needs the bearer token", &[], post(corrections::undo)),
        ep(M::POST, "/query", "Run query-language statements; JSON results", &query::PARAMS, post(query::query)),
    ]
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
