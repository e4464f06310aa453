//! `POST /maps/{map}/revisions`: a new revision from an upload. Accepted:
//! multipart with a ROS map YAML and its image (extracted with the default
//! parameters) or with one model file (IndoorGML `.gml`/`.xml`, model
//! `.json`, `.geojson`), or such a model file as the raw body
//! (`application/xml`, `application/json`, `application/geo+json`).
//! Everything is read and checked before the one import transaction, so a
//! malformed upload stores nothing. The model goes in through
//! [`crate::ingest::ingest`] (walked connection lengths); IndoorGML
//! Transitions with a missing or 0 weight are fixed on reading and counted
//! in the answer's `weights_fixed`.

use axum::Json;
use axum::body::Body;
use axum::extract::{Path, State};
use axum::http::{HeaderMap, HeaderValue, StatusCode, Uri, header};
use axum::response::{IntoResponse, Response};
use serde_json::json;

use crate::extract::{ExtractParams, extract};
use crate::grid::{LoadOptions, OccupancyGrid, load_map};
use crate::model::Nrg;
use crate::server::auth::require_write;
use crate::server::body::read_limited;
use crate::server::endpoint::{ParamDoc, q};
use crate::server::error::ApiError;
use crate::server::multipart::{self, Part};
use crate::server::params::Params;
use crate::server::state::AppState;
use crate::store::{ImportMeta, sha256_hex};

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

/// What an uploaded file is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    MapYaml,
    Image,
    IndoorGml,
    Json,
    GeoJson,
}

fn kind_of_name(name: &str) -> Option<Kind> {
    let ext = name.rsplit_once('.')?.1.to_ascii_lowercase();
    match ext.as_str() {
        "yaml" | "yml" => Some(Kind::MapYaml),
        "pgm" | "png" => Some(Kind::Image),
        "gml" | "xml" => Some(Kind::IndoorGml),
        "json" => Some(Kind::Json),
        "geojson" => Some(Kind::GeoJson),
        _ => None,
    }
}

fn kind_of_type(content_type: &str) -> Option<Kind> {
    let mime = content_type.split(';').next()?.trim().to_ascii_lowercase();
    match mime.as_str() {
        "application/xml" | "text/xml" | "application/gml+xml" => Some(Kind::IndoorGml),
        "application/json" => Some(Kind::Json),
        "application/geo+json" => Some(Kind::GeoJson),
        "application/yaml" | "application/x-yaml" | "text/yaml" => Some(Kind::MapYaml),
        "image/png" | "image/x-portable-graymap" => Some(Kind::Image),
        _ => None,
    }
}

/// A part's kind: by file name, then content type, then field name.
fn kind_of_part(p: &Part<'_>) -> Option<Kind> {
    let by_field = match p.name.as_deref() {
        Some("yaml") => Some(Kind::MapYaml),
        Some("image") => Some(Kind::Image),
        Some("indoorgml" | "gml") => Some(Kind::IndoorGml),
        Some("geojson") => Some(Kind::GeoJson),
        Some("model" | "json") => Some(Kind::Json),
        _ => None,
    };
    p.filename
        .as_deref()
        .and_then(kind_of_name)
        .or_else(|| p.content_type.as_deref().and_then(kind_of_type))
        .or(by_field)
}

fn utf8(bytes: &[u8], what: &str) -> Result<String, ApiError> {
    String::from_utf8(bytes.to_vec())
        .map_err(|_| ApiError::BadUpload(format!("{what} is not UTF-8 text")))
}

/// Reads a model file of `kind`, with how many IndoorGML Transition
/// weights were missing or 0 and fixed.
fn read_model(kind: Kind, bytes: &[u8], name: &str) -> Result<(Nrg, usize), ApiError> {
    let text = utf8(bytes, name)?;
    let bad = |e: String| ApiError::BadUpload(format!("{name}: {e}"));
    let nrg = match kind {
        Kind::IndoorGml => {
            return crate::indoorgml::read_str(&text)
                .and_then(|d| crate::format::from_document(&d))
                .map(|(nrg, fixes)| (nrg, fixes.total()))
                .map_err(|e| bad(e.to_string()));
        }
        Kind::GeoJson => crate::geojson::from_geojson(&text).map_err(|e| bad(e.to_string())),
        _ if text.contains("\"FeatureCollection\"") => {
            crate::geojson::from_geojson(&text).map_err(|e| bad(e.to_string()))
        }
        _ => Nrg::from_json(&text).map_err(|e| bad(e.to_string())),
    }?;
    Ok((nrg, 0))
}

/// Extracts a model from a map YAML and its image (written to a temporary
/// directory; the YAML's `image:` is pointed at the uploaded image).
fn extract_map(
    yaml: &[u8],
    image: &[u8],
    image_name: &str,
) -> Result<(Nrg, OccupancyGrid, serde_json::Value), ApiError> {
    let bad = |e: String| ApiError::BadUpload(e);
    let mut doc: serde_yaml_ng::Value =
        serde_yaml_ng::from_slice(yaml).map_err(|e| bad(format!("map YAML: {e}")))?;
    let ext = if image_name.to_ascii_lowercase().ends_with(".png") {
        "png"
    } else {
        "pgm"
    };
    let file = format!("image.{ext}");
    match &mut doc {
        serde_yaml_ng::Value::Mapping(m) => {
            m.insert("image".into(), file.as_str().into());
        }
        _ => {
            return Err(bad(
                "map YAML: expected a mapping with image, resolution, origin".into(),
            ));
        }
    }
    let dir = tempfile::tempdir().map_err(|e| ApiError::Internal(format!("temp dir: {e}")))?;
    let text = serde_yaml_ng::to_string(&doc).map_err(|e| bad(format!("map YAML: {e}")))?;
    let yaml_path = dir.path().join("map.yaml");
    std::fs::write(&yaml_path, text)
        .and_then(|()| std::fs::write(dir.path().join(&file), image))
        .map_err(|e| ApiError::Internal(format!("temp files: {e}")))?;
    let grid = load_map(&yaml_path, &LoadOptions::default()).map_err(|e| {
        // Paths in the message are our temporary files; name the upload.
        bad(format!(
            "map: {}",
            e.to_string()
                .replace(&dir.path().display().to_string(), "upload")
        ))
    })?;
    let params = ExtractParams::default();
    let extraction = extract(&grid, &params).map_err(|e| bad(format!("extraction: {e}")))?;
    let params = serde_json::to_value(&params).unwrap_or(serde_json::Value::Null);
    Ok((extraction.nrg, grid, params))
}

