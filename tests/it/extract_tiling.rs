#![cfg(test)]
//! Every shared map's spaces tile their area: the geometric checks of
//! `nrgdb check` find nothing in the extracted model, and the union of the
//! space polygons has the summed area (no overlaps). Skips without the
//! shared maps (see `support::shared_dir`).

use geo::{Area, Coord, LineString, Polygon, unary_union};
use nrgdb::extract::{ExtractParams, extract};
use nrgdb::grid::{LoadOptions, load_map};
use nrgdb::indoorgml::{check, from_nrg};

/// The finding codes of `indoorgml::check` about geometry.
const GEOMETRIC: [&str; 6] = [
    "degenerate",
    "unclosed-ring",
    "self-intersection",
    "invalid-polygon",
    "wrong-orientation",
    "cells-overlap",
];

#[test]
fn every_shared_map_extracts_to_valid_spaces_that_tile_without_overlap() {
    let Some(shared) = crate::support::shared_dir("maps") else {
        return;
    };
    let dir = shared.join("maps");
    let mut maps: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .collect();
    maps.sort();
    assert!(!maps.is_empty());
    let mut bad = Vec::new();
    for path in &maps {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        let grid = load_map(path, &LoadOptions::default()).unwrap();
        let x = extract(&grid, &ExtractParams::default()).unwrap();
        for f in check(&from_nrg(&x.nrg)) {
            if GEOMETRIC.contains(&f.code) {
                bad.push(format!("{name}: {f}"));
            }
        }
        let line = |r: &[[f64; 2]]| {
            LineString::new(r.iter().map(|p| Coord { x: p[0], y: p[1] }).collect())
        };
        let polys: Vec<Polygon> = x
            .nrg
            .spaces()
            .iter()
            .map(|s| Polygon::new(line(&s.polygon), s.holes.iter().map(|h| line(h)).collect()))
            .collect();
        let sum: f64 = polys.iter().map(Area::unsigned_area).sum();
        let union = unary_union(&polys).unsigned_area();
        if (union - sum).abs() > 1e-6 * sum {
            bad.push(format!(
                "{name}: union {union} m² but the spaces sum to {sum} m²"
            ));
        }
        // The polygons follow the label image (within the simplification).
        let px = x.labels.data.iter().filter(|&&l| l != 0).count() as f64;
        let labelled = px * grid.resolution * grid.resolution;
        if (sum - labelled).abs() > 0.02 * labelled {
            bad.push(format!("{name}: spaces {sum} m², labels {labelled} m²"));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
