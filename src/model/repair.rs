//! Repairs of a model's cell geometry that keep what the model says: an
//! outline that crosses itself is made simple, a hole outside its shell is
//! dropped, a sliver where two cells overlap is cut from the larger one,
//! and a cell drawn inside another is cut out of it (the outer cell gets a
//! hole or a notch, as IndoorGML's cells must not overlap). Anything else
//! (two cells overlapping by more than a sliver without one lying inside
//! the other, such as floors drawn on one plane) is left for the caller to
//! refuse: guessing which cell owns the shared area would change the model.
//!
//! Each change is reported as a [`Repair`] so that the caller can say what
//! it did. Geometry by `geo`'s boolean operations (i_overlay); the overlap
//! candidates by an R-tree of bounding boxes, so the work grows with the
//! number of overlapping pairs, not with the square of the cells.

use std::fmt;

use geo::algorithm::bool_ops::FillRule;
use geo::{Area, BooleanOps, BoundingRect, Coord, LineString, MultiPolygon, Polygon};
use rstar::{AABB, RTree, RTreeObject};

use super::geometry::{Point, Ring, point_in_ring, ring_is_ccw};
use super::interior_point::pole_of_inaccessibility;
use super::{ModelError, Nrg, Space, SpaceId};

/// Two cells sharing less than this (m²) do not overlap: rounding, not
/// modelling. The one tolerance of the checker and of these repairs.
pub const MIN_OVERLAP_M2: f64 = 1e-4;

/// Exact intersections computed at most (pairs of cells whose boxes
/// overlap), by the checker per document and by [`repair_geometry`]: a
/// model of many cells piled on each other stops there (issue 21).
pub const MAX_OVERLAP_TESTS: usize = 100_000;

/// An overlap at most this share of the smaller cell is a sliver (drawing
/// noise along a shared wall): it is cut from the larger cell.
const SLIVER_SHARE: f64 = 0.05;

/// An overlap at most this thick on average (twice its area over its
/// perimeter, metres) is a sliver too, whatever its share: a corridor
/// outline drawn a few centimetres into a door.
const SLIVER_WIDTH_M: f64 = 0.1;

/// A cell at least this share of whose area lies in another cell is drawn
/// inside it: it is cut out of the outer cell.
const NESTED_SHARE: f64 = 0.95;

/// One change [`repair_geometry`] made to a space.
#[derive(Debug, Clone, PartialEq)]
pub struct Repair {
    /// The space changed.
    pub space: SpaceId,
    /// Its label (name or kind and id), for messages.
    pub label: String,
    /// What was done.
    pub what: RepairKind,
}

/// What [`repair_geometry`] did to a space.
#[derive(Debug, Clone, PartialEq)]
pub enum RepairKind {
    /// The outline crossed itself (or a hole lay outside it): it was
    /// rebuilt as a simple polygon; `dropped_m2` of detached pieces went.
    MadeSimple {
        /// Area of the pieces that were not kept (only the largest is).
        dropped_m2: f64,
    },
    /// A sliver shared with another space was cut from this one.
    SliverCut {
        /// The other space.
        other: SpaceId,
        /// The area cut, m².
        area_m2: f64,
    },
    /// Another space drawn inside this one was cut out of it.
    InnerCut {
        /// The inner space.
        inner: SpaceId,
        /// The area cut, m².
        area_m2: f64,
    },
}

impl fmt::Display for Repair {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.what {
            RepairKind::MadeSimple { dropped_m2 } if *dropped_m2 > 0.0 => write!(
                f,
                "{}: its outline crossed itself; made simple, dropping {dropped_m2:.3} m² of detached pieces",
                self.label
            ),
            RepairKind::MadeSimple { .. } => {
                write!(f, "{}: its outline crossed itself; made simple", self.label)
            }
            RepairKind::SliverCut { other, area_m2 } => write!(
                f,
                "{}: overlapped space {other} by a sliver of {area_m2:.4} m²; cut from it",
                self.label
            ),
            RepairKind::InnerCut { inner, area_m2 } => write!(
                f,
                "{}: space {inner} is drawn inside it; its {area_m2:.4} m² cut out",
                self.label
            ),
        }
    }
}

