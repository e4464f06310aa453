//! Issue 21, "paper cuts a new user hits": each through the real binary,
//! as a new user would meet it.

use std::io::Read;
use std::path::Path;
use std::process::{Command, Output, Stdio};

fn nrgdb(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_nrgdb"))
        .args(args)
        .current_dir(dir)
        .env_remove("NRGDB_DB")
        .env_remove("RUST_LOG")
        .output()
        .unwrap()
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// The answers a golden file expects, as the CLI prints them: the
/// `# @expect:` blocks without their `# ` prefix, and how many are errors.
fn expected_answers(golden: &str) -> (String, usize) {
    let (mut out, mut errors) = (String::new(), 0);
    let mut lines = golden.lines().peekable();
    while let Some(line) = lines.next() {
        if line != "# @expect:" {
            continue;
        }
        let mut block = String::new();
        while let Some(l) = lines.next_if(|l| l.starts_with('#')) {
            block.push_str(l.strip_prefix("# ").unwrap_or(""));
            block.push('\n');
        }
        if block.starts_with("error: ") {
            errors += 1;
        } else {
            out.push_str(&block);
        }
    }
    (out, errors)
}

#[test]
fn issue_21_paper_cut_query_files_run_as_their_headers_say() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<_> = std::fs::read_dir(root.join("queries"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "nrgq"))
        .collect();
    files.sort();
    assert!(files.len() >= 4, "{files:?}");
    for path in files {
        let golden = std::fs::read_to_string(&path).unwrap();
        let name = path.display();
        let command = golden
            .lines()
            .find_map(|l| l.trim_start_matches('#').trim().strip_prefix("nrgdb "))
            .unwrap_or_else(|| panic!("{name}: no '#   nrgdb query …' line in its header"));
        let status: i32 = golden
            .lines()
            .find_map(|l| l.strip_prefix("# exit status: "))
            .map_or(0, |s| s.trim().parse().unwrap());
        let args: Vec<&str> = command.split_whitespace().collect();
        let out = nrgdb(root, &args);
        let (stdout, stderr) = (text(&out.stdout), text(&out.stderr));
        assert_eq!(out.status.code(), Some(status), "{name}: {stderr}");
        let (answers, errors) = expected_answers(&golden);
        assert_eq!(
            stdout, answers,
            "{name}: the answers differ from the golden file"
        );
        assert_eq!(
            stderr.matches("statement failed").count(),
            errors,
            "{name}: {stderr}"
        );
    }
}

#[test]
fn issue_21_paper_cut_keep_going_runs_past_a_syntax_error() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("three.nrgq");
    std::fs::write(
        &file,
        "# three statements, the second misspelt\nSHOW MAPS;\nFIND rooms ORDRE BY area;\nSHOW REVISIONS;\n",
    )
    .unwrap();
    let f = file.to_str().unwrap();
    // By default the first failed statement stops the file, after the ones
    // before it ran.
    let out = nrgdb(dir.path(), &["query", "--demo", "2", "-f", f]);
    assert_eq!(out.status.code(), Some(2));
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("demo") && !stdout.contains("connections"),
        "{stdout}"
    );
    assert!(
        text(&out.stderr).contains("three.nrgq:3"),
        "{}",
        text(&out.stderr)
    );
    // --keep-going runs the rest, reports the error with its file:line and
    // still exits 2.
    let out = nrgdb(
        dir.path(),
        &["query", "--demo", "2", "--keep-going", "-f", f],
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stdout).contains("connections"),
        "{}",
        text(&out.stdout)
    );
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("three.nrgq:3: statement failed"),
        "{stderr}"
    );
    assert!(
        stderr.contains("syntax error at line 3, column 12"),
        "{stderr}"
    );
    assert!(stderr.contains("1 of 3 statements failed"), "{stderr}");
}

