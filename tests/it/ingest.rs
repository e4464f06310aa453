//! Issue 19: one `ingest` turns bytes into a model and its grid, for the
//! CLI (files) and the server (uploads) alike. A map generated here and
//! written as ROS map files in a temp dir reads the same from its files
//! as from its bytes, and the same as the grid loader and the extraction
//! give on their own.

use std::path::Path;

use nrgdb::extract::{ExtractParams, extract};
use nrgdb::format::{Declared, FormatError};
use nrgdb::grid::{LoadOptions, load_map};
use nrgdb::ingest::{IngestError, IngestOptions, InputFile, read, read_path};

use super::support::{building, nrgdb};

/// A 10 m × 6 m floor at 5 cm per pixel: a corridor along the bottom and
/// two rooms above it, each with a door, as 8-bit grey rows (row 0 at the
/// top): free 254, wall 0, unknown 205 outside the walls.
fn floor_grey() -> (u32, u32, Vec<u8>) {
    let res = 0.05;
    let (w, h) = (200u32, 120u32);
    let free = [
        (0.2, 0.2, 9.8, 2.0),
        (0.2, 2.2, 4.9, 5.8),
        (5.1, 2.2, 9.8, 5.8),
        (2.0, 1.9, 2.9, 2.3),
        (7.0, 1.9, 7.9, 2.3),
    ];
    let mut grey = Vec::with_capacity((w * h) as usize);
    for row in 0..h {
        for col in 0..w {
            let x = (f64::from(col) + 0.5) * res;
            let y = 6.0 - (f64::from(row) + 0.5) * res;
            let inside = free
                .iter()
                .any(|&(x0, y0, x1, y1)| x >= x0 && x < x1 && y >= y0 && y < y1);
            let border = col == 0 || row == 0 || col == w - 1 || row == h - 1;
            grey.push(match (inside, border) {
                (true, _) => 254,
                (false, true) => 205,
                (false, false) => 0,
            });
        }
    }
    (w, h, grey)
}

const YAML: &str = "image: floor.pgm\nresolution: 0.05\norigin: [-2.5, 1.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";

/// Writes `floor.yaml` + `floor.pgm` into `dir`; returns their bytes.
fn write_floor(dir: &Path) -> (Vec<u8>, Vec<u8>) {
    let (w, h, grey) = floor_grey();
    let mut pgm = format!("P5\n{w} {h}\n255\n").into_bytes();
    pgm.extend_from_slice(&grey);
    std::fs::write(dir.join("floor.yaml"), YAML).unwrap();
    std::fs::write(dir.join("floor.pgm"), &pgm).unwrap();
    (YAML.as_bytes().to_vec(), pgm)
}

#[test]
fn issue_19_ingest_from_bytes_equals_ingest_from_files() {
    let dir = tempfile::tempdir().unwrap();
    let (yaml, pgm) = write_floor(dir.path());
    let options = IngestOptions::default();
    let yaml_path = dir.path().join("floor.yaml");

    let from_files = read_path(&yaml_path, &options).unwrap();
    // The server's way: the parts' bytes, names as sent, in any order.
    let from_bytes = read(
        &[
            InputFile::named("floor.pgm", &pgm),
            InputFile::named("floor.yaml", &yaml),
        ],
        &options,
    )
    .unwrap();
    assert_eq!(from_bytes, from_files);

    // And what the grid loader and the extraction give on their own.
    let grid = load_map(&yaml_path, &LoadOptions::default()).unwrap();
    assert_eq!(from_bytes.grid.as_ref(), Some(&grid));
    assert_eq!(grid.origin, [-2.5, 1.0, 0.0]);
    let extraction = extract(&grid, &ExtractParams::default()).unwrap();
    assert_eq!(from_bytes.nrg, extraction.nrg);
    assert!(
        from_bytes.nrg.spaces().len() >= 3,
        "two rooms, a corridor, doors"
    );

    assert_eq!(from_bytes.source_name, "floor.yaml + floor.pgm");
    assert_eq!(
        from_bytes.source_sha256,
        nrgdb::store::sha256_hex(&[yaml.as_slice(), &pgm].concat())
    );
    assert_eq!(from_bytes.params, Some(ExtractParams::default()));
    let meta = from_bytes.meta("first", "ada");
    assert_eq!(meta.source_name.as_deref(), Some("floor.yaml + floor.pgm"));
    assert!(meta.params.is_some_and(|p| p.is_object()));

    // The same map as a PNG, told by its bytes though named .pgm.
    let (w, h, grey) = floor_grey();
    let img = image::GrayImage::from_raw(w, h, grey).unwrap();
    let mut png = Vec::new();
    img.write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .unwrap();
    let from_png = read(
        &[
            InputFile::named("floor.yaml", &yaml),
            InputFile::named("floor.pgm", &png),
        ],
        &options,
    )
    .unwrap();
    assert_eq!(from_png.grid, from_files.grid);
    assert_eq!(from_png.nrg, from_files.nrg);
}