/// The model with the repairs above made, and what was done (empty when
/// nothing needed repair, and then the model is returned unchanged).
/// Overlaps it cannot repair are left in place; the caller's check finds
/// them.
pub fn repair_geometry(nrg: &Nrg) -> Result<(Nrg, Vec<Repair>), ModelError> {
    let mut repairs = Vec::new();
    let mut shapes: Vec<Polygon> = nrg.spaces().iter().map(to_geo).collect();
    let mut changed = vec![false; shapes.len()];
    for (i, space) in nrg.spaces().iter().enumerate() {
        // The R-tree test, not geo's `is_valid` (all pairs of segments: a
        // 500 000-vertex outline took minutes).
        if super::validity::polygon_errors(&shapes[i]).is_empty() {
            continue;
        }
        // Even-odd: a figure-eight is two pieces, a hole stays a hole.
        let pieces =
            shapes[i].union_with_fill_rule(&MultiPolygon::new(Vec::new()), FillRule::EvenOdd);
        let total = pieces.unsigned_area();
        if let Some(largest) = largest(pieces) {
            repairs.push(Repair {
                space: space.id,
                label: space.label(),
                what: RepairKind::MadeSimple {
                    dropped_m2: (total - largest.unsigned_area()).max(0.0),
                },
            });
            shapes[i] = largest;
            changed[i] = true;
        }
    }
    // Past the bound, overlaps are left for the caller's check to refuse.
    for (i, j) in overlapping_pairs(&shapes)
        .into_iter()
        .take(MAX_OVERLAP_TESTS)
    {
        let overlap = shapes[i].intersection(&shapes[j]);
        let shared = overlap.unsigned_area();
        if shared <= MIN_OVERLAP_M2 {
            continue;
        }
        let (ai, aj) = (shapes[i].unsigned_area(), shapes[j].unsigned_area());
        let (small, big) = if ai <= aj { (i, j) } else { (j, i) };
        let share = shared / ai.min(aj).max(f64::MIN_POSITIVE);
        let thickness = 2.0 * shared / perimeter(&overlap).max(f64::MIN_POSITIVE);
        let what = if share <= SLIVER_SHARE || thickness <= SLIVER_WIDTH_M {
            RepairKind::SliverCut {
                other: nrg.spaces()[small].id,
                area_m2: shared,
            }
        } else if share >= NESTED_SHARE {
            RepairKind::InnerCut {
                inner: nrg.spaces()[small].id,
                area_m2: shared,
            }
        } else {
            continue;
        };
        let Some(cut) = largest(shapes[big].difference(&shapes[small])) else {
            continue;
        };
        shapes[big] = cut;
        changed[big] = true;
        let space = &nrg.spaces()[big];
        repairs.push(Repair {
            space: space.id,
            label: space.label(),
            what,
        });
    }
    if repairs.is_empty() {
        return Ok((nrg.clone(), repairs));
    }
    let spaces = nrg
        .spaces()
        .iter()
        .zip(&shapes)
        .zip(&changed)
        .map(|((space, shape), &changed)| {
            if changed {
                reshaped(space, shape)
            } else {
                space.clone()
            }
        })
        .collect();
    Ok((Nrg::new(spaces, nrg.connections().to_vec())?, repairs))
}

