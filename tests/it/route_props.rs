//! Property tests of ROUTE on random buildings with known geometry: a
//! corridor split into open segments, rooms on both sides with doors at
//! random places and widths, some with furniture, some joined to their
//! neighbour by a door. Routes stay inside the spaces they pass, honour
//! VIA and AVOID, and alternatives are sorted and distinct by their doors.

use std::collections::BTreeSet;
use std::sync::Arc;

use nrgdb::model::{Point, SpaceId};
use nrgdb::route::{Budget, Endpoint, NavMesh, Profile, RouteRequest, shortest_route};
use proptest::prelude::*;

use crate::route_building::{Building, building, inside_any, outside_samples};

fn nav(b: &Building) -> NavMesh {
    NavMesh::new(Arc::new(b.nrg.clone()))
}

fn exact(from: SpaceId, to: SpaceId) -> RouteRequest {
    let mut r = RouteRequest::new(from, to);
    r.profile = Profile::exact();
    r
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// The walked length at zero clearance is the free-space geodesic: an
    /// independent raster search (`eval::free_space_geodesic`, 2.5 cm
    /// cells, any-angle moves) over the union of the spaces agrees within 2 %.
    #[test]
    fn route_length_is_the_geodesic(b in building(), i in 0usize..64, j in 0usize..64) {
        let nav = nav(&b);
        let n = b.rooms.len();
        let (a, c) = (b.rooms[i % n], b.rooms[j % n]);
        prop_assume!(a != c);
        let r = shortest_route(&nav, &exact(a, c), &Budget::unlimited()).unwrap();
        let anchor = |id: SpaceId| b.nrg.space(id).unwrap().anchor;
        let geodesic = nrgdb::eval::free_space_geodesic(&b.nrg, anchor(a), anchor(c), 0.025).unwrap();
        let ratio = r[0].length_m / geodesic;
        prop_assert!((0.98..=1.02).contains(&ratio), "walked {} m, geodesic {} m", r[0].length_m, geodesic);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn routes_stay_inside_their_spaces(b in building(), i in 0usize..64, j in 0usize..64) {
        let nav = nav(&b);
        let (a, c) = (b.rooms[i % b.rooms.len()], b.rooms[j % b.rooms.len()]);
        let routes = shortest_route(&nav, &exact(a, c), &Budget::unlimited()).unwrap();
        prop_assert_eq!(routes.len(), 1, "every room of a generated building is reachable");
        let r = &routes[0];
        prop_assert_eq!(r.spaces.first(), Some(&a));
        prop_assert_eq!(r.spaces.last(), Some(&c));
        let walked: f64 = r.waypoints.windows(2).map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1])).sum();
        prop_assert!((walked - r.length_m).abs() < 1e-9);
        prop_assert_eq!(outside_samples(&b.nrg, &r.waypoints, 0.02), 0);
        let anchors = |id: SpaceId| b.nrg.space(id).unwrap().anchor;
        let (p, q): (Point, Point) = (anchors(a), anchors(c));
        prop_assert!(r.length_m + 1e-9 >= (p[0] - q[0]).hypot(p[1] - q[1]));
    }

    #[test]
    fn points_route_from_themselves(b in building(), i in 0usize..64, fx in 0.2f64..0.8, fy in 0.2f64..0.8) {
        let nav = nav(&b);
        let room = b.nrg.space(b.rooms[i % b.rooms.len()]).unwrap();
        let (lo, hi) = bounds(&room.polygon);
        let p = [lo[0] + fx * (hi[0] - lo[0]), lo[1] + fy * (hi[1] - lo[1])];
        prop_assume!(inside_any(&b.nrg, p));
        let mut req = RouteRequest::between(Endpoint::Point(p), Endpoint::Space(b.rooms[0]));
        req.profile = Profile::exact();
        let r = shortest_route(&nav, &req, &Budget::unlimited()).unwrap();
        prop_assert_eq!(r[0].waypoints[0], p);
        prop_assert_eq!(outside_samples(&b.nrg, &r[0].waypoints, 0.02), 0);
    }

    #[test]
    fn via_and_avoid_are_honoured(b in building(), i in 0usize..64, j in 0usize..64, k in 0usize..64) {
        let nav = nav(&b);
        let n = b.rooms.len();
        let (a, c, v) = (b.rooms[i % n], b.rooms[j % n], b.rooms[k % n]);
        let direct = shortest_route(&nav, &exact(a, c), &Budget::unlimited()).unwrap();
        let mut via = exact(a, c);
        via.via = vec![Endpoint::Space(v)];
        let routes = shortest_route(&nav, &via, &Budget::unlimited()).unwrap();
        prop_assert!(routes[0].spaces.contains(&v));
        prop_assert!(routes[0].length_m >= 0.99 * direct[0].length_m);
        let legs: f64 = routes[0].leg_lengths_m.iter().sum();
        prop_assert!((legs - routes[0].length_m).abs() < 1e-6);
        // Avoiding a door of the direct route: never through it.
        if let Some(d) = direct[0].doors.first() {
            let mut avoid = exact(a, c);
            avoid.avoid = vec![*d];
            let got = shortest_route(&nav, &avoid, &Budget::unlimited()).unwrap();
            if let Some(r) = got.first() {
                prop_assert!(!r.spaces.contains(d));
                // The search chooses door sequences by their lengths through
                // three crossing points of each doorway (its two ends and
                // its middle); the straightened walk may then be a little
                // shorter on another sequence (worst seen: none shorter in
                // 648 avoiding routes); it must never lose more than 1 %.
                prop_assert!(r.length_m >= 0.99 * direct[0].length_m);
            }
        }
        let mut bad = exact(a, c);
        bad.avoid = vec![a];
        prop_assert!(shortest_route(&nav, &bad, &Budget::unlimited()).is_err());
    }

    #[test]
    fn alternatives_are_distinct_and_sorted(b in building(), i in 0usize..64, j in 0usize..64, k in 1usize..5) {
        let nav = nav(&b);
        let n = b.rooms.len();
        let (a, c) = (b.rooms[i % n], b.rooms[j % n]);
        let mut req = exact(a, c);
        req.alternatives = k;
        let routes = shortest_route(&nav, &req, &Budget::unlimited()).unwrap();
        prop_assert!(!routes.is_empty() && routes.len() <= k);
        let best = shortest_route(&nav, &exact(a, c), &Budget::unlimited()).unwrap();
        // The first is the plain shortest route, or one a little shorter
        // that the door-distinct search found.
        prop_assert!(routes[0].length_m <= best[0].length_m + 1e-9);
        prop_assert!(routes[0].length_m >= 0.99 * best[0].length_m);
        for w in routes.windows(2) {
            prop_assert!(w[0].length_m <= w[1].length_m + 1e-9);
        }
        let distinct: BTreeSet<_> = routes.iter().map(|r| r.doors.clone()).collect();
        prop_assert_eq!(distinct.len(), routes.len());
    }
}

