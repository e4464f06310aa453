//! How the server is started: address, database, token, limits, CORS.

use std::net::SocketAddr;
use std::time::Duration;

/// Everything [`super::serve`] needs. [`ServerConfig::new`] gives the safe
/// defaults: loopback only, read-only, no CORS, 32 MiB uploads, 10 s per
/// request, 10 s to send a request head, 60 s to send a body, 512
/// connections.
#[derive(Debug, Clone, PartialEq)]
pub struct ServerConfig {
    /// The nrgdb database: an SQLite file (created if missing) or a
    /// PostgreSQL URL.
    pub db: String,
    /// Address to listen on (default `127.0.0.1:8080`).
    pub addr: SocketAddr,
    /// Bearer token that writes must present; `None` makes the server read-only.
    pub token: Option<String>,
    /// Origins allowed by CORS (`*` for any); empty turns CORS off.
    pub cors_origins: Vec<String>,
    /// Largest upload body in bytes (413 above it).
    pub max_upload_bytes: usize,
    /// Largest body of any other request in bytes (POST /query).
    pub max_body_bytes: usize,
    /// Time bound of one request (uploads excepted: they are bounded by size).
    pub timeout: Duration,
    /// Revisions kept indexed in memory at most.
    pub cache_revisions: usize,
    /// Time a client has to send a request's head, counted from when the
    /// connection opens or its previous response was sent: slow or idle
    /// connections are closed past it.
    pub header_timeout: Duration,
    /// Time a client has to send a request's body (uploads included; 408
    /// past it).
    pub body_timeout: Duration,
    /// Time a response write may stay blocked (a client that does not
    /// read its answer) before the connection is closed.
    pub write_timeout: Duration,
    /// Connections open at once at most; more wait to be accepted.
    pub max_connections: usize,
}

/// The default listening address.
pub const DEFAULT_ADDR: &str = "127.0.0.1:8080";

impl ServerConfig {
    /// Defaults for serving `db`.
    ///
    /// ```
    /// let c = nrgdb::server::ServerConfig::new("nrgdb.sqlite");
    /// assert!(c.addr.ip().is_loopback() && c.token.is_none());
    /// ```
    pub fn new(db: impl AsRef<std::path::Path>) -> ServerConfig {
        ServerConfig {
            db: db.as_ref().to_string_lossy().into_owned(),
            addr: SocketAddr::from(([127, 0, 0, 1], 8080)),
            token: None,
            cors_origins: Vec::new(),
            max_upload_bytes: 32 << 20,
            max_body_bytes: 1 << 20,
            timeout: Duration::from_secs(10),
            cache_revisions: 64,
            header_timeout: Duration::from_secs(10),
            body_timeout: Duration::from_secs(60),
            write_timeout: Duration::from_secs(30),
            max_connections: 512,
        }
    }

    /// Whether writes are accepted at all (a token is configured).
    pub fn writable(&self) -> bool {
        self.token.as_deref().is_some_and(|t| !t.is_empty())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn empty_token_is_read_only() {
        let mut c = ServerConfig::new("x");
        assert!(!c.writable());
        c.token = Some(String::new());
        assert!(!c.writable());
        c.token = Some("t".into());
        assert!(c.writable());
        assert_eq!(c.addr.to_string(), DEFAULT_ADDR);
    }
}
