//! Reading a request body with a size limit and a time limit: a declared
//! `Content-Length` above the size is refused before reading, a body that
//! grows past it while streaming too (413 either way); a body that has not
//! all arrived in time is a 408 (issue 21, defect 9: slow clients held
//! connections for ever).

use std::time::Duration;

use axum::body::{Body, Bytes};
use axum::http::{HeaderMap, header};

use super::error::ApiError;

/// The whole body, at most `limit` bytes, arrived within `time`.
pub async fn read_limited(
    headers: &HeaderMap,
    body: Body,
    limit: usize,
    time: Duration,
) -> Result<Bytes, ApiError> {
    let declared = headers
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.parse::<u64>().ok());
    if declared.is_some_and(|n| n > limit as u64) {
        return Err(ApiError::TooLarge { limit });
    }
    let read = tokio::time::timeout(time, axum::body::to_bytes(body, limit)).await;
    let read = read.map_err(|_| ApiError::BodyTimeout(time.as_millis()))?;
    read.map_err(|e| {
        // axum wraps http-body-util's LengthLimitError ("length limit exceeded").
        if e.to_string().contains("length limit") {
            ApiError::TooLarge { limit }
        } else {
            ApiError::BadUpload(format!("cannot read the request body: {e}"))
        }
    })
}
