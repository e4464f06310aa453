//! The web viewer end to end: the server in-process on an ephemeral port,
//! headless Chromium loading `/?map=building&from=10&to=12`, which makes
//! the page fetch the SVG and the route and draw it; the DOM Chromium
//! dumps must hold the route polyline. Skips with a notice when Chromium
//! is missing (scripts/install-test-tools.sh installs it), unless
//! NRGDB_REQUIRE_SHARED=1.

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::server_client::TestServer;

const CHROMIUM: &str = "/usr/bin/chromium";

pub fn chromium_or_skip() -> Option<&'static str> {
    if Path::new(CHROMIUM).exists() {
        return Some(CHROMIUM);
    }
    if std::env::var("NRGDB_REQUIRE_SHARED").as_deref() == Ok("1") {
        panic!(
            "NRGDB_REQUIRE_SHARED=1 but {CHROMIUM} is missing (run scripts/install-test-tools.sh)"
        );
    }
    eprintln!(
        "notice: skipping the viewer test, {CHROMIUM} not found (run scripts/install-test-tools.sh)"
    );
    None
}

/// Runs headless Chromium on `url` and returns the DOM it dumps after the
/// page's requests settle (virtual time budget), killing it after 90 s.
fn dump_dom(chromium: &str, url: &str) -> String {
    let profile = tempfile::tempdir().unwrap();
    let mut child = Command::new(chromium)
        .args(crate::support::HEADLESS_CHROMIUM)
        .args(["--virtual-time-budget=15000", "--window-size=1200,900"])
        .arg(format!("--user-data-dir={}", profile.path().display()))
        .arg("--dump-dom")
        .arg(url)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let started = Instant::now();
    loop {
        if child.try_wait().unwrap().is_some() {
            break;
        }
        if started.elapsed() > Duration::from_secs(90) {
            let _ = child.kill();
            break;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    let out = child.wait_with_output().unwrap();
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The `points` of the element with id `route`, as pairs.
fn route_points(dom: &str) -> Vec<[f64; 2]> {
    let Some(at) = dom.find("id=\"route\"") else {
        return Vec::new();
    };
    let start = dom[..at].rfind('<').unwrap_or(0);
    let end = at + dom[at..].find('>').unwrap_or(0);
    let element = &dom[start..end];
    let Some(points) = element
        .split("points=\"")
        .nth(1)
        .and_then(|p| p.split('"').next())
    else {
        return Vec::new();
    };
    points
        .split_whitespace()
        .filter_map(|xy| {
            let (x, y) = xy.split_once(',')?;
            Some([x.parse().ok()?, y.parse().ok()?])
        })
        .collect()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn viewer_draws_a_requested_route_in_headless_chromium() {
    let Some(chromium) = chromium_or_skip() else {
        return;
    };
    let server = TestServer::read_only().await;
    // The page itself and the SVG it loads.
    let page = server.get("/").await;
    assert_eq!(page.status, 200);
    let svg = server
        .get("/maps/building/revisions/1/svg?route=10,12")
        .await;
    assert_eq!(svg.status, 200);
    let url = format!("http://{}/?map=building&from=10&to=12", server.addr);
    let dom = tokio::task::spawn_blocking({
        let chromium = chromium.to_string();
        move || dump_dom(&chromium, &url)
    })
    .await
    .unwrap();
    assert!(
        dom.contains("data-state=\"route-drawn\""),
        "the page did not draw the route:\n{}",
        &dom[..dom.len().min(3000)]
    );
    let points = route_points(&dom);
    // Room 10 → its door → corridor → door of room 12 → room 12, walked:
    // the line bends around the doorways, so it has more than its two ends.
    assert!(points.len() >= 4, "{points:?}");
    // The first point is room 10's anchor (2, 4.6) in the page's SVG pixels:
    // it sits on room 10's node, which the server drew.
    let node = dom
        .split("class=\"node\" data-space=\"10\"")
        .nth(1)
        .and_then(|rest| rest.split("/>").next())
        .unwrap_or_default()
        .to_string();
    let attr = |n: &str| -> f64 {
        node.split(&format!("{n}=\""))
            .nth(1)
            .and_then(|v| v.split('"').next())
            .and_then(|v| v.parse().ok())
            .unwrap_or(f64::NAN)
    };
    assert!(
        (points[0][0] - attr("cx")).abs() < 0.01 && (points[0][1] - attr("cy")).abs() < 0.01,
        "{points:?} vs {node}"
    );
    // The side panel shows the route's length and steps.
    assert!(dom.contains("From 10 to 12:"), "no route summary");
    // Two revisions compared: the page shows the diff the server drew.
    nrgdb::store::Store::open(&server.db)
        .unwrap()
        .import(
            "building",
            &nrgdb::fixtures::corridor_building(7),
            nrgdb::store::ImportMeta::new("one more room", "test"),
        )
        .unwrap();
    let url = format!("http://{}/?map=building&rev=2&diff=1", server.addr);
    let dom = tokio::task::spawn_blocking({
        let chromium = chromium.to_string();
        move || dump_dom(&chromium, &url)
    })
    .await
    .unwrap();
    assert!(
        dom.contains("data-state=\"ready\""),
        "{}",
        &dom[..dom.len().min(3000)]
    );
    assert_eq!(dom.matches("class=\"diff added\"").count(), 2);
    server.stop().await;
}

/// The page's client coordinates of the centre of a space's polygon.
fn centre_of(browser: &mut crate::viewer_cdp::Browser, id: u32) -> (f64, f64) {
    let v = browser.eval(&format!(
        "(() => {{ const r = document.querySelector('#stage .space[data-space=\"{id}\"]').getBoundingClientRect(); \
         return [r.left + r.width / 2, r.top + r.height / 2]; }})()"
    ));
    (v[0].as_f64().unwrap(), v[1].as_f64().unwrap())
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn viewer_clicks_show_details_then_a_route() {
    let Some(chromium) = chromium_or_skip() else {
        return;
    };
    let server = TestServer::read_only().await;
    let url = format!("http://{}/?map=building", server.addr);
    let chromium = chromium.to_string();
    let outcome = tokio::task::spawn_blocking(move || {
        let mut b = crate::viewer_cdp::Browser::start(&chromium);
        b.call("Page.enable", serde_json::json!({}));
        b.call("Page.navigate", serde_json::json!({ "url": url }));
        let ready = b.wait_for("document.body && document.body.dataset.state === 'ready'", Duration::from_secs(30));
        assert!(ready, "the page never became ready: {}", b.eval("document.body.outerHTML.slice(0, 2000)"));
        // Zoom out with the wheel, then pan by dragging: the view box changes,
        // and a drag is not a click (no space picked).
        let view = |b: &mut crate::viewer_cdp::Browser| -> Vec<f64> {
            b.eval("document.querySelector('#stage svg').getAttribute('viewBox')")
                .as_str()
                .unwrap_or("")
                .split(' ')
                .filter_map(|v| v.parse().ok())
                .collect()
        };
        let home = view(&mut b);
        let (x, y) = centre_of(&mut b, 1);
        b.wheel(x, y, 200.0);
        let zoomed = view(&mut b);
        assert!(zoomed[2] > home[2] * 1.1, "wheel did not zoom out: {home:?} → {zoomed:?}");
        b.drag((x, y), (x + 40.0, y + 20.0));
        let panned = view(&mut b);
        assert!(panned[0] < zoomed[0] && panned[1] < zoomed[1], "drag did not pan: {zoomed:?} → {panned:?}");
        assert_eq!(panned[2], zoomed[2]);
        assert!(b.eval("document.getElementById('details').textContent") == "Click a space.");
        // Click room 10: its details appear.
        let (x, y) = centre_of(&mut b, 10);
        b.click(x, y);
        let shown = b.wait_for("document.getElementById('details').textContent.includes('Office 1')", Duration::from_secs(10));
        let details = b.eval("document.getElementById('details').textContent");
        // Then room 12: the route is drawn.
        let (x, y) = centre_of(&mut b, 12);
        b.click(x, y);
        let drawn = b.wait_for("document.body.dataset.state === 'route-drawn'", Duration::from_secs(10));
        let points = b.eval("document.getElementById('route') && document.getElementById('route').getAttribute('points')");
        let summary = b.eval("document.getElementById('route-info').textContent");
        (shown, details, drawn, points, summary)
    })
    .await
    .unwrap();
    let (shown, details, drawn, points, summary) = outcome;
    assert!(shown, "no details after clicking room 10: {details}");
    assert!(drawn, "no route after clicking rooms 10 and 12: {summary}");
    assert!(
        points.as_str().unwrap_or("").split(' ').count() >= 4,
        "{points}"
    );
    assert!(
        summary.as_str().unwrap_or("").starts_with("From 10 to 12:"),
        "{summary}"
    );
    server.stop().await;
}

#[tokio::test]
async fn viewer_svg_endpoint_draws_routes_and_diffs_and_names_bad_parameters() {
    let server = TestServer::read_only().await;
    // A second revision with one more room (and its door).
    nrgdb::store::Store::open(&server.db)
        .unwrap()
        .import(
            "building",
            &nrgdb::fixtures::corridor_building(7),
            nrgdb::store::ImportMeta::new("one more room", "test"),
        )
        .unwrap();
    let page = server.get("/").await;
    assert_eq!(
        page.header("content-type"),
        Some("text/html; charset=utf-8")
    );
    assert!(page.text().contains("<title>nrgdb viewer</title>"));
    let plain = server.get("/maps/building/revisions/1/svg").await;
    assert_eq!(plain.status, 200);
    assert_eq!(plain.header("content-type"), Some("image/svg+xml"));
    let text = plain.text();
    assert!(text.starts_with("<svg") && text.contains("data-px-per-m="));
    assert_eq!(text.matches("<path class=\"space ").count(), 13); // corridor + 6 rooms + 6 doors
    assert!(!text.contains("id=\"route\""));
    let routed = server
        .get("/maps/building/revisions/1/svg?route=Office%201,12")
        .await;
    assert_eq!(routed.status, 200, "{}", routed.text());
    assert_eq!(routed.text().matches("id=\"route\"").count(), 1);
    let diff = server
        .get("/maps/building/revisions/latest/svg?diff=1")
        .await;
    assert_eq!(diff.status, 200, "{}", diff.text());
    assert_eq!(
        diff.text().matches("class=\"diff added\"").count(),
        2,
        "{}",
        diff.text()
    );
    assert_eq!(diff.text().matches("class=\"diff changed\"").count(), 1);
    server
        .get("/maps/building/revisions/1/svg?route=10")
        .await
        .assert_error(400, "route");
    server
        .get("/maps/building/revisions/1/svg?route=10,999")
        .await
        .assert_error(404, "route");
    server
        .get("/maps/building/revisions/1/svg?diff=x")
        .await
        .assert_error(400, "diff");
    server
        .get("/maps/building/revisions/1/svg?colour=red")
        .await
        .assert_error(400, "colour");
    assert_eq!(server.get("/maps/nope/revisions/1/svg").await.status, 404);
    assert_eq!(
        server
            .get("/maps/building/revisions/1/svg?diff=9")
            .await
            .status,
        404
    );
    // A revision extracted from an occupancy grid is drawn over it, unless
    // map=false; one imported from a model file has no map to draw.
    let grid = nrgdb::grid::OccupancyGrid::from_ascii(
        &["#".repeat(30), format!("#{}#", ".".repeat(28))]
            .into_iter()
            .chain(std::iter::repeat_n(format!("#{}#", ".".repeat(28)), 18))
            .chain(["#".repeat(30)])
            .collect::<Vec<_>>()
            .join("\n"),
        0.1,
    );
    let x = nrgdb::extract::extract(&grid, &nrgdb::extract::ExtractParams::default()).unwrap();
    nrgdb::store::Store::open(&server.db)
        .unwrap()
        .import_with_grid(
            "floor",
            &x.nrg,
            nrgdb::store::ImportMeta::new("scan", "test"),
            Some(&grid),
        )
        .unwrap();
    let with_map = server.get("/maps/floor/revisions/1/svg").await;
    assert_eq!(with_map.status, 200, "{}", with_map.text());
    assert_eq!(with_map.text().matches("<image class=\"map\"").count(), 1);
    let without = server.get("/maps/floor/revisions/1/svg?map=false").await;
    assert_eq!(without.text().matches("<image class=\"map\"").count(), 0);
    assert!(!plain.text().contains("<image class=\"map\""));
    server
        .get("/maps/floor/revisions/1/svg?map=perhaps")
        .await
        .assert_error(400, "map");
    server.stop().await;
}

/// Issue 21: `/?map=nosuch&rev=99` showed the first map without a word.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn issue_21_paper_cut_viewer_says_the_map_or_revision_does_not_exist() {
    let Some(chromium) = chromium_or_skip() else {
        return;
    };
    let server = TestServer::read_only().await;
    for (query, says) in [
        (
            "map=buildng&rev=99",
            "no map named 'buildng'; did you mean 'building'?",
        ),
        (
            "map=building&rev=99",
            "revision 99 of map 'building' does not exist",
        ),
    ] {
        let url = format!("http://{}/?{query}", server.addr);
        let dom = tokio::task::spawn_blocking({
            let chromium = chromium.to_string();
            move || dump_dom(&chromium, &url)
        })
        .await
        .unwrap();
        let head = &dom[..dom.len().min(3000)];
        assert!(dom.contains("data-state=\"not-found\""), "{query}: {head}");
        assert!(dom.contains(says), "{query}: {head}");
        assert!(!dom.contains("class=\"space"), "{query}: drew a map anyway");
    }
    server.stop().await;
}

/// The client coordinates of the map point `p` (metres) in the page.
fn client_of(browser: &mut crate::viewer_cdp::Browser, p: [f64; 2]) -> (f64, f64) {
    let v = browser.eval(&format!(
        "(() => {{ const q = state.toPx([{}, {}]); const pt = state.svg.createSVGPoint(); \
         pt.x = q[0]; pt.y = q[1]; const c = pt.matrixTransform(state.svg.getScreenCTM()); return [c.x, c.y]; }})()",
        p[0], p[1]
    ));
    (v[0].as_f64().unwrap(), v[1].as_f64().unwrap())
}

/// Issue 22: the viewer's edit mode. With the token given once: pick two
/// rooms and click the wall between them (a door), merge them, see a
/// refused merge say why, undo the last edit, and split the corridor by two
/// clicks; each edit is a revision and the picture follows.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn viewer_edits_add_a_door_merge_refuse_and_undo() {
    let Some(chromium) = chromium_or_skip() else {
        return;
    };
    let server = TestServer::writable().await;
    let url = format!("http://{}/?map=building", server.addr);
    let chromium = chromium.to_string();
    let outcome = tokio::task::spawn_blocking(move || {
        let mut b = crate::viewer_cdp::Browser::start(&chromium);
        b.call("Page.enable", serde_json::json!({}));
        b.call("Page.navigate", serde_json::json!({ "url": url }));
        let secs = Duration::from_secs(20);
        assert!(b.wait_for("document.body && document.body.dataset.state === 'ready'", secs));
        b.eval(&format!("document.getElementById('token').value = '{}'", crate::server_client::TOKEN));
        let pick_two = |b: &mut crate::viewer_cdp::Browser, x: u32, y: u32| {
            let (cx, cy) = centre_of(b, x);
            b.click(cx, cy);
            let (cx, cy) = centre_of(b, y);
            b.click(cx, cy);
            assert!(b.wait_for("document.body.dataset.state === 'route-drawn' || document.body.dataset.state === 'no-route'", secs));
        };
        let button = |b: &mut crate::viewer_cdp::Browser, id: &str| {
            b.eval(&format!("document.getElementById('{id}').click()"));
        };
        let info = |b: &mut crate::viewer_cdp::Browser| b.eval("document.getElementById('edit-info').textContent").as_str().unwrap_or("").to_string();
        let mut seen = Vec::new();
        // A door through the wall at x = 4 between rooms 10 and 11.
        pick_two(&mut b, 10, 11);
        button(&mut b, "ed-door");
        let (x, y) = client_of(&mut b, [4.0, 4.0]);
        b.click(x, y);
        assert!(b.wait_for("document.body.dataset.state === 'edited'", secs), "{}", info(&mut b));
        seen.push((info(&mut b), b.eval("document.getElementById('rev').value").as_str().unwrap_or("").to_string()));
        // Merge them.
        pick_two(&mut b, 10, 11);
        button(&mut b, "ed-merge");
        assert!(b.wait_for("document.body.dataset.state === 'edited'", secs), "{}", info(&mut b));
        let spaces_after_merge = b.eval("document.querySelectorAll('#stage .space[data-space=\"11\"]').length");
        seen.push((info(&mut b), b.eval("document.getElementById('rev').value").as_str().unwrap_or("").to_string()));
        // Rooms 12 and 14 do not touch: refused, with the reason.
        pick_two(&mut b, 12, 14);
        button(&mut b, "ed-merge");
        assert!(b.wait_for("document.body.dataset.state === 'edit-refused'", secs));
        seen.push((info(&mut b), String::new()));
        // Undo the merge.
        button(&mut b, "ed-undo");
        assert!(b.wait_for("document.body.dataset.state === 'edited'", secs), "{}", info(&mut b));
        seen.push((info(&mut b), b.eval("document.getElementById('rev').value").as_str().unwrap_or("").to_string()));
        // Split the corridor by two clicks across it at x = 5 (drawn short
        // of its walls, as a hand does).
        let (cx, cy) = centre_of(&mut b, 1);
        b.click(cx, cy);
        assert!(b.wait_for("document.getElementById('details').textContent.includes('Main corridor')", secs));
        button(&mut b, "ed-split");
        for p in [[5.0, 0.3], [5.0, 1.7]] {
            let (x, y) = client_of(&mut b, p);
            b.click(x, y);
        }
        assert!(b.wait_for("document.body.dataset.state === 'edited'", secs), "{}", info(&mut b));
        seen.push((info(&mut b), b.eval("document.getElementById('rev').value").as_str().unwrap_or("").to_string()));
        (seen, spaces_after_merge)
    })
    .await
    .unwrap();
    let (seen, spaces_after_merge) = outcome;
    assert!(
        seen[0].0.contains("door between Office 1 and room 11"),
        "{seen:?}"
    );
    assert_eq!(seen[0].1, "2");
    assert!(
        seen[1].0.contains("merge of Office 1 and room 11"),
        "{seen:?}"
    );
    assert_eq!(seen[1].1, "3");
    assert_eq!(spaces_after_merge, 0, "room 11 still drawn after the merge");
    assert!(seen[2].0.contains("do not touch"), "{seen:?}");
    assert!(seen[3].0.contains("Undid correction 2"), "{seen:?}");
    assert_eq!(seen[3].1, "4");
    assert!(seen[4].0.contains("split of Main corridor"), "{seen:?}");
    assert_eq!(seen[4].1, "5");
    // Independent of the page: the store holds the revisions, the undo
    // restored revision 2's model, correction 2 is dropped, and the split
    // left two corridors where there was one, the smaller about 10 m² (the
    // corridor runs from x = 0 to 15 and is 2 m wide; the cut is at x = 5).
    let store = nrgdb::store::Store::open(&server.db).unwrap();
    assert_eq!(store.revisions("building").unwrap().len(), 5);
    assert_eq!(
        store.load("building", Some(4)).unwrap(),
        store.load("building", Some(2)).unwrap()
    );
    let corrections = store.corrections("building").unwrap();
    assert_eq!(corrections.len(), 3);
    assert_eq!(corrections[1].state, nrgdb::store::CorrectionState::Dropped);
    assert_eq!(corrections[2].state, nrgdb::store::CorrectionState::Applied);
    let before = store.load("building", Some(4)).unwrap();
    let after = store.load("building", Some(5)).unwrap();
    let corridors = |nrg: &nrgdb::model::Nrg| -> Vec<f64> {
        let mut areas: Vec<f64> = nrg
            .spaces()
            .iter()
            .filter(|s| s.kind == nrgdb::model::SpaceKind::Corridor)
            .map(|s| s.area_m2)
            .collect();
        areas.sort_by(f64::total_cmp);
        areas
    };
    assert_eq!(corridors(&before).len(), 1);
    let split = corridors(&after);
    assert_eq!(split.len(), 2, "{split:?}");
    assert!((split[0] - 10.0).abs() < 0.15, "{split:?}");
    assert!(
        (split[0] + split[1] - corridors(&before)[0]).abs() < 0.05,
        "{split:?}"
    );
    server.stop().await;
}
