//! `GET /maps/{map}/diff?from=&to=&align=`: what changed between two
//! revisions of a map ([`crate::query::compare_revisions`], the change-set
//! service on the revisions and their stored grids: spaces added, removed,
//! resized, split, merged, re-kinded, renamed; connections; door widths),
//! aligning the two when their frames differ.

use axum::Json;
use axum::extract::{Path, State};
use axum::http::Uri;
use serde_json::{Value, json};

use crate::diff::{AlignMode, DiffOptions};
use crate::query::compare_revisions;
use crate::server::endpoint::{ParamDoc, q};
use crate::server::error::{ApiError, comparing_error};
use crate::server::params::{Params, parse_rev};
use crate::server::state::AppState;
use crate::store::StoreError;

/// Query parameters of the diff endpoint.
pub const PARAMS: [ParamDoc; 3] = [
    q(
        "from",
        "string",
        true,
        "base revision: a number or 'latest'",
    ),
    q(
        "to",
        "string",
        true,
        "revision compared with the base: a number or 'latest'",
    ),
    q(
        "align",
        "string",
        false,
        "auto (default: align when the frames differ), always or never",
    ),
];

fn align_mode(raw: Option<&str>) -> Result<AlignMode, ApiError> {
    match raw.map(str::trim) {
        None | Some("auto") => Ok(AlignMode::Auto),
        Some("always") => Ok(AlignMode::Always),
        Some("never") => Ok(AlignMode::Never),
        Some(other) => Err(ApiError::bad(
            "align",
            format!("'{other}' is not auto, always or never"),
        )),
    }
}

/// A store error on revision `name` ("from" or "to"), naming it.
fn named(name: &str, e: StoreError) -> ApiError {
    match e {
        StoreError::NoSuchRevision { .. } => ApiError::not_found(name, e.to_string()),
        other => other.into(),
    }
}

/// `GET /maps/{map}/diff`.
pub async fn diff(
    State(state): State<AppState>,
    Path(map): Path<String>,
    uri: Uri,
) -> Result<Json<Value>, ApiError> {
    let p = Params::parse(&uri, &["from", "to", "align"])?;
    let from = parse_rev("from", p.required("from")?)?;
    let to = parse_rev("to", p.required("to")?)?;
    let mode = align_mode(p.get("align"))?;
    let timeout = state.config().timeout;
    // The comparison stops when the client gets its 503.
    let deadline = std::time::Instant::now().checked_add(timeout);
    state
        .blocking(move |ctx| {
            let a_seq = ctx
                .store()
                .revision(&map, from)
                .map_err(|e| named("from", e))?
                .seq;
            let b_seq = ctx
                .store()
                .revision(&map, to)
                .map_err(|e| named("to", e))?
                .seq;
            let options = DiffOptions {
                align: mode,
                deadline,
                ..DiffOptions::default()
            };
            let done = compare_revisions(
                &*ctx.store(),
                &map,
                u64::from(a_seq),
                u64::from(b_seq),
                &options,
            )
            .map_err(|e| {
                comparing_error(
                    e,
                    "align",
                    "align=never compares the revisions as they are",
                    timeout.as_millis(),
                )
            })?
            .comparison;
            let changes = done.changes;
            // The transform itself is in `changes.alignment`; this is its quality.
            let alignment = done.alignment.map(|al| {
                json!({"inliers": al.inliers, "tolerance_m": al.tolerance_m, "rms_m": al.rms_m})
            });
            Ok(Json(json!({
                "map": map,
                "from": a_seq,
                "to": b_seq,
                "unchanged": changes.is_empty(),
                "alignment": alignment,
                "changes": changes,
            })))
        })
        .await
}