fn bounds(ring: &[Point]) -> (Point, Point) {
    let mut lo = [f64::MAX; 2];
    let mut hi = [f64::MIN; 2];
    for p in ring {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (lo, hi)
}

/// Issue 18: neighbouring rooms on one corridor are a few metres apart on
/// foot, not the sum of anchor-to-anchor hops. Office 1 (anchor (2, 4.6))
/// and room 11 (anchor (6, 4.6)) open through 1 m doors at x 1.5–2.5 and
/// 5.5–6.5 onto the corridor's wall at y = 2: at zero clearance the walk
/// bends at the doorway corners (2.5, 2) and (5.5, 2).
#[test]
fn neighbouring_rooms_are_a_few_metres_apart() {
    let nrg = nrgdb::fixtures::corridor_building(6);
    let nav = NavMesh::new(Arc::new(nrg));
    let r = shortest_route(&nav, &exact(SpaceId(10), SpaceId(11)), &Budget::unlimited()).unwrap();
    let expected = 2.0 * 0.5f64.hypot(2.6) + 3.0;
    assert!((r[0].length_m - expected).abs() < 1e-9, "{}", r[0].length_m);
    assert_eq!(
        r[0].waypoints,
        vec![[2.0, 4.6], [2.5, 2.0], [5.5, 2.0], [6.0, 4.6]]
    );
    // With a person's clearance it is a little longer, still a few metres.
    let walked = shortest_route(
        &nav,
        &RouteRequest::new(SpaceId(10), SpaceId(11)),
        &Budget::unlimited(),
    )
    .unwrap();
    assert!(walked[0].length_m > expected && walked[0].length_m < expected + 1.0);
}

/// A hall with hundreds of doors (one corridor space, 400 door gates) gets
/// approximate in-space tables instead of 1 200² funnels, so its first
/// route comes back at once; the route is still walked through doorways.
#[test]
fn a_corridor_with_hundreds_of_doors_routes_without_stalling() {
    let nrg = nrgdb::fixtures::corridor_building(400);
    let nav = NavMesh::new(Arc::new(nrg));
    let r = shortest_route(
        &nav,
        &exact(SpaceId(10), SpaceId(409)),
        &Budget::unlimited(),
    )
    .unwrap();
    // Down through door 10000, along the wall face, up through door 10399.
    let straight = 4.0 * 399.0;
    assert!(
        r[0].length_m >= straight && r[0].length_m < straight + 6.0,
        "{}",
        r[0].length_m
    );
    assert_eq!(r[0].doors, vec![SpaceId(10_000), SpaceId(10_399)]);
}
