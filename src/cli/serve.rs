//! `nrgdb serve`: the HTTP JSON navigation backend over a database.

use std::io::Write;
use std::net::SocketAddr;
use std::process::ExitCode;

use super::db::DbArg;

/// Serve maps, revisions, spaces, routes and queries as HTTP JSON (see GET
/// /openapi.json). Binds 127.0.0.1 by default; read-only unless a token is
/// set; stops cleanly on Ctrl-C or SIGTERM (in-flight requests finish).
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub db: DbArg,
    /// Address to listen on (use 0.0.0.0:PORT to accept other machines).
    #[arg(long, default_value = "127.0.0.1:8080", value_name = "IP:PORT")]
    pub addr: SocketAddr,
    /// Bearer token that uploads and NAME queries must present; without one
    /// the server is read-only (writes get 403).
    #[arg(
        long,
        env = "NRGDB_TOKEN",
        value_name = "TOKEN",
        hide_env_values = true
    )]
    pub token: Option<String>,
    /// Allow browsers on this origin (repeatable; `*` for any). CORS is off
    /// unless given.
    #[arg(long = "cors", value_name = "ORIGIN")]
    pub cors: Vec<String>,
    /// Largest upload in MiB (413 above it).
    #[arg(long, default_value_t = 32, value_name = "MIB")]
    pub max_upload_mb: usize,
    /// Time bound of one request in milliseconds (503 past it; uploads are
    /// bounded by size instead).
    #[arg(long, default_value_t = 10_000, value_name = "MS")]
    pub timeout_ms: u64,
    /// Revisions kept indexed in memory.
    #[arg(long, default_value_t = 64, value_name = "N")]
    pub cache_revisions: usize,
    /// Time a client has to send a request's head, in milliseconds, from
    /// when it connects or got its previous answer: slow and idle
    /// connections are closed past it.
    #[arg(long, default_value_t = 10_000, value_name = "MS")]
    pub header_timeout_ms: u64,
    /// Time a client has to send a request's body (uploads too), in
    /// milliseconds (408 past it).
    #[arg(long, default_value_t = 60_000, value_name = "MS")]
    pub body_timeout_ms: u64,
    /// Time an answer may wait for a client that does not read it, in
    /// milliseconds: the connection is closed past it.
    #[arg(long, default_value_t = 30_000, value_name = "MS")]
    pub write_timeout_ms: u64,
    /// Connections open at once at most; further clients wait to be
    /// accepted.
    #[arg(long, default_value_t = 512, value_name = "N")]
    pub max_connections: usize,
}

/// Runs `nrgdb serve` until a signal stops it.
#[cfg(feature = "server")]
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    use miette::IntoDiagnostic;
    use nrgdb::server::{AppState, ServerConfig, bind, serve_on, shutdown_signal};

    if [
        args.timeout_ms,
        args.header_timeout_ms,
        args.body_timeout_ms,
        args.write_timeout_ms,
    ]
    .contains(&0)
        || args.max_upload_mb == 0
        || args.max_connections == 0
    {
        miette::bail!(
            "--timeout-ms, --header-timeout-ms, --body-timeout-ms, --write-timeout-ms, \
             --max-upload-mb and --max-connections must be at least 1"
        );
    }
    let mut config = ServerConfig::new(args.db.db.clone());
    config.addr = args.addr;
    config.token = args.token.filter(|t| !t.is_empty());
    config.cors_origins = args.cors;
    config.max_upload_bytes = args.max_upload_mb.saturating_mul(1 << 20);
    config.timeout = std::time::Duration::from_millis(args.timeout_ms);
    config.cache_revisions = args.cache_revisions;
    config.header_timeout = std::time::Duration::from_millis(args.header_timeout_ms);
    config.body_timeout = std::time::Duration::from_millis(args.body_timeout_ms);
    config.write_timeout = std::time::Duration::from_millis(args.write_timeout_ms);
    config.max_connections = args.max_connections;
    let runtime = tokio::runtime::Runtime::new().into_diagnostic()?;
    runtime.block_on(async {
        let listener = bind(config.addr).await.into_diagnostic()?;
        let local = listener.local_addr().into_diagnostic()?;
        let mode = if config.writable() {
            "writes need the bearer token"
        } else {
            "read-only"
        };
        let state = AppState::new(config.clone()).map_err(|e| {
            miette::miette!(
                "opening database {}: {e}",
                super::db::hide_password(&config.db)
            )
        })?;
        writeln!(
            out,
            "nrgdb serving {} on http://{local} ({mode}); Ctrl-C stops",
            super::db::hide_password(&config.db)
        )
        .into_diagnostic()?;
        out.flush().into_diagnostic()?;
        serve_on(listener, state, shutdown_signal())
            .await
            .into_diagnostic()?;
        writeln!(out, "nrgdb serve: stopped").into_diagnostic()?;
        Ok(ExitCode::SUCCESS)
    })
}

/// Without the `server` feature the subcommand only explains itself.
#[cfg(not(feature = "server"))]
pub fn run(_args: Args, _out: &mut dyn Write) -> miette::Result<ExitCode> {
    miette::bail!(
        "this nrgdb was built without the `server` feature (rebuild with --features server)"
    )
}
