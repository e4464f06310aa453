//! Issue 6: `nrgdb diff` and `nrgdb apply` end to end, on generated maps
//! written as ROS map files in a temp dir.

use std::path::Path;

use nrgdb::diff::ChangeSet;
use nrgdb::grid::Cell;

use super::diff_support::{extracted, floor, paint, turned, write_map};
use super::support::nrgdb;

fn run(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = nrgdb(dir, args);
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn diff_apply_and_update_through_the_store() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let f = floor();
    write_map(dir, "a", &f.grid);
    let mut shut = f.grid.clone();
    paint(&mut shut, f.doors[2], Cell::Occupied);
    write_map(dir, "b", &shut);
    for m in ["a.yaml", "b.yaml"] {
        let (code, _, err) = run(dir, &["import", m, "--map", "floor", "--db", "db.sqlite"]);
        assert_eq!(code, 0, "{err}");
    }
    let (code, out, err) = run(dir, &["diff", "floor", "1", "2", "--db", "db.sqlite"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.starts_with("floor@1 → floor@2\n"), "{out}");
    assert!(
        out.contains("removed") && out.contains("1 removed, 2 connections removed"),
        "{out}"
    );

    let (code, out, err) = run(
        dir,
        &[
            "diff",
            "floor",
            "1",
            "2",
            "--db",
            "db.sqlite",
            "--json",
            "-o",
            "cs.json",
            "--gml",
            "up.gml",
        ],
    );
    assert_eq!(code, 1, "{err}");
    let cs = ChangeSet::from_json(&out).unwrap();
    assert_eq!(cs.summary.removed, 1);
    assert_eq!(cs.from.as_deref(), Some("floor@1"));
    assert_eq!(
        ChangeSet::from_json(&std::fs::read_to_string(dir.join("cs.json")).unwrap()).unwrap(),
        cs
    );
    // The update keeps A's ids for every matched space.
    let update = nrgdb::indoorgml::read_nrg_file(&dir.join("up.gml"), 1 << 30).unwrap();
    for (old, _) in cs.matched() {
        assert!(update.space(old).is_some(), "space {old} lost its id");
    }
    assert_eq!(
        update.spaces().len(),
        cs.spaces.iter().filter(|e| e.new.is_some()).count()
    );

    // Issue 22: applying to a revision that is not the latest would undo
    // the later ones; it is refused, and --rebase carries the change over
    // (here revision 2 already is the result: nothing to store).
    let (code, _, err) = run(dir, &["apply", "floor@1", "cs.json", "--db", "db.sqlite"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("not the latest revision (2)") && err.contains("--rebase"),
        "{err}"
    );
    let (code, out, err) = run(
        dir,
        &[
            "apply",
            "floor@1",
            "cs.json",
            "--rebase",
            "--db",
            "db.sqlite",
        ],
    );
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("rebased from floor@1 onto floor@2"), "{out}");
    assert!(out.contains("nothing changed"), "{out}");
    let (code, out, _) = run(dir, &["revisions", "floor", "--db", "db.sqlite"]);
    assert_eq!(code, 0);
    let revs: Vec<&str> = out
        .lines()
        .skip(1)
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert_eq!(revs, ["1", "2"], "{out}");
    // A change set computed from another revision is refused by name.
    let (code, _, err) = run(dir, &["apply", "floor@2", "cs.json", "--db", "db.sqlite"]);
    assert_eq!(code, 2);
    assert!(err.contains("computed from floor@1, not floor@2"), "{err}");
    let (code, _, err) = run(dir, &["diff", "floor", "1", "9", "--db", "db.sqlite"]);
    assert_eq!(code, 2);
    assert!(err.contains("revision 9"), "{err}");
}

#[test]
fn files_in_other_frames_are_aligned() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let f = floor();
    write_map(dir, "a", &f.grid);
    write_map(dir, "c", &turned(&f.grid, 10, [5.0, 1.0, 0.3]));
    let (code, out, err) = run(dir, &["diff", "a.yaml", "a.yaml"]);
    assert_eq!(
        (code, out.as_str()),
        (0, "a.yaml → a.yaml\nno changes (9 unchanged)\n"),
        "{err}"
    );
    let (code, out, err) = run(dir, &["diff", "a.yaml", "c.yaml"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("aligned: rotation") && out.contains("no changes"),
        "{out}"
    );
    let (code, out, _) = run(dir, &["diff", "a.yaml", "c.yaml", "--no-align"]);
    assert_eq!(code, 1, "{out}");
    // Models without grids are aligned on their spaces' outlines.
    let c = extracted(&turned(&f.grid, 10, [5.0, 1.0, 0.3]));
    std::fs::write(dir.join("c.json"), c.to_json()).unwrap();
    let (code, out, err) = run(dir, &["diff", "a.yaml", "c.json"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("aligned: rotation"), "{out}");
}

#[test]
fn stored_revisions_from_other_runs_align_on_their_grids() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let f = floor();
    write_map(dir, "a", &f.grid);
    write_map(dir, "c", &turned(&f.grid, 10, [-2.0, 6.0, -0.4]));
    for m in ["a.yaml", "c.yaml"] {
        let (code, _, err) = run(dir, &["import", m, "--map", "floor", "--db", "db.sqlite"]);
        assert_eq!(code, 0, "{err}");
    }
    let store = nrgdb::store::Store::open(&dir.join("db.sqlite")).unwrap();
    assert!(store.grid("floor", Some(2)).unwrap().is_some());
    drop(store);
    let (code, out, err) = run(dir, &["diff", "floor", "1", "2", "--db", "db.sqlite"]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        out.contains("aligned: rotation") && out.contains("no changes"),
        "{out}"
    );
    let (code, out, _) = run(
        dir,
        &["diff", "floor", "1", "2", "--db", "db.sqlite", "--no-align"],
    );
    assert_eq!(code, 1, "{out}");
}
