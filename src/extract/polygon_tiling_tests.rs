//! Tiling tests of [`outlines`] after [`tidy_labels`] on hand-made label
//! images: shared edges, no gaps, no overlaps, valid polygons.

use geo::{Area, BooleanOps, Coord, LineString, Polygon, Validation, unary_union};

use super::*;
use crate::extract::tidy::tidy_labels;
use crate::grid::Cell;

const RES: f64 = 0.05;

fn geo_polygon((ext, holes): &(Ring, Vec<Ring>)) -> Polygon {
    let line = |r: &Ring| LineString::new(r.iter().map(|p| Coord { x: p[0], y: p[1] }).collect());
    Polygon::new(line(ext), holes.iter().map(line).collect())
}

/// Tidies and outlines `labels`; asserts that every label is one valid
/// polygon (exterior CCW, holes CW, no repeated points), that no two
/// overlap, and that their union has the summed area. Returns the tidied
/// labels and the outlines.
fn tile(mut labels: Labels, simplify_m: f64) -> (Labels, Vec<(Ring, Vec<Ring>)>) {
    tidy_labels(&mut labels);
    let (w, h) = (labels.width, labels.height);
    let grid = OccupancyGrid::from_cells(w, h, RES, [0.0; 3], vec![Cell::Free; (w * h) as usize]);
    let out = outlines(&labels, &grid, simplify_m);
    let mut polys = Vec::new();
    for (l, o) in out.iter().enumerate().skip(1) {
        let n = labels.data.iter().filter(|&&v| v as usize == l).count();
        if n == 0 {
            assert!(o.0.is_empty(), "label {l} has no pixels but a polygon");
            continue;
        }
        assert!(polygon_area(&o.0) > 0.0, "label {l}: exterior not CCW");
        for hole in &o.1 {
            assert!(polygon_area(hole) < 0.0, "label {l}: hole not CW");
        }
        for r in std::iter::once(&o.0).chain(&o.1) {
            for (i, p) in r.iter().enumerate() {
                assert_ne!(*p, r[(i + 1) % r.len()], "label {l}: repeated point");
            }
        }
        let p = geo_polygon(o);
        assert!(p.is_valid(), "label {l}: {:?}", p.validation_errors());
        polys.push(p);
    }
    for (i, a) in polys.iter().enumerate() {
        for b in &polys[i + 1..] {
            assert!(a.intersection(b).unsigned_area() < 1e-12, "overlap");
        }
    }
    let sum: f64 = polys.iter().map(Area::unsigned_area).sum();
    let union = unary_union(&polys).unsigned_area();
    assert!(
        (union - sum).abs() < 1e-6 * sum,
        "union {union} vs sum {sum}"
    );
    (labels, out)
}

/// Each label's polygon area equals its pixel count × res².
fn assert_exact_areas(labels: &Labels, out: &[(Ring, Vec<Ring>)]) {
    for (l, (ext, holes)) in out.iter().enumerate().skip(1) {
        let n = labels.data.iter().filter(|&&v| v as usize == l).count() as f64;
        let a = polygon_area(ext) + holes.iter().map(|h| polygon_area(h)).sum::<f64>();
        assert!(
            (a - n * RES * RES).abs() < 1e-9,
            "label {l}: {a} m² for {n} px"
        );
    }
}

/// The directed edges of a polygon's rings.
fn edges(o: &(Ring, Vec<Ring>)) -> Vec<([f64; 2], [f64; 2])> {
    std::iter::once(&o.0)
        .chain(&o.1)
        .flat_map(|r| (0..r.len()).map(move |i| (r[i], r[(i + 1) % r.len()])))
        .collect()
}

/// How many edges of `a` are edges of `b` run the other way, bit for bit.
fn shared_edges(a: &(Ring, Vec<Ring>), b: &(Ring, Vec<Ring>)) -> usize {
    let eb = edges(b);
    edges(a)
        .iter()
        .filter(|(p, q)| eb.contains(&(*q, *p)))
        .count()
}

