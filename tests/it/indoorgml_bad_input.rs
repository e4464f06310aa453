//! Bad IndoorGML gets a clear error with its line, a non-zero exit, and
//! never a half-written output.

use nrgdb::indoorgml::{self, read_str};

use crate::support::nrgdb;

const HEAD: &str = r#"<?xml version="1.0"?>
<core:IndoorFeatures xmlns:core="http://www.opengis.net/indoorgml/1.0/core"
    xmlns:gml="http://www.opengis.net/gml/3.2" xmlns:xlink="http://www.w3.org/1999/xlink" gml:id="F">
"#;

fn doc_with(body: &str) -> String {
    format!("{HEAD}{body}\n</core:IndoorFeatures>\n")
}

fn cell(id: &str, pos_list: &str) -> String {
    format!(
        r#"<core:primalSpaceFeatures><core:PrimalSpaceFeatures gml:id="P"><core:cellSpaceMember>
<core:CellSpace {id}><core:cellSpaceGeometry><core:Geometry2D><gml:Polygon><gml:exterior><gml:LinearRing>
<gml:posList>{pos_list}</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></core:Geometry2D></core:cellSpaceGeometry>
</core:CellSpace></core:cellSpaceMember></core:PrimalSpaceFeatures></core:primalSpaceFeatures>"#
    )
}

fn err(text: &str) -> String {
    read_str(text).expect_err("must be refused").to_string()
}

#[test]
fn malformed_xml_names_the_line() {
    let e = err("<a>\n<b></a>");
    assert!(e.starts_with("line 2: malformed XML"), "{e}");
    let e = err(&doc_with("<core:primalSpaceFeatures>"));
    assert!(
        e.starts_with("line 5: malformed XML") && e.contains("primalSpaceFeatures"),
        "{e}"
    );
    let e = err(&HEAD[..HEAD.len() - 20]);
    assert!(e.contains("malformed XML"), "{e}");
    let e = err(HEAD);
    assert!(e.contains("never closed"), "{e}");
}

#[test]
fn wrong_or_missing_namespace_and_unknown_root() {
    let e = err("<IndoorFeatures gml:id=\"x\" xmlns:gml=\"http://www.opengis.net/gml/3.2\"/>");
    assert!(
        e.contains("has no namespace") || e.contains("no namespace"),
        "{e}"
    );
    let e = err("<x:IndoorFeatures xmlns:x=\"http://example.com/other\"/>");
    assert!(e.contains("expected core:IndoorFeatures"), "{e}");
    let e = err("<core:Nothing xmlns:core=\"http://www.opengis.net/indoorgml/1.0/core\"/>");
    assert!(e.contains("core:Nothing"), "{e}");
}

#[test]
fn missing_ids_and_bad_numbers_name_element_and_line() {
    let e = err(&doc_with(&cell("", "0 0 1 0 1 1 0 0")));
    assert!(e.contains("core:CellSpace has no gml:id"), "{e}");
    assert!(e.starts_with("line 5"), "{e}");
    let e = err(&doc_with(&cell("gml:id=\"C1\"", "0 0 1 zero 1 1 0 0")));
    assert!(
        e.contains("'zero' is not a finite number") && e.contains("gml:posList"),
        "{e}"
    );
    let e = err(&doc_with(&cell("gml:id=\"C1\"", "0 0 1 NaN 1 1 0 0")));
    assert!(e.contains("'NaN'"), "{e}");
    let e = err(&doc_with(&cell("gml:id=\"C1\"", "0 0 1 0 1")));
    assert!(e.contains("not a multiple"), "{e}");
}

