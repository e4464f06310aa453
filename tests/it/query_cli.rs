//! `nrgdb query` run as a binary.

use std::process::Command;

fn nrgdb(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_nrgdb"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The demo building written as model JSON in a new temporary folder.
fn model_file() -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("m.json");
    std::fs::write(&path, nrgdb::query::demo::building(3).to_json()).unwrap();
    let p = path.to_str().unwrap().to_string();
    (dir, p)
}

#[test]
fn query_a_model_file() {
    let (_dir, p) = model_file();
    let p = p.as_str();
    let (code, out, err) = nrgdb(&[
        "query",
        "--model",
        p,
        "ROUTE FROM \"Kitchen\" TO \"Library\"",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("route 1: 6.30 m"), "{out}");
    let (code, out, _) = nrgdb(&["query", "--model", p, "--csv", "LOCATE (2, 9); SHOW MAPS"]);
    assert_eq!(code, 0);
    assert_eq!(
        out,
        "id,kind,name,area_m2\n3,room,Kitchen,13.69\nmap,revisions,latest\nmodel,1,1\n"
    );
    let (code, _, _) = nrgdb(&["query", "--model", p, "LOCATE (-9, -9)"]);
    assert_eq!(code, 1, "an empty answer exits 1");
}

#[test]
fn a_model_file_before_the_statements_is_read_as_model() {
    let (dir, p) = model_file();
    let p = p.as_str();
    let (code, out, err) = nrgdb(&["query", p, "ROUTE FROM \"Kitchen\" TO \"Library\""]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("route 1: 6.30 m"), "{out}");
    // Not a file: said, and the statements are not run against anything.
    let missing = dir.path().join("missing.json");
    let (code, out, err) = nrgdb(&["query", missing.to_str().unwrap(), "FIND rooms"]);
    assert_eq!(code, 2, "{out}");
    assert!(
        err.contains("missing.json") && err.contains("not a model file"),
        "{err}"
    );
    // A model already named: two statement arguments are refused.
    let (code, _, err) = nrgdb(&["query", "--model", p, "FIND rooms", "FIND doors"]);
    assert_eq!(code, 2);
    assert!(err.contains("one argument"), "{err}");
}

#[test]
fn errors_exit_2_with_a_caret() {
    let (code, _, err) = nrgdb(&["query", "--demo", "2", "FIND rooms WHERE aera > 1"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("did you mean area?") && err.contains("line 1, column 18"),
        "{err}"
    );
    let (code, _, err) = nrgdb(&["query", "--db", "x.sqlite", "SHOW MAPS"]);
    assert_eq!(code, 2);
    assert!(err.contains("no database at x.sqlite"), "{err}");
}