/// A model to import, the occupancy grid it was extracted from (kept with
/// the revision, see [`crate::store::Store::grid`]) and how many IndoorGML
/// Transition weights were fixed on reading.
type Upload = (Nrg, Option<OccupancyGrid>, usize);

fn from_multipart(body: &[u8], boundary: &str, meta: &mut ImportMeta) -> Result<Upload, ApiError> {
    let parts = multipart::parse(body, boundary).map_err(|e| ApiError::BadUpload(e.to_string()))?;
    let mut yaml = None;
    let mut image = None;
    let mut model = None;
    for p in &parts {
        match p.name.as_deref() {
            Some("message") if p.filename.is_none() => meta.message = utf8(p.data, "message")?,
            Some("author") if p.filename.is_none() => meta.author = utf8(p.data, "author")?,
            _ => match kind_of_part(p) {
                Some(Kind::MapYaml) => yaml = Some(p),
                Some(Kind::Image) => image = Some(p),
                Some(k) => model = Some((k, p)),
                None => {
                    return Err(ApiError::BadUpload(format!(
                        "part '{}' is neither a map YAML, a PGM/PNG image nor a model file (.gml, .xml, .json, .geojson)",
                        p.filename.as_deref().or(p.name.as_deref()).unwrap_or("?")
                    )));
                }
            },
        }
    }
    let name =
        |p: &Part<'_>, default: &str| p.filename.clone().unwrap_or_else(|| default.to_string());
    match (yaml, image, model) {
        (Some(y), Some(i), None) => {
            let image_name = name(i, "map.pgm");
            let (nrg, grid, params) = extract_map(y.data, i.data, &image_name)?;
            let mut bytes = y.data.to_vec();
            bytes.extend_from_slice(i.data);
            meta.source_name = Some(format!("{} + {image_name}", name(y, "map.yaml")));
            meta.source_sha256 = Some(sha256_hex(&bytes));
            meta.params = Some(params);
            Ok((nrg, Some(grid), 0))
        }
        (None, None, Some((k, p))) => {
            let file = name(p, "upload");
            let (nrg, fixed) = read_model(k, p.data, &file)?;
            *meta = std::mem::take(meta).with_source(file, p.data);
            Ok((nrg, None, fixed))
        }
        (Some(_), None, _) => Err(ApiError::BadUpload(
            "a map YAML needs its image (a PGM or PNG part)".into(),
        )),
        (None, Some(_), _) => Err(ApiError::BadUpload(
            "an image needs its map YAML (a .yaml part)".into(),
        )),
        (None, None, None) => Err(ApiError::BadUpload(
            "no file part (send a map YAML + image, or one model file)".into(),
        )),
        _ => Err(ApiError::BadUpload(
            "send either a map YAML + image or one model file, not both".into(),
        )),
    }
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
    let bytes = read_limited(&headers, body, state.config().max_upload_bytes).await?;
    let content_type = headers
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .unwrap_or("")
        .to_string();
    let mut meta = ImportMeta::new(
        p.get("message").unwrap_or(""),
        p.get("author").unwrap_or("nrgdb serve"),
    );
    let (done, weights_fixed) = state
        .blocking(move |ctx| {
            let (nrg, grid, fixed) = if let Some(b) = multipart::boundary(&content_type) {
                from_multipart(&bytes, &b, &mut meta)?
            } else {
                let kind = kind_of_type(&content_type).filter(|k| !matches!(k, Kind::MapYaml | Kind::Image));
                let Some(kind) = kind else {
                    return Err(ApiError::BadUpload(format!(
                        "Content-Type '{content_type}' is not accepted: use multipart/form-data, application/xml (IndoorGML), application/json or application/geo+json"
                    )));
                };
                let (nrg, fixed) = read_model(kind, &bytes, "body")?;
                meta = std::mem::take(&mut meta).with_source("upload", &bytes);
                (nrg, None, fixed)
            };
            let done = crate::ingest::ingest(ctx.store(), &map, &nrg, meta, grid.as_ref())?;
            Ok((done.imported, fixed))
        })
        .await?;
    let info = &done.revision;
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
        StatusCode::CREATED,
        Json(json!({ "revision": info, "ids": ids, "weights_fixed": weights_fixed })),
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
    fn kinds() {
        assert_eq!(kind_of_name("a.YAML"), Some(Kind::MapYaml));
        assert_eq!(kind_of_name("a.gml"), Some(Kind::IndoorGml));
        assert_eq!(kind_of_name("a"), None);
        assert_eq!(
            kind_of_type("application/json; charset=utf-8"),
            Some(Kind::Json)
        );
        let nrg = crate::fixtures::corridor_building(2);
        assert_eq!(
            read_model(Kind::Json, nrg.to_json().as_bytes(), "x").unwrap(),
            (nrg, 0)
        );
        assert!(read_model(Kind::Json, b"{", "x").is_err());
    }
}
