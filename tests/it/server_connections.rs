//! Issue 21, defect 9: slow clients were never dropped (1 100 connections
//! that sent half a request head were held for 70 s and more). A request
//! head must arrive within the header timeout, a body within the body
//! timeout, and at most `max_connections` are open at once. Every wait
//! here is bounded; the server binds 127.0.0.1 only.

use std::io::{ErrorKind, Read};
use std::time::Duration;

use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tokio::net::TcpStream;

use super::server_client::{TestServer, read_reply};

/// Longest any step of these tests may wait before it counts as a hang.
const HANG: Duration = Duration::from_secs(20);

/// Reads until the server closes the connection; the bytes it sent.
async fn read_to_close(stream: &mut TcpStream) -> Vec<u8> {
    let mut all = Vec::new();
    let mut buf = [0u8; 4096];
    let closed = tokio::time::timeout(HANG, async {
        loop {
            match stream.read(&mut buf).await {
                Ok(0) | Err(_) => break,
                Ok(n) => all.extend_from_slice(&buf[..n]),
            }
        }
    })
    .await;
    assert!(closed.is_ok(), "the server kept the connection open");
    all
}

fn short_header_timeout(c: &mut nrgdb::server::ServerConfig) {
    c.header_timeout = Duration::from_millis(300);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue_21_defect_9_a_partial_header_is_dropped() {
    let s = TestServer::start(short_header_timeout).await;
    let mut slow = TcpStream::connect(s.addr).await.unwrap();
    slow.write_all(b"GET /health HTTP/1.1\r\nHost: x\r\n")
        .await
        .unwrap();
    let answer = read_to_close(&mut slow).await;
    assert!(
        !answer.starts_with(b"HTTP/1.1 200"),
        "served a half request"
    );
    // A client that connects and says nothing is dropped the same way.
    let mut silent = TcpStream::connect(s.addr).await.unwrap();
    assert!(read_to_close(&mut silent).await.is_empty());
    // The server still serves.
    assert_eq!(s.get("/health").await.status, 200);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue_21_defect_9_an_idle_keep_alive_connection_is_dropped() {
    let s = TestServer::start(short_header_timeout).await;
    let mut idle = TcpStream::connect(s.addr).await.unwrap();
    idle.write_all(b"GET /health HTTP/1.1\r\nHost: x\r\n\r\n")
        .await
        .unwrap();
    // Keep-alive: the answer comes, then the connection stays idle until
    // the header timeout closes it.
    let answer = read_to_close(&mut idle).await;
    assert!(answer.starts_with(b"HTTP/1.1 200"), "{answer:?}");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue_21_defect_9_a_slow_body_gets_408() {
    let s = TestServer::start(|c| {
        c.body_timeout = Duration::from_millis(300);
        c.timeout = Duration::from_secs(60);
    })
    .await;
    let mut slow = TcpStream::connect(s.addr).await.unwrap();
    slow.write_all(
        b"POST /query HTTP/1.1\r\nHost: x\r\nConnection: close\r\nContent-Length: 100\r\n\r\nSHOW",
    )
    .await
    .unwrap();
    let reply = tokio::time::timeout(HANG, read_reply(&mut slow))
        .await
        .expect("no answer to a stalled body");
    reply.assert_error_code(408, "BodyTimeout");
    s.stop().await;
}

/// With one connection allowed, a second client is only served once the
/// first (silent) one has been closed by the header timeout: when its
/// answer arrives, the first connection is already shut.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue_21_defect_9_connections_are_capped() {
    let s = TestServer::start(|c| {
        c.max_connections = 1;
        c.header_timeout = Duration::from_millis(500);
    })
    .await;
    let mut first = std::net::TcpStream::connect(s.addr).unwrap();
    first.set_nonblocking(true).unwrap();
    let mut buf = [0u8; 16];
    // Give the server time to accept the first connection before the
    // second queues behind it (if it has not, the test still passes).
    tokio::time::sleep(Duration::from_millis(100)).await;
    let open_before = matches!(first.read(&mut buf), Err(e) if e.kind() == ErrorKind::WouldBlock);
    let reply = tokio::time::timeout(HANG, s.get("/health"))
        .await
        .expect("the second client was never served");
    assert_eq!(reply.status, 200);
    assert!(open_before, "the first connection was closed at once");
    assert!(
        matches!(first.read(&mut buf), Ok(0)),
        "the second client was served while the first held the only connection"
    );
    s.stop().await;
}

/// Issue 21: a client that asks and never reads its answers held its
/// connection for ever (and a graceful shutdown waited for it). Pipelined
/// requests fill both socket buffers; past the write timeout the server
/// closes the connection, long before the answers run out.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue_21_a_client_that_never_reads_is_dropped() {
    let s = TestServer::start(|c| {
        c.write_timeout = Duration::from_millis(300);
        c.header_timeout = Duration::from_secs(60);
        c.timeout = Duration::from_secs(60);
    })
    .await;
    let one = s.get("/maps/building/revisions/1/indoorgml").await;
    assert_eq!(one.status, 200);
    let socket = tokio::net::TcpSocket::new_v4().unwrap();
    socket.set_recv_buffer_size(4096).unwrap();
    let mut stalled = socket.connect(s.addr).await.unwrap();
    let request = b"GET /maps/building/revisions/1/indoorgml HTTP/1.1\r\nHost: x\r\n\r\n";
    let answers = 2000;
    // Far more than the buffers between us hold: the server blocks.
    let total = answers * one.body.len();
    assert!(total > 16 << 20, "answers too small to block: {total}");
    stalled.write_all(&request.repeat(answers)).await.unwrap();
    tokio::time::sleep(Duration::from_millis(1500)).await;
    let got = read_to_close(&mut stalled).await;
    assert!(
        got.len() < total / 2,
        "the server kept writing: {} of {total} bytes",
        got.len()
    );
    // Others are served, and the server stops at once.
    assert_eq!(s.get("/health").await.status, 200);
    tokio::time::timeout(HANG, s.stop())
        .await
        .expect("shutdown waited for the stalled client");
}
