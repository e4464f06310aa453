//! Validity of one 2D polygon: geo's polygon rules (simple rings with at
//! least three distinct points, finite coordinates, holes inside the
//! exterior, rings touching at points only), with the same messages, but
//! without geo's all-pairs loop over a ring's segments (issue 21, defect
//! 8: `check` on a 50 000-vertex polygon took 17.8 s). Segments are paired
//! through an R-tree of their bounding boxes, holes likewise, and the
//! segment pairs looked at are bounded ([`MAX_SEGMENT_PAIRS`]).
//!
//! Used by `nrgdb check` (`indoorgml::check`) and by the geometry repairs
//! ([`super::repair_geometry`]). Uses geo (predicates, relate) and rstar;
//! nothing of the crate.

use geo::coordinate_position::CoordPos;
use geo::dimensions::Dimensions;
use geo::{
    BoundingRect, Coord, Intersects, Line, LineString, Polygon, PreparedGeometry, Relate,
    RemoveRepeatedPoints,
};
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{AABB, RTree, RTreeObject};

/// Segment pairs with overlapping boxes looked at per ring at most; past
/// it the ring is reported as too complex instead of being checked.
pub(crate) const MAX_SEGMENT_PAIRS: usize = 4_000_000;

/// What is wrong with a polygon, worded as geo words it ("exterior ring
/// has a self-intersection").
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum PolygonError {
    /// A ring crosses or touches itself.
    SelfIntersection(String),
    /// Anything else.
    Invalid(String),
}

fn role(ring: usize) -> String {
    match ring {
        0 => "exterior ring".to_string(),
        i => format!("interior ring at index {}", i - 1),
    }
}

/// Every rule `polygon` breaks.
pub(crate) fn polygon_errors(polygon: &Polygon) -> Vec<PolygonError> {
    let mut errors = Vec::new();
    let rings = std::iter::once(polygon.exterior()).chain(polygon.interiors());
    for (i, ring) in rings.enumerate() {
        if ring.0.is_empty() {
            continue;
        }
        if ring.remove_repeated_points().0.len() < 4 {
            errors.push(PolygonError::Invalid(format!(
                "{} must have at least 3 distinct points",
                role(i)
            )));
        }
        // Non-finite coordinates first: the R-tree cannot order them.
        if let Some(k) = ring
            .0
            .iter()
            .position(|c| !(c.x.is_finite() && c.y.is_finite()))
        {
            errors.push(PolygonError::Invalid(format!(
                "{} has a non-finite coordinate at index {k}",
                role(i)
            )));
            continue;
        }
        match ring_self_intersects(ring) {
            Some(true) => errors.push(PolygonError::SelfIntersection(format!(
                "{} has a self-intersection",
                role(i)
            ))),
            Some(false) => {}
            None => errors.push(PolygonError::Invalid(format!(
                "{} is too complex to check for self-intersections (more than \
                 {MAX_SEGMENT_PAIRS} pairs of segments with overlapping boxes)",
                role(i)
            ))),
        }
    }
    if errors.is_empty() {
        check_holes(polygon, &mut errors);
    }
    errors
}