/// The space with `shape` as its outline and holes, its anchor kept if it
/// is still inside and otherwise moved to the pole of inaccessibility.
pub(crate) fn reshaped(space: &Space, shape: &Polygon) -> Space {
    let mut out = space.clone();
    out.polygon = open_ring(shape.exterior(), true);
    out.holes = shape
        .interiors()
        .iter()
        .map(|r| open_ring(r, false))
        .collect();
    let inside = point_in_ring(out.anchor, &out.polygon)
        && !out.holes.iter().any(|h| point_in_ring(out.anchor, h));
    if !inside && let Some((pole, _)) = pole_of_inaccessibility(&out.polygon, &out.holes, 0.01) {
        out.anchor = pole;
    }
    out.update_area();
    out.update_doorway();
    out
}

/// `line` as an open ring, counter-clockwise when `ccw` (else clockwise).
fn open_ring(line: &LineString, ccw: bool) -> Ring {
    let mut ring: Ring = line.coords().map(|c| [c.x, c.y]).collect();
    if ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
    if ring_is_ccw(&ring) != ccw {
        ring.reverse();
    }
    ring
}

pub(crate) fn to_geo(space: &Space) -> Polygon {
    let line =
        |r: &[Point]| LineString::new(r.iter().map(|p| Coord { x: p[0], y: p[1] }).collect());
    Polygon::new(
        line(&space.polygon),
        space.holes.iter().map(|h| line(h)).collect(),
    )
}

fn perimeter(shape: &MultiPolygon) -> f64 {
    shape
        .iter()
        .flat_map(|p| std::iter::once(p.exterior()).chain(p.interiors()))
        .map(|ring| ring.lines().map(|l| l.dx().hypot(l.dy())).sum::<f64>())
        .sum()
}

fn largest(pieces: MultiPolygon) -> Option<Polygon> {
    pieces
        .into_iter()
        .max_by(|a, b| a.unsigned_area().total_cmp(&b.unsigned_area()))
}

struct Boxed {
    index: usize,
    envelope: AABB<[f64; 2]>,
}

impl RTreeObject for Boxed {
    type Envelope = AABB<[f64; 2]>;
    fn envelope(&self) -> Self::Envelope {
        self.envelope
    }
}

