//! Issue #7: uploads. Token rules (403 read-only, 401 without the token),
//! size limit (413), malformed uploads store nothing, a new revision is
//! served by the next request, multipart map YAML + image is extracted.
//! Issue #19: an upload is read from memory, never written to a temporary
//! folder.

use std::io::{BufRead, BufReader};
use std::process::{Command, Stdio};

use super::server_client::{TOKEN, TestServer, request};

const AUTH: (&str, &str) = ("Authorization", "Bearer test-token-42");

/// A 12 m × 8 m floor (corridor and three rooms with doors) as a PGM at
/// 5 cm per pixel, with its map YAML.
fn floor_pgm() -> (String, Vec<u8>) {
    let res = 0.05;
    let (w, h) = (240u32, 160u32);
    let free = [
        (0.2, 1.0, 11.8, 3.0),
        (0.2, 3.2, 3.9, 7.2),
        (4.1, 3.2, 7.9, 7.2),
        (8.1, 3.2, 11.8, 7.2),
        (1.6, 2.9, 2.5, 3.3),
        (5.55, 2.9, 6.45, 3.3),
        (9.5, 2.9, 10.4, 3.3),
    ];
    let mut pgm = format!("P5\n{w} {h}\n255\n").into_bytes();
    for row in 0..h {
        for col in 0..w {
            let x = (f64::from(col) + 0.5) * res;
            let y = 8.0 - (f64::from(row) + 0.5) * res;
            let is_free = free
                .iter()
                .any(|&(x0, y0, x1, y1)| x >= x0 && x < x1 && y >= y0 && y < y1);
            pgm.push(if is_free { 254 } else { 0 });
        }
    }
    let yaml = "image: floor.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n".to_string();
    (yaml, pgm)
}

fn multipart(boundary: &str, parts: &[(&str, Option<&str>, &[u8])]) -> Vec<u8> {
    let mut body = Vec::new();
    for (name, filename, data) in parts {
        body.extend_from_slice(format!("--{boundary}\r\n").as_bytes());
        let disposition = match filename {
            Some(f) => {
                format!("Content-Disposition: form-data; name=\"{name}\"; filename=\"{f}\"\r\n")
            }
            None => format!("Content-Disposition: form-data; name=\"{name}\"\r\n"),
        };
        body.extend_from_slice(disposition.as_bytes());
        body.extend_from_slice(b"\r\n");
        body.extend_from_slice(data);
        body.extend_from_slice(b"\r\n");
    }
    body.extend_from_slice(format!("--{boundary}--\r\n").as_bytes());
    body
}