/// Holes inside the exterior, touching it and each other at points only;
/// only holes whose boxes meet are related to each other.
fn check_holes(polygon: &Polygon, errors: &mut Vec<PolygonError>) {
    let holes: Vec<Polygon> = polygon
        .interiors()
        .iter()
        .filter(|r| !r.0.is_empty())
        .map(|r| Polygon::new(r.clone(), vec![]))
        .collect();
    if holes.is_empty() {
        return;
    }
    let outer = Polygon::new(polygon.exterior().clone(), vec![]);
    let outer = PreparedGeometry::from(&outer);
    let boxes: Vec<GeomWithData<Rectangle<[f64; 2]>, usize>> = holes
        .iter()
        .enumerate()
        .filter_map(|(k, h)| {
            let r = h.bounding_rect()?;
            Some(GeomWithData::new(
                Rectangle::from_corners([r.min().x, r.min().y], [r.max().x, r.max().y]),
                k,
            ))
        })
        .collect();
    let tree = RTree::bulk_load(boxes.clone());
    for b in &boxes {
        let k = b.data;
        let hole = PreparedGeometry::from(&holes[k]);
        let m = outer.relate(&hole);
        if !m.is_contains() {
            errors.push(PolygonError::Invalid(format!(
                "{} is not contained within the polygon's exterior",
                role(k + 1)
            )));
        }
        if m.get(CoordPos::OnBoundary, CoordPos::OnBoundary) == Dimensions::OneDimensional {
            errors.push(PolygonError::Invalid(format!(
                "{} and {} intersect on a line",
                role(0),
                role(k + 1)
            )));
        }
        for other in tree.locate_in_envelope_intersecting(&b.geom().envelope()) {
            let j = other.data;
            if j <= k {
                continue;
            }
            let m = hole.relate(&holes[j]);
            if m.get(CoordPos::Inside, CoordPos::Inside) == Dimensions::TwoDimensional {
                errors.push(PolygonError::Invalid(format!(
                    "{} and {} intersect on an area",
                    role(k + 1),
                    role(j + 1)
                )));
            }
            if m.get(CoordPos::OnBoundary, CoordPos::OnBoundary) == Dimensions::OneDimensional {
                errors.push(PolygonError::Invalid(format!(
                    "{} and {} intersect on a line",
                    role(k + 1),
                    role(j + 1)
                )));
            }
        }
    }
}

/// Whether two segments of `ring` other than neighbours meet (geo's rule:
/// segments that share an end with the other's start are neighbours).
/// `None` when more than [`MAX_SEGMENT_PAIRS`] pairs would be looked at.
/// The coordinates must be finite (the R-tree orders them).
pub(crate) fn ring_self_intersects(ring: &LineString) -> Option<bool> {
    let lines: Vec<Line> = ring.lines().collect();
    let boxes: Vec<GeomWithData<Rectangle<[f64; 2]>, usize>> = lines
        .iter()
        .enumerate()
        .map(|(i, l)| GeomWithData::new(Rectangle::from_corners(xy(l.start), xy(l.end)), i))
        .collect();
    let tree = RTree::bulk_load(boxes);
    let mut pairs = 0usize;
    for (i, a) in lines.iter().enumerate() {
        let envelope = AABB::from_corners(xy(a.start), xy(a.end));
        for other in tree.locate_in_envelope_intersecting(&envelope) {
            let j = other.data;
            if j <= i {
                continue;
            }
            pairs += 1;
            if pairs > MAX_SEGMENT_PAIRS {
                return None;
            }
            let Some(b) = lines.get(j) else { continue };
            if a.intersects(b) && a.start != b.end && a.end != b.start {
                return Some(true);
            }
        }
    }
    Some(false)
}

fn xy(c: Coord) -> [f64; 2] {
    [c.x, c.y]
}

#[cfg(test)]
mod tests {
    use geo::{Validation, line_string, polygon};

    use super::*;

