//! ROS 2 recordings in (issue 24): maps published on `/map` in MCAP files
//! and SQLite bags become one revision per map that changed, at the
//! message's time; bad recordings store nothing.

use std::time::Duration;

use nrgdb::grid::{Cell, LoadOptions, load_map};
use nrgdb::ingest::{IngestOptions, RecordingImportError, import_recording};
use nrgdb::recording::{Recording, RecordingError, RecordingOptions, scan};
use nrgdb::store::{ImportMeta, Store};

use crate::diff_support::{floor, paint, write_map};
use crate::recording_support::{Msg, grid_message, write_db3_bag, write_mcap};
use crate::support::nrgdb;

const GRID: &str = "nav_msgs/msg/OccupancyGrid";
const SCAN: &str = "sensor_msgs/msg/LaserScan";
const S: u64 = 1_000_000_000;
/// 2026-12-03 10:00:00 UTC.
const T0: u64 = 1_796_292_000 * S;

/// Two maps 10 s apart and an identical third, with scans between.
fn three_maps() -> Vec<Msg> {
    let first = floor().grid;
    let mut second = first.clone();
    // Room 3 split by a wall with a door: the building changed.
    paint(&mut second, (440, 14, 444, 196), Cell::Occupied);
    paint(&mut second, (440, 100, 444, 118), Cell::Free);
    let map = |t: u64, g: &nrgdb::grid::OccupancyGrid| Msg {
        topic: "/map",
        kind: GRID,
        time_ns: T0 + t * S,
        data: grid_message(g, T0 + t * S, true),
    };
    let scan = |t: u64| Msg {
        topic: "/scan",
        kind: SCAN,
        time_ns: T0 + t * S,
        data: vec![0, 1, 0, 0, 1, 2, 3, 4],
    };
    vec![
        scan(0),
        map(1, &first),
        scan(5),
        map(11, &second),
        scan(15),
        map(21, &second),
    ]
}

fn import(
    store: &mut Store,
    path: &std::path::Path,
    options: &RecordingOptions,
) -> Result<nrgdb::ingest::RecordingImport, RecordingImportError> {
    let recording = Recording::open(path)?;
    import_recording(
        store,
        "lab",
        &recording,
        options,
        &IngestOptions::default(),
        &ImportMeta::new("", "robot"),
        |_| {},
    )
}

#[test]
fn an_mcap_recording_becomes_one_revision_per_changed_map() {
    let dir = tempfile::tempdir().unwrap();
    for compress in [false, true] {
        let path = dir.path().join(format!("run-{compress}.mcap"));
        write_mcap(&path, &three_maps(), compress);
        let mut store = Store::open_in_memory().unwrap();
        let done = import(&mut store, &path, &RecordingOptions::default()).unwrap();
        assert_eq!(done.messages, 3);
        assert_eq!(done.identical, 1, "the third map is the second's");
        let revisions: Vec<_> = done.revisions().cloned().collect();
        assert_eq!(revisions.len(), 2);
        let stored = store.revisions("lab").unwrap();
        assert_eq!(stored.len(), 2);
        // The message's time is the revision's time.
        assert_eq!(stored[0].created_at, "2026-12-03T10:00:01.000Z");
        assert_eq!(stored[1].created_at, "2026-12-03T10:00:11.000Z");
        assert!(stored[0].message.contains(&format!("run-{compress}.mcap")));
        assert!(stored[0].message.contains("/map"));
        // The second revision has one room more (the split).
        let (a, b) = (
            store.load("lab", Some(1)).unwrap(),
            store.load("lab", Some(2)).unwrap(),
        );
        let rooms = |n: &nrgdb::model::Nrg| {
            n.spaces()
                .iter()
                .filter(|s| s.kind != nrgdb::model::SpaceKind::Door)
                .count()
        };
        assert_eq!(rooms(&b), rooms(&a) + 1, "{} → {}", rooms(&a), rooms(&b));
        // The grid is kept with the revision, in the message's frame.
        let grid = store.grid("lab", Some(1)).unwrap().unwrap();
        assert_eq!(grid.origin, floor().grid.origin);
        // Importing the same recording again writes nothing: its maps
        // are stored already (same map, same time).
        let again = import(&mut store, &path, &RecordingOptions::default()).unwrap();
        assert_eq!(again.revisions().count(), 0);
        assert_eq!(again.already_stored, 2);
        assert_eq!(store.revisions("lab").unwrap().len(), 2);
    }
}