/// The fixture with one more room: a model JSON for revision 2.
fn bigger_model() -> String {
    nrgdb::fixtures::corridor_building(7).to_json()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn writes_need_a_token() {
    let ro = TestServer::read_only().await;
    let json = [("Content-Type", "application/json")];
    let r = ro
        .post("/maps/building/revisions", &json, bigger_model().as_bytes())
        .await;
    assert_eq!(
        (r.status, r.json()["code"].as_str()),
        (403, Some("ReadOnly"))
    );
    ro.stop().await;

    let s = TestServer::writable().await;
    let r = s
        .post("/maps/building/revisions", &json, bigger_model().as_bytes())
        .await;
    assert_eq!(r.status, 401);
    assert!(r.header("www-authenticate").unwrap().starts_with("Bearer"));
    let wrong = [
        ("Content-Type", "application/json"),
        ("Authorization", "Bearer nope"),
    ];
    assert_eq!(
        s.post(
            "/maps/building/revisions",
            &wrong,
            bigger_model().as_bytes()
        )
        .await
        .status,
        401
    );
    assert_eq!(s.revision_count("building"), 1);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn upload_is_visible_to_the_next_request() {
    let s = TestServer::writable().await;
    // Warm the cache on revision 1.
    let before = s.get("/maps/building/route?from=10&to=15").await.json();
    assert_eq!(before["revision"], 1);
    s.get("/maps/building/route?from=10&to=16")
        .await
        .assert_error(404, "to");
    let r = s
        .post(
            "/maps/building/revisions?message=one%20more%20room",
            &[("Content-Type", "application/json"), AUTH],
            bigger_model().as_bytes(),
        )
        .await;
    assert_eq!(r.status, 201, "{}", r.text());
    let rev = &r.json()["revision"];
    assert_eq!(rev["seq"], 2);
    assert_eq!(rev["message"], "one more room");
    assert_eq!(rev["spaces_added"], 2);
    assert_eq!(
        r.header("location"),
        Some("/maps/building/revisions/2/geojson")
    );
    let new_room = r.json()["ids"]["16"].as_u64().unwrap();
    assert_eq!(r.json()["ids"]["10"], 10, "kept spaces keep their ids");
    let after = s
        .get(&format!("/maps/building/route?from=10&to={new_room}"))
        .await
        .json();
    assert_eq!(after["revision"], 2);
    assert_eq!(after["code"], "Ok");
    // The old revision is still served as it was.
    s.get(&format!("/maps/building/route?from=10&to={new_room}&rev=1"))
        .await
        .assert_error(404, "to");

    // IndoorGML as a raw body, then as a multipart file.
    let gml = nrgdb::indoorgml::write_string(&nrgdb::indoorgml::from_nrg(
        &nrgdb::fixtures::corridor_building(5),
    ));
    let r = s
        .post(
            "/maps/other/revisions",
            &[("Content-Type", "application/xml"), AUTH],
            gml.as_bytes(),
        )
        .await;
    assert_eq!(r.status, 201, "{}", r.text());
    let gml6 = nrgdb::indoorgml::write_string(&nrgdb::indoorgml::from_nrg(
        &nrgdb::fixtures::corridor_building(6),
    ));
    let body = multipart(
        "b0undary",
        &[
            ("model", Some("floor.gml"), gml6.as_bytes()),
            ("message", None, b"again"),
        ],
    );
    let r = s
        .post(
            "/maps/other/revisions",
            &[
                ("Content-Type", "multipart/form-data; boundary=b0undary"),
                AUTH,
            ],
            &body,
        )
        .await;
    assert_eq!(r.status, 201, "{}", r.text());
    assert_eq!(r.json()["revision"]["message"], "again");
    assert_eq!(r.json()["revision"]["spaces_added"], 2);
    let r = s
        .post(
            "/maps/other/revisions",
            &[
                ("Content-Type", "multipart/form-data; boundary=b0undary"),
                AUTH,
            ],
            &body,
        )
        .await;
    // The same building again (issue 22): nothing changed, no revision.
    assert_eq!(r.status, 200, "{}", r.text());
    assert_eq!(r.json()["unchanged"], true);
    assert_eq!(r.json()["revision"]["seq"], 2);
    assert_eq!(r.json()["corrections"]["reapplied"], 0);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn malformed_uploads_store_nothing() {
    let s = TestServer::writable().await;
    let json = [("Content-Type", "application/json"), AUTH];
    let bad_json = s
        .post("/maps/building/revisions", &json, b"{\"spaces\": [")
        .await;
    assert_eq!(
        (bad_json.status, bad_json.json()["code"].as_str()),
        (400, Some("BadUpload"))
    );
    let gml = [("Content-Type", "application/xml"), AUTH];
    assert_eq!(
        s.post("/maps/building/revisions", &gml, b"<not-indoorgml/>")
            .await
            .status,
        400
    );
    let ct = [("Content-Type", "image/gif"), AUTH];
    assert_eq!(
        s.post("/maps/building/revisions", &ct, b"GIF89a")
            .await
            .status,
        400
    );
    let mp = [("Content-Type", "multipart/form-data; boundary=XYZ"), AUTH];
    let (yaml, _) = floor_pgm();
    let lonely_yaml = multipart("XYZ", &[("yaml", Some("floor.yaml"), yaml.as_bytes())]);
    assert_eq!(
        s.post("/maps/building/revisions", &mp, &lonely_yaml)
            .await
            .status,
        400
    );
    let broken_image = multipart(
        "XYZ",
        &[
            ("yaml", Some("floor.yaml"), yaml.as_bytes()),
            ("image", Some("floor.pgm"), b"P5\n999"),
        ],
    );
    assert_eq!(
        s.post("/maps/building/revisions", &mp, &broken_image)
            .await
            .status,
        400
    );
    assert_eq!(
        s.post("/maps/building/revisions", &mp, b"garbage")
            .await
            .status,
        400
    );
    assert_eq!(s.revision_count("building"), 1);
    let maps = s.get("/maps").await.json();
    assert_eq!(maps["maps"].as_array().unwrap().len(), 1, "{maps}");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn oversized_upload_is_413() {
    let s = TestServer::start(|c| {
        c.token = Some(TOKEN.into());
        c.max_upload_bytes = 64 * 1024;
    })
    .await;
    let big = vec![b' '; 200 * 1024];
    let r = s
        .post(
            "/maps/building/revisions",
            &[("Content-Type", "application/json"), AUTH],
            &big,
        )
        .await;
    assert_eq!(
        (r.status, r.json()["code"].as_str()),
        (413, Some("TooLarge"))
    );
    assert_eq!(s.revision_count("building"), 1);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn map_yaml_and_image_are_extracted() {
    let s = TestServer::writable().await;
    let (yaml, pgm) = floor_pgm();
    let body = multipart(
        "----nrgdb",
        &[
            ("yaml", Some("floor.yaml"), yaml.as_bytes()),
            ("image", Some("floor.pgm"), &pgm),
            ("author", None, b"robot 7"),
        ],
    );
    let r = s
        .post(
            "/maps/floor/revisions",
            &[
                ("Content-Type", "multipart/form-data; boundary=----nrgdb"),
                AUTH,
            ],
            &body,
        )
        .await;
    assert_eq!(r.status, 201, "{}", r.text());
    let rev = &r.json()["revision"];
    assert_eq!(rev["author"], "robot 7");
    assert_eq!(rev["source_name"], "floor.yaml + floor.pgm");
    assert!(rev["params"].is_object());
    let rooms = s.get("/maps/floor/spaces?kind=room").await.json();
    assert_eq!(rooms["spaces"].as_array().unwrap().len(), 3, "{rooms}");
    let doors = s.get("/maps/floor/spaces?kind=door").await.json();
    assert_eq!(doors["spaces"].as_array().unwrap().len(), 3);
    // Route between the outer rooms by point.
    let route = s.get("/maps/floor/route?from=1,5&to=11,5").await.json();
    assert_eq!(route["code"], "Ok", "{route}");
    assert_eq!(route["routes"][0]["doors"].as_array().unwrap().len(), 2);
    // The grid is kept with the revision: the SVG is drawn over it.
    let grid = nrgdb::store::Store::open(&s.db)
        .unwrap()
        .grid("floor", None)
        .unwrap();
    assert!(grid.is_some());
    let svg = s.get("/maps/floor/revisions/1/svg").await.text();
    assert_eq!(svg.matches("<image class=\"map\"").count(), 1);
    s.stop().await;
}

/// Issue 21, defect 10: NAME through /query without the token answered
/// 200 with an error inside; it is a 401 like every other write, with
/// the wrong token too, and nothing is written.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn name_query_without_token_is_401() {
    let s = TestServer::writable().await;
    for headers in [&[][..], &[("Authorization", "Bearer nope")][..]] {
        let r = s
            .post("/query?map=building", headers, b"NAME 11 AS \"Lab\";")
            .await;
        assert_eq!(r.status, 401, "{}", r.text());
        assert!(r.header("www-authenticate").unwrap().starts_with("Bearer"));
    }
    assert_eq!(s.revision_count("building"), 1);
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn name_query_with_token_writes_a_revision() {
    let s = TestServer::writable().await;
    let r = s
        .post(
            "/query?map=building",
            &[AUTH],
            b"NAME 11 AS \"Lab\"; FIND rooms WHERE name = \"Lab\";",
        )
        .await;
    let v = r.json();
    assert_eq!(v["results"][0]["type"], "message", "{v}");
    assert_eq!(v["results"][1]["rows"][0]["id"], 11);
    assert_eq!(s.revision_count("building"), 2);
    s.stop().await;
}

/// Issue 22: corrections go through `/query` with the token, write a
/// revision each and are kept; a refused one says why and writes nothing;
/// without the token nothing is written.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn corrections_through_query_need_the_token_and_are_kept() {
    let s = TestServer::writable().await;
    let r = s
        .post(
            "/query?map=building",
            &[],
            b"SET 11 ATTRIBUTE restricted = TRUE;",
        )
        .await;
    assert_eq!(r.status, 401, "{}", r.text());
    assert_eq!(s.revision_count("building"), 1);
    let r = s
        .post(
            "/query?map=building&author=ada",
            &[AUTH],
            b"SET 11 ATTRIBUTE restricted = TRUE; MERGE 11, 13; \
              ADD DOOR BETWEEN 10 AND 11 AT (4, 4); ADD DOOR BETWEEN 11 AND 12 AT (8, 4); \
              ROUTE FROM 10 TO 12; ROUTE FROM 10 TO 12 AVOID WHERE attr.restricted = TRUE;",
        )
        .await;
    let v = r.json();
    assert_eq!(v["results"][0]["type"], "message", "{v}");
    assert!(
        v["results"][0]["message"]
            .as_str()
            .unwrap()
            .contains("kept as correction 1"),
        "{v}"
    );
    assert_eq!(v["results"][1]["type"], "error", "{v}");
    assert!(
        v["results"][1]["message"]
            .as_str()
            .unwrap()
            .contains("do not touch"),
        "{v}"
    );
    // Through the new doors the way from 10 to 12 crosses room 11; once
    // it is restricted, AVOID WHERE keeps the route in the corridor.
    let through = |k: usize| {
        v["results"][k]["routes"][0]["spaces"]
            .as_array()
            .unwrap()
            .contains(&serde_json::json!(11))
    };
    assert!(through(4), "{v}");
    assert!(!through(5), "{v}");
    assert_eq!(s.revision_count("building"), 4);
    // The same over GET /route.
    let ids = |r: &super::server_client::Reply| -> Vec<u64> {
        r.json()["routes"][0]["spaces"]
            .as_array()
            .unwrap()
            .iter()
            .filter_map(|s| s["id"].as_u64())
            .collect()
    };
    let r = s
        .get("/maps/building/route?from=10&to=12&avoid_where=attr.restricted%20%3D%20TRUE")
        .await;
    assert_eq!(r.status, 200, "{}", r.text());
    let avoiding = ids(&r);
    assert!(
        avoiding.contains(&1) && !avoiding.contains(&11),
        "{avoiding:?}"
    );
    let direct = ids(&s.get("/maps/building/route?from=10&to=12").await);
    assert!(direct.contains(&11), "{direct:?}");
    let store = nrgdb::store::Store::open(&s.db).unwrap();
    let authors: Vec<String> = store
        .corrections("building")
        .unwrap()
        .into_iter()
        .map(|c| c.author)
        .collect();
    assert_eq!(authors, ["ada", "ada", "ada"]);
    assert_eq!(store.revision("building", None).unwrap().author, "ada");
    s.get("/maps/building/route?from=10&to=12&avoid_where=restricted%20%3D%3D")
        .await
        .assert_error(400, "avoid_where");
    s.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn shutdown_lets_in_flight_requests_finish() {
    use tokio::io::AsyncWriteExt;
    let mut s = TestServer::read_only().await;
    // A request whose body is still on its way when the signal comes.
    let mut stream = tokio::net::TcpStream::connect(s.addr).await.unwrap();
    let body = b"FIND rooms;";
    let head = format!(
        "POST /query HTTP/1.1\r\nHost: x\r\nConnection: close\r\nContent-Length: {}\r\n\r\n",
        body.len()
    );
    stream.write_all(head.as_bytes()).await.unwrap();
    stream.write_all(&body[..4]).await.unwrap();
    tokio::time::sleep(std::time::Duration::from_millis(100)).await;
    s.signal_stop();
    tokio::time::sleep(std::time::Duration::from_millis(100)).await;
    stream.write_all(&body[4..]).await.unwrap();
    let reply = super::server_client::read_reply(&mut stream).await;
    assert_eq!(reply.status, 200, "{}", reply.text());
    assert_eq!(
        reply.json()["results"][0]["rows"].as_array().unwrap().len(),
        6
    );
    s.join().await;
    // Nothing listens any more.
    assert!(
        tokio::net::TcpStream::connect(("127.0.0.1", 1))
            .await
            .is_err()
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn revision_written_by_another_process_is_served_next() {
    let s = TestServer::read_only().await;
    for _ in 0..3 {
        let r = s.get("/maps/building/spaces?kind=room").await.json();
        assert_eq!(r["revision"], 1);
    }
    // As `nrgdb import` would, from outside the server.
    let mut store = nrgdb::store::Store::open(&s.db).unwrap();
    store
        .import(
            "building",
            &nrgdb::fixtures::corridor_building(8),
            nrgdb::store::ImportMeta::new("cli", "test"),
        )
        .unwrap();
    let r = s.get("/maps/building/spaces?kind=room").await.json();
    assert_eq!(r["revision"], 2);
    assert_eq!(r["spaces"].as_array().unwrap().len(), 8);
    s.stop().await;
}

/// A child process killed when dropped, so a failing test leaves no
/// server behind.
struct Killed(std::process::Child);

impl Drop for Killed {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue_19_map_upload_leaves_no_temporary_files() {
    // The server's temporary folder does not exist: an upload written to
    // a temporary file (as before issue 19) fails; one read in memory not.
    let dir = tempfile::tempdir().unwrap();
    let tmp = dir.path().join("no-temp-dir");
    let db = dir.path().join("up.sqlite");
    let mut child = Killed(
        Command::new(env!("CARGO_BIN_EXE_nrgdb"))
            .args(["serve", "--addr", "127.0.0.1:0", "--token", TOKEN, "--db"])
            .arg(&db)
            .env("TMPDIR", &tmp)
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap(),
    );
    let mut line = String::new();
    BufReader::new(child.0.stdout.as_mut().unwrap())
        .read_line(&mut line)
        .unwrap();
    let url = line
        .split_whitespace()
        .find(|w| w.starts_with("http://"))
        .unwrap();
    let addr: std::net::SocketAddr = url.trim_start_matches("http://").parse().unwrap();
    let (yaml, pgm) = floor_pgm();
    let headers = [("Content-Type", "multipart/form-data; boundary=B"), AUTH];
    let broken = multipart(
        "B",
        &[
            ("yaml", Some("floor.yaml"), yaml.as_bytes()),
            ("image", Some("floor.pgm"), b"P5\n240 160\n255\n"),
        ],
    );
    let r = request(addr, "POST", "/maps/floor/revisions", &headers, &broken).await;
    assert_eq!(r.status, 400, "{}", r.text());
    let message = r.json()["message"].as_str().unwrap_or_default().to_string();
    assert!(
        message.contains("nothing stored: floor.pgm: cannot decode the image"),
        "{message}"
    );
    let body = multipart(
        "B",
        &[
            ("yaml", Some("floor.yaml"), yaml.as_bytes()),
            ("image", Some("floor.pgm"), &pgm),
        ],
    );
    let r = request(addr, "POST", "/maps/floor/revisions", &headers, &body).await;
    assert_eq!(r.status, 201, "{}", r.text());
    let killed = Command::new("kill")
        .args(["-TERM", &child.0.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    assert!(child.0.wait().unwrap().success());
    assert!(!tmp.exists(), "nothing may create the temporary folder");
    let left: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .flatten()
        .map(|e| e.file_name())
        .collect();
    assert!(
        left.iter()
            .all(|n| n.to_string_lossy().starts_with("up.sqlite")),
        "files left: {left:?}"
    );
    let store = nrgdb::store::Store::open(&db).unwrap();
    assert_eq!(store.revisions("floor").unwrap().len(), 1);
}
