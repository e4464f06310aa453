//! Integration tests of the simulator: maps, ground truth, determinism,
//! the CLI and bad input.

use std::collections::VecDeque;
use std::path::{Path, PathBuf};
use std::process::Command;

use nrgdb::model::{Nrg, SpaceKind, point_in_ring};
use nrgdb::sim::{GreyMap, SimParams, Simulation, simulate, write_simulation};

fn small(seed: u64, furniture: bool, non_manhattan: bool) -> Simulation {
    let mut p = SimParams::new(seed);
    p.plan.furniture = furniture;
    p.plan.non_manhattan = non_manhattan;
    p.plan.corridor_length_m = (10.0, 18.0);
    simulate(&p).unwrap()
}

/// Every pixel's centre in metres (map frame) with its grey value.
fn pixel_centres(map: &GreyMap) -> impl Iterator<Item = ([f64; 2], u8)> + '_ {
    let (w, h, r) = (map.width as usize, map.height as usize, map.resolution_m);
    (0..h).flat_map(move |row| {
        (0..w).map(move |col| {
            let x = map.origin_m[0] + (col as f64 + 0.5) * r;
            let y = map.origin_m[1] + ((h - 1 - row) as f64 + 0.5) * r;
            ([x, y], map.grey[row * w + col])
        })
    })
}

fn white_components_8(grey: &[u8], w: usize, h: usize) -> usize {
    let mut seen = vec![false; w * h];
    let mut n = 0;
    for start in 0..w * h {
        if seen[start] || grey[start] <= 250 {
            continue;
        }
        n += 1;
        seen[start] = true;
        let mut q = VecDeque::from([start]);
        while let Some(i) = q.pop_front() {
            let (x, y) = ((i % w) as i64, (i / w) as i64);
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let (nx, ny) = (x + dx, y + dy);
                    if nx < 0 || ny < 0 || nx >= w as i64 || ny >= h as i64 {
                        continue;
                    }
                    let j = ny as usize * w + nx as usize;
                    if !seen[j] && grey[j] > 250 {
                        seen[j] = true;
                        q.push_back(j);
                    }
                }
            }
        }
    }
    n
}

#[test]
fn sim_map_has_free_space_in_every_true_room() {
    for (seed, furn, diag) in [
        (1, false, false),
        (2, true, false),
        (3, false, true),
        (4, true, true),
    ] {
        let sim = small(seed, furn, diag);
        let nrg = sim.plan.truth().unwrap();
        for s in nrg.spaces().iter().filter(|s| s.kind != SpaceKind::Door) {
            let (mut inside, mut free) = (0, 0);
            for (p, g) in pixel_centres(&sim.map) {
                if point_in_ring(p, &s.polygon) {
                    inside += 1;
                    free += usize::from(g == 254);
                }
            }
            let share = free as f64 / inside as f64;
            assert!(
                share > 0.6,
                "seed {seed}: {} only {share:.2} free",
                s.label()
            );
        }
        // walls were seen: some occupied pixels, and nothing free far outside
        assert!(sim.map.grey.contains(&0));
    }
}

#[test]
fn sim_ground_truth_has_one_white_component_per_room_and_corridor_run() {
    for (seed, furn, diag) in [(5, false, false), (6, true, true), (7, false, true)] {
        let sim = small(seed, furn, diag);
        let dir = tempfile::tempdir().unwrap();
        let files = write_simulation(dir.path(), &sim).unwrap();
        let gt = image::open(&files.gt_png).unwrap().into_luma8();
        assert_eq!((gt.width(), gt.height()), (sim.map.width, sim.map.height));
        let n = white_components_8(gt.as_raw(), gt.width() as usize, gt.height() as usize);
        let nrg = Nrg::from_json(&std::fs::read_to_string(&files.truth_json).unwrap()).unwrap();
        let spaces = nrg
            .spaces()
            .iter()
            .filter(|s| matches!(s.kind, SpaceKind::Room | SpaceKind::Corridor))
            .count();
        // Open passages between corridors are no doorways, so get no line:
        // corridors joined by them are one component.
        let corridor_groups = sim.plan.corridors.len() - sim.plan.openings.len();
        assert_eq!(n, spaces - sim.plan.openings.len(), "seed {seed}");
        assert_eq!(n, sim.plan.rooms.len() + corridor_groups);
    }
}

#[test]
fn sim_same_seed_gives_the_same_bytes() {
    let read = |d: &Path| -> Vec<Vec<u8>> {
        ["map.yaml", "map.pgm", "map_gt.png", "truth.json"]
            .iter()
            .map(|f| std::fs::read(d.join(f)).unwrap())
            .collect()
    };
    let (a, b) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    write_simulation(a.path(), &small(11, true, true)).unwrap();
    write_simulation(b.path(), &small(11, true, true)).unwrap();
    assert_eq!(read(a.path()), read(b.path()));
    let c = tempfile::tempdir().unwrap();
    write_simulation(c.path(), &small(12, true, true)).unwrap();
    assert_ne!(read(a.path())[3], read(c.path())[3]);
}

