//! `nrgdb render` and the picture/batch options of `nrgdb extract`, run as
//! the binary in a temp folder.

use crate::support::{building, nrgdb};

fn png_size(path: &std::path::Path) -> (u32, u32) {
    image::image_dimensions(path).unwrap()
}

#[test]
fn render_cli_writes_png_and_svg_with_a_route() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("b.json"), building(4).to_json()).unwrap();
    let out = nrgdb(
        dir.path(),
        &[
            "render", "b.json", "--out", "b.png", "--route", "Office 1", "13", "--scale", "20",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("route"), "{text}");
    let (w, h) = png_size(&dir.path().join("b.png"));
    assert!(w >= 16 * 20 && h >= 7 * 20, "{w}×{h}");
    let out = nrgdb(
        dir.path(),
        &["render", "b.json", "--out", "b.svg", "--route", "10", "13"],
    );
    assert!(out.status.success());
    let svg = std::fs::read_to_string(dir.path().join("b.svg")).unwrap();
    let route = svg.lines().find(|l| l.contains("id=\"route\"")).unwrap();
    // Office 1 → its door → corridor → door of room 13 → room 13, walked:
    // the line bends around both doorways' corners, so it has more points
    // than its two ends (it is no straight line through the walls).
    let points = route
        .split("points=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .split(' ')
        .count();
    assert!(points >= 4, "{route}");
}

#[test]
fn render_cli_diff_of_two_stored_revisions() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("a.json"), building(3).to_json()).unwrap();
    std::fs::write(dir.path().join("b.json"), building(4).to_json()).unwrap();
    for f in ["a.json", "b.json"] {
        let out = nrgdb(dir.path(), &["import", f, "--map", "m", "--db", "t.db"]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let out = nrgdb(
        dir.path(),
        &[
            "render", "m", "--db", "t.db", "--diff", "1", "2", "--out", "d.svg",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = std::fs::read_to_string(dir.path().join("d.svg")).unwrap();
    // Room 13 and its door are new (the store gives them fresh ids); the corridor grew.
    assert_eq!(svg.matches("class=\"diff added\"").count(), 2, "{svg}");
    assert!(svg.contains("class=\"diff changed\" data-space=\"1\""));
    assert!(!svg.contains("class=\"diff removed\""));
}

#[test]
fn render_cli_bad_inputs_are_errors_not_panics() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("b.json"), building(2).to_json()).unwrap();
    for (args, needle) in [
        (
            vec!["render", "b.json", "--out", "b.jpg"],
            "unknown picture format",
        ),
        (vec!["render", "nope.json", "--out", "b.png"], "no database"),
        (
            vec!["render", "b.json", "--out", "b.png", "--route", "10", "999"],
            "no space '999'",
        ),
        (
            vec!["render", "b.json", "--out", "b.png", "--scale", "100000"],
            "would be",
        ),
        (
            vec!["render", "b.json", "--out", "b.png", "--diff", "1", "2"],
            "bare revision number",
        ),
    ] {
        let out = nrgdb(dir.path(), &args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
    assert!(!dir.path().join("b.png").exists());
    assert!(!dir.path().join("nrgdb.sqlite").exists());
}

/// A small map: two 1.8 m rooms joined by a door gap, as a PGM + YAML.
fn write_map(dir: &std::path::Path, stem: &str) {
    let (w, h) = (40usize, 20usize);
    let mut pgm = format!("P5\n{w} {h}\n255\n").into_bytes();
    for y in 0..h {
        for x in 0..w {
            pgm.push(
                if is_wall(x, y, w, h) && !(x == 19 && (8..12).contains(&y)) {
                    0
                } else {
                    254
                },
            );
        }
    }
    std::fs::write(dir.join(format!("{stem}.pgm")), pgm).unwrap();
    std::fs::write(
        dir.join(format!("{stem}.yaml")),
        format!(
            "image: {stem}.pgm\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n\
             occupied_thresh: 0.65\nfree_thresh: 0.196\n"
        ),
    )
    .unwrap();
}

fn is_wall(x: usize, y: usize, w: usize, h: usize) -> bool {
    x == 0 || y == 0 || x == w - 1 || y == h - 1 || x == 19
}

#[test]
fn extract_png_shortcut_and_batch_into_out_dir() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("maps")).unwrap();
    write_map(&dir.path().join("maps"), "a");
    write_map(&dir.path().join("maps"), "b");
    let out = nrgdb(dir.path(), &["extract", "maps/a.yaml", "--png", "a.png"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(png_size(&dir.path().join("a.png")).0 > 40);
    // Several maps need --out-dir; a folder counts as its .yaml maps.
    let out = nrgdb(dir.path(), &["extract", "maps/a.yaml", "maps/b.yaml"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--out-dir"));
    let out = nrgdb(
        dir.path(),
        &[
            "extract",
            "maps",
            "--out-dir",
            "out",
            "--formats",
            "json,svg",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("2 of 2 maps extracted"), "{text}");
    for f in ["a.json", "a.svg", "b.json", "b.svg"] {
        assert!(dir.path().join("out").join(f).is_file(), "{f}");
    }
    // Piped: no progress bar escape codes on stderr.
    assert!(!String::from_utf8_lossy(&out.stderr).contains('\u{1b}'));
}

#[test]
fn eval_over_a_folder_scores_maps_with_a_ground_truth_and_skips_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let maps = dir.path().join("maps");
    std::fs::create_dir(&maps).unwrap();
    write_map(&maps, "a");
    write_map(&maps, "b");
    // a's ground truth: the two rooms, the doorway (column 19) closed by a dark line.
    let gt = image::GrayImage::from_fn(40, 20, |x, y| {
        image::Luma([if is_wall(x as usize, y as usize, 40, 20) {
            0
        } else {
            255
        }])
    });
    gt.save(maps.join("a_gt.png")).unwrap();
    let out = nrgdb(dir.path(), &["eval", "maps"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let row = text.lines().find(|l| l.starts_with("a ")).unwrap();
    let numbers: Vec<f64> = row
        .split_whitespace()
        .filter_map(|w| w.parse().ok())
        .collect();
    // Eight scores in %, then the door width error's median and p90 (m).
    assert_eq!(numbers.len(), 10, "{row}");
    assert!(numbers[0] > 50.0, "room recall {row}");
    assert!(numbers[8] <= 0.1, "width error {row}");
    assert!(text.contains("mean of 1"), "{text}");
    assert!(text.contains("b: skipped, no b_gt.png"), "{text}");
    let out = nrgdb(dir.path(), &["eval", "maps", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v.as_array().map(Vec::len), Some(1));
    // --gt names one file: refused with several maps.
    let out = nrgdb(
        dir.path(),
        &[
            "eval",
            "maps/a.yaml",
            "maps/b.yaml",
            "--gt",
            "maps/a_gt.png",
        ],
    );
    assert_eq!(out.status.code(), Some(2));
    // --picture draws one map: its size, and the found doorway line in green.
    let out = nrgdb(
        dir.path(),
        &["eval", "maps/a.yaml", "--picture", "a_eval.png"],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let pic = image::open(dir.path().join("a_eval.png"))
        .unwrap()
        .to_rgb8();
    assert_eq!(pic.dimensions(), (40, 20));
    let found = pic
        .pixels()
        .filter(|p| p.0 == nrgdb::eval::LINE_FOUND)
        .count();
    assert!(found > 0, "the doorway line is drawn as found");
    let out = nrgdb(dir.path(), &["eval", "maps", "--picture", "x.png"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(!dir.path().join("x.png").exists());
}
