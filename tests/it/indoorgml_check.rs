//! `check` finds each kind of defect it promises, on documents broken on
//! purpose, and nothing on a clean export.

use nrgdb::indoorgml::document::{BoundaryClass, CellClass, CellGeometry, Document};
use nrgdb::indoorgml::{self, from_nrg};

use crate::support::{building, nrgdb};

fn codes(doc: &Document) -> Vec<&'static str> {
    indoorgml::check(doc).into_iter().map(|f| f.code).collect()
}

fn base() -> Document {
    from_nrg(&building(3))
}

fn layer(doc: &mut Document) -> &mut nrgdb::indoorgml::document::Layer {
    &mut doc.graph.as_mut().unwrap().layer_groups[0].layers[0]
}

#[test]
fn clean_export_has_no_findings() {
    assert!(codes(&base()).is_empty());
}

#[test]
fn dangling_and_mistyped_references() {
    let mut doc = base();
    doc.primal.as_mut().unwrap().cells[0].duality = Some("nowhere".into());
    layer(&mut doc).transitions[0].connects[0] = "C10".into();
    let c = codes(&doc);
    assert!(c.contains(&"dangling-href"), "{c:?}");
    assert!(c.contains(&"wrong-target"), "{c:?}");
}

#[test]
fn duality_and_connects_not_mutual() {
    let mut doc = base();
    layer(&mut doc).states[0].duality = Some("C10".into());
    layer(&mut doc).states[1].connects.clear();
    let c = codes(&doc);
    assert!(c.contains(&"duality-not-mutual"), "{c:?}");
    assert!(c.contains(&"connects-not-mutual"), "{c:?}");
}

#[test]
fn broken_polygons() {
    let mut doc = base();
    let cells = &mut doc.primal.as_mut().unwrap().cells;
    // Unclosed ring: drop the closing position.
    if let Some(CellGeometry::Surface(p)) = &mut cells[0].geometry {
        p.exterior.values.truncate(p.exterior.values.len() - 2);
        p.exterior
            .values
            .extend([p.exterior.values[0] + 0.5, p.exterior.values[1]]);
    }
    // Self-intersecting bow tie.
    if let Some(CellGeometry::Surface(p)) = &mut cells[1].geometry {
        p.exterior.values = vec![
            100.0, 100.0, 101.0, 101.0, 101.0, 100.0, 100.0, 101.0, 100.0, 100.0,
        ];
    }
    // Clockwise exterior.
    if let Some(CellGeometry::Surface(p)) = &mut cells[2].geometry {
        let pts: Vec<f64> = p
            .exterior
            .values
            .chunks(2)
            .rev()
            .flatten()
            .copied()
            .collect();
        p.exterior.values = pts;
    }
    let c = codes(&doc);
    for want in ["unclosed-ring", "self-intersection", "wrong-orientation"] {
        assert!(c.contains(&want), "{want} missing from {c:?}");
    }
}

#[test]
fn overlapping_cells_in_one_layer() {
    let mut doc = base();
    let cells = &mut doc.primal.as_mut().unwrap().cells;
    let copy = cells[2].geometry.clone();
    cells[3].geometry = copy;
    assert!(codes(&doc).contains(&"cells-overlap"));
}

#[test]
fn thick_and_thin_doors_mixed() {
    let mut doc = base();
    let p = doc.primal.as_mut().unwrap();
    assert!(
        p.cells
            .iter()
            .any(|c| c.class == CellClass::ConnectionSpace)
    );
    p.boundaries[0].class = BoundaryClass::ConnectionBoundary;
    assert!(codes(&doc).contains(&"doors-mixed"));
}

#[test]
fn cli_check_exit_codes() {
    let dir = tempfile::tempdir().unwrap();
    let clean = dir.path().join("clean.gml");
    indoorgml::write_file(&base(), &clean).unwrap();
    let out = nrgdb(dir.path(), &["check", "clean.gml", "--no-schema"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let mut broken = base();
    layer(&mut broken).states[0].duality = Some("nowhere".into());
    indoorgml::write_file(&broken, &dir.path().join("broken.gml")).unwrap();
    let out = nrgdb(dir.path(), &["check", "broken.gml", "--no-schema"]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("dangling-href") && stdout.contains("line "),
        "{stdout}"
    );
    let out = nrgdb(dir.path(), &["check", "missing.gml"]);
    assert_eq!(out.status.code(), Some(2));
}

/// `n`×`n` square rooms of 1.5 m on a 2 m grid (none overlapping), then
/// `piled` more rooms all on the first one.
fn many_rooms(n: u32, piled: u32) -> nrgdb::model::Nrg {
    use nrgdb::model::{Nrg, Space, SpaceId, SpaceKind};
    let square = |x: f64, y: f64| vec![[x, y], [x + 1.5, y], [x + 1.5, y + 1.5], [x, y + 1.5]];
    let mut spaces = Vec::new();
    for k in 0..n * n {
        let (x, y) = (f64::from(k % n) * 2.0, f64::from(k / n) * 2.0);
        spaces.push(Space::new(
            SpaceId(k + 1),
            SpaceKind::Room,
            [x + 0.7, y + 0.7],
            square(x, y),
        ));
    }
    for k in 0..piled {
        let id = SpaceId(n * n + k + 1);
        spaces.push(Space::new(
            id,
            SpaceKind::Room,
            [0.7, 0.7],
            square(0.0, 0.0),
        ));
    }
    Nrg::new(spaces, vec![]).unwrap()
}

/// Issue 21, defect 8: `check` compared every pair of cells (20 000 cells:
/// 200 million pairs). Cells are paired through an R-tree of their boxes:
/// 22 500 side by side give no finding; a pile of 1 000 cells on one spot
/// (half a million overlapping pairs) stops at the bound with one finding
/// saying so, instead of computing every intersection.
#[test]
fn issue_21_defect_8_overlaps_of_many_cells_are_bounded() {
    let doc = from_nrg(&many_rooms(150, 0));
    let found = indoorgml::check(&doc);
    assert!(found.is_empty(), "{:?}", &found[..found.len().min(3)]);
    let doc = from_nrg(&many_rooms(10, 1_000));
    let c = codes(&doc);
    assert_eq!(
        c.iter().filter(|&&c| c == "overlap-check-stopped").count(),
        1
    );
    let overlaps = c.iter().filter(|&&c| c == "cells-overlap").count();
    assert!((1_000..=100_000).contains(&overlaps), "{overlaps}");
}