fn nrgdb(args: &[&str], cwd: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_nrgdb"))
        .args(args)
        .current_dir(cwd)
        .output()
        .unwrap()
}

/// Runs `nrgdb` in `cwd`, asserts it succeeded, and returns its stdout.
fn nrgdb_ok(args: &[&str], cwd: &Path) -> String {
    let out = nrgdb(args, cwd);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn sim_cli_writes_and_names_its_files() {
    let dir = tempfile::tempdir().unwrap();
    let text = nrgdb_ok(
        &[
            "simulate",
            "--seed",
            "3",
            "--out",
            "o",
            "--resolution",
            "0.1",
        ],
        dir.path(),
    );
    for f in ["map.yaml", "map.pgm", "map_gt.png", "truth.json"] {
        assert!(dir.path().join("o").join(f).is_file(), "{f}");
        assert!(text.contains(f), "{text}");
    }
    let yaml = std::fs::read_to_string(dir.path().join("o/map.yaml")).unwrap();
    assert!(
        yaml.contains("resolution: 0.1") && yaml.contains("mode: trinary"),
        "{yaml}"
    );
}

/// `--house`: one living area, a room in the truth, furnished, with the
/// bedrooms off it through doors.
#[test]
fn sim_cli_house_is_a_living_area_with_rooms_off_it() {
    let dir = tempfile::tempdir().unwrap();
    let text = nrgdb_ok(
        &["simulate", "--house", "--seed", "5", "--out", "h"],
        dir.path(),
    );
    assert!(text.contains("1 living area,"), "{text}");
    let truth: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("h/truth.json")).unwrap())
            .unwrap();
    let spaces = truth["spaces"].as_array().unwrap();
    let kind = |k: &str| spaces.iter().filter(|s| s["kind"] == k).count();
    assert_eq!(kind("corridor"), 0, "{text}");
    assert!(
        kind("room") >= 5 && kind("door") >= kind("room") - 1,
        "{text}"
    );
    let living = spaces
        .iter()
        .find(|s| s["name"] == "living area 1")
        .expect("the living area");
    assert_eq!(living["kind"], "room");
    // A house has no wings to turn: the flags are refused together.
    let out = nrgdb(
        &["simulate", "--house", "--non-manhattan", "--out", "n"],
        dir.path(),
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--non-manhattan"));
    assert!(!dir.path().join("n").exists());
}

#[test]
fn sim_cli_rejects_bad_resolution_without_output() {
    let dir = tempfile::tempdir().unwrap();
    for r in ["0", "-0.05"] {
        let out = nrgdb(
            &["simulate", "--out", "o", &format!("--resolution={r}")],
            dir.path(),
        );
        assert_eq!(out.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&out.stderr).contains("--resolution"));
        assert!(!dir.path().join("o").exists());
    }
}

#[test]
fn sim_map_log_reports_bad_lines_and_missing_files() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("bad.log"), "PARAM a 1 h 0\nFLASER 3 1 2\n").unwrap();
    let out = nrgdb(&["map-log", "bad.log", "--out", "o"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("bad.log:2"), "{err}");
    assert!(!dir.path().join("o").exists());
    let out = nrgdb(&["map-log", "missing.log.gz", "--out", "o"], dir.path());
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("missing.log.gz"));
}

