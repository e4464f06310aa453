//! Buildings with floors (issue 25): levels in the model, kept through
//! model JSON and IndoorGML (3D polygons at each level's elevation, the
//! level in the cell's description), a document of stacked 3D floors read
//! as its levels, and the checker judging overlaps floor by floor.

use nrgdb::format::{ModelFormat, model_from_bytes, render};
use nrgdb::model::{ConnectionKind, SpaceKind};
use nrgdb::route::walked_model;

use crate::support::shared_dir;

#[test]
fn a_three_storey_building_goes_through_indoorgml_whole() {
    let nrg = nrgdb::fixtures::storeys(3, 4);
    let walked = walked_model(&nrg);
    let gml = render(&walked, ModelFormat::IndoorGml);
    // Level 2's cells lie at 7 m.
    assert!(gml.contains(r#"srsDimension="3""#));
    assert!(gml.contains(" 7 ") || gml.contains(" 7\n") || gml.contains(" 7<"));
    let doc = nrgdb::indoorgml::read_str(&gml).unwrap();
    assert!(
        nrgdb::indoorgml::check(&doc).is_empty(),
        "{:?}",
        nrgdb::indoorgml::check(&doc)
    );
    let (back, _) =
        model_from_bytes(gml.as_bytes(), ModelFormat::IndoorGml, "t.gml".as_ref()).unwrap();
    assert_eq!(back, walked.nrg);
    assert_eq!(back.levels().len(), 3);
    let vertical = back
        .connections()
        .iter()
        .filter(|c| c.kind == ConnectionKind::Vertical)
        .count();
    assert_eq!(vertical, 5);
    // Walking does not flatten a climb: stairs keep their cost.
    for (c, w) in nrg.connections().iter().zip(back.connections()) {
        if c.kind == ConnectionKind::Vertical {
            assert_eq!(c.length_m, w.length_m, "{}-{}", c.a, c.b);
        }
    }
    // Floors stacked on one plane would overlap; per level they do not.
    let stairs = back
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Stairs)
        .count();
    assert_eq!(stairs, 3);
}

#[test]
fn levels_come_from_the_heights_of_a_3d_document() {
    // Two floors written at 0 m and 3.5 m without the level extras, as
    // another program writes stacked floors.
    let nrg = nrgdb::fixtures::storeys(2, 3);
    let gml = render(&walked_model(&nrg), ModelFormat::IndoorGml);
    let mut doc = nrgdb::indoorgml::read_str(&gml).unwrap();
    for cell in &mut doc.primal.as_mut().unwrap().cells {
        let text = cell.info.description.take().unwrap();
        let mut value: serde_json::Value = serde_json::from_str(&text).unwrap();
        value
            .as_object_mut()
            .unwrap()
            .remove("nrgdb:level")
            .unwrap();
        if value.as_object().is_some_and(|o| !o.is_empty()) {
            cell.info.description = Some(value.to_string());
        }
    }
    let gml = nrgdb::indoorgml::write_string(&doc);
    assert!(!gml.contains("nrgdb:level"), "the extras are gone");
    let (back, _) =
        model_from_bytes(gml.as_bytes(), ModelFormat::IndoorGml, "t.gml".as_ref()).unwrap();
    let levels = back.levels();
    assert_eq!(
        levels
            .iter()
            .map(|l| (l.name.as_str(), l.elevation_m))
            .collect::<Vec<_>>(),
        [("0", 0.0), ("1", 3.5)]
    );
    assert_eq!(back.spaces().len(), nrg.spaces().len());
}

#[test]
fn sample_201_reads_as_its_three_floors() {
    let Some(shared) = shared_dir("indoorgml/samples/201-2019-05-24-corrected.gml") else {
        return;
    };
    let path = shared.join("indoorgml/samples/201-2019-05-24-corrected.gml");
    let bytes = std::fs::read(&path).unwrap();
    let (nrg, _) = model_from_bytes(&bytes, ModelFormat::IndoorGml, &path).unwrap();
    // The file: 80 cells (MANIFEST.md), on three floors.
    assert_eq!(nrg.spaces().len(), 80);
    let levels = nrg.levels();
    assert_eq!(levels.len(), 3, "{levels:?}");
    let mut per_level: Vec<usize> = levels
        .iter()
        .map(|l| {
            nrg.spaces()
                .iter()
                .filter(|s| s.level.as_ref().is_some_and(|m| m.name == l.name))
                .count()
        })
        .collect();
    eprintln!("201: levels {levels:?}, spaces per level {per_level:?}");
    per_level.sort_unstable();
    assert!(per_level[0] >= 10, "{per_level:?}");
}
