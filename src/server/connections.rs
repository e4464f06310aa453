//! Accepting connections and bounding what a client can hold (issue 21,
//! defect 9: 1 100 connections that sent half a request head were kept
//! for 70 s and more).
//!
//! Owns the accept loop: at most [`ServerConfig::max_connections`] are
//! open at once (further clients wait in the kernel's backlog until one
//! closes), and a connection whose request head has not fully arrived
//! [`ServerConfig::header_timeout`] after the server started waiting for it
//! is closed. The wait starts when the connection opens and again after
//! each response, so the same bound drops idle keep-alive connections.
//! A response write blocked for [`ServerConfig::write_timeout`] (a client
//! that does not read) closes the connection (`server/write_timeout.rs`).
//! Request bodies are bounded by [`ServerConfig::body_timeout`] where they
//! are read (`server/body.rs`), the whole request by
//! [`ServerConfig::timeout`] (`server/timeout.rs`). HTTP/1.1 only, as
//! before: `axum::serve`, which this replaces, was built without HTTP/2
//! and sets no timer, so hyper's header timeout never ran.

use std::future::Future;
use std::pin::pin;
use std::sync::Arc;
use std::time::Duration;

use axum::Router;
use hyper::server::conn::http1;
use hyper_util::rt::{TokioIo, TokioTimer};
use hyper_util::service::TowerToHyperService;
use tokio::net::TcpListener;
use tokio::sync::{Semaphore, watch};
use tokio::task::JoinSet;

use super::config::ServerConfig;
use super::write_timeout::WriteTimeout;

/// Serves `app` on `listener` until `shutdown` resolves; then stops
/// accepting, lets each connection finish the request it is serving and
/// waits for them all.
pub(crate) async fn serve_connections(
    listener: TcpListener,
    app: Router,
    config: &ServerConfig,
    shutdown: impl Future<Output = ()> + Send + 'static,
) {
    let mut builder = http1::Builder::new();
    builder
        .timer(TokioTimer::new())
        .header_read_timeout(config.header_timeout);
    let permits = Arc::new(Semaphore::new(config.max_connections.max(1)));
    let (stop_tx, stop_rx) = watch::channel(());
    let mut connections = JoinSet::new();
    let mut shutdown = pin!(shutdown);
    loop {
        let accepted = tokio::select! {
            () = &mut shutdown => break,
            accepted = accept(&listener, &permits) => accepted,
        };
        let Some((stream, permit)) = accepted else {
            continue;
        };
        // Forget the connections that have ended.
        while connections.try_join_next().is_some() {}
        let service = TowerToHyperService::new(app.clone());
        let builder = builder.clone();
        let mut stop = stop_rx.clone();
        let io = TokioIo::new(WriteTimeout::new(stream, config.write_timeout));
        connections.spawn(async move {
            let _permit = permit;
            let mut conn = pin!(builder.serve_connection(io, service));
            tokio::select! {
                result = conn.as_mut() => log_end(result),
                _ = stop.changed() => {
                    conn.as_mut().graceful_shutdown();
                    log_end(conn.await);
                }
            }
        });
    }
    drop(listener);
    drop(stop_tx);
    while connections.join_next().await.is_some() {}
}

/// The next connection, once a permit is free. `None` after an accept
/// error (logged; after a pause when out of file descriptors).
async fn accept(
    listener: &TcpListener,
    permits: &Arc<Semaphore>,
) -> Option<(tokio::net::TcpStream, tokio::sync::OwnedSemaphorePermit)> {
    // The semaphore is never closed, so acquiring only waits.
    let permit = Arc::clone(permits).acquire_owned().await.ok()?;
    match listener.accept().await {
        Ok((stream, _)) => {
            // Small JSON answers: do not wait to fill a segment.
            let _ = stream.set_nodelay(true);
            Some((stream, permit))
        }
        Err(e) => {
            tracing::warn!(error = %e, "accepting a connection failed");
            // EMFILE/ENFILE: give the other connections time to close.
            tokio::time::sleep(Duration::from_millis(50)).await;
            None
        }
    }
}

fn log_end(result: Result<(), hyper::Error>) {
    if let Err(e) = result {
        // Time-outs, resets and malformed requests: the client's doing.
        tracing::debug!(error = %e, "connection ended");
    }
}
