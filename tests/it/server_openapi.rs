//! Issue #7: `/openapi.json` matches the routes the router really serves.

use std::collections::BTreeSet;

use super::server_client::{TOKEN, TestServer};

/// A concrete path for a pattern (`{map}` → building, `{id}` → 10, `{rev}` → 1).
fn concrete(pattern: &str) -> String {
    pattern
        .replace("{map}", "building")
        .replace("{id}", "10")
        .replace("{rev}", "1")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn openapi_paths_are_the_router_paths() {
    let s = TestServer::start(|c| c.token = Some(TOKEN.into())).await;
    let doc = s.get("/openapi.json").await.json();
    assert!(doc["openapi"].as_str().unwrap().starts_with("3."));
    let documented: BTreeSet<(String, String)> = doc["paths"]
        .as_object()
        .unwrap()
        .iter()
        .flat_map(|(path, item)| {
            item.as_object()
                .unwrap()
                .keys()
                .filter(|k| ["get", "post", "put", "delete", "patch"].contains(&k.as_str()))
                .map(move |m| (m.to_uppercase(), path.clone()))
        })
        .collect();
    let table: BTreeSet<(String, String)> = nrgdb::server::routes::endpoints()
        .iter()
        .map(|e| (e.method.to_string(), e.path.to_string()))
        .collect();
    assert_eq!(documented, table);
    // Every documented operation is served: never the router's "no
    // endpoint" 404 nor a 405.
    for (method, path) in &documented {
        let reply = super::server_client::request(s.addr, method, &concrete(path), &[], b"").await;
        let code = serde_json::from_slice::<serde_json::Value>(&reply.body)
            .ok()
            .and_then(|v| v["code"].as_str().map(str::to_string));
        assert!(
            reply.status != 405 && code.as_deref() != Some("NoEndpoint"),
            "{method} {path}: {} {}",
            reply.status,
            reply.text()
        );
    }
    // And an undocumented path is not.
    let reply = s.get("/maps/building/teleport").await;
    assert_eq!(reply.json()["code"], "NoEndpoint");
    s.stop().await;
}