#[test]
fn a_room_a_door_strip_and_a_corridor_share_their_edges() {
    let labels = Labels::from_digits(&[
        "0000000000",
        "0111102220",
        "0111132220",
        "0111132220",
        "0111102220",
        "0000000000",
    ]);
    // At 1 px tolerance the room's outer corners are cut; still a tiling.
    let (_, cut) = tile(labels.clone(), 0.05);
    assert_eq!(shared_edges(&cut[3], &cut[1]), 1);
    let (labels, out) = tile(labels, 0.01);
    assert_exact_areas(&labels, &out);
    // The door strip is a rectangle one pixel thick.
    assert_eq!(out[3].0.len(), 4);
    assert!((polygon_area(&out[3].0) - 2.0 * RES * RES).abs() < 1e-12);
    assert_eq!(shared_edges(&out[3], &out[1]), 1);
    assert_eq!(shared_edges(&out[3], &out[2]), 1);
    assert_eq!(shared_edges(&out[1], &out[2]), 0);
}

#[test]
fn simplified_staircases_stay_shared_without_gaps_or_overlaps() {
    // A frame of straight walls around three labels split by staircases.
    let mut rows = Vec::new();
    for y in 0..40 {
        let row: String = (0..60)
            .map(|x| match (x, y) {
                _ if x == 0 || y == 0 || x == 59 || y == 39 => '0',
                _ if 2 * x < 3 * y => '1',
                _ if x + y / 3 < 45 => '2',
                _ => '3',
            })
            .collect();
        rows.push(row);
    }
    let rows: Vec<&str> = rows.iter().map(String::as_str).collect();
    let (labels, out) = tile(Labels::from_digits(&rows), 0.2);
    // Shared arcs leave no gap: the union is one polygon without holes,
    // and only the outer corners (cut by the tolerance) lose area.
    let polys: Vec<Polygon> = out[1..].iter().map(geo_polygon).collect();
    let union = unary_union(&polys);
    assert_eq!(union.0.len(), 1);
    assert!(union.0[0].interiors().is_empty());
    let n = labels.data.iter().filter(|&&v| v != 0).count() as f64;
    let lost = n * RES * RES - union.unsigned_area();
    assert!(
        (0.0..0.03 * n * RES * RES).contains(&lost),
        "{lost} m² lost"
    );
    assert!(out[1].0.len() < 10, "the staircase was not simplified");
    assert!(shared_edges(&out[1], &out[2]) > 0);
    assert!(shared_edges(&out[2], &out[3]) > 0);
}

#[test]
fn a_checkerboard_pinch_gives_simple_rings() {
    let labels = Labels::from_digits(&["000000", "011220", "011220", "012120", "022110", "000000"]);
    let (labels, out) = tile(labels, 0.01);
    assert_exact_areas(&labels, &out);
    assert!(out[1].1.is_empty() && out[2].1.is_empty());
}

#[test]
fn a_label_with_a_hole_shares_it_with_the_label_inside() {
    let labels = Labels::from_digits(&[
        "0000000", "0111110", "0122210", "0122010", "0111110", "0000000",
    ]);
    let (labels, out) = tile(labels, 0.01);
    assert_exact_areas(&labels, &out);
    assert_eq!(out[1].1.len(), 1);
    // The hole is label 2 and the 0 pixel beside it; only 2's edges are shared.
    assert!(shared_edges(&out[1], &out[2]) >= 3);
    let hole_area = -polygon_area(&out[1].1[0]);
    assert!((hole_area - 6.0 * RES * RES).abs() < 1e-12);
}

#[test]
fn a_label_in_two_pieces_keeps_its_largest() {
    let labels = Labels::from_digits(&["00000000", "01110220", "01110210", "01110220", "00000000"]);
    let (labels, out) = tile(labels, 0.01);
    assert_exact_areas(&labels, &out);
    // The lone 1 in the 2s went to 2: labels and polygons agree.
    assert_eq!(labels.data[2 * 8 + 6], 2);
    assert!((polygon_area(&out[1].0) - 9.0 * RES * RES).abs() < 1e-12);
}
