//! Issue 23: errors keep their class. A fault of the storage (here a
//! damaged row in the database file) is the server's, not the client's:
//! every endpoint, `/query` included, answers 500 "Internal" with the
//! details in the server's log, not in the answer; a client mistake stays
//! a 4xx.

use super::server_client::TestServer;

/// Damages the stored outline of room 10 in the latest revision (its
/// geometry blob) behind the server's back.
fn damage_room_10(db: &std::path::Path) {
    let conn = rusqlite::Connection::open(db).unwrap();
    let n = conn
        .execute(
            "UPDATE spaces SET geometry = x'0102' WHERE space_id = 10 AND valid_to IS NULL",
            [],
        )
        .unwrap();
    assert_eq!(n, 1);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_damaged_database_is_a_500_everywhere_and_says_no_more() {
    let s = TestServer::read_only().await;
    damage_room_10(&s.db);
    for (method, path, body) in [
        ("POST", "/query?map=building", &b"FIND rooms;"[..]),
        (
            "POST",
            "/query",
            &b"SHOW MAPS; USE building; FIND rooms;"[..],
        ),
        ("GET", "/maps/building/route?from=10&to=12", &b""[..]),
        ("GET", "/maps/building/spaces", &b""[..]),
    ] {
        let r = if method == "POST" {
            s.post(path, &[], body).await
        } else {
            s.get(path).await
        };
        r.assert_error_code(500, "Internal");
        let text = r.text();
        assert!(
            !text.contains("damaged") && !text.contains("row"),
            "{path}: {text}"
        );
    }
    // A mistake of the client's is still its own: 4xx.
    let r = s.post("/query?map=nowhere", &[], b"FIND rooms;").await;
    assert_eq!(r.status, 404, "{}", r.text());
    let r = s
        .post("/query?map=building", &[], b"FIND rooms WHERE;")
        .await;
    assert_eq!(r.status, 400, "{}", r.text());
    s.stop().await;
}