#[test]
fn issue_19_models_read_the_same_from_bytes_and_files() {
    let dir = tempfile::tempdir().unwrap();
    let nrg = building(3);
    for name in ["b.gml", "b.json", "b.geojson"] {
        let path = dir.path().join(name);
        nrgdb::format::write_model(&nrg, &path).unwrap();
        let bytes = std::fs::read(&path).unwrap();
        let from_file = read_path(&path, &IngestOptions::default()).unwrap();
        let from_bytes =
            read(&[InputFile::named(name, &bytes)], &IngestOptions::default()).unwrap();
        assert_eq!(from_bytes, from_file, "{name}");
        assert_eq!(from_file.source_name, name);
        assert!(from_file.grid.is_none() && from_file.params.is_none());
        assert_eq!(
            from_file.nrg,
            nrgdb::format::read_model(&path, u64::MAX).unwrap(),
            "{name}"
        );
        // Told by content alone: a form field, no file name.
        let anonymous = InputFile {
            declared: Declared {
                field: Some("model"),
                ..Declared::default()
            },
            bytes: &bytes,
        };
        let by_content = read(&[anonymous], &IngestOptions::default()).unwrap();
        assert_eq!(by_content.nrg, from_file.nrg, "{name}");
    }
}

#[test]
fn issue_19_bad_input_names_the_file_or_part() {
    let dir = tempfile::tempdir().unwrap();
    let (yaml, pgm) = write_floor(dir.path());
    let opts = IngestOptions::default();
    let err = |files: &[InputFile<'_>]| read(files, &opts).unwrap_err().to_string();

    let e = err(&[InputFile::named("floor.yaml", &yaml)]);
    assert!(
        e.starts_with("floor.yaml: a map YAML needs its image"),
        "{e}"
    );
    let e = err(&[InputFile::named("floor.pgm", &pgm)]);
    assert!(
        e.starts_with("floor.pgm: an image needs its map YAML"),
        "{e}"
    );
    let e = err(&[]);
    assert!(e.starts_with("no file given"), "{e}");
    let json = building(2).to_json();
    let e = err(&[
        InputFile::named("floor.yaml", &yaml),
        InputFile::named("floor.pgm", &pgm),
        InputFile::named("b.json", json.as_bytes()),
    ]);
    assert!(e.contains("not both"), "{e}");
    let e = err(&[
        InputFile::named("a.json", json.as_bytes()),
        InputFile::named("b.json", json.as_bytes()),
    ]);
    assert!(e.starts_with("a.json and b.json: two model files"), "{e}");
    let e = err(&[
        InputFile::named("floor.yaml", &yaml),
        InputFile::named("floor.pgm", b"P5\n200 120\n255\n\0\0"),
    ]);
    assert!(e.starts_with("floor.pgm: cannot decode the image"), "{e}");
    let e = err(&[
        InputFile::named("floor.yaml", b"image: floor.pgm\norigin: [0, 0, 0]\n"),
        InputFile::named("floor.pgm", &pgm),
    ]);
    assert!(
        e.starts_with("floor.yaml: field `resolution` is missing"),
        "{e}"
    );
    let e = err(&[InputFile::named("b.json", b"{\"spaces\": [")]);
    assert!(e.starts_with("b.json: "), "{e}");
    let e = err(&[InputFile::named("b.gml", json.as_bytes())]);
    assert!(
        e.starts_with("b.gml: its name says IndoorGML (XML) but its content is model JSON"),
        "{e}"
    );
    assert!(matches!(
        read(&[InputFile::named("b.gml", json.as_bytes())], &opts),
        Err(IngestError::Format(FormatError::Conflict { .. }))
    ));
    let e = err(&[InputFile::named("b.gml", b"<a>\n\xe9</a>")]);
    assert!(e.starts_with("b.gml: line 2: not UTF-8"), "{e}");

    // Files: the image a YAML names is missing; a file over the limit.
    std::fs::remove_file(dir.path().join("floor.pgm")).unwrap();
    let e = read_path(&dir.path().join("floor.yaml"), &opts)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("floor.yaml: cannot read its image: ") && e.contains("floor.pgm"),
        "{e}"
    );
    let small = IngestOptions {
        max_bytes: 10,
        ..IngestOptions::default()
    };
    let e = read_path(&dir.path().join("floor.yaml"), &small)
        .unwrap_err()
        .to_string();
    assert!(e.contains("above the limit of 10 bytes"), "{e}");
}

#[test]
fn issue_19_import_cli_reads_a_map_through_ingest() {
    let dir = tempfile::tempdir().unwrap();
    write_floor(dir.path());
    let out = nrgdb(
        dir.path(),
        &["import", "floor.yaml", "--map", "floor", "--db", "f.sqlite"],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let store = nrgdb::store::Store::open(&dir.path().join("f.sqlite")).unwrap();
    let rev = store.revision("floor", None).unwrap();
    assert_eq!(rev.source_name.as_deref(), Some("floor.yaml + floor.pgm"));
    assert!(store.grid("floor", None).unwrap().is_some());
    // A broken image: exit 2, the image named, nothing stored.
    std::fs::write(dir.path().join("floor.pgm"), b"P5\n200 120\n255\n").unwrap();
    let out = nrgdb(
        dir.path(),
        &["import", "floor.yaml", "--map", "floor", "--db", "f.sqlite"],
    );
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("floor.pgm: cannot decode the image"),
        "{stderr}"
    );
    assert_eq!(store.revisions("floor").unwrap().len(), 1);
}
