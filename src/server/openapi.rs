//! The OpenAPI 3.1 document, built with utoipa from the same route table
//! as the router ([`super::routes::endpoints`]), so the two cannot drift.

use std::sync::OnceLock;

use serde_json::Value;
use utoipa::openapi::path::{HttpMethod, OperationBuilder, ParameterBuilder, ParameterIn};
use utoipa::openapi::schema::{ObjectBuilder, Type};
use utoipa::openapi::security::{Http, HttpAuthScheme, SecurityRequirement, SecurityScheme};
use utoipa::openapi::{
    ComponentsBuilder, InfoBuilder, OpenApiBuilder, PathItem, Paths, Required, ResponseBuilder,
};

use super::routes::{Endpoint, ParamDoc, endpoints, path_param_doc, path_params};

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

fn build() -> Value {
    let mut paths = Paths::new();
    for e in endpoints() {
        let method = if e.method == axum::http::Method::POST {
            HttpMethod::Post
        } else {
            HttpMethod::Get
        };
        let item = PathItem::new(method, operation(&e));
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

/// The document as JSON (built once).
pub fn document() -> Value {
    static DOC: OnceLock<Value> = OnceLock::new();
    DOC.get_or_init(build).clone()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_endpoint_documented() {
        let doc = document();
        let paths = doc["paths"].as_object().unwrap();
        for e in endpoints() {
            let m = e.method.as_str().to_lowercase();
            assert!(paths[e.path].get(&m).is_some(), "{e:?} missing");
        }
        assert!(paths["/maps/{map}/revisions"]["post"]["security"].is_array());
    }
}
