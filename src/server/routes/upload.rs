//! `POST /maps/{map}/revisions`: a new revision from an upload. Accepted:
//! multipart with a ROS map YAML and its image (extracted with the default
//! parameters) or with one model file (IndoorGML `.gml`/`.xml`, model
//! `.json`, `.geojson`), or such a model file as the raw body
//! (`application/xml`, `application/json`, `application/geo+json`).
//!
//! The handler only unpacks the request: the parts go to
//! [`crate::ingest::read`] (the same code `nrgdb import` runs on files),
//! which tells each part's format ([`crate::format::detect`]: file name,
//! Content-Type, bytes, field name), reads the map from the bytes in
//! memory (nothing is written to disk) and checks everything before the
//! one import transaction of [`crate::ingest::ingest`], so a malformed
//! upload stores nothing. IndoorGML Transitions with a missing or 0 weight
//! are fixed on reading and counted in the answer's `weights_fixed`.

use axum::Json;
use axum::body::Body;
use axum::extract::{Path, State};
use axum::http::{HeaderMap, HeaderValue, StatusCode, Uri, header};
use axum::response::{IntoResponse, Response};
use serde_json::json;

use crate::format::{Declared, FileKind};
use crate::ingest::{IngestError, IngestOptions, InputFile, read};
use crate::server::auth::require_write;
use crate::server::body::read_limited;
use crate::server::endpoint::{ParamDoc, q};
use crate::server::error::ApiError;
use crate::server::multipart::{self, Part};
use crate::server::params::Params;
use crate::server::state::AppState;

/// Query parameters of the upload (multipart fields of the same names win).
pub const PARAMS: [ParamDoc; 2] = [
    q("message", "string", false, "commit message of the revision"),
    q(
        "author",
        "string",
        false,
        "author of the revision (default 'nrgdb serve')",
    ),
];

fn utf8(bytes: &[u8], what: &str) -> Result<String, ApiError> {
    String::from_utf8(bytes.to_vec())
        .map_err(|_| ApiError::BadUpload(format!("{what} is not UTF-8 text")))
}

fn bad(e: IngestError) -> ApiError {
    ApiError::BadUpload(e.to_string())
}

/// The file parts of a multipart upload; the `message` and `author`
/// fields set those of the revision.
fn file_parts<'a>(
    parts: &'a [Part<'a>],
    message: &mut String,
    author: &mut String,
) -> Result<Vec<InputFile<'a>>, ApiError> {
    let mut files = Vec::with_capacity(parts.len());
    for p in parts {
        match p.name.as_deref() {
            Some("message") if p.filename.is_none() => *message = utf8(p.data, "message")?,
            Some("author") if p.filename.is_none() => *author = utf8(p.data, "author")?,
            _ => files.push(InputFile {
                declared: Declared {
                    name: p.filename.as_deref(),
                    media_type: p.content_type.as_deref(),
                    field: p.name.as_deref(),
                },
                bytes: p.data,
            }),
        }
    }
    Ok(files)
}

/// A raw body's one file: a model, its format declared by Content-Type.
fn body_file<'a>(content_type: &'a str, bytes: &'a [u8]) -> Result<InputFile<'a>, ApiError> {
    if !matches!(
        FileKind::by_media_type(content_type),
        Some(FileKind::Model(_))
    ) {
        return Err(ApiError::BadUpload(format!(
            "Content-Type '{content_type}' is not accepted: use multipart/form-data, application/xml (IndoorGML), application/json or application/geo+json"
        )));
    }
    Ok(InputFile {
        declared: Declared {
            media_type: Some(content_type),
            ..Declared::default()
        },
        bytes,
    })
}

/// `POST /maps/{map}/revisions` (bearer token).
pub async fn upload(
    State(state): State<AppState>,
    Path(map): Path<String>,
    uri: Uri,
    headers: HeaderMap,
    body: Body,
) -> Result<Response, ApiError> {
    require_write(state.config(), &headers)?;
    let p = Params::parse(&uri, &["message", "author"])?;
    let config = state.config();
    let bytes = read_limited(&headers, body, config.max_upload_bytes, config.body_timeout).await?;
    let content_type = headers
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .unwrap_or("")
        .to_string();
    let mut message = p.get("message").unwrap_or("").to_string();
    let mut author = p.get("author").unwrap_or("nrgdb serve").to_string();
    let (done, weights_fixed, repairs) = state
        .blocking(move |ctx| {
            let parts;
            let files = match multipart::boundary(&content_type) {
                Some(b) => {
                    parts = multipart::parse(&bytes, &b).map_err(ApiError::BadUpload)?;
                    file_parts(&parts, &mut message, &mut author)?
                }
                None => vec![body_file(&content_type, &bytes)?],
            };
            let options = IngestOptions {
                frame: crate::ingest::map_frame(ctx.store(), &map)?,
                ..IngestOptions::default()
            };
            let prepared = read(&files, &options).map_err(bad)?;
            let meta = prepared.meta(message, author);
            let done = crate::ingest::ingest_prepared(ctx.store(), &map, &prepared, meta)?;
            let repairs: Vec<String> = prepared.repairs.iter().map(|r| r.to_string()).collect();
            Ok((done, prepared.weights_fixed.total(), repairs))
        })
        .await?;
    let corrections = json!({
        "reapplied": done.corrections_applied.len(),
        "failed": done.corrections_failed.iter().map(|(id, statement, reason)| {
            json!({"id": id, "statement": statement, "reason": reason})
        }).collect::<Vec<_>>(),
    });
    let georef_set = done.georef_set.clone();
    let done = done.imported;
    let info = &done.revision;
    let status = if done.unchanged {
        StatusCode::OK
    } else {
        StatusCode::CREATED
    };
    // Stable ids: a space continuing one of the parent keeps its id, new
    // spaces get fresh ones; clients map their ids with this.
    let ids: serde_json::Map<String, serde_json::Value> = done
        .ids
        .iter()
        .map(|(from, to)| (from.to_string(), json!(to)))
        .collect();
    tracing::info!(map = %info.map, revision = info.seq, spaces = info.spaces, "revision uploaded");
    let location = format!("/maps/{}/revisions/{}/geojson", info.map, info.seq);
    let mut response = (
        status,
        Json(json!({
            "revision": info,
            "unchanged": done.unchanged,
            "ids": ids,
            "weights_fixed": weights_fixed,
            "repairs": repairs,
            "corrections": corrections,
            "georef_set": georef_set,
        })),
    )
        .into_response();
    if let Ok(v) = HeaderValue::from_str(&location) {
        response.headers_mut().insert(header::LOCATION, v);
    }
    Ok(response)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parts_and_bodies() {
        let body = b"--X\r\nContent-Disposition: form-data; name=\"message\"\r\n\r\nhi\r\n--X\r\nContent-Disposition: form-data; name=\"model\"; filename=\"m.json\"\r\nContent-Type: application/json\r\n\r\n{}\r\n--X--\r\n";
        let parts = multipart::parse(body, "X").unwrap();
        let (mut message, mut author) = (String::new(), "a".to_string());
        let files = file_parts(&parts, &mut message, &mut author).unwrap();
        assert_eq!((message.as_str(), author.as_str()), ("hi", "a"));
        assert_eq!(files.len(), 1);
        assert_eq!(files[0].declared.name, Some("m.json"));
        assert_eq!(files[0].declared.field, Some("model"));
        assert_eq!(files[0].bytes, b"{}");
        assert!(body_file("application/geo+json", b"{}").is_ok());
        assert!(body_file("image/png", b"").is_err());
        assert!(body_file("text/plain", b"").is_err());
    }
}
