//! Cells of one layer must not overlap (IndoorGML Req 2, which the OGC
//! test suite computes but ignores). Each cell's 2D footprint (3D cells:
//! floor face, with the solid's z range) is compared with the others of its
//! layer whose bounding boxes overlap its own (found with an R-tree, so
//! 20 000 cells are not 200 million pairs: issue 21, defect 8), then by the
//! exact intersection area. At most [`MAX_OVERLAP_TESTS`] intersections
//! are computed per document; past it one finding says the check stopped.

use std::collections::HashMap;

use geo::{
    Area, BooleanOps, BoundingRect, Coord, LineString as GeoLine, Polygon as GeoPolygon, Rect,
};
use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{AABB, RTree};

use super::super::convert::footprint;
use super::super::document::{CellGeometry, Document, Target};
use super::{Finding, finding};

use crate::model::{MAX_OVERLAP_TESTS, MIN_OVERLAP_M2};

struct Footprint<'a> {
    id: &'a str,
    line: usize,
    polygon: GeoPolygon,
    rect: Rect,
    z: (f64, f64),
}

pub fn check_overlaps(doc: &Document, out: &mut Vec<Finding>) {
    let index = doc.index();
    // Group cells by the layer of their dual State; cells without one form
    // the primal group (usize::MAX).
    let mut groups: HashMap<usize, Vec<Footprint>> = HashMap::new();
    for c in doc.cells() {
        let group = c
            .duality
            .as_deref()
            .and_then(|d| index.get(d))
            .and_then(|t| {
                if let Target::State(l, _) = t {
                    Some(*l)
                } else {
                    None
                }
            })
            .unwrap_or(usize::MAX);
        let Ok((ring, holes)) = footprint(c) else {
            continue;
        };
        // geo's boolean operations panic on coordinates near 1e308 (issue
        // 21, defect 5): such a cell is a finding of its own, not compared.
        let limit = crate::model::MAX_COORD_M;
        if std::iter::once(&ring)
            .chain(&holes)
            .flatten()
            .any(|p| !(p[0].abs() <= limit && p[1].abs() <= limit))
        {
            out.push(finding(
                "coordinates-out-of-range",
                &c.info.id,
                c.info.line,
                format!("has a coordinate more than {limit} m from the origin (or not a number)"),
            ));
            continue;
        }
        let line =
            |r: &[[f64; 2]]| GeoLine::new(r.iter().map(|p| Coord { x: p[0], y: p[1] }).collect());
        let polygon = GeoPolygon::new(line(&ring), holes.iter().map(|h| line(h)).collect());
        let Some(rect) = polygon.bounding_rect() else {
            continue;
        };
        let z = match &c.geometry {
            Some(CellGeometry::Solid(s)) => s
                .exterior
                .iter()
                .flat_map(|p| p.exterior.z())
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), z| {
                    (lo.min(z), hi.max(z))
                }),
            // A flat cell lies at its height (0 in 2D).
            Some(CellGeometry::Surface(p)) => p.exterior.z().next().map_or((0.0, 0.0), |z| (z, z)),
            None => (0.0, 0.0),
        };
        groups.entry(group).or_default().push(Footprint {
            id: &c.info.id,
            line: c.info.line,
            polygon,
            rect,
            z,
        });
    }
    let mut groups: Vec<(usize, Vec<Footprint>)> = groups.into_iter().collect();
    groups.sort_by_key(|(g, _)| *g);
    let mut tests = 0usize;
    for (_, cells) in &groups {
        let tree = RTree::bulk_load(
            cells
                .iter()
                .enumerate()
                .map(|(i, c)| {
                    GeomWithData::new(Rectangle::from_corners(lower(&c.rect), upper(&c.rect)), i)
                })
                .collect(),
        );
        for (i, a) in cells.iter().enumerate() {
            let envelope = AABB::from_corners(lower(&a.rect), upper(&a.rect));
            let mut near: Vec<usize> = tree
                .locate_in_envelope_intersecting(&envelope)
                .map(|r| r.data)
                .filter(|&j| j > i)
                .collect();
            near.sort_unstable();
            for b in near.into_iter().filter_map(|j| cells.get(j)) {
                if !rects_overlap(&a.rect, &b.rect) || !z_overlap(a.z, b.z) {
                    continue;
                }
                tests += 1;
                if tests > MAX_OVERLAP_TESTS {
                    out.push(finding(
                        "overlap-check-stopped",
                        a.id,
                        a.line,
                        format!(
                            "more than {MAX_OVERLAP_TESTS} pairs of cells have overlapping \
                             bounding boxes; the cells from here on were not compared"
                        ),
                    ));
                    return;
                }
                let area = a.polygon.intersection(&b.polygon).unsigned_area();
                if area > MIN_OVERLAP_M2 {
                    out.push(finding(
                        "cells-overlap",
                        b.id,
                        b.line,
                        if a.line > 0 {
                            format!(
                                "overlaps cell {} (line {}) by {area:.4} m² in the same layer",
                                a.id, a.line
                            )
                        } else {
                            format!("overlaps cell {} by {area:.4} m² in the same layer", a.id)
                        },
                    ));
                }
            }
        }
    }
}

fn lower(r: &Rect) -> [f64; 2] {
    [r.min().x, r.min().y]
}

fn upper(r: &Rect) -> [f64; 2] {
    [r.max().x, r.max().y]
}

fn rects_overlap(a: &Rect, b: &Rect) -> bool {
    a.min().x < b.max().x && b.min().x < a.max().x && a.min().y < b.max().y && b.min().y < a.max().y
}

fn z_overlap(a: (f64, f64), b: (f64, f64)) -> bool {
    // Two flat cells (2D, or a level's floor) meet when at one height; a
    // flat cell and a solid are compared as in 2D.
    match (a.0 == a.1, b.0 == b.1) {
        (true, true) => return (a.0 - b.0).abs() < 1e-6,
        (true, false) | (false, true) => return true,
        (false, false) => {}
    }
    a.0.max(b.0) < a.1.min(b.1) - 1e-6
}
