#![cfg(test)]
//! The route-fidelity harness checked against a model whose shortest walks
//! are known exactly: two rooms south of a corridor (a 0.2 m wall between
//! them) and one north, each joined to the corridor by a 1 m door space;
//! doors share their edges with the spaces they join.
//!
//! ```text
//!   y=9  +--------------+
//!        |    room 3    |          room 3: x 0..10, y 5..9
//!   y=5  +----[d6]------+          door 6: x 4..5,  y 4..5
//!   y=4  |   corridor   |          corridor 1: x 0..10, y 2..4
//!   y=2  +-[d4]----[d5]-+          door 4: x 1..2, door 5: x 8..9, y 1..2
//!   y=1  | room 2 || r 7 |         room 2: x 0..5, room 7: x 5.2..10, y -3..1
//!  y=-3  +--------++-----+
//! ```

use nrgdb::eval::{FidelityReport, route_fidelity};
use nrgdb::model::{Nrg, Point, Ring, Space, SpaceId, SpaceKind};

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Ring {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

fn space(id: u32, kind: SpaceKind, anchor: Point, polygon: Ring) -> Space {
    Space::new(SpaceId(id), kind, anchor, polygon)
}

fn building() -> Nrg {
    Nrg::new(
        vec![
            space(
                1,
                SpaceKind::Corridor,
                [5.0, 3.0],
                rect(0.0, 2.0, 10.0, 4.0),
            ),
            space(2, SpaceKind::Room, [2.5, -1.0], rect(0.0, -3.0, 5.0, 1.0)),
            space(3, SpaceKind::Room, [5.0, 7.0], rect(0.0, 5.0, 10.0, 9.0)),
            space(4, SpaceKind::Door, [1.5, 1.5], rect(1.0, 1.0, 2.0, 2.0)),
            space(5, SpaceKind::Door, [8.5, 1.5], rect(8.0, 1.0, 9.0, 2.0)),
            space(6, SpaceKind::Door, [4.5, 4.5], rect(4.0, 4.0, 5.0, 5.0)),
            space(7, SpaceKind::Room, [7.6, -1.0], rect(5.2, -3.0, 10.0, 1.0)),
        ],
        vec![],
    )
    .unwrap()
}

/// The true shortest walk between two room anchors of [`building`]: the
/// corners it wraps around, in order (found by hand).
fn exact_walk(from: Point, to: Point) -> Vec<Point> {
    let key = |p: Point| match p {
        [2.5, -1.0] => 2,
        [5.0, 7.0] => 3,
        [7.6, -1.0] => 7,
        _ => unreachable!("not a room anchor: {p:?}"),
    };
    let corners: Vec<Point> = match (key(from), key(to)) {
        // Room 2 -> door 4 -> corridor -> door 6 -> room 3: round (2,1)
        // and (2,2), then (4,4) and straight through the door.
        (2, 3) => vec![[2.0, 1.0], [2.0, 2.0], [4.0, 4.0]],
        // Room 2 -> door 4 -> corridor -> door 5 -> room 7.
        (2, 7) => vec![[2.0, 1.0], [2.0, 2.0], [8.0, 2.0], [8.0, 1.0]],
        // Room 7 -> door 5 -> corridor -> door 6 -> room 3.
        (7, 3) => vec![[8.0, 1.0], [8.0, 2.0], [5.0, 4.0]],
        (a, b) => {
            let mut w = exact_walk(to, from);
            w.reverse();
            assert_ne!(a, b);
            return w;
        }
    };
    let mut w = vec![from];
    w.extend(corners);
    w.push(to);
    w
}

fn length(line: &[Point]) -> f64 {
    line.windows(2)
        .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
        .sum()
}

fn run(router: &dyn Fn(Point, Point) -> Option<(f64, Vec<Point>)>) -> FidelityReport {
    route_fidelity(&building(), 10, 7, 0.05, router)
}

#[test]
fn the_exact_walk_scores_one_and_stays_inside() {
    let report = run(&|a, b| {
        let w = exact_walk(a, b);
        Some((length(&w), w))
    });
    let s = &report.summary;
    // Three rooms: all three pairs.
    assert_eq!((s.pairs, s.routes, s.n), (3, 3, 3), "{report:#?}");
    for p in &report.pairs {
        let r = p.ratio.unwrap();
        assert!((r - 1.0).abs() < 0.01, "{p:?}");
        assert_eq!(p.outside_fraction, Some(0.0), "{p:?}");
        assert_eq!(p.length_consistent, Some(true));
    }
    assert_eq!(
        (s.routes_outside, s.one_sided, s.length_mismatches),
        (0, 0, 0)
    );
}

#[test]
fn the_straight_line_across_walls_is_caught() {
    let report = run(&|a: Point, b: Point| {
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        Some((len, vec![a, b]))
    });
    let s = &report.summary;
    assert_eq!(s.routes_outside, 3, "{report:#?}");
    assert!(s.max_outside_fraction > 0.0);
    // Shorter than any walk: ratios below 1.
    assert!(s.max_ratio.unwrap() < 1.0);
}

#[test]
fn a_wrong_length_and_a_missing_route_are_counted() {
    let report = run(&|a, b| {
        let w = exact_walk(a, b);
        (a != [5.0, 7.0] && b != [5.0, 7.0]).then(|| (length(&w) * 1.5, w))
    });
    let s = &report.summary;
    // Only room 2 <-> room 7 is routed, with 1.5 times its length.
    assert_eq!((s.routes, s.one_sided, s.length_mismatches), (1, 2, 1));
    assert!((s.median_ratio.unwrap() - 1.5).abs() < 0.015);
}