/// A map message and the same map saved as the map saver writes it
/// (free 254, occupied 0, unknown 205, its thresholds 0.25 / 0.65) give
/// the same grid.
#[test]
fn a_map_message_reads_as_the_saved_map() {
    let dir = tempfile::tempdir().unwrap();
    let grid = floor().grid;
    write_map(dir.path(), "saved", &grid);
    let from_yaml = load_map(&dir.path().join("saved.yaml"), &LoadOptions::default()).unwrap();
    let path = dir.path().join("one.mcap");
    write_mcap(
        &path,
        &[Msg {
            topic: "/map",
            kind: GRID,
            time_ns: T0,
            data: grid_message(&grid, T0, true),
        }],
        false,
    );
    let recording = Recording::open(&path).unwrap();
    let options = RecordingOptions::default();
    let found = scan(&recording, &options).unwrap();
    let mut got = Vec::new();
    nrgdb::recording::read_chosen::<RecordingError>(&recording, &options, &found, |_, g| {
        got.push(g);
        Ok(())
    })
    .unwrap();
    assert_eq!(got.len(), 1);
    assert_eq!(got[0].cells, from_yaml.cells);
    assert_eq!(
        (got[0].width, got[0].height),
        (from_yaml.width, from_yaml.height)
    );
    for k in 0..3 {
        assert!((got[0].origin[k] - from_yaml.origin[k]).abs() < 1e-9);
    }
    assert!((got[0].resolution - from_yaml.resolution).abs() < 1e-7);
}

#[test]
fn every_keeps_one_map_per_interval() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("run.mcap");
    write_mcap(&path, &three_maps(), true);
    let mut store = Store::open_in_memory().unwrap();
    let options = RecordingOptions {
        every: Some(Duration::from_secs(30)),
        ..RecordingOptions::default()
    };
    let done = import(&mut store, &path, &options).unwrap();
    // All three maps fall in the first 30 s: the last one is kept.
    assert_eq!(done.revisions().count(), 1);
    assert_eq!(done.thinned, 2);
    let stored = store.revisions("lab").unwrap();
    assert_eq!(stored[0].created_at, "2026-12-03T10:00:21.000Z");
}

#[test]
fn a_sqlite_bag_reads_like_the_mcap_file() {
    let dir = tempfile::tempdir().unwrap();
    let bag = dir.path().join("rosbag2_2026_12_03");
    write_db3_bag(&bag, &three_maps());
    let mcap = dir.path().join("run.mcap");
    write_mcap(&mcap, &three_maps(), false);
    let (mut a, mut b) = (
        Store::open_in_memory().unwrap(),
        Store::open_in_memory().unwrap(),
    );
    let from_bag = import(&mut a, &bag, &RecordingOptions::default()).unwrap();
    let from_mcap = import(&mut b, &mcap, &RecordingOptions::default()).unwrap();
    assert_eq!(from_bag.revisions().count(), 2);
    assert_eq!(from_bag.messages, from_mcap.messages);
    assert_eq!(from_bag.identical, 1);
    for rev in [1, 2] {
        assert_eq!(
            a.load("lab", Some(rev)).unwrap(),
            b.load("lab", Some(rev)).unwrap()
        );
    }
    // The .db3 file given on its own reads the same.
    let mut c = Store::open_in_memory().unwrap();
    let alone = import(&mut c, &bag.join("bag_0.db3"), &RecordingOptions::default()).unwrap();
    assert_eq!(alone.revisions().count(), 2);
}

#[test]
fn bad_recordings_store_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.mcap");
    write_mcap(&good, &three_maps(), true);
    let bytes = std::fs::read(&good).unwrap();
    let expect_nothing = |path: &std::path::Path, options: &RecordingOptions, says: &str| {
        let mut store = Store::open_in_memory().unwrap();
        let err = import(&mut store, path, options).unwrap_err().to_string();
        assert!(err.contains(says), "{}: {err}", path.display());
        assert!(
            err.contains(&path.file_name().unwrap().to_string_lossy().to_string()),
            "{err}"
        );
        assert!(store.maps().unwrap().is_empty(), "{err}");
    };
    let defaults = RecordingOptions::default();
    // Truncated mid-file (inside the data section).
    for cut in [bytes.len() / 2, bytes.len() - 30, 20] {
        let path = dir.path().join(format!("cut-{cut}.mcap"));
        std::fs::write(&path, &bytes[..cut]).unwrap();
        expect_nothing(&path, &defaults, "nothing was stored");
    }
    // A flipped byte inside a compressed chunk.
    let mut corrupt = bytes.clone();
    let mid = corrupt.len() / 3;
    corrupt[mid] ^= 0x5a;
    let path = dir.path().join("corrupt.mcap");
    std::fs::write(&path, &corrupt).unwrap();
    expect_nothing(&path, &defaults, "nothing was stored");
    // No such topic: the topics there are named.
    let other = RecordingOptions {
        topic: "/floor".into(),
        ..RecordingOptions::default()
    };
    expect_nothing(
        &good,
        &other,
        "no messages on /floor; the recording has topics /map, /scan",
    );
    // The topic carries something else.
    let scans = RecordingOptions {
        topic: "/scan".into(),
        ..RecordingOptions::default()
    };
    expect_nothing(&good, &scans, "carries sensor_msgs/msg/LaserScan in cdr");
    // An unknown CDR layout in the second map.
    let mut maps = three_maps();
    maps[3].data[1] = 0x07;
    let path = dir.path().join("xcdr2.mcap");
    write_mcap(&path, &maps, false);
    expect_nothing(&path, &defaults, "map message 2 on /map");
    expect_nothing(&path, &defaults, "unknown CDR layout 0x0007");
    // A map message whose data is shorter than width × height.
    let mut maps = three_maps();
    let n = maps[5].data.len();
    maps[5].data.truncate(n - 100);
    let path = dir.path().join("short.mcap");
    write_mcap(&path, &maps, false);
    expect_nothing(&path, &defaults, "map message 3");
    // Not a recording; a bag folder naming a file outside itself.
    let path = dir.path().join("notes.mcap");
    std::fs::write(&path, b"hello").unwrap();
    expect_nothing(&path, &defaults, "notes.mcap");
    let bag = dir.path().join("escape");
    std::fs::create_dir_all(&bag).unwrap();
    std::fs::write(
        bag.join("metadata.yaml"),
        "rosbag2_bagfile_information:\n  storage_identifier: sqlite3\n  relative_file_paths: [../good.db3]\n",
    )
    .unwrap();
    let mut store = Store::open_in_memory().unwrap();
    let err = import(&mut store, &bag, &defaults).unwrap_err().to_string();
    assert!(err.contains("must be inside its folder"), "{err}");
}

