//! Issue 18: a route round a hole must take the shorter side. Found by
//! `route_props::route_length_is_the_geodesic`: a room with a rectangular
//! hole, a door, a room; the route walked 5.95 m round the upper side where
//! 5.42 m exists round the lower one, because the in-space tree over
//! triangles reached the door's triangle only from above. Spaces with holes
//! now walk the visibility graph of their corners (`route/nav/visibility`).

use std::sync::Arc;

use nrgdb::model::Point;
use nrgdb::model::{Connection, ConnectionKind, Nrg, Space, SpaceId, SpaceKind};
use nrgdb::route::{Budget, Endpoint, NavMesh, Profile, RouteRequest, shortest_route};

/// A door connection between spaces `a` and `b`.
fn link(a: u32, b: u32) -> Connection {
    Connection {
        a: SpaceId(a),
        b: SpaceId(b),
        kind: ConnectionKind::Door,
        length_m: 1.0,
    }
}

/// Room 9 (with a 3.15 m × 1.52 m hole) – door 13 – room 11.
fn rooms_round_a_hole() -> Nrg {
    let mut r9 = Space::new(
        SpaceId(9),
        SpaceKind::Room,
        [8.74, -1.86],
        vec![
            [8.44, -3.62],
            [13.19, -3.62],
            [13.19, -2.3],
            [13.19, -1.32],
            [13.19, -0.1],
            [10.1, -0.1],
            [8.89, -0.1],
            [8.44, -0.1],
        ],
    );
    r9.holes = vec![vec![
        [9.24, -1.1],
        [12.39, -1.1],
        [12.39, -2.62],
        [9.24, -2.62],
    ]];
    let door = Space::new(
        SpaceId(13),
        SpaceKind::Door,
        [13.24, -1.81],
        vec![[13.19, -2.3], [13.29, -2.3], [13.29, -1.32], [13.19, -1.32]],
    );
    let r11 = Space::new(
        SpaceId(11),
        SpaceKind::Room,
        [13.59, -2.565],
        vec![
            [13.29, -1.32],
            [13.29, -2.3],
            [13.29, -5.03],
            [17.72, -5.03],
            [17.72, -0.1],
            [13.29, -0.1],
        ],
    );
    Nrg::new(vec![r9, r11, door], vec![link(9, 13), link(11, 13)]).unwrap()
}

/// Routes from `from` to `to` at zero clearance and compares the length
/// with the raster geodesic between `a` and `b` (their positions).
fn assert_geodesic(nrg: &Nrg, from: Endpoint, to: Endpoint, a: Point, b: Point) {
    let nrg = nrg.clone();
    let geodesic = nrgdb::eval::free_space_geodesic(&nrg, a, b, 0.025).unwrap();
    let nav = NavMesh::new(Arc::new(nrg));
    let mut request = RouteRequest::between(from, to);
    request.profile = Profile::exact();
    let routes = shortest_route(&nav, &request, &Budget::unlimited()).unwrap();
    let ratio = routes[0].length_m / geodesic;
    assert!(
        (0.98..=1.02).contains(&ratio),
        "{from:?} -> {to:?}: walked {} m, geodesic {geodesic} m",
        routes[0].length_m
    );
}

#[test]
fn issue_18_a_route_round_a_hole_takes_the_shorter_side() {
    let nrg = rooms_round_a_hole();
    let (a, b) = ([8.74, -1.86], [13.59, -2.565]);
    assert_geodesic(
        &nrg,
        Endpoint::Space(SpaceId(9)),
        Endpoint::Space(SpaceId(11)),
        a,
        b,
    );
    assert_geodesic(
        &nrg,
        Endpoint::Space(SpaceId(11)),
        Endpoint::Space(SpaceId(9)),
        b,
        a,
    );
}

#[test]
fn routes_from_points_round_a_hole_take_the_shorter_side() {
    let nrg = rooms_round_a_hole();
    // From points left of the hole to the other room, and between points
    // of the holed room on either side of the hole.
    for (q, r) in [
        ([8.74, -1.86], [12.9, -2.0]),
        ([8.7, -2.0], [13.0, -1.9]),
        ([8.7, -1.5], [12.9, -2.9]),
    ] {
        assert_geodesic(&nrg, Endpoint::Point(q), Endpoint::Point(r), q, r);
        assert_geodesic(&nrg, Endpoint::Point(r), Endpoint::Point(q), r, q);
    }
    let room_11 = [13.59, -2.565];
    for p in [[8.74, -1.86], [8.7, -2.0], [8.6, -1.3], [8.7, -2.9]] {
        assert_geodesic(
            &nrg,
            Endpoint::Point(p),
            Endpoint::Space(SpaceId(11)),
            p,
            room_11,
        );
    }
}

/// Room 6 (anchor west of its 3.51 m × 2.51 m hole) – door 12 (east side,
/// low) – room 8 (anchor just past the door, beside its own hole).
fn anchors_beside_holes() -> Nrg {
    let mut r6 = Space::new(
        SpaceId(6),
        SpaceKind::Room,
        [1.2, -2.355],
        vec![
            [0.9, -4.61],
            [6.01, -4.61],
            [6.01, -2.54],
            [6.01, -1.62],
            [6.01, -0.1],
            [0.9, -0.1],
        ],
    );
    r6.holes = vec![vec![[1.7, -1.1], [5.21, -1.1], [5.21, -3.61], [1.7, -3.61]]];
    let door = Space::new(
        SpaceId(12),
        SpaceKind::Door,
        [6.06, -2.08],
        vec![[6.01, -2.54], [6.11, -2.54], [6.11, -1.62], [6.01, -1.62]],
    );
    let mut r8 = Space::new(
        SpaceId(8),
        SpaceKind::Room,
        [6.41, -2.63],
        vec![
            [6.11, -1.62],
            [6.11, -2.54],
            [6.11, -5.16],
            [10.06, -5.16],
            [10.06, -0.1],
            [6.11, -0.1],
        ],
    );
    r8.holes = vec![vec![
        [6.91, -1.1],
        [9.26, -1.1],
        [9.26, -4.16],
        [6.91, -4.16],
    ]];
    Nrg::new(vec![r6, door, r8], vec![link(6, 12), link(8, 12)]).unwrap()
}

#[test]
fn routes_from_an_anchor_take_the_channel_their_table_measured() {
    let nrg = anchors_beside_holes();
    let (a, b) = ([1.2, -2.355], [6.41, -2.63]);
    let (six, eight) = (Endpoint::Space(SpaceId(6)), Endpoint::Space(SpaceId(8)));
    assert_geodesic(&nrg, six, eight, a, b);
    assert_geodesic(&nrg, eight, six, b, a);
    let in_door = [6.05, -2.5];
    assert_geodesic(&nrg, six, Endpoint::Point(in_door), a, in_door);
    assert_geodesic(&nrg, Endpoint::Point(in_door), six, in_door, a);
}
