//! A building with levels over HTTP and in the viewer (issue 25): the
//! levels endpoint, `level` on the listing, point location and the SVG,
//! and the page's level switcher with a route that changes level, in
//! headless Chromium. Figures are checked against the fixture itself.

use std::time::Duration;

use nrgdb::model::Nrg;
use nrgdb::store::{ImportMeta, Store};

use crate::server_client::TestServer;

/// A server holding `tower`: three storeys of three rooms each.
async fn tower_server() -> (TestServer, Nrg) {
    let server = TestServer::read_only().await;
    let tower = nrgdb::fixtures::storeys(3, 3);
    Store::open(&server.db)
        .unwrap()
        .import("tower", &tower, ImportMeta::new("three storeys", "test"))
        .unwrap();
    (server, tower)
}

fn on_level(nrg: &Nrg, level: &str) -> Vec<u32> {
    nrg.spaces()
        .iter()
        .filter(|s| s.level.as_ref().is_some_and(|l| l.name == level))
        .map(|s| s.id.0)
        .collect()
}

/// The `data-space` ids of the spaces an SVG draws.
fn drawn_spaces(svg: &str) -> Vec<u32> {
    let mut ids: Vec<u32> = svg
        .split("class=\"space ")
        .skip(1)
        .filter_map(|rest| {
            let at = rest.split("data-space=\"").nth(1)?;
            at.split('"').next()?.parse().ok()
        })
        .collect();
    ids.sort_unstable();
    ids.dedup();
    ids
}