/// Pairs `(i, j)`, `i < j`, whose bounding boxes overlap, in order; at
/// most [`MAX_OVERLAP_TESTS`] + 1 are collected.
fn overlapping_pairs(shapes: &[Polygon]) -> Vec<(usize, usize)> {
    let boxes: Vec<Boxed> = shapes
        .iter()
        .enumerate()
        .filter_map(|(index, s)| {
            let r = s.bounding_rect()?;
            Some(Boxed {
                index,
                envelope: AABB::from_corners([r.min().x, r.min().y], [r.max().x, r.max().y]),
            })
        })
        .collect();
    let tree = RTree::bulk_load(boxes);
    let mut pairs: Vec<(usize, usize)> = tree
        .iter()
        .flat_map(|a| {
            tree.locate_in_envelope_intersecting(&a.envelope)
                .filter(move |b| b.index > a.index)
                .map(move |b| (a.index, b.index))
        })
        .take(MAX_OVERLAP_TESTS + 1)
        .collect();
    pairs.sort_unstable();
    pairs
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Connection, SpaceKind};

    fn square(id: u32, x: f64, y: f64, side: f64) -> Space {
        let ring = vec![[x, y], [x + side, y], [x + side, y + side], [x, y + side]];
        Space::new(
            SpaceId(id),
            SpaceKind::Room,
            [x + side / 2.0, y + side / 2.0],
            ring,
        )
    }

    #[test]
    fn a_valid_model_is_returned_unchanged() {
        let nrg = Nrg::new(
            vec![square(1, 0.0, 0.0, 4.0), square(2, 4.0, 0.0, 4.0)],
            vec![],
        )
        .unwrap();
        let (out, repairs) = repair_geometry(&nrg).unwrap();
        assert!(repairs.is_empty());
        assert_eq!(out, nrg);
    }

    #[test]
    fn a_bow_tie_outline_is_made_simple() {
        let mut s = square(1, 0.0, 0.0, 4.0);
        // A figure eight: the outline crosses itself at (2, 2).
        s.polygon = vec![[0.0, 0.0], [4.0, 4.0], [4.0, 0.0], [0.0, 4.0]];
        s.anchor = [3.5, 2.0];
        let nrg = Nrg::new(vec![s], vec![]).unwrap();
        let (out, repairs) = repair_geometry(&nrg).unwrap();
        assert_eq!(repairs.len(), 1, "{repairs:?}");
        let RepairKind::MadeSimple { dropped_m2 } = repairs[0].what else {
            panic!("{repairs:?}")
        };
        // Two triangles of 4 m² each: one is kept, the other reported.
        assert!((dropped_m2 - 4.0).abs() < 1e-5, "{dropped_m2}");
        let kept = &out.spaces()[0];
        assert!((kept.area_m2 - 4.0).abs() < 1e-5);
        assert!(super::super::validity::polygon_errors(&to_geo(kept)).is_empty());
        assert!(point_in_ring(kept.anchor, &kept.polygon));
    }

    #[test]
    fn a_sliver_is_cut_from_the_larger_cell() {
        // The room reaches 0.05 m into the corridor along a 4 m wall.
        let room = square(1, 0.0, 0.0, 4.0);
        let mut corridor = square(2, 3.95, -4.0, 12.0);
        corridor.kind = SpaceKind::Corridor;
        let nrg = Nrg::new(vec![room, corridor], vec![]).unwrap();
        let (out, repairs) = repair_geometry(&nrg).unwrap();
        assert_eq!(repairs.len(), 1, "{repairs:?}");
        assert_eq!(repairs[0].space, SpaceId(2));
        assert!(
            matches!(repairs[0].what, RepairKind::SliverCut { other: SpaceId(1), area_m2 } if (area_m2 - 0.2).abs() < 1e-6)
        );
        // Boolean operations snap to a grid: micrometres here.
        assert!((out.spaces()[1].area_m2 - (144.0 - 0.2)).abs() < 1e-5);
        assert_eq!(out.spaces()[0], nrg.spaces()[0], "the smaller cell is kept");
        assert!(
            to_geo(&out.spaces()[0])
                .intersection(&to_geo(&out.spaces()[1]))
                .unsigned_area()
                < MIN_OVERLAP_M2
        );
    }

    #[test]
    fn a_cell_inside_another_becomes_its_hole() {
        let hall = square(1, 0.0, 0.0, 10.0);
        let kiosk = square(2, 4.0, 4.0, 2.0);
        let nrg = Nrg::new(
            vec![hall, kiosk],
            vec![Connection {
                a: SpaceId(1),
                b: SpaceId(2),
                kind: crate::model::ConnectionKind::Open,
                length_m: 1.0,
            }],
        )
        .unwrap();
        let (out, repairs) = repair_geometry(&nrg).unwrap();
        assert_eq!(repairs.len(), 1, "{repairs:?}");
        assert!(matches!(
            repairs[0].what,
            RepairKind::InnerCut {
                inner: SpaceId(2),
                ..
            }
        ));
        let hall = &out.spaces()[0];
        assert_eq!(hall.holes.len(), 1);
        assert!((hall.area_m2 - 96.0).abs() < 1e-5);
        // The hall's anchor (5, 5) fell into the kiosk: it moved inside.
        assert!(point_in_ring(hall.anchor, &hall.polygon));
        assert!(!point_in_ring(hall.anchor, &hall.holes[0]));
        assert_eq!(out.connections(), nrg.connections());
    }

    #[test]
    fn a_partial_overlap_is_left_for_the_caller() {
        // Half of each: neither a sliver nor nested.
        let nrg = Nrg::new(
            vec![square(1, 0.0, 0.0, 4.0), square(2, 2.0, 0.0, 4.0)],
            vec![],
        )
        .unwrap();
        let (out, repairs) = repair_geometry(&nrg).unwrap();
        assert!(repairs.is_empty());
        assert_eq!(out, nrg);
    }
}