    /// Same verdicts and messages as geo's own validation on small cases.
    #[test]
    fn agrees_with_geo() {
        let cases = [
            polygon![(x: 0., y: 0.), (x: 4., y: 0.), (x: 4., y: 4.), (x: 0., y: 4.)],
            polygon![(x: 0., y: 0.), (x: 4., y: 4.), (x: 4., y: 0.), (x: 0., y: 4.)],
            polygon![(x: 0., y: 0.), (x: 4., y: 0.), (x: 0., y: 0.)],
            polygon![
                exterior: [(x: 0., y: 0.), (x: 10., y: 0.), (x: 10., y: 10.), (x: 0., y: 10.)],
                interiors: [
                    [(x: 1., y: 1.), (x: 1., y: 3.), (x: 3., y: 3.), (x: 3., y: 1.)],
                    [(x: 2., y: 2.), (x: 2., y: 4.), (x: 4., y: 4.), (x: 4., y: 2.)],
                    [(x: 8., y: 8.), (x: 8., y: 12.), (x: 12., y: 12.), (x: 12., y: 8.)],
                ],
            ],
            // A spike: the ring goes out and back along the same line.
            polygon![(x: 0., y: 0.), (x: 4., y: 0.), (x: 6., y: 0.), (x: 4., y: 0.), (x: 4., y: 4.), (x: 0., y: 4.)],
        ];
        for p in cases {
            let ours: Vec<String> = polygon_errors(&p)
                .into_iter()
                .map(|e| match e {
                    PolygonError::SelfIntersection(m) | PolygonError::Invalid(m) => m,
                })
                .collect();
            let geos: Vec<String> = p
                .validation_errors()
                .iter()
                .map(|e| e.to_string())
                .collect();
            if ours.is_empty() || geos.is_empty() {
                assert_eq!(ours, geos, "{p:?}");
            } else {
                // geo goes on to the holes after a bad ring; we stop there.
                assert!(
                    ours.iter().all(|m| geos.contains(m)),
                    "{ours:?} vs {geos:?}"
                );
            }
        }
    }

    #[test]
    fn squares_and_bow_ties() {
        let square = line_string![(x: 0., y: 0.), (x: 1., y: 0.), (x: 1., y: 1.), (x: 0., y: 1.), (x: 0., y: 0.)];
        let bow_tie = line_string![(x: 0., y: 0.), (x: 1., y: 1.), (x: 1., y: 0.), (x: 0., y: 1.), (x: 0., y: 0.)];
        assert_eq!(ring_self_intersects(&square), Some(false));
        assert_eq!(ring_self_intersects(&bow_tie), Some(true));
    }

    /// Issue 21, defect 8: a ring of 200 000 vertices (a zigzag whose
    /// segments' boxes meet their neighbours only) is checked pairing
    /// neighbours only, where geo's loop would look at 4·10¹⁰ pairs; a
    /// crossing in it is found.
    #[test]
    fn issue_21_defect_8_a_huge_ring_is_checked_without_all_pairs() {
        let n = 100_000;
        let mut coords: Vec<Coord> = (0..n)
            .map(|i| Coord {
                x: f64::from(i),
                y: f64::from(i % 2),
            })
            .collect();
        coords.extend((0..n).rev().map(|i| Coord {
            x: f64::from(i),
            y: -1.0 - f64::from(i % 2),
        }));
        coords.push(coords[0]);
        let ring = LineString::new(coords);
        assert_eq!(ring_self_intersects(&ring), Some(false));
        // One vertex of the upper zigzag pulled down through the lower one.
        let mut crossed = ring.0.clone();
        crossed[10].y = -5.0;
        assert_eq!(ring_self_intersects(&LineString::new(crossed)), Some(true));
    }

    /// Issue 21, defect 8: where most segments' boxes overlap (a serpentine
    /// of long parallel diagonals) the work stops at the bound and the
    /// ring is reported as too complex, not checked for minutes.
    #[test]
    fn issue_21_defect_8_overlapping_boxes_stop_at_the_bound() {
        let mut coords = Vec::new();
        for k in 0..3_000 {
            let x = f64::from(k) * 2.0;
            let (a, b) = ([x, 0.0], [x + 2000.0, 2000.0]);
            let (first, second) = if k % 2 == 0 { (a, b) } else { (b, a) };
            coords.push(Coord {
                x: first[0],
                y: first[1],
            });
            coords.push(Coord {
                x: second[0],
                y: second[1],
            });
        }
        let last = coords[coords.len() - 1];
        coords.push(Coord { x: last.x, y: -1.0 });
        coords.push(Coord { x: 0.0, y: -1.0 });
        coords.push(coords[0]);
        let ring = LineString::new(coords);
        assert_eq!(ring_self_intersects(&ring), None);
        let errors = polygon_errors(&Polygon::new(ring, vec![]));
        assert!(
            errors
                .iter()
                .any(|e| matches!(e, PolygonError::Invalid(m) if m.contains("too complex"))),
            "{errors:?}"
        );
    }
}