#[test]
fn issue_21_paper_cut_nrgdb_db_in_the_environment_does_not_conflict_with_demo() {
    let dir = tempfile::tempdir().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_nrgdb"))
        .args(["query", "--demo", "2", "SHOW MAPS"])
        .current_dir(dir.path())
        .env("NRGDB_DB", "elsewhere.sqlite")
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", text(&out.stderr));
}

#[test]
fn issue_21_paper_cut_maps_on_a_missing_db_is_an_error() {
    let dir = tempfile::tempdir().unwrap();
    let reads: [&[&str]; 8] = [
        &["maps"],
        &["revisions", "demo"],
        &["log", "demo"],
        &["export", "demo", "--out", "x.gml"],
        &["query", "SHOW MAPS"],
        &["diff", "demo", "1", "2"],
        &["render", "demo", "--out", "x.svg"],
        &["serve", "--addr", "127.0.0.1:0"],
    ];
    for args in reads {
        let mut args = args.to_vec();
        args.extend(["--db", "nosuch.sqlite"]);
        let out = nrgdb(dir.path(), &args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = text(&out.stderr);
        assert!(
            stderr.contains("no database at nosuch.sqlite")
                || stderr.contains("no database nosuch.sqlite"),
            "{args:?}: {stderr}"
        );
        assert!(
            !dir.path().join("nosuch.sqlite").exists(),
            "{args:?} created it"
        );
    }
    let out = nrgdb(dir.path(), &["maps", "--db", "nosuch.sqlite"]);
    assert!(
        text(&out.stderr).contains("`nrgdb import` creates one"),
        "{}",
        text(&out.stderr)
    );
}

#[test]
fn issue_21_paper_cut_unknown_map_names_suggest_the_closest() {
    let dir = tempfile::tempdir().unwrap();
    let model = dir.path().join("m.json");
    std::fs::write(&model, nrgdb::fixtures::corridor_building(3).to_json()).unwrap();
    let out = nrgdb(
        dir.path(),
        &["import", model.to_str().unwrap(), "--map", "office_g"],
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    for args in [
        &["revisions", "ofice_g"][..],
        &["query", "--map", "ofice_g", "SHOW MAPS"],
        &["query", "USE ofice_g"],
        &["export", "ofice_g", "--out", "x.json"],
    ] {
        let out = nrgdb(dir.path(), args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            text(&out.stderr).contains("did you mean 'office_g'?"),
            "{args:?}: {}",
            text(&out.stderr)
        );
    }
    // The same message is the HTTP 404's (ApiError from StoreError).
    let store = nrgdb::store::Store::open(&dir.path().join("nrgdb.sqlite")).unwrap();
    let e = store.revisions("ofice_g").unwrap_err().to_string();
    assert!(e.contains("did you mean 'office_g'?"), "{e}");
}

#[test]
fn issue_21_paper_cut_a_closed_stdout_ends_quietly() {
    let dir = tempfile::tempdir().unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_nrgdb"))
        .args(["query", "--demo", "300", "FIND spaces"])
        .current_dir(dir.path())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Like `| head -1`: read a little, then close the pipe.
    let mut stdout = child.stdout.take().unwrap();
    let mut first = [0u8; 16];
    stdout.read_exact(&mut first).unwrap();
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "{:?}", out.status);
    assert_eq!(text(&out.stderr), "");
}

fn write_map(dir: &Path, image: &str) -> std::path::PathBuf {
    let yaml = dir.join("map.yaml");
    std::fs::write(
        &yaml,
        format!("image: {image}\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n"),
    )
    .unwrap();
    yaml
}

#[test]
fn issue_21_paper_cut_missing_image_names_the_yaml_and_the_path() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("maps")).unwrap();
    write_map(&dir.path().join("maps"), "gone.pgm");
    let out = nrgdb(dir.path(), &["extract", "maps/map.yaml", "--out", "x.gml"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("maps/map.yaml: cannot read its image maps/gone.pgm"),
        "{stderr}"
    );
}