#[test]
fn sim_map_log_maps_a_generated_log() {
    // A square 6 m room scanned from its centre, written as FLASER lines.
    let mut log = String::new();
    for k in 0..12 {
        let th = k as f64 * std::f64::consts::PI / 6.0;
        let (x, y) = (3.0 + th.cos(), 3.0 + th.sin());
        let walls = nrgdb::sim::WallIndex::new(
            vec![
                [[0.0, 0.0], [6.0, 0.0]],
                [[6.0, 0.0], [6.0, 6.0]],
                [[6.0, 6.0], [0.0, 6.0]],
                [[0.0, 6.0], [0.0, 0.0]],
            ],
            1.0,
        );
        log.push_str("FLASER 180");
        for i in 0..180 {
            let a = th - std::f64::consts::FRAC_PI_2 + (i as f64).to_radians();
            let r = walls.cast([x, y], a, 80.0).unwrap_or(81.9);
            log.push_str(&format!(" {r:.3}"));
        }
        log.push_str(&format!(" {x} {y} {th} {x} {y} {th} {k} host {k}\n"));
    }
    let dir = tempfile::tempdir().unwrap();
    let path: PathBuf = dir.path().join("room.log");
    std::fs::write(&path, log).unwrap();
    // `--out NAME.yaml` writes that map YAML and its image beside it; a
    // folder gets map.yaml + map.pgm.
    let out = nrgdb(
        &["map-log", "room.log", "--out", "maps/room.yaml"],
        dir.path(),
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let yaml = std::fs::read_to_string(dir.path().join("maps/room.yaml")).unwrap();
    assert!(yaml.contains("image: room.pgm"), "{yaml}");
    assert!(dir.path().join("maps/room.pgm").is_file());
    let out = nrgdb(&["map-log", "room.log", "--out", "o"], dir.path());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(dir.path().join("o/map.yaml").is_file() && dir.path().join("o/map.pgm").is_file());
    let built =
        nrgdb::sim::map_carmen_log(&path, 0.05, 20.0, nrgdb::sim::OccupancyRule::RECORDED).unwrap();
    assert_eq!(built.scans, 12);
    let m = &built.map;
    // the room is 6 m plus a 1 m margin each side, give or take a cell
    let w = f64::from(m.width) * m.resolution_m;
    assert!((w - 8.0).abs() < 0.2, "{w}");
    let free = m.grey.iter().filter(|&&g| g == 254).count() as f64 * 0.0025;
    assert!(free > 25.0 && free < 36.0, "free area {free}");
    let occupied = m.grey.iter().filter(|&&g| g == 0).count() as f64 * 0.05;
    assert!(occupied > 15.0 && occupied < 40.0, "wall length {occupied}");
}

/// A file of the shared reference data, by its path inside it.
fn shared_file(rel: &str) -> Option<PathBuf> {
    crate::support::shared_dir(rel).map(|dir| dir.join(rel))
}

#[test]
fn sim_map_log_intel_has_the_building_size() {
    let Some(log) = shared_file("carmen/intel-corrected.log.gz") else {
        return;
    };
    let built =
        nrgdb::sim::map_carmen_log(&log, 0.05, 20.0, nrgdb::sim::OccupancyRule::RECORDED).unwrap();
    assert_eq!(built.scans, 910);
    let m = &built.map;
    let (w, h) = (m.width as usize, m.height as usize);
    let (mut c0, mut c1, mut r0, mut r1) = (w, 0, h, 0);
    for r in 0..h {
        for c in 0..w {
            if m.grey[r * w + c] == 254 {
                (c0, c1, r0, r1) = (c0.min(c), c1.max(c), r0.min(r), r1.max(r));
            }
        }
    }
    // The Intel lab is a square building of about 29 m a side.
    let (bw, bh) = ((c1 - c0 + 1) as f64 * 0.05, (r1 - r0 + 1) as f64 * 0.05);
    assert!(
        (27.5..31.0).contains(&bw) && (27.5..31.0).contains(&bh),
        "{bw} x {bh} m"
    );
}

/// Our map of a recorded log against ROSE²'s map of the same log (another
/// mapper's, in another frame): `nrgdb eval --gt-map` aligns the two and
/// says how much of each map's walls lie within 0.1 m of the other's.
/// Measured at this commit: FR079 90.5 % / 86.6 %, Intel 84 % / 71 %; the
/// log-odds rule, whose late grazing beams clear corridor walls, gives
/// 86 % / 81 % and 73 % / 69 %.
#[test]
fn sim_map_log_walls_lie_on_another_mappers_map_of_the_same_log() {
    let cases = [
        (
            "carmen/freiburg-079-corrected.log.gz",
            "maps/rose2_fr079_carmen.yaml",
            [0.88, 0.84],
        ),
        (
            "carmen/intel-corrected.log.gz",
            "maps/rose2_intel_carmen.yaml",
            [0.80, 0.70],
        ),
    ];
    for (log, reference, least) in cases {
        let (Some(log), Some(reference)) = (shared_file(log), shared_file(reference)) else {
            return;
        };
        let dir = tempfile::tempdir().unwrap();
        let log = log.to_string_lossy().into_owned();
        let out = nrgdb(&["map-log", &log, "--out", "ours.yaml"], dir.path());
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let reference = reference.to_string_lossy().into_owned();
        let out = nrgdb(
            &["eval", "ours.yaml", "--gt-map", &reference, "--json"],
            dir.path(),
        );
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        let carried = &v["gt_alignment"];
        let ours_on_theirs = carried["alignment"]["inliers"].as_f64().unwrap();
        let theirs_on_ours = carried["walls_found"].as_f64().unwrap();
        assert!(
            ours_on_theirs >= least[0] && theirs_on_ours >= least[1],
            "{log}: {ours_on_theirs:.3} of our walls on theirs, {theirs_on_ours:.3} of theirs on ours"
        );
    }
}