#[test]
fn a_model_with_dangling_references_is_still_readable_as_a_document() {
    // A State pointing nowhere: the reader keeps it (the checker reports it).
    let body = r##"<core:multiLayeredGraph><core:MultiLayeredGraph gml:id="G"><core:spaceLayers gml:id="L0">
<core:spaceLayerMember><core:SpaceLayer gml:id="L"><core:nodes gml:id="N"><core:stateMember>
<core:State gml:id="S1"><core:duality xlink:href="#missing"/></core:State></core:stateMember></core:nodes>
</core:SpaceLayer></core:spaceLayerMember></core:spaceLayers></core:MultiLayeredGraph></core:multiLayeredGraph>"##;
    let doc = read_str(&doc_with(body)).unwrap();
    let findings = indoorgml::check(&doc);
    assert!(
        findings
            .iter()
            .any(|f| f.code == "dangling-href" && f.element == "S1"),
        "{findings:?}"
    );
}

#[test]
fn cli_refuses_bad_input_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("bad.gml"),
        doc_with(&cell("gml:id=\"C1\"", "0 0 x")),
    )
    .unwrap();
    std::fs::write(dir.path().join("out.json"), "keep").unwrap();
    let out = nrgdb(dir.path(), &["convert", "bad.gml", "out.json"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("bad.gml") && stderr.contains("line"),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(dir.path().join("out.json")).unwrap(),
        "keep"
    );
    let leftovers: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(leftovers.len(), 2, "no temporary files may be left behind");
}

#[test]
fn cli_refuses_files_over_the_size_limit() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("big.gml"), doc_with("")).unwrap();
    let out = nrgdb(
        dir.path(),
        &["convert", "big.gml", "out.json", "--max-bytes", "100"],
    );
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("above the limit of 100 bytes"), "{stderr}");
    assert!(!dir.path().join("out.json").exists());
}

#[test]
fn cli_refuses_unknown_formats() {
    let dir = tempfile::tempdir().unwrap();
    // Output formats go by extension.
    std::fs::write(dir.path().join("a.gml"), doc_with("")).unwrap();
    let out = nrgdb(dir.path(), &["convert", "a.gml", "b.txt"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown format"));
    // An input goes by extension and content: neither tells here.
    std::fs::write(dir.path().join("a.txt"), "hello").unwrap();
    let out = nrgdb(dir.path(), &["convert", "a.txt", "b.json"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("a.txt: cannot tell the format"), "{stderr}");
    // Content that contradicts the extension is refused, naming both.
    std::fs::write(dir.path().join("c.json"), doc_with("")).unwrap();
    let out = nrgdb(dir.path(), &["convert", "c.json", "d.geojson"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("its name says model JSON but its content is IndoorGML"),
        "{stderr}"
    );
    assert!(!dir.path().join("d.geojson").exists());
}

#[test]
fn non_utf8_input_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("latin1.gml");
    std::fs::write(&path, b"<a>\n\xe9</a>").unwrap();
    let e = indoorgml::read_file(&path, indoorgml::DEFAULT_MAX_BYTES)
        .unwrap_err()
        .to_string();
    assert!(e.contains("line 2") && e.contains("UTF-8"), "{e}");
}

/// Issue 21, defect 5: cells with a coordinate near 1e308 made the
/// overlap check panic inside geo, and convert/import with it. Now the
/// checker names the cell and the converter refuses the model, naming
/// the space.
#[test]
fn far_flung_coordinates_are_a_finding_not_a_panic() {
    let far = |id: &str| cell(&format!("gml:id=\"{id}\""), "0 0 1e308 0 1e308 1e308 0 0");
    let doc = read_str(&doc_with(&far("C1"))).unwrap();
    let findings = indoorgml::check(&doc);
    assert!(
        findings
            .iter()
            .any(|f| f.code == "coordinates-out-of-range" && f.element == "C1"),
        "{findings:?}"
    );
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("far.gml"), doc_with(&far("C1"))).unwrap();
    let out = nrgdb(dir.path(), &["convert", "far.gml", "out.json"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{stderr}");
    assert!(stderr.contains("from the origin"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(!dir.path().join("out.json").exists());
}