/// `map.yaml` and `room.png` in `dir`: one room of 4 m × 4 m, drawn in grey.
fn write_one_room(dir: &Path) {
    let grey = image::GrayImage::from_fn(40, 40, |x, y| {
        let wall = x < 2 || y < 2 || x > 37 || y > 37;
        image::Luma([if wall { 0 } else { 254 }])
    });
    grey.save(dir.join("room.png")).unwrap();
    write_map(dir, "room.png");
}

#[test]
fn issue_21_paper_cut_a_colour_photo_is_extracted_with_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    // One room of 4 m x 4 m, drawn in grey: no warning, and the counts
    // are in the singular where they are one.
    write_one_room(dir.path());
    let out = nrgdb(dir.path(), &["extract", "map.yaml", "--out", "x.gml"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(!text(&out.stderr).contains("WARN"), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("1 room,") && !stdout.contains("1 rooms"),
        "{stdout}"
    );
    // The same room as a colour photo: extracted, with a warning saying
    // what was assumed.
    let photo = image::RgbImage::from_fn(40, 40, |x, y| {
        let wall = x < 2 || y < 2 || x > 37 || y > 37;
        if wall {
            image::Rgb([20, 60, 20])
        } else {
            image::Rgb([250, 200, (x * 6) as u8])
        }
    });
    photo.save(dir.path().join("room.png")).unwrap();
    let out = nrgdb(dir.path(), &["extract", "map.yaml", "--out", "x.gml"]);
    let stderr = text(&out.stderr);
    assert!(stderr.contains("room.png: a colour image"), "{stderr}");
    assert!(stderr.contains("free at grey >= 250"), "{stderr}");
}

#[test]
fn issue_21_paper_cut_check_prints_no_line_0_and_no_repeats() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("bad.gml"), "<IndoorFeatures><unclosed>").unwrap();
    let out = nrgdb(dir.path(), &["check", "bad.gml", "--no-schema"]);
    assert_eq!(out.status.code(), Some(1));
    let stdout = text(&out.stdout);
    assert!(!stdout.contains("line 0"), "{stdout}");
    assert!(stdout.contains("bad.gml: [unreadable]: "), "{stdout}");
    assert!(stdout.contains("bad.gml: 1 finding\n"), "{stdout}");
    let f = nrgdb::indoorgml::Finding {
        code: "x",
        element: "e".into(),
        line: 3,
        message: "m".into(),
    };
    assert_eq!(nrgdb::indoorgml::tidy(vec![f.clone(), f.clone()]), vec![f]);
}

/// `extract --out x.json` wrote IndoorGML XML into a file named .json.
/// The output's extension now names its format, as for `export` and
/// `convert`; a name that says no format fails before the extraction and
/// writes nothing.
#[test]
fn paper_cut_extract_out_writes_the_format_its_extension_names() {
    let dir = tempfile::tempdir().unwrap();
    write_one_room(dir.path());
    let out = nrgdb(dir.path(), &["extract", "map.yaml", "--out", "x.json"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let written = std::fs::read_to_string(dir.path().join("x.json")).unwrap();
    let json: serde_json::Value = serde_json::from_str(&written).unwrap();
    let spaces = json["spaces"].as_array().unwrap();
    assert_eq!(spaces.len(), 1, "{written}");
    assert_eq!(spaces[0]["kind"], "room");
    let out = nrgdb(dir.path(), &["extract", "map.yaml", "--out", "x.geojson"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let geo: serde_json::Value =
        serde_json::from_slice(&std::fs::read(dir.path().join("x.geojson")).unwrap()).unwrap();
    assert_eq!(geo["type"], "FeatureCollection");
    let out = nrgdb(dir.path(), &["extract", "map.yaml", "--out", "x.txt"]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    assert!(
        text(&out.stderr).contains("x.txt: unknown format"),
        "{}",
        text(&out.stderr)
    );
    assert!(!dir.path().join("x.txt").exists());
}
