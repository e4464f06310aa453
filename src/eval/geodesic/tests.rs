use super::*;
use crate::model::{Ring, Space, SpaceId, SpaceKind};

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Ring {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

fn space(id: u32, kind: SpaceKind, polygon: Ring) -> Space {
    let anchor = crate::model::polygon_centroid(&polygon).unwrap();
    Space::new(SpaceId(id), kind, anchor, polygon)
}

fn model(spaces: Vec<Space>) -> Nrg {
    Nrg::new(spaces, vec![]).unwrap()
}

/// Relative error of `got` against `want`.
fn rel(got: f64, want: f64) -> f64 {
    (got - want).abs() / want
}

fn d(a: Point, b: Point) -> f64 {
    distance(a, b)
}

#[test]
fn neighbourhood_has_the_primitive_offsets_and_conservative_sight() {
    let (steps, sight) = neighbourhood(100);
    // 8 * (phi(1) + ... + phi(6)) = 8 * 12
    assert_eq!(steps.len(), 96);
    let diagonal = steps.iter().find(|s| s.delta == 101).unwrap();
    let mut cells = sight[diagonal.sight.clone()].to_vec();
    cells.sort();
    // Touching (1, 0) and (0, 1) at a corner counts: no squeezing diagonally
    // between two blocked cells.
    assert_eq!(cells, vec![1, 100, 101]);
    let straight = steps.iter().find(|s| s.delta == 1).unwrap();
    assert_eq!(&sight[straight.sight.clone()], &[1]);
}

#[test]
fn empty_rectangle_gives_the_straight_distance() {
    let nrg = model(vec![space(1, SpaceKind::Room, rect(0.0, 0.0, 10.0, 4.0))]);
    // Directions between the neighbourhood's (worst near the axes).
    let pairs = [
        ([0.2, 1.0], [9.8, 1.8]),
        ([0.3, 0.2], [9.7, 3.9]),
        ([0.1, 3.9], [9.9, 0.1]),
        ([0.5, 0.5], [9.5, 1.25]),
    ];
    for cell in [0.05, 0.025] {
        let grid = FreeSpaceGrid::new(&nrg, cell).unwrap();
        for (a, b) in pairs {
            let got = grid.shortest_path(a, b).unwrap();
            assert!(
                rel(got.length_m, d(a, b)) < 0.005,
                "{a:?} {b:?} at {cell}: {got:?}"
            );
            assert!(got.length_m >= d(a, b) - 1e-9);
            assert_eq!(got.points.first(), Some(&a));
            assert_eq!(got.points.last(), Some(&b));
        }
    }
    assert_eq!(
        free_space_geodesic(&nrg, [1.0, 1.0], [1.0, 1.0], 0.05),
        Some(0.0)
    );
}

#[test]
fn l_shaped_corridor_goes_round_the_inner_corner() {
    // Arms y in [0, 2] and x in [4, 6]; inner corner (4, 2).
    let l = vec![
        [0.0, 0.0],
        [6.0, 0.0],
        [6.0, 6.0],
        [4.0, 6.0],
        [4.0, 2.0],
        [0.0, 2.0],
    ];
    let nrg = model(vec![space(1, SpaceKind::Corridor, l)]);
    let want = 2.0 * 10f64.sqrt(); // (1,1) -> (4,2) -> (5,5)
    let got = free_space_geodesic(&nrg, [1.0, 1.0], [5.0, 5.0], 0.025).unwrap();
    assert!(rel(got, want) < 0.005, "{got} vs {want}");
    let coarse = free_space_geodesic(&nrg, [1.0, 1.0], [5.0, 5.0], 0.05).unwrap();
    assert!(rel(coarse, want) < 0.01, "{coarse} vs {want}");
}

#[test]
fn room_with_a_square_hole_goes_around_it() {
    let mut room = space(1, SpaceKind::Room, rect(0.0, 0.0, 10.0, 10.0));
    let mut hole = rect(3.0, 3.0, 7.0, 7.0);
    hole.reverse();
    room.holes.push(hole);
    let nrg = model(vec![room]);
    let grid = FreeSpaceGrid::new(&nrg, 0.05).unwrap();
    assert!(!grid.is_free([5.0, 5.0]) && grid.is_free([1.0, 5.0]));
    let want = 2.0 * 8f64.sqrt() + 4.0; // via (3,7) and (7,7), or below
    let got = grid.shortest_path([1.0, 5.0], [9.0, 5.0]).unwrap();
    assert!(
        rel(got.length_m, want) < 0.005,
        "{} vs {want}",
        got.length_m
    );
    assert!(got.points.iter().all(|&p| grid.is_free(p)));
}

#[test]
fn two_rooms_through_a_one_metre_door() {
    let nrg = model(vec![
        space(1, SpaceKind::Room, rect(0.0, 0.0, 5.0, 5.0)),
        space(2, SpaceKind::Door, rect(5.0, 2.0, 6.0, 3.0)),
        space(3, SpaceKind::Room, rect(6.0, 0.0, 11.0, 5.0)),
    ]);
    let want = 2.0 * 17f64.sqrt() + 1.0; // via (5,3) and (6,3)
    for cell in [0.05, 0.025] {
        let got = free_space_geodesic(&nrg, [1.0, 4.0], [10.0, 4.0], cell).unwrap();
        assert!(rel(got, want) < 0.005, "{got} vs {want} at {cell}");
    }
    // Straight through the door's middle.
    let got = free_space_geodesic(&nrg, [1.0, 2.5], [10.0, 2.5], 0.05).unwrap();
    assert!(rel(got, 9.0) < 0.005, "{got}");
}

#[test]
fn unreachable_or_off_the_map_is_none() {
    let nrg = model(vec![
        space(1, SpaceKind::Room, rect(0.0, 0.0, 4.0, 4.0)),
        space(2, SpaceKind::Room, rect(4.2, 0.0, 8.0, 4.0)),
    ]);
    assert_eq!(
        free_space_geodesic(&nrg, [1.0, 1.0], [6.0, 1.0], 0.05),
        None
    );
    // In the gap but within two cells of the first room: snapped into it.
    let near = free_space_geodesic(&nrg, [1.0, 1.0], [4.03, 1.0], 0.05).unwrap();
    assert!(rel(near, 3.03) < 0.02, "{near}");
    assert_eq!(
        free_space_geodesic(&nrg, [1.0, 1.0], [4.1, 9.0], 0.05),
        None
    );
    assert_eq!(
        free_space_geodesic(&nrg, [1.0, 1.0], [f64::NAN, 1.0], 0.05),
        None
    );
}

#[test]
fn a_point_just_outside_snaps_to_the_nearest_free_cell() {
    let nrg = model(vec![space(1, SpaceKind::Room, rect(0.0, 0.0, 4.0, 4.0))]);
    let got = free_space_geodesic(&nrg, [-0.06, 2.0], [3.0, 2.0], 0.05).unwrap();
    assert!(rel(got, 3.06) < 0.005, "{got}");
}

#[test]
fn oversized_or_bad_rasters_are_refused() {
    let nrg = model(vec![space(
        1,
        SpaceKind::Room,
        rect(0.0, 0.0, 400.0, 400.0),
    )]);
    assert!(matches!(
        FreeSpaceGrid::new(&nrg, 0.01),
        Err(EvalError::TooManyCells { .. })
    ));
    assert_eq!(
        free_space_geodesic(&nrg, [1.0, 1.0], [2.0, 2.0], 0.01),
        None
    );
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            FreeSpaceGrid::new(&nrg, bad),
            Err(EvalError::BadCellSize { .. })
        ));
    }
    assert!(matches!(
        FreeSpaceGrid::new(&Nrg::default(), 0.05),
        Err(EvalError::NoSpaces)
    ));
}
