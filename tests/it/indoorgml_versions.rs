//! IndoorGML 1.1 next to 1.0.3: nrgdb writes 1.1 on request (the same
//! elements, the 1.1 schemas named) and reads 1.1 documents. Checked with
//! the independent checker (`indoorgml::check`, `nrgdb check`), the OGC
//! 1.0.3 XSD via xmllint (the elements written are 1.0.3's) and, when a
//! copy is present offline, the OGC 1.1 XSD.

use std::path::Path;
use std::process::Command;

use nrgdb::format::{ModelFormat, from_document, render, render_as};
use nrgdb::indoorgml::{self, IndoorGmlVersion, NS_CORE, NS_NAVI};
use nrgdb::route::walked_model;

use crate::support::{building, have_xmllint, nrgdb, nrgdb_ok, shared_dir};

const CORE_1_1_XSD: &str = "http://schemas.opengis.net/indoorgml/1.1/indoorgmlcore.xsd";

fn gml_1_1() -> String {
    render_as(
        &walked_model(&building(4)),
        ModelFormat::IndoorGml,
        IndoorGmlVersion::V1_1,
    )
}

/// The root start tag's text, up to its `>`.
fn root_tag(text: &str) -> &str {
    let start = text.find("<core:IndoorFeatures").unwrap();
    let end = start + text[start..].find('>').unwrap();
    &text[start..end]
}

#[test]
fn v1_1_names_the_1_1_schemas_in_the_1_0_namespaces() {
    let text = gml_1_1();
    let root = root_tag(&text);
    assert!(
        root.contains(&format!("xmlns:core=\"{NS_CORE}\"")),
        "{root}"
    );
    assert!(
        root.contains(&format!("xmlns:navi=\"{NS_NAVI}\"")),
        "{root}"
    );
    assert!(root.contains(CORE_1_1_XSD), "{root}");
    assert!(!root.contains("indoorgml/1.0/indoorgmlcore.xsd"), "{root}");
    let default = render(&walked_model(&building(4)), ModelFormat::IndoorGml);
    assert!(root_tag(&default).contains("indoorgml/1.0/indoorgmlcore.xsd"));
    // Everything after the root tag is the same document.
    let body = |t: &str| {
        t[t.find("<core:IndoorFeatures").unwrap()..]
            .split_once('>')
            .unwrap()
            .1
            .to_string()
    };
    assert_eq!(body(&text), body(&default));
}

#[test]
fn v1_1_reads_back_as_1_1_with_the_walked_model() {
    let nrg = building(4);
    let walked = walked_model(&nrg).nrg;
    let doc = indoorgml::read_str(&gml_1_1()).unwrap();
    assert_eq!(doc.version, IndoorGmlVersion::V1_1);
    assert!(
        indoorgml::check(&doc).is_empty(),
        "{:?}",
        indoorgml::check(&doc)
    );
    let (back, fixes) = from_document(&doc).unwrap();
    assert_eq!(fixes.total(), 0);
    assert_eq!(back.spaces().len(), walked.spaces().len());
    for (a, b) in back.spaces().iter().zip(walked.spaces()) {
        assert_eq!(
            (a.id, a.kind, &a.polygon, &a.holes),
            (b.id, b.kind, &b.polygon, &b.holes)
        );
    }
    assert_eq!(back.connections().len(), walked.connections().len());
    for c in walked.connections() {
        let r = back.connection(c.a, c.b).unwrap();
        assert_eq!(r.kind, c.kind);
        assert!((r.length_m - c.length_m).abs() < 1e-9, "{c:?} vs {r:?}");
    }
    // Written again, a 1.1 document stays 1.1.
    let again = indoorgml::write_string(&doc);
    assert!(root_tag(&again).contains(CORE_1_1_XSD));
}

/// A 1.1 document written by hand (not nrgdb's writer): two rooms and a
/// door in the navigation module, the 1.1 schemas named.
const HAND_WRITTEN_1_1: &str = r##"<?xml version="1.0" encoding="UTF-8"?>
<IndoorFeatures xmlns="http://www.opengis.net/indoorgml/1.0/core"
  xmlns:nv="http://www.opengis.net/indoorgml/1.0/navigation"
  xmlns:g="http://www.opengis.net/gml/3.2" xmlns:xl="http://www.w3.org/1999/xlink"
  xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" g:id="hand"
  xsi:schemaLocation="http://www.opengis.net/indoorgml/1.0/core http://schemas.opengis.net/indoorgml/1.1/indoorgmlcore.xsd http://www.opengis.net/indoorgml/1.0/navigation http://schemas.opengis.net/indoorgml/1.1/indoorgmlnavi.xsd">
 <primalSpaceFeatures><PrimalSpaceFeatures g:id="p">
  <cellSpaceMember><nv:GeneralSpace g:id="a"><g:name>West</g:name>
   <cellSpaceGeometry><Geometry2D><g:Polygon g:id="pa"><g:exterior><g:LinearRing>
    <g:posList>0 0 4 0 4 3 0 3 0 0</g:posList></g:LinearRing></g:exterior></g:Polygon></Geometry2D></cellSpaceGeometry>
   <duality xl:href="#sa"/></nv:GeneralSpace></cellSpaceMember>
  <cellSpaceMember><nv:GeneralSpace g:id="b"><g:name>East</g:name>
   <cellSpaceGeometry><Geometry2D><g:Polygon g:id="pb"><g:exterior><g:LinearRing>
    <g:posList>4.2 0 8 0 8 3 4.2 3 4.2 0</g:posList></g:LinearRing></g:exterior></g:Polygon></Geometry2D></cellSpaceGeometry>
   <duality xl:href="#sb"/></nv:GeneralSpace></cellSpaceMember>
 </PrimalSpaceFeatures></primalSpaceFeatures>
 <multiLayeredGraph><MultiLayeredGraph g:id="g"><spaceLayers g:id="ls"><spaceLayerMember>
  <SpaceLayer g:id="l"><nodes g:id="n">
   <stateMember><State g:id="sa"><duality xl:href="#a"/><connects xl:href="#t"/>
    <geometry><g:Point g:id="qa"><g:pos>2 1.5</g:pos></g:Point></geometry></State></stateMember>
   <stateMember><State g:id="sb"><duality xl:href="#b"/><connects xl:href="#t"/>
    <geometry><g:Point g:id="qb"><g:pos>6 1.5</g:pos></g:Point></geometry></State></stateMember>
  </nodes><edges g:id="e">
   <transitionMember><Transition g:id="t"><weight>4</weight>
    <connects xl:href="#sa"/><connects xl:href="#sb"/>
    <geometry><g:LineString g:id="lt"><g:posList>2 1.5 6 1.5</g:posList></g:LineString></geometry>
   </Transition></transitionMember>
  </edges></SpaceLayer></spaceLayerMember></spaceLayers></MultiLayeredGraph></multiLayeredGraph>
