//! Every real IndoorGML sample either imports or is refused with one clear
//! line; importable ones survive import → export → import unchanged, and
//! their exports are schema-valid.

use std::path::{Path, PathBuf};

use nrgdb::indoorgml::document::{BoundaryClass, CellClass, Document};
use nrgdb::indoorgml::{self, read_file, read_str, write_string};

use crate::support::{have_xmllint, shared_dir};

/// Samples that are refused, and why (the error must say so).
const REFUSED: &[(&str, &str)] = &[
    // (FZK-Haus_full.gml misspells <SpaceLayer> as <spaceLayer>: read with
    // a warning since issue 21, see below.)
    // Extension elements substituting core:State, no schema: schema-invalid.
    (
        "KU-Central-Plaza-IndoorGML-PS-without-Texture-04-26-corrected.gml",
        "PublicSafetyFirePump",
    ),
    // Root is navi:Route, not IndoorFeatures.
    ("navi.gml", "the root element is navi:Route"),
    // IndoorGML 2.0 draft namespace.
    ("sample-PUN-IT-2026-05-06.gml", "IndoorGML 2.0"),
];

fn samples() -> Option<Vec<PathBuf>> {
    let shared = shared_dir("indoorgml/samples")?;
    let mut files: Vec<PathBuf> = std::fs::read_dir(shared.join("indoorgml/samples"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "gml"))
        .collect();
    files.sort();
    Some(files)
}

fn name(p: &Path) -> &str {
    p.file_name().and_then(|n| n.to_str()).unwrap()
}

/// Forgets source line numbers and maps extension classes to what is
/// written for them, so two reads of equivalent documents compare equal.
fn normalise(mut doc: Document) -> Document {
    doc.info.line = 0;
    doc.warnings.clear();
    if let Some(p) = &mut doc.primal {
        p.info.line = 0;
        for c in &mut p.cells {
            c.info.line = 0;
            if let CellClass::Extension(_) = c.class {
                c.class = CellClass::CellSpace;
            }
        }
        for b in &mut p.boundaries {
            b.info.line = 0;
            if let BoundaryClass::Extension(_) = b.class {
                b.class = BoundaryClass::CellSpaceBoundary;
            }
        }
    }
    if let Some(g) = &mut doc.graph {
        g.info.line = 0;
        for group in &mut g.layer_groups {
            for l in &mut group.layers {
                l.info.line = 0;
                l.states.iter_mut().for_each(|s| s.info.line = 0);
                l.transitions.iter_mut().for_each(|t| t.info.line = 0);
            }
        }
        for group in &mut g.inter_edges {
            group.connections.iter_mut().for_each(|c| c.info.line = 0);
        }
    }
    doc
}

#[test]
fn every_sample_imports_or_is_refused_clearly() {
    let Some(files) = samples() else { return };
    assert!(
        files.len() >= 10,
        "expected the dev samples, found {}",
        files.len()
    );
    for file in &files {
        let result = read_file(file, indoorgml::DEFAULT_MAX_BYTES);
        match REFUSED.iter().find(|(n, _)| *n == name(file)) {
            Some((_, why)) => {
                let err = result.expect_err(name(file)).to_string();
                assert!(err.contains(why), "{}: {err}", name(file));
                assert!(
                    err.starts_with("line "),
                    "{}: error must give the line: {err}",
                    name(file)
                );
                assert!(
                    !err.contains('\n'),
                    "{}: error must be one line: {err}",
                    name(file)
                );
            }
            None => {
                let doc = result.unwrap_or_else(|e| panic!("{}: {e}", name(file)));
                indoorgml::to_nrg(&doc).unwrap_or_else(|e| panic!("{}: to model: {e}", name(file)));
            }
        }
    }
}

#[test]
fn importable_samples_round_trip() {
    let Some(files) = samples() else { return };
    for file in files
        .iter()
        .filter(|f| !REFUSED.iter().any(|(n, _)| *n == name(f)))
    {
        let first = read_file(file, indoorgml::DEFAULT_MAX_BYTES).unwrap();
        let text = write_string(&first);
        let second = read_str(&text).unwrap_or_else(|e| panic!("{}: re-import: {e}", name(file)));
        assert_eq!(
            normalise(second.clone()),
            normalise(first.clone()),
            "{}",
            name(file)
        );
        assert_eq!(
            write_string(&second),
            text,
            "{}: export must be byte-stable",
            name(file)
        );
        let m1 = indoorgml::to_nrg(&first).unwrap();
        let m2 = indoorgml::to_nrg(&second).unwrap();
        assert_eq!(m1, m2, "{}", name(file));
    }
}

