//! Space outlines that tile the labelled area: each label's polygon is the
//! boundary of the union of its pixel squares (`boundaries.rs`), with every
//! boundary arc simplified once (`simplify.rs`) and shared, reversed, by the
//! two labels on its sides; in metres in the map frame, exterior CCW and
//! holes CW.
//!
//! Simplification never changes the topology: arcs whose simplified form
//! crosses or touches another, turns a junction or misplaces a ring
//! (`conflicts.rs`) are simplified again with half the tolerance, down to
//! the unsimplified staircase. Expects a tidied label image (`tidy.rs`): one
//! 4-connected piece per label, no diagonal pinches.
//!
//! Uses grid (pixel → metre) and imaging (labels) only.

use super::boundaries::{RingArcs, ring_corners, trace_boundaries, twice_area};
use super::conflicts::{Junctions, LabelRings, mark_bad_rings, mark_crossings};
use super::simplify::{Corner, simplify_arc};
use crate::grid::OccupancyGrid;
use crate::imaging::Labels;
use crate::model::{Ring, polygon_area};

/// Tolerances tried for an arc, as fractions of `simplify_m`; the last
/// keeps every turn of the staircase.
const LEVELS: [f64; 4] = [1.0, 0.5, 0.25, 0.0];

/// The outline (exterior, holes) of every label, indexed by label (index 0
/// and labels without pixels get empty rings). Neighbouring labels share
/// their boundary points exactly.
pub(crate) fn outlines(
    labels: &Labels,
    grid: &OccupancyGrid,
    simplify_m: f64,
) -> Vec<(Ring, Vec<Ring>)> {
    let b = trace_boundaries(labels);
    let raw: Vec<Vec<Corner>> = b.arcs.iter().map(|a| a.pts.clone()).collect();
    let rings: Vec<Option<LabelRings>> = b.rings.into_iter().map(|r| split(r, &raw)).collect();
    let eps_px = simplify_m / grid.resolution;
    let mut level = vec![0usize; raw.len()];
    let mut geom: Vec<Vec<Corner>> = raw.iter().map(|p| simplify_arc(p, eps_px)).collect();
    let junctions = Junctions::new(&b.arcs);
    let mut changed: Option<Vec<bool>> = None;
    for _ in 0..=LEVELS.len() {
        let mut bad = vec![false; raw.len()];
        mark_crossings(&geom, changed.as_deref(), &mut bad);
        junctions.mark_turned(&geom, &mut bad);
        mark_bad_rings(&rings, &geom, &mut bad);
        let mut moved = vec![false; raw.len()];
        for k in 0..raw.len() {
            if bad[k] && level[k] + 1 < LEVELS.len() {
                level[k] += 1;
                geom[k] = simplify_arc(&raw[k], eps_px * LEVELS[level[k]]);
                moved[k] = true;
            }
        }
        if !moved.contains(&true) {
            break;
        }
        changed = Some(moved);
    }
    let to_m = |ring: &RingArcs, ccw: bool| -> Ring {
        let mut r: Ring = ring_corners(ring, &geom)
            .into_iter()
            .map(|[x, y]| grid.pixel_to_metres(f64::from(x), f64::from(y)))
            .collect();
        if (polygon_area(&r) > 0.0) != ccw {
            r.reverse();
        }
        r
    };
    rings
        .iter()
        .map(|l| match l {
            Some(l) => (
                to_m(&l.exterior, true),
                l.holes.iter().map(|h| to_m(h, false)).collect(),
            ),
            None => (Vec::new(), Vec::new()),
        })
        .collect()
}

/// A label's exterior (the largest ring with the label on its inside; a
/// tidied label has one) and its holes.
fn split(rings: Vec<RingArcs>, raw: &[Vec<Corner>]) -> Option<LabelRings> {
    let mut exterior: Option<(i64, RingArcs)> = None;
    let mut holes = Vec::new();
    for r in rings {
        let a = twice_area(&ring_corners(&r, raw));
        if a > 0 {
            holes.push(r);
        } else if exterior.as_ref().is_none_or(|(best, _)| a < *best) {
            exterior = Some((a, r));
        }
    }
    exterior.map(|(_, exterior)| LabelRings { exterior, holes })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::Cell;

    #[test]
    fn square_outline_in_metres_ccw_with_hole() {
        let grid = OccupancyGrid::from_cells(7, 7, 1.0, [0.0; 3], vec![Cell::Free; 49]);
        let mut labels = Labels::new(7, 7);
        for y in 1..6 {
            for x in 1..6 {
                labels.data[y * 7 + x] = if (x, y) == (3, 3) { 0 } else { 1 };
            }
        }
        labels.count = 1;
        let out = outlines(&labels, &grid, 0.01);
        let (ext, holes) = &out[1];
        assert_eq!(ext.len(), 4);
        assert!((polygon_area(ext) - 25.0).abs() < 1e-12);
        // Pixel corners 1..6 in x, and y = 7 - row.
        assert!(ext.contains(&[1.0, 6.0]) && ext.contains(&[6.0, 1.0]));
        assert_eq!(holes.len(), 1);
        assert!((polygon_area(&holes[0]) + 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_thin_line_is_a_one_pixel_rectangle() {
        let grid = OccupancyGrid::from_cells(5, 1, 1.0, [0.0; 3], vec![Cell::Free; 5]);
        let labels = Labels {
            width: 5,
            height: 1,
            data: vec![0, 1, 1, 1, 0],
            count: 1,
        };
        let out = outlines(&labels, &grid, 0.01);
        assert_eq!(out[1].0.len(), 4);
        assert!((polygon_area(&out[1].0) - 3.0).abs() < 1e-9);
    }
}

#[cfg(test)]
#[path = "polygon_tiling_tests.rs"]
mod tiling_tests;
