//! Issue #7: `GET /maps/{map}/diff?from=&to=`.

use super::server_client::TestServer;

const AUTH: (&str, &str) = ("Authorization", "Bearer test-token-42");

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn diff_between_two_revisions() {
    let s = TestServer::writable().await;
    let more = nrgdb::fixtures::corridor_building(7).to_json();
    let r = s
        .post(
            "/maps/building/revisions",
            &[("Content-Type", "application/json"), AUTH],
            more.as_bytes(),
        )
        .await;
    assert_eq!(r.status, 201, "{}", r.text());
    let d = s
        .get("/maps/building/diff?from=1&to=latest&align=never")
        .await;
    assert_eq!(d.status, 200, "{}", d.text());
    let v = d.json();
    assert_eq!((v["from"].as_u64(), v["to"].as_u64()), (Some(1), Some(2)));
    assert_eq!(v["unchanged"], false);
    assert_eq!(
        v["changes"]["summary"]["added"], 2,
        "a room and its door: {v}"
    );
    assert_eq!(v["changes"]["summary"]["removed"], 0);
    assert_eq!(v["changes"]["from"], "building@1");
    let same = s.get("/maps/building/diff?from=2&to=2").await.json();
    assert_eq!(same["unchanged"], true, "{same}");
    s.get("/maps/building/diff?from=1")
        .await
        .assert_error(400, "to");
    s.get("/maps/building/diff?from=x&to=2")
        .await
        .assert_error(400, "from");
    s.get("/maps/building/diff?from=1&to=9")
        .await
        .assert_error(404, "to");
    s.get("/maps/building/diff?from=1&to=2&align=maybe")
        .await
        .assert_error(400, "align");
    s.get("/maps/nope/diff?from=1&to=2")
        .await
        .assert_error(404, "map");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_request_past_the_time_bound_is_503() {
    let s = TestServer::start(|c| c.timeout = std::time::Duration::from_millis(1)).await;
    let mut store = nrgdb::store::Store::open(&s.db).unwrap();
    for rooms in [1500, 1501] {
        store
            .import(
                "big",
                &nrgdb::fixtures::corridor_building(rooms),
                nrgdb::store::ImportMeta::new("", "test"),
            )
            .unwrap();
    }
    let r = s.get("/maps/big/diff?from=1&to=2&align=never").await;
    assert_eq!(r.status, 503, "{}", r.text());
    assert_eq!(r.json()["code"], "Timeout", "{}", r.text());
    s.stop().await;
}