#[tokio::test]
async fn levels_over_http_list_locate_and_draw_one_floor_at_a_time() {
    let (server, tower) = tower_server().await;
    let body = server.get("/maps/tower/levels").await.json();
    let levels: Vec<(String, f64, usize)> = body["levels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| {
            (
                l["name"].as_str().unwrap().to_string(),
                l["elevation_m"].as_f64().unwrap(),
                l["spaces"].as_u64().unwrap() as usize,
            )
        })
        .collect();
    let want: Vec<(String, f64, usize)> = ["0", "1", "2"]
        .iter()
        .zip([0.0, 3.5, 7.0])
        .map(|(l, z)| (l.to_string(), z, on_level(&tower, l).len()))
        .collect();
    assert_eq!(levels, want);
    // A map without levels has none.
    let flat = server.get("/maps/building/levels").await.json();
    assert_eq!(flat["levels"].as_array().unwrap().len(), 0);
    // The listing by level.
    let listed = server.get("/maps/tower/spaces?level=2").await.json();
    let mut ids: Vec<u32> = listed["spaces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["id"].as_u64().unwrap() as u32)
        .collect();
    ids.sort_unstable();
    let mut want = on_level(&tower, "2");
    want.sort_unstable();
    assert_eq!(ids, want);
    server
        .get("/maps/tower/spaces?level=9")
        .await
        .assert_error(404, "level");
    server
        .get("/maps/building/spaces?level=0")
        .await
        .assert_error(400, "level");
    // A point inside room 11 on every floor: one space a level, lowest
    // first; on level 2 only, room 200 011.
    let [x, y] = tower.space(nrgdb::model::SpaceId(11)).unwrap().anchor;
    let found = server
        .get(&format!("/maps/tower/locate?x={x}&y={y}"))
        .await
        .json();
    let ids: Vec<u64> = found["spaces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["id"].as_u64().unwrap())
        .collect();
    assert_eq!(ids, [11, 100_011, 200_011]);
    let found = server
        .get(&format!("/maps/tower/locate?x={x}&y={y}&level=2"))
        .await
        .json();
    assert_eq!(found["space"]["id"], 200_011);
    assert_eq!(found["space"]["level"], "2");
    // The SVG of level 1 draws level 1's spaces only, and the part of a
    // route from level 0 to level 2 there: passing on the stairs.
    let svg = server
        .get("/maps/tower/revisions/1/svg?level=1&route=10,200012")
        .await;
    assert_eq!(svg.status, 200);
    let svg = svg.text();
    let mut want = on_level(&tower, "1");
    want.sort_unstable();
    assert_eq!(drawn_spaces(&svg), want);
    assert!(
        svg.contains("tower@1 level 1</text>"),
        "the title says the level"
    );
    assert!(svg.contains(">from level 0, up to level 2<"));
    assert!(!svg.contains("route-start") && !svg.contains("route-goal"));
    // Without a level: the lowest, with the route's start.
    let svg = server
        .get("/maps/tower/revisions/1/svg?route=10,200012")
        .await
        .text();
    let mut want = on_level(&tower, "0");
    want.sort_unstable();
    assert_eq!(drawn_spaces(&svg), want);
    assert!(svg.contains("route-start") && svg.contains(">up to level 1<"));
    server
        .get("/maps/tower/revisions/1/svg?level=M")
        .await
        .assert_error(404, "level");
    // A route between points on two levels (`x,y@L`): it starts and ends
    // at the points, at their levels' heights.
    let [bx, by] = tower.space(nrgdb::model::SpaceId(200_012)).unwrap().anchor;
    let body = server
        .get(&format!("/maps/tower/route?from={x},{y}@0&to={bx},{by}@2"))
        .await
        .json();
    assert_eq!(body["code"], "Ok", "{body}");
    let coords = body["routes"][0]["geometry"]["coordinates"]
        .as_array()
        .unwrap()
        .clone();
    let xyz = |c: &serde_json::Value| -> Vec<f64> {
        c.as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect()
    };
    let round = |v: f64| (v * 1000.0).round() / 1000.0;
    assert_eq!(xyz(&coords[0]), [round(x), round(y), 0.0]);
    assert_eq!(xyz(coords.last().unwrap()), [round(bx), round(by), 7.0]);
    assert_eq!(body["waypoints"][0]["space"], 11);
    assert_eq!(body["waypoints"][1]["space"], 200_012);
    // The route's ends are never avoided, a point's space included.
    let body = server
        .get(&format!(
            "/maps/tower/route?from={x},{y}@0&to=200012&avoid_where=kind%20%3D%20room"
        ))
        .await
        .json();
    assert_eq!(body["code"], "Ok", "{body}");
    // A point alone as a waypoint.
    let body = server
        .get(&format!(
            "/maps/tower/route?from=10&to=200012&via={x},{y}@1"
        ))
        .await
        .json();
    assert_eq!(body["code"], "Ok", "{body}");
    server
        .get(&format!("/maps/tower/route?from={x},{y}@9&to=10"))
        .await
        .assert_error(404, "from");
    server.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_viewer_switches_levels_and_follows_a_route_up_the_stairs() {
    let Some(chromium) = crate::viewer_e2e::chromium_or_skip() else {
        return;
    };
    let (server, _) = tower_server().await;
    let url = format!("http://{}/?map=tower&from=10&to=200012", server.addr);
    let chromium = chromium.to_string();
    let seen = tokio::task::spawn_blocking(move || {
        let mut b = crate::viewer_cdp::Browser::start(&chromium);
        b.call("Page.enable", serde_json::json!({}));
        b.call("Page.navigate", serde_json::json!({ "url": url }));
        let drawn = b.wait_for(
            "document.body && document.body.dataset.state === 'route-drawn'",
            Duration::from_secs(30),
        );
        assert!(drawn, "no route: {}", b.eval("document.body.outerHTML.slice(0, 3000)"));
        let text = |b: &mut crate::viewer_cdp::Browser, js: &str| -> String {
            b.eval(js).as_str().unwrap_or_default().to_string()
        };
        let switcher = b.eval("!document.getElementById('level-box').hidden");
        let options = text(&mut b, "[...document.querySelectorAll('#level option')].map(o => o.value).join(',')");
        let level0 = text(&mut b, "document.getElementById('level').value");
        let title0 = text(&mut b, "document.querySelector('#stage svg .title').textContent");
        let marks0 = text(&mut b, "[...document.querySelectorAll('#overlay .route-level-text')].map(t => t.textContent).join('|')");
        let start0 = b.eval("!!document.querySelector('#overlay .route-start')");
        let buttons = text(&mut b, "[...document.querySelectorAll('#route-levels button')].map(x => x.textContent).join(',')");
        let view0 = text(&mut b, "document.querySelector('#stage svg').getAttribute('viewBox')");
        // Click the mark: the page shows level 1, where the route passes
        // on the stairs; the view box stays.
        let at = b.eval(
            "(() => { const r = document.querySelector('#overlay .route-level circle').getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2]; })()",
        );
        b.click(at[0].as_f64().unwrap(), at[1].as_f64().unwrap());
        let moved = b.wait_for(
            "document.querySelector('#stage svg .title') && document.querySelector('#stage svg .title').textContent.endsWith('level 1')",
            Duration::from_secs(10),
        );
        let level1 = text(&mut b, "document.getElementById('level').value");
        let marks1 = text(&mut b, "[...document.querySelectorAll('#overlay .route-level-text')].map(t => t.textContent).join('|')");
        let view1 = text(&mut b, "document.querySelector('#stage svg').getAttribute('viewBox')");
        let address = text(&mut b, "location.search");
        // The level select: level 2 has the goal.
        b.eval("(() => { const s = document.getElementById('level'); s.value = '2'; s.dispatchEvent(new Event('change')); })()");
        let goal = b.wait_for("!!document.querySelector('#overlay .route-goal')", Duration::from_secs(10));
        let marks2 = text(&mut b, "[...document.querySelectorAll('#overlay .route-level-text')].map(t => t.textContent).join('|')");
        (switcher, options, level0, title0, marks0, start0, buttons, view0, moved, level1, marks1, view1, address, goal, marks2)
    })
    .await
    .unwrap();
    let (
        switcher,
        options,
        level0,
        title0,
        marks0,
        start0,
        buttons,
        view0,
        moved,
        level1,
        marks1,
        view1,
        address,
        goal,
        marks2,
    ) = seen;
    assert_eq!(switcher, true);
    assert_eq!(options, "0,1,2");
    assert_eq!(level0, "0", "a route starts on its first level");
    assert!(title0.ends_with("level 0"), "{title0}");
    assert_eq!(marks0, "up to level 1");
    assert_eq!(start0, true);
    assert_eq!(buttons, "0,1,2");
    assert!(moved, "clicking the mark did not show level 1");
    assert_eq!(level1, "1");
    assert_eq!(marks1, "from level 0, up to level 2");
    assert_eq!(view0, view1, "switching levels keeps the view");
    assert!(address.contains("level=1"), "{address}");
    assert!(goal, "no goal on level 2");
    assert_eq!(marks2, "from level 1");
    server.stop().await;
}
