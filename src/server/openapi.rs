//! The OpenAPI 3.1 document, built with utoipa from the same route table
//! as the router, so the two cannot drift. The table is passed in
//! ([`super::openapi_document`] passes [`super::routes::endpoints`]): this
//! file knows the table's types (`endpoint.rs`), not the handlers, and the
//! `/openapi.json` handler gets the document from the router, so routes and
//! OpenAPI do not import each other.

use serde_json::Value;
use utoipa::openapi::path::{HttpMethod, OperationBuilder, ParameterBuilder, ParameterIn};
use utoipa::openapi::schema::{ObjectBuilder, Type};
use utoipa::openapi::security::{Http, HttpAuthScheme, SecurityRequirement, SecurityScheme};
use utoipa::openapi::{
    ComponentsBuilder, InfoBuilder, OpenApiBuilder, PathItem, Paths, Required, ResponseBuilder,
};

use super::endpoint::{Endpoint, ParamDoc, path_param_doc, path_params};

fn schema(kind: &str) -> ObjectBuilder {
    let t = match kind {
        "integer" => Type::Integer,
        "number" => Type::Number,
        "boolean" => Type::Boolean,
        _ => Type::String,
    };
    ObjectBuilder::new().schema_type(t)
}

fn query_param(p: &ParamDoc) -> utoipa::openapi::path::Parameter {
    ParameterBuilder::new()
        .name(p.name)
        .parameter_in(ParameterIn::Query)
        .required(if p.required {
            Required::True
        } else {
            Required::False
        })
        .description(Some(p.doc))
        .schema(Some(schema(p.kind)))
        .build()
}

fn operation(e: &Endpoint) -> utoipa::openapi::path::Operation {
    let mut op = OperationBuilder::new()
        .summary(Some(e.summary))
        .operation_id(Some(format!(
            "{}{}",
            e.method.as_str().to_lowercase(),
            e.path.replace(['/', '{', '}', '.'], "_")
        )));
    for name in path_params(e.path) {
        op = op.parameter(
            ParameterBuilder::new()
                .name(name)
                .parameter_in(ParameterIn::Path)
                .required(Required::True)
                .description(Some(path_param_doc(name)))
                .schema(Some(schema(if name == "id" {
                    "integer"
                } else {
                    "string"
                }))),
        );
    }
    for p in e.params {
        op = op.parameter(query_param(p));
    }
    op = op
        .response("200", ResponseBuilder::new().description("success"))
        .response(
            "400",
            ResponseBuilder::new().description("bad parameter: {code, message, parameter}"),
        )
        .response(
            "404",
            ResponseBuilder::new().description("unknown map, revision or space"),
        );
    if e.method == axum::http::Method::POST && e.path != "/query" {
        op = op
            .response(
                "201",
                ResponseBuilder::new().description("revision created"),
            )
            .response(
                "401",
                ResponseBuilder::new().description("missing or wrong bearer token"),
            )
            .response(
                "403",
                ResponseBuilder::new().description("server is read-only (no token configured)"),
            )
            .response(
                "413",
                ResponseBuilder::new().description("upload too large"),
            )
            .security(SecurityRequirement::new("bearer", Vec::<String>::new()));
    }
    op.build()
}

/// The OpenAPI document of `endpoints`, as JSON.
pub fn document(endpoints: &[Endpoint]) -> Value {
    let mut paths = Paths::new();
    for e in endpoints {
        let method = if e.method == axum::http::Method::POST {
            HttpMethod::Post
        } else {
            HttpMethod::Get
        };
        let item = PathItem::new(method, operation(e));
        match paths.paths.get_mut(e.path) {
            Some(existing) => existing.merge_operations(item),
            None => {
                paths.paths.insert(e.path.to_string(), item);
            }
        }
    }
    let doc = OpenApiBuilder::new()
        .info(
            InfoBuilder::new()
                .title("nrgdb navigation API")
                .version(env!("CARGO_PKG_VERSION"))
                .description(Some(
                    "Maps, revisions, spaces and routes of indoor models. Coordinates and \
                     distances are metres in the map frame; errors are {code, message, parameter}.",
                )),
        )
        .paths(paths)
        .components(Some(
            ComponentsBuilder::new()
                .security_scheme(
                    "bearer",
                    SecurityScheme::Http(Http::new(HttpAuthScheme::Bearer)),
                )
                .build(),
        ))
        .build();
    serde_json::to_value(&doc).unwrap_or(Value::Null)
}

#[cfg(test)]
mod tests {
    use super::*;

    use axum::http::Method;
    use axum::routing::{get, post};

    use crate::server::endpoint::{REV, ep, q};

    #[test]
    fn every_endpoint_documented() {
        const UP: [ParamDoc; 1] = [q("message", "string", false, "commit message")];
        let table = [
            ep(
                Method::GET,
                "/maps/{map}/spaces/{id}",
                "a space",
                &[REV],
                get(|| async {}),
            ),
            ep(
                Method::GET,
                "/maps/{map}/revisions",
                "history",
                &[],
                get(|| async {}),
            ),
            ep(
                Method::POST,
                "/maps/{map}/revisions",
                "upload",
                &UP,
                post(|| async {}),
            ),
        ];
        let doc = document(&table);
        let paths = doc["paths"].as_object().unwrap();
        for e in &table {
            let m = e.method.as_str().to_lowercase();
            assert!(paths[e.path].get(&m).is_some(), "{e:?} missing");
        }
        let space = &paths["/maps/{map}/spaces/{id}"]["get"]["parameters"];
        assert_eq!(space.as_array().unwrap().len(), 3, "map, id and rev");
        assert!(paths["/maps/{map}/revisions"]["post"]["security"].is_array());
    }
}
