//! `nrgdb demo`, the README's first command, runs the whole pipeline with
//! no arguments and no files, and what it writes is sound.

use crate::support::nrgdb;

#[test]
fn demo_runs_end_to_end_and_writes_valid_indoorgml() {
    let dir = tempfile::tempdir().unwrap();
    let out = nrgdb(dir.path(), &["demo"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for want in [
        "simulated building",
        "extracted the NRG",
        "stored revisions 1 and 3",
        "is correction 1 (SET space",
        "1 re-applied, 0 failed",
        "route 1:",
        "removed",
        "building.gml",
    ] {
        assert!(stdout.contains(want), "missing '{want}' in:\n{stdout}");
    }
    let demo = dir.path().join("nrgdb-demo");
    for file in [
        "map.yaml",
        "map.pgm",
        "map_gt.png",
        "truth.json",
        "building.gml",
        "building-rev1.png",
        "building-rev3.png",
    ] {
        assert!(demo.join(file).is_file(), "{file} not written");
    }
    assert!(dir.path().join("nrgdb.sqlite").is_file());
    // The exported revision passes the conformance checker.
    let check = nrgdb(
        dir.path(),
        &["check", "nrgdb-demo/building.gml", "--no-schema"],
    );
    assert_eq!(
        check.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&check.stdout)
    );
    // The stored revisions answer queries.
    let q = nrgdb(
        dir.path(),
        &["query", "--map", "demo", "SHOW REVISIONS OF demo"],
    );
    assert_eq!(
        q.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&q.stderr)
    );
    assert!(
        String::from_utf8_lossy(&q.stdout).contains("door"),
        "{}",
        String::from_utf8_lossy(&q.stdout)
    );
}

/// Issue 21: the demo drew revision 1 only (and called it `building.png`
/// beside the `building.gml` of revision 2), so no picture showed the
/// shut door.
#[test]
fn issue_21_paper_cut_demo_draws_each_revision_and_says_which() {
    let dir = tempfile::tempdir().unwrap();
    let out = nrgdb(dir.path(), &["demo"]);
    assert!(out.status.success());
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("building-rev1.png (revision 1, as mapped)")
            && stdout.contains("building-rev3.png (revision 3, door"),
        "{stdout}"
    );
    let demo = dir.path().join("nrgdb-demo");
    let a = std::fs::read(demo.join("building-rev1.png")).unwrap();
    let b = std::fs::read(demo.join("building-rev3.png")).unwrap();
    assert_ne!(a, b, "the two revisions look the same");
}
