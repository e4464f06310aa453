//! Issue #7: the read endpoints over a real socket: maps, revisions,
//! spaces, neighbours, locate, route, exports, query, metrics, errors.

use super::server_client::TestServer;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn health_maps_revisions() {
    let s = TestServer::read_only().await;
    let h = s.get("/health").await;
    assert_eq!(h.status, 200);
    assert_eq!(h.json()["status"], "ok");
    assert_eq!(h.json()["writable"], false);
    let maps = s.get("/maps").await.json();
    assert_eq!(maps["maps"][0]["name"], "building");
    assert_eq!(maps["maps"][0]["latest"], 1);
    let one = s.get("/maps/building").await.json();
    assert_eq!(one["map"]["name"], "building");
    assert_eq!(one["latest"]["seq"], 1);
    s.get("/maps/elsewhere").await.assert_error(404, "map");
    let first = s.get("/maps/building/revisions/1").await.json();
    assert_eq!(first["revision"]["message"], "first");
    s.get("/maps/building/revisions/2")
        .await
        .assert_error(404, "rev");
    let revs = s.get("/maps/building/revisions").await.json();
    assert_eq!(revs["revisions"][0]["seq"], 1);
    assert_eq!(revs["revisions"][0]["spaces"], 13);
    s.get("/maps/nowhere/revisions")
        .await
        .assert_error(404, "map");
    s.get("/maps?x=1").await.assert_error(400, "x");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn spaces_space_neighbours_locate() {
    let s = TestServer::read_only().await;
    let rooms = s.get("/maps/building/spaces?kind=room").await.json();
    assert_eq!(rooms["spaces"].as_array().unwrap().len(), 6);
    assert_eq!(rooms["revision"], 1);
    let named = s.get("/maps/building/spaces?name=office%25").await.json();
    let ids: Vec<u64> = named["spaces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v["id"].as_u64().unwrap())
        .collect();
    assert_eq!(ids, vec![10, 13]);
    s.get("/maps/building/spaces?kind=attic")
        .await
        .assert_error(400, "kind");
    s.get("/maps/building/spaces?rev=7")
        .await
        .assert_error(404, "rev");
    s.get("/maps/building/spaces?rev=zero")
        .await
        .assert_error(400, "rev");

    let one = s.get("/maps/building/spaces/10").await.json();
    assert_eq!(one["space"]["name"], "Office 1");
    assert_eq!(one["space"]["attributes"]["floor"], 2);
    assert_eq!(one["space"]["polygon"].as_array().unwrap().len(), 4);
    assert_eq!(one["space"]["connections"].as_array().unwrap().len(), 2);
    s.get("/maps/building/spaces/99")
        .await
        .assert_error(404, "id");
    s.get("/maps/building/spaces/abc")
        .await
        .assert_error(400, "id");
    s.get("/maps/nope/spaces/10").await.assert_error(404, "map");

    let n = s.get("/maps/building/neighbours/10?depth=2").await.json();
    let rows = n["neighbours"].as_array().unwrap();
    assert_eq!(rows[0]["id"], 10000);
    assert_eq!(rows[0]["depth"], 1);
    assert!(rows.iter().any(|r| r["id"] == 1 && r["depth"] == 2));
    s.get("/maps/building/neighbours/10?depth=0")
        .await
        .assert_error(400, "depth");
    s.get("/maps/building/neighbours/10?depth=x")
        .await
        .assert_error(400, "depth");
    s.get("/maps/building/neighbours/77")
        .await
        .assert_error(404, "id");

    let at = s.get("/maps/building/locate?x=2&y=5").await.json();
    assert_eq!(at["space"]["id"], 10);
    let outside = s.get("/maps/building/locate?x=-50&y=5").await;
    assert_eq!(outside.status, 200);
    assert!(outside.json()["space"].is_null());
    s.get("/maps/building/locate?y=5")
        .await
        .assert_error(400, "x");
    s.get("/maps/building/locate?x=1&y=inf")
        .await
        .assert_error(400, "y");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn route_is_osrm_shaped() {
    let s = TestServer::read_only().await;
    // Zero clearance: from Office 1's anchor (2, 4.6) to the corner of its
    // doorway (2.5, 2.0), along the corridor's wall face to the corner of
    // room 15's doorway (21.5, 2.0), up to its anchor (22, 4.6).
    let r = s
        .get("/maps/building/route?from=10&to=15&clearance=0")
        .await;
    assert_eq!(r.status, 200, "{}", r.text());
    let v = r.json();
    assert_eq!(v["code"], "Ok");
    let route = &v["routes"][0];
    let expected = 2.0 * 0.5f64.hypot(2.6) + 19.0;
    assert!(
        (route["distance"].as_f64().unwrap() - expected).abs() < 0.001,
        "{route}"
    );
    assert_eq!(route["geometry"]["type"], "LineString");
    let coords = route["geometry"]["coordinates"].as_array().unwrap();
    let points: Vec<[f64; 2]> = coords
        .iter()
        .map(|c| [c[0].as_f64().unwrap(), c[1].as_f64().unwrap()])
        .collect();
    assert_eq!(
        points,
        vec![[2.0, 4.6], [2.5, 2.0], [21.5, 2.0], [22.0, 4.6]]
    );
    assert_eq!(route["doors"], serde_json::json!([10000, 10005]));
    let spaces: Vec<u64> = route["spaces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["id"].as_u64().unwrap())
        .collect();
    assert_eq!(spaces, vec![10, 10000, 1, 10005, 15]);
    // The default clearance (0.2 m) keeps that far from the two corners
    // (to the millimetre the answer is given in).
    let cleared = s.get("/maps/building/route?from=10&to=15").await.json();
    let line: Vec<[f64; 2]> = cleared["routes"][0]["geometry"]["coordinates"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| [c[0].as_f64().unwrap(), c[1].as_f64().unwrap()])
        .collect();
    for corner in [[2.5, 2.0], [21.5, 2.0], [1.5, 2.0], [22.5, 2.0]] {
        let nearest = line
            .windows(2)
            .map(|w| nrgdb::model::segment_distance(corner, w[0], w[1]))
            .fold(f64::INFINITY, f64::min);
        assert!(
            nearest >= 0.2 - 1e-3,
            "{corner:?} is {nearest} m from the route"
        );
    }
    assert!(cleared["routes"][0]["distance"].as_f64().unwrap() > expected);
    let narrow = s
        .get("/maps/building/route?from=10&to=15&min_door_width=1.2")
        .await
        .json();
    assert_eq!(narrow["code"], "NoRoute");
    assert!(
        narrow["message"]
            .as_str()
            .unwrap()
            .contains("narrower than 1.2 m"),
        "{narrow}"
    );
    let leg = &route["legs"][0];
    assert_eq!(leg["distance"], route["distance"]);
    let steps = leg["steps"].as_array().unwrap();
    assert!(steps.len() >= 2);
    assert_eq!(steps.last().unwrap()["turn"], "arrive");
    let walked: f64 = steps.iter().map(|s| s["distance"].as_f64().unwrap()).sum();
    assert!((walked - expected).abs() < 0.01);
    assert_eq!(v["waypoints"][0]["name"], "Office 1");

    // Names, points, waypoints, avoidance and alternatives.
    let by_name = s
        .get("/maps/building/route?from=office%201&to=13.5,4")
        .await
        .json();
    assert_eq!(by_name["waypoints"][1]["space"], 13);
    let via = s
        .get("/maps/building/route?from=10&to=15&via=12")
        .await
        .json();
    assert_eq!(via["routes"][0]["legs"].as_array().unwrap().len(), 2);
    let cut = s
        .get("/maps/building/route?from=10&to=15&avoid=1")
        .await
        .json();
    assert_eq!(cut["code"], "NoRoute");
    assert!(cut["routes"].as_array().unwrap().is_empty());
    let alt = s
        .get("/maps/building/route?from=10&to=15&alternatives=3")
        .await;
    assert_eq!(alt.status, 200);
    assert!(!alt.json()["routes"].as_array().unwrap().is_empty());

    s.get("/maps/building/route?to=15")
        .await
        .assert_error(400, "from");
    s.get("/maps/building/route?from=10")
        .await
        .assert_error(400, "to");
    s.get("/maps/building/route?from=10&to=999")
        .await
        .assert_error(404, "to");
    s.get("/maps/building/route?from=Kitchen&to=15")
        .await
        .assert_error(404, "from");
    s.get("/maps/building/route?from=10&to=15&via=42")
        .await
        .assert_error(404, "via");
    s.get("/maps/building/route?from=10&to=15&avoid=10")
        .await
        .assert_error(400, "avoid");
    s.get("/maps/building/route?from=10&to=15&alternatives=99")
        .await
        .assert_error(400, "alternatives");
    s.get("/maps/building/route?from=10&to=15&via=12&alternatives=2")
        .await
        .assert_error(400, "alternatives");
    s.get("/maps/building/route?from=10&to=15&clearance=-1")
        .await
        .assert_error(400, "clearance");
    s.get("/maps/building/route?from=-40,0&to=15")
        .await
        .assert_error(404, "from");
    s.get("/maps/building/route?from=10&to=15&form=1")
        .await
        .assert_error(400, "form");
    s.get("/maps/nope/route?from=10&to=15")
        .await
        .assert_error(404, "map");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn exports_query_metrics_and_unknown_paths() {
    let s = TestServer::read_only().await;
    let gml = s.get("/maps/building/revisions/1/indoorgml").await;
    assert_eq!(gml.status, 200);
    assert!(gml.header("content-type").unwrap().contains("xml"));
    let doc = nrgdb::indoorgml::read_str(&gml.text()).unwrap();
    assert_eq!(nrgdb::indoorgml::to_nrg(&doc).unwrap().spaces().len(), 13);
    assert!(gml.header("cache-control").unwrap().contains("immutable"));
    let geo = s.get("/maps/building/revisions/latest/geojson").await;
    assert_eq!(geo.status, 200);
    assert_eq!(geo.json()["type"], "FeatureCollection");
    s.get("/maps/building/revisions/5/geojson")
        .await
        .assert_error(404, "rev");
    s.get("/maps/building/revisions/x/geojson")
        .await
        .assert_error(400, "rev");

    let q = s
        .post(
            "/query",
            &[("Content-Type", "text/plain")],
            b"FIND rooms WHERE area > 10 LIMIT 2; ROUTE FROM 10 TO 12;",
        )
        .await;
    assert_eq!(q.status, 200, "{}", q.text());
    let v = q.json();
    assert_eq!(v["using"]["map"], "building");
    assert_eq!(v["results"][0]["type"], "table");
    assert_eq!(v["results"][0]["rows"].as_array().unwrap().len(), 2);
    assert_eq!(v["results"][1]["type"], "routes");
    let j = s
        .post(
            "/query",
            &[("Content-Type", "application/json")],
            br#"{"query": "NEIGHBOURS OF 1;", "map": "building", "rev": 1}"#,
        )
        .await
        .json();
    assert_eq!(j["results"][0]["rows"].as_array().unwrap().len(), 6);
    s.post("/query", &[], b"FIND rooms WHERE")
        .await
        .assert_error(400, "query");
    s.post("/query?map=nope", &[], b"FIND rooms;")
        .await
        .assert_error(404, "map");
    s.post(
        "/query",
        &[("Content-Type", "application/json")],
        b"{\"q\": 1}",
    )
    .await
    .assert_error(400, "body");
    // NAME writes: a read-only server refuses the whole request with 403
    // (issue 21, defect 10: it answered 200 with an error inside), and
    // runs none of its statements.
    let named = s
        .post("/query", &[], b"FIND rooms; NAME 11 AS \"Lab\";")
        .await;
    assert_eq!(
        (named.status, named.json()["code"].as_str()),
        (403, Some("ReadOnly"))
    );
    assert_eq!(s.revision_count("building"), 1);

    let m = s.get("/metrics").await;
    assert_eq!(m.status, 200);
    let text = m.text();
    assert!(text.contains("nrgdb_http_requests_total{route=\"/maps/{map}/revisions/{rev}/indoorgml\",method=\"GET\",status=\"200\"} 1"), "{text}");
    assert!(
        text.contains("nrgdb_http_request_duration_seconds_bucket{route=\"/query\",le=\"+Inf\"}")
    );
    assert!(text.contains("nrgdb_cache_hits_total"));

    let none = s.get("/no/such/path").await;
    assert_eq!(none.status, 404);
    assert_eq!(none.json()["code"], "NoEndpoint");
    let wrong = s.post("/maps", &[], b"").await;
    assert_eq!(wrong.status, 405);
    assert_eq!(wrong.json()["code"], "MethodNotAllowed");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn cors_is_opt_in() {
    let s = TestServer::read_only().await;
    let r = super::server_client::request(
        s.addr,
        "GET",
        "/maps",
        &[("Origin", "http://viewer.example")],
        b"",
    )
    .await;
    assert!(r.header("access-control-allow-origin").is_none());
    s.stop().await;

    let s = TestServer::start(|c| c.cors_origins = vec!["http://viewer.example".into()]).await;
    let preflight = super::server_client::request(
        s.addr,
        "OPTIONS",
        "/maps/building/route",
        &[
            ("Origin", "http://viewer.example"),
            ("Access-Control-Request-Method", "GET"),
        ],
        b"",
    )
    .await;
    assert_eq!(
        preflight.header("access-control-allow-origin"),
        Some("http://viewer.example")
    );
    let other = super::server_client::request(
        s.addr,
        "GET",
        "/maps",
        &[("Origin", "http://elsewhere.example")],
        b"",
    )
    .await;
    assert_eq!(other.status, 200);
    assert!(other.header("access-control-allow-origin").is_none());
    s.stop().await;
}

/// Issue 21, defect 1: a 4 KB query of nested brackets (or NOTs) aborted
/// the whole server, read-only included. Now it is a 400 and the server
/// goes on answering.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn nested_query_does_not_crash_the_server() {
    let s = TestServer::read_only().await;
    let brackets = format!(
        "FIND rooms WHERE {}area > 1{};",
        "(".repeat(2_000),
        ")".repeat(2_000)
    );
    let nots = format!("FIND rooms WHERE {}area > 1;", "NOT ".repeat(5_000));
    for body in [brackets, nots] {
        let r = s.post("/query", &[], body.as_bytes()).await;
        r.assert_error(400, "query");
        assert!(r.text().contains("nest at most 64 deep"), "{}", r.text());
    }
    let h = s.get("/health").await;
    assert_eq!(h.status, 200);
    assert_eq!(h.json()["status"], "ok");
    s.stop().await;
}
