//! Bearer-token check for writes. Without a configured token the server is
//! read-only: writes get 403; with one, a missing or wrong token gets 401.

use axum::http::{HeaderMap, header};
use sha2::{Digest, Sha256};

use super::config::ServerConfig;
use super::error::ApiError;

/// Whether the request carries the configured token (constant-time compare).
pub fn has_token(config: &ServerConfig, headers: &HeaderMap) -> bool {
    let Some(expected) = config.token.as_deref().filter(|t| !t.is_empty()) else {
        return false;
    };
    let given = headers
        .get(header::AUTHORIZATION)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| {
            v.strip_prefix("Bearer ")
                .or_else(|| v.strip_prefix("bearer "))
        })
        .map(str::trim);
    // Compare fixed-length digests in constant time: comparing the tokens
    // themselves returned early on a length mismatch, which told an
    // attacker the token's length.
    given.is_some_and(|g| {
        let (a, b) = (
            Sha256::digest(g.as_bytes()),
            Sha256::digest(expected.as_bytes()),
        );
        a.iter()
            .zip(b.iter())
            .fold(0u8, |acc, (x, y)| acc | (x ^ y))
            == 0
    })
}

/// `Ok` when a write may go ahead; 403 on a read-only server, 401 without
/// the right token.
pub fn require_write(config: &ServerConfig, headers: &HeaderMap) -> Result<(), ApiError> {
    if !config.writable() {
        return Err(ApiError::ReadOnly);
    }
    if has_token(config, headers) {
        Ok(())
    } else {
        Err(ApiError::Unauthorized)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn read_only_unauthorized_ok() {
        let mut c = ServerConfig::new("x");
        let mut h = HeaderMap::new();
        assert!(matches!(require_write(&c, &h), Err(ApiError::ReadOnly)));
        c.token = Some("s3cret".into());
        assert!(matches!(require_write(&c, &h), Err(ApiError::Unauthorized)));
        h.insert(header::AUTHORIZATION, "Bearer wrong!".parse().unwrap());
        assert!(matches!(require_write(&c, &h), Err(ApiError::Unauthorized)));
        h.insert(header::AUTHORIZATION, "Bearer s3cret".parse().unwrap());
        assert!(require_write(&c, &h).is_ok());
    }
}
