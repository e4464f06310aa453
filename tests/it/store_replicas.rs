//! Issue 23: stateless replicas. Two `nrgdb serve` processes over one
//! PostgreSQL database answer the same; a revision written through one (or
//! by any other writer) is served by the other on its next request, with
//! the revision cache never serving a stale "latest".

use std::io::{BufRead, BufReader};
use std::net::SocketAddr;
use std::process::{Child, Command, Stdio};

use nrgdb::store::{ImportMeta, Store};

use super::server_client::request;
use super::store_engines::fresh_postgres_database;

const AUTH: (&str, &str) = ("Authorization", "Bearer replica-token");

/// `nrgdb serve --db url --token …` on a free loopback port.
fn serve(url: &str) -> (Child, SocketAddr) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_nrgdb"))
        .args([
            "serve",
            "--addr",
            "127.0.0.1:0",
            "--token",
            "replica-token",
            "--db",
            url,
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.as_mut().unwrap())
        .read_line(&mut line)
        .unwrap();
    // The start-up line names the database without its password.
    if let Some(password) = url
        .split_once("://")
        .and_then(|(_, r)| r.split_once('@'))
        .and_then(|(u, _)| u.split_once(':'))
        .map(|(_, p)| p)
    {
        assert!(!line.contains(password), "{line}");
    }
    let http = line
        .split_whitespace()
        .find(|w| w.starts_with("http://"))
        .unwrap_or_else(|| panic!("no address in {line:?}"));
    (child, http.trim_start_matches("http://").parse().unwrap())
}

async fn blocking<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    tokio::task::spawn_blocking(f).await.unwrap()
}

async fn latest(addr: SocketAddr) -> u64 {
    let r = request(addr, "GET", "/maps/floor", &[], b"").await;
    assert_eq!(r.status, 200, "{}", r.text());
    r.json()["latest"]["seq"]
        .as_u64()
        .unwrap_or_else(|| panic!("{}", r.text()))
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn two_servers_over_one_postgres_serve_the_same_latest() {
    // The PostgreSQL client blocks: store work runs off the async workers.
    let Some(url) = blocking(fresh_postgres_database).await else {
        return;
    };
    let db = url.clone();
    let mut store = blocking(move || {
        let mut store = Store::open_db(&db).unwrap();
        store
            .import(
                "floor",
                &nrgdb::fixtures::corridor_building(4),
                ImportMeta::new("a", "t"),
            )
            .unwrap();
        store
    })
    .await;
    let (mut a, addr_a) = serve(&url);
    let (mut b, addr_b) = serve(&url);
    // Both answer, and warm their caches on revision 1.
    for addr in [addr_a, addr_b] {
        assert_eq!(latest(addr).await, 1);
        let r = request(addr, "GET", "/maps/floor/route?from=10&to=13", &[], b"").await;
        assert_eq!(r.json()["code"], "Ok", "{}", r.text());
    }
    let route_a = request(addr_a, "GET", "/maps/floor/route?from=10&to=13", &[], b"").await;
    let route_b = request(addr_b, "GET", "/maps/floor/route?from=10&to=13", &[], b"").await;
    assert_eq!(route_a.json()["routes"], route_b.json()["routes"]);
    // A write through A is served by B on its next request.
    let r = request(
        addr_a,
        "POST",
        "/query?map=floor",
        &[AUTH],
        b"NAME 11 AS \"Canteen\";",
    )
    .await;
    assert_eq!(r.status, 200, "{}", r.text());
    assert_eq!(latest(addr_b).await, 2);
    let r = request(
        addr_b,
        "GET",
        "/maps/floor/route?from=10&to=Canteen",
        &[],
        b"",
    )
    .await;
    assert_eq!(r.json()["code"], "Ok", "{}", r.text());
    // So is a revision another writer (a robot's upload elsewhere) makes.
    blocking(move || {
        store
            .import(
                "floor",
                &nrgdb::fixtures::corridor_building(5),
                ImportMeta::new("b", "robot"),
            )
            .unwrap()
    })
    .await;
    assert_eq!(latest(addr_a).await, 3);
    assert_eq!(latest(addr_b).await, 3);
    // Revision 3 has a fifth room and its door (11 spaces), and keeps the
    // name given through A.
    let r = request(addr_b, "GET", "/maps/floor", &[], b"").await;
    assert_eq!(r.json()["latest"]["spaces"], 11, "{}", r.text());
    let r = request(
        addr_b,
        "GET",
        "/maps/floor/route?from=10&to=Canteen",
        &[],
        b"",
    )
    .await;
    assert_eq!(r.json()["code"], "Ok", "{}", r.text());
    // Writes without the token are refused by either.
    let r = request(
        addr_b,
        "POST",
        "/query?map=floor",
        &[],
        b"NAME 10 AS \"x\";",
    )
    .await;
    r.assert_error_code(401, "Unauthorized");
    for child in [&mut a, &mut b] {
        child.kill().unwrap();
        child.wait().unwrap();
    }
}