</IndoorFeatures>
"##;

#[test]
fn a_hand_written_1_1_document_is_read() {
    let doc = indoorgml::read_str(HAND_WRITTEN_1_1).unwrap();
    assert_eq!(doc.version, IndoorGmlVersion::V1_1);
    assert_eq!((doc.cells().len(), doc.layers().len()), (2, 1));
    let (nrg, _) = from_document(&doc).unwrap();
    let names: Vec<_> = nrg.spaces().iter().filter_map(|s| s.name.clone()).collect();
    assert_eq!(names, ["West", "East"]);
    assert_eq!(nrg.connections().len(), 1);
    assert_eq!(nrg.connections()[0].length_m, 4.0);
}

fn xmllint(xsd: &Path, file: &Path) -> std::process::Output {
    Command::new("xmllint")
        .args(["--nonet", "--noout", "--schema"])
        .arg(xsd)
        .arg(file)
        .output()
        .unwrap()
}

#[test]
fn v1_1_output_is_schema_valid() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("v11.gml");
    std::fs::write(&path, gml_1_1()).unwrap();
    let out = nrgdb(dir.path(), &["check", "--no-schema", "v11.gml"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    if !have_xmllint() {
        eprintln!("notice: skipping schema validation, xmllint missing");
        return;
    }
    // The elements nrgdb writes in 1.1 are 1.0.3's: the OGC 1.0.3 XSD
    // (offline, in the shared data) judges them.
    if let Some(shared) = shared_dir("indoorgml/validate.sh") {
        let v = Command::new(shared.join("indoorgml/validate.sh"))
            .arg(&path)
            .output()
            .unwrap();
        assert!(v.status.success(), "{}", String::from_utf8_lossy(&v.stderr));
    }
    let xsd =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/schemas/indoorgml-1.1/indoorgmlnavi.xsd");
    if !xsd.exists() {
        eprintln!(
            "notice: skipping IndoorGML 1.1 XSD validation, {} not present (see its README)",
            xsd.display()
        );
        return;
    }
    let v = xmllint(&xsd, &path);
    assert!(v.status.success(), "{}", String::from_utf8_lossy(&v.stderr));
}

#[test]
fn cli_export_and_convert_take_the_version() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("b.json"), building(3).to_json()).unwrap();
    let ok = |args: &[&str]| {
        nrgdb_ok(dir.path(), args);
    };
    let read = |f: &str| std::fs::read_to_string(dir.path().join(f)).unwrap();
    ok(&["import", "--db", "t.db", "--map", "m", "b.json"]);
    ok(&[
        "export",
        "--db",
        "t.db",
        "m",
        "--out",
        "e11.gml",
        "--indoorgml-version",
        "1.1",
    ]);
    ok(&["export", "--db", "t.db", "m", "--out", "e10.gml"]);
    assert!(root_tag(&read("e11.gml")).contains(CORE_1_1_XSD));
    assert!(!root_tag(&read("e10.gml")).contains(CORE_1_1_XSD));
    // IndoorGML to IndoorGML keeps the input's version unless told.
    ok(&["convert", "e11.gml", "c11.gml"]);
    assert!(root_tag(&read("c11.gml")).contains(CORE_1_1_XSD));
    ok(&[
        "convert",
        "e11.gml",
        "c10.gml",
        "--indoorgml-version",
        "1.0.3",
    ]);
    assert!(!root_tag(&read("c10.gml")).contains(CORE_1_1_XSD));
    let bad = nrgdb(
        dir.path(),
        &[
            "export",
            "--db",
            "t.db",
            "m",
            "--out",
            "x.gml",
            "--indoorgml-version",
            "2.0",
        ],
    );
    assert!(!bad.status.success());
    let err = String::from_utf8_lossy(&bad.stderr);
    assert!(err.contains("2.0") && err.contains("1.1"), "{err}");
}