#[test]
fn sample_counts_match_the_manifest() {
    let Some(shared) = shared_dir("indoorgml/samples") else {
        return;
    };
    let dir = shared.join("indoorgml/samples");
    // (file, cells, boundaries, states, transitions, layers, inter-layer connections): MANIFEST.md
    let expected = [
        ("201-2019-05-24-corrected.gml", 80, 192, 80, 184, 1, 0),
        ("313-4F-2D-190612.gml", 30, 58, 30, 0, 1, 0),
        ("313_4F_2D.gml", 54, 58, 54, 55, 1, 0),
        ("sample-3D.gml", 54, 104, 128, 232, 4, 75),
        ("KU-EngBuilding-IndoorGML-2019-01-31.gml", 7, 39, 0, 0, 0, 0),
        ("indoorgml_core_mockup.gml", 3, 6, 7, 7, 2, 4),
        (
            "FJK-Haus_IndoorGML_withEXR-corrected_1_0_3.gml",
            14,
            0,
            14,
            30,
            1,
            0,
        ),
    ];
    for (file, cells, boundaries, states, transitions, layers, ilcs) in expected {
        let doc = read_file(&dir.join(file), indoorgml::DEFAULT_MAX_BYTES).unwrap();
        let ls = doc.layers();
        let got = (
            doc.cells().len(),
            doc.boundaries().len(),
            ls.iter().map(|l| l.states.len()).sum::<usize>(),
            ls.iter().map(|l| l.transitions.len()).sum::<usize>(),
            ls.len(),
            doc.graph
                .iter()
                .flat_map(|g| &g.inter_edges)
                .map(|e| e.connections.len())
                .sum::<usize>(),
        );
        assert_eq!(
            got,
            (cells, boundaries, states, transitions, layers, ilcs),
            "{file}"
        );
    }
}

#[test]
fn exports_of_valid_samples_are_schema_valid() {
    let Some(shared) = shared_dir("indoorgml/validate.sh") else {
        return;
    };
    if !have_xmllint() && std::env::var("NRGDB_REQUIRE_SHARED").as_deref() != Ok("1") {
        eprintln!("notice: skipping, xmllint missing");
        return;
    }
    let Some(files) = samples() else { return };
    let out = tempfile::tempdir().unwrap();
    let mut written = Vec::new();
    for file in files
        .iter()
        .filter(|f| !REFUSED.iter().any(|(n, _)| *n == name(f)))
    {
        let doc = read_file(file, indoorgml::DEFAULT_MAX_BYTES).unwrap();
        let path = out.path().join(name(file));
        indoorgml::write_file(&doc, &path).unwrap();
        written.push(path);
    }
    let status = std::process::Command::new("bash")
        .arg(shared.join("indoorgml/validate.sh"))
        .arg("--quiet")
        .args(&written)
        .status()
        .unwrap();
    assert!(
        status.success(),
        "some exported samples are not schema-valid (see stderr)"
    );
}