#[test]
fn the_cli_imports_a_recording() {
    let dir = tempfile::tempdir().unwrap();
    write_mcap(&dir.path().join("run.mcap"), &three_maps(), true);
    let out = nrgdb(
        dir.path(),
        &["import", "run.mcap", "--map", "lab", "--db", "t.sqlite"],
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{text}{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        text.contains("lab@1 (map message 1, 2026-12-03T10:00:01.000Z)"),
        "{text}"
    );
    assert!(
        text.contains("lab@2 (map message 2, 2026-12-03T10:00:11.000Z)"),
        "{text}"
    );
    assert!(
        text.contains("run.mcap: 3 map messages on /map")
            && text.contains("2 revisions stored, 1 identical to the map before"),
        "{text}"
    );
    let log = nrgdb(dir.path(), &["log", "lab", "--db", "t.sqlite"]);
    let log_text = String::from_utf8_lossy(&log.stdout);
    assert!(log_text.contains("2026-12-03T10:00:11"), "{log_text}");
    // A truncated copy: an error naming the file, exit status non-zero,
    // the map untouched.
    let bytes = std::fs::read(dir.path().join("run.mcap")).unwrap();
    std::fs::write(dir.path().join("cut.mcap"), &bytes[..bytes.len() / 2]).unwrap();
    let out = nrgdb(
        dir.path(),
        &["import", "cut.mcap", "--map", "lab2", "--db", "t.sqlite"],
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(
        err.contains("cut.mcap") && err.contains("nothing was stored"),
        "{err}"
    );
    let maps = nrgdb(dir.path(), &["maps", "--db", "t.sqlite"]);
    assert!(!String::from_utf8_lossy(&maps.stdout).contains("lab2"));
    let bad = nrgdb(
        dir.path(),
        &[
            "import", "run.mcap", "--map", "x", "--every", "0s", "--db", "t.sqlite",
        ],
    );
    assert!(!bad.status.success());
}

/// A robot's first maps are often too small to hold a room: they are left
/// out with the reason, and the maps after them are stored.
#[test]
fn maps_too_small_to_extract_are_left_out_and_said() {
    let dir = tempfile::tempdir().unwrap();
    let tiny = nrgdb::grid::OccupancyGrid::from_cells(
        20,
        10,
        0.05,
        [0.0, 0.0, 0.0],
        vec![Cell::Free; 200],
    );
    let mut messages = vec![Msg {
        topic: "/map",
        kind: GRID,
        time_ns: T0,
        data: grid_message(&tiny, T0, false),
    }];
    messages.extend(three_maps().into_iter().filter(|m| m.topic == "/map"));
    let path = dir.path().join("growing.mcap");
    write_mcap(&path, &messages, false);
    let mut store = Store::open_in_memory().unwrap();
    let done = import(&mut store, &path, &RecordingOptions::default()).unwrap();
    assert_eq!(done.unusable.len(), 1);
    let (index, time, why) = &done.unusable[0];
    assert_eq!((*index, time.as_str()), (1, "2026-12-03T10:00:00.000Z"));
    assert!(why.contains("extraction failed"), "{why}");
    assert_eq!(done.revisions().count(), 2);
    // Only unusable maps: the CLI says nothing was stored and fails.
    let only = dir.path().join("only.mcap");
    write_mcap(&only, &messages[..1], false);
    let out = nrgdb(
        dir.path(),
        &["import", "only.mcap", "--map", "x", "--db", "t.sqlite"],
    );
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("nothing was stored"), "{err}");
}