/// 313_4F_2D's Transitions all have weight 0 but a LineString: on import
/// each gets its LineString's length, no connection is 0 m long, and the
/// import says how many it fixed (the library's count, the CLI's line).
#[test]
fn sample_313_zero_weights_are_fixed_on_import() {
    let Some(shared) = shared_dir("indoorgml/samples/313_4F_2D.gml") else {
        return;
    };
    let file = shared
        .join("indoorgml/samples/313_4F_2D.gml")
        .canonicalize()
        .unwrap();
    let doc = read_file(&file, indoorgml::DEFAULT_MAX_BYTES).unwrap();
    let zero: usize = doc
        .layers()
        .iter()
        .flat_map(|l| &l.transitions)
        .filter(|t| t.weight.is_none_or(|w| w == 0.0))
        .count();
    assert!(zero > 0, "the sample has weight-0 Transitions");
    let (nrg, fixes) = nrgdb::format::from_document(&doc).unwrap();
    let navigable: Vec<_> = nrg
        .connections()
        .iter()
        .filter(|c| c.kind.is_navigable())
        .collect();
    assert_eq!(fixes.total(), navigable.len());
    assert!(fixes.total() <= zero);
    assert_eq!(fixes.from_geometry, fixes.total(), "all have a LineString");
    for c in nrg.connections() {
        assert!(c.length_m > 0.0, "{:?} has length {}", c.key(), c.length_m);
    }
    // Each fixed length is its Transition's own LineString length.
    let t = doc
        .layers()
        .iter()
        .flat_map(|l| &l.transitions)
        .find(|t| t.info.id == "T1")
        .unwrap();
    let pts: Vec<[f64; 2]> = t.geometry.as_ref().unwrap().coords.xy().collect();
    let own: f64 = pts
        .windows(2)
        .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
        .sum();
    assert!(own > 0.0);
    assert!(
        nrg.connections()
            .iter()
            .any(|c| (c.length_m - own).abs() < 1e-9)
    );

    let dir = tempfile::tempdir().unwrap();
    let out = crate::support::nrgdb(
        dir.path(),
        &[
            "import",
            "--db",
            "t.db",
            "--map",
            "m",
            // Two of its rooms overlap by 25 m²: refused without this.
            "--allow-invalid",
            file.to_str().unwrap(),
        ],
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let line = format!(
        "fixed {} transition weights (missing or 0): set from their geometry",
        fixes.total()
    );
    assert!(stdout.contains(&line), "{stdout}");
    let stored = nrgdb::store::Store::open(&dir.path().join("t.db"))
        .unwrap()
        .load("m", None)
        .unwrap();
    assert!(stored.connections().iter().all(|c| c.length_m > 0.0));
}

/// Issue 19: converting a sample into a model file either refuses it (the
/// cells overlap by more than slivers) and writes nothing, or writes a
/// file that `nrgdb check` (with the OGC schema when xmllint is there)
/// calls clean — whatever was repaired on the way.
#[test]
fn issue_19_sample_models_written_by_convert_check_clean_or_are_refused() {
    let Some(files) = samples() else { return };
    let out = tempfile::tempdir().unwrap();
    let mut written = 0;
    for file in files
        .iter()
        .filter(|f| !REFUSED.iter().any(|(n, _)| *n == name(f)))
    {
        let gml = out.path().join(name(file));
        let convert = std::process::Command::new(env!("CARGO_BIN_EXE_nrgdb"))
            .arg("convert")
            .arg(file)
            .arg(out.path().join("model.json"))
            .output()
            .unwrap();
        if !convert.status.success() {
            let said = String::from_utf8_lossy(&convert.stderr);
            assert!(said.contains("cells-overlap"), "{}: {said}", name(file));
            continue;
        }
        let back = std::process::Command::new(env!("CARGO_BIN_EXE_nrgdb"))
            .arg("convert")
            .arg(out.path().join("model.json"))
            .arg(&gml)
            .output()
            .unwrap();
        assert!(back.status.success(), "{}", name(file));
        let check = std::process::Command::new(env!("CARGO_BIN_EXE_nrgdb"))
            .arg("check")
            .arg(&gml)
            .output()
            .unwrap();
        let said = String::from_utf8_lossy(&check.stdout);
        assert!(
            check.status.success() && said.contains("clean"),
            "{}: {said}",
            name(file)
        );
        written += 1;
    }
    assert!(written >= 4, "most 2D samples convert: {written}");
}

/// Issue 21: two independent real files write `core:spaceLayer` (the
/// property's spelling) for the `core:SpaceLayer` feature inside
/// `core:spaceLayerMember`; the file is read with a warning naming the
/// line instead of being refused whole.
#[test]
fn issue_21_paper_cut_misspelt_space_layer_imports_with_a_warning() {
    let Some(files) = samples() else { return };
    let fzk = files
        .iter()
        .find(|f| name(f) == "FZK-Haus_full.gml")
        .expect("FZK-Haus_full.gml among the samples");
    let doc = read_file(fzk, indoorgml::DEFAULT_MAX_BYTES).unwrap();
    assert_eq!(doc.warnings.len(), 1, "{:?}", doc.warnings);
    assert!(
        doc.warnings[0].starts_with("line 2192: core:spaceLayer read as core:SpaceLayer"),
        "{:?}",
        doc.warnings
    );
    let layers = &doc.graph.as_ref().unwrap().layer_groups[0].layers;
    assert!(!layers.is_empty() && !layers[0].states.is_empty());
    let nrg = indoorgml::to_nrg(&doc).unwrap();
    assert!(!nrg.spaces().is_empty());
    // A well-spelt document has no warnings.
    assert!(read_str(&write_string(&doc)).unwrap().warnings.is_empty());
}
