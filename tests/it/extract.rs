//! Extraction on generated floor plans (and, when present, the shared maps).

use std::path::PathBuf;

use nrgdb::extract::{DoorRule, ExtractParams, Method, extract};
use nrgdb::grid::{Cell, LoadOptions, OccupancyGrid, load_map};
use nrgdb::model::{ConnectionKind, SpaceKind, point_in_ring};

/// A 12 m × 8 m floor: a 2 m corridor along the bottom, three 4 m deep
/// rooms above it, each with a 0.9 m door onto the corridor.
fn floor_plan(res: f64) -> OccupancyGrid {
    let (wm, hm) = (12.0, 8.0);
    let (w, h) = ((wm / res).round() as u32, (hm / res).round() as u32);
    let free_rects = [
        // corridor
        (0.2, 1.0, 11.8, 3.0),
        // rooms
        (0.2, 3.2, 3.9, 7.2),
        (4.1, 3.2, 7.9, 7.2),
        (8.1, 3.2, 11.8, 7.2),
        // doors through the 0.2 m wall at y 3.0..3.2
        (1.6, 2.9, 2.5, 3.3),
        (5.55, 2.9, 6.45, 3.3),
        (9.5, 2.9, 10.4, 3.3),
    ];
    let mut cells = Vec::with_capacity((w * h) as usize);
    for row in 0..h {
        for col in 0..w {
            let x = (f64::from(col) + 0.5) * res;
            let y = hm - (f64::from(row) + 0.5) * res;
            let free = free_rects
                .iter()
                .any(|&(x0, y0, x1, y1)| x >= x0 && x < x1 && y >= y0 && y < y1);
            cells.push(if free { Cell::Free } else { Cell::Occupied });
        }
    }
    OccupancyGrid::from_cells(w, h, res, [0.0, 0.0, 0.0], cells)
}

fn check_plan(grid: &OccupancyGrid, params: &ExtractParams) {
    let x = extract(grid, params).unwrap();
    let nrg = &x.nrg;
    let of = |k: SpaceKind| {
        nrg.spaces()
            .iter()
            .filter(|s| s.kind == k)
            .collect::<Vec<_>>()
    };
    let (rooms, corridors, doors) = (
        of(SpaceKind::Room),
        of(SpaceKind::Corridor),
        of(SpaceKind::Door),
    );
    assert_eq!(
        (rooms.len(), corridors.len(), doors.len()),
        (3, 1, 3),
        "{}",
        nrg.to_json()
    );
    let corridor = corridors[0].id;
    for d in &doors {
        let ends: Vec<_> = nrg.connections_of(d.id).collect();
        assert_eq!(ends.len(), 2);
        assert!(ends.iter().all(|c| c.kind == ConnectionKind::Door));
        assert!(ends.iter().any(|c| c.other(d.id) == Some(corridor)));
        // Door anchors sit in the wall gap (y ≈ 3.1 m).
        assert!(
            (d.anchor[1] - 3.1).abs() < 0.4,
            "door anchor {:?}",
            d.anchor
        );
    }
    for r in &rooms {
        assert!((r.area_m2 - 14.8).abs() < 2.0, "room area {}", r.area_m2);
        assert!(point_in_ring(r.anchor, &r.polygon));
        assert!(r.anchor[1] > 3.2);
        assert_eq!(nrg.connections_of(r.id).count(), 1);
    }
    assert!(
        (corridors[0].area_m2 - 23.2).abs() < 3.0,
        "corridor area {}",
        corridors[0].area_m2
    );
    // No room–room or door–door edges.
    for c in nrg.connections() {
        let (a, b) = (nrg.space(c.a).unwrap().kind, nrg.space(c.b).unwrap().kind);
        assert!(!(a == SpaceKind::Room && b == SpaceKind::Room));
        assert!(!(a == SpaceKind::Door && b == SpaceKind::Door));
        assert!(c.length_m > 0.5);
    }
    assert_eq!(x.labels.count as usize, nrg.spaces().len());
}

#[test]
fn watershed_finds_three_rooms_a_corridor_and_three_doors_at_two_resolutions() {
    check_plan(&floor_plan(0.05), &ExtractParams::default());
    check_plan(&floor_plan(0.1), &ExtractParams::default());
}

#[test]
fn ccl_finds_the_same_plan() {
    let params = ExtractParams {
        method: Method::Ccl,
        ..ExtractParams::default()
    };
    check_plan(&floor_plan(0.05), &params);
}

#[test]
fn the_papers_skeleton_door_rule_finds_the_same_plan() {
    let params = ExtractParams {
        door_rule: DoorRule::Skeleton,
        ..ExtractParams::default()
    };
    check_plan(&floor_plan(0.05), &params);
    check_plan(&floor_plan(0.1), &params);
}

#[test]
fn a_coarser_working_resolution_finds_the_same_plan() {
    let params = ExtractParams {
        working_resolution_m: 0.1,
        ..ExtractParams::default()
    };
    check_plan(&floor_plan(0.05), &params);
    let x = extract(&floor_plan(0.05), &params).unwrap();
    // The labels come back at the map's own size.
    assert_eq!((x.labels.width, x.labels.height), (240, 160));
}

/// A folder holding the 0.1 m/px floor plan as `m.pgm`.
fn floor_plan_pgm() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let grid = floor_plan(0.1);
    let pgm = [
        format!("P5\n{} {}\n255\n", grid.width, grid.height).into_bytes(),
        grid.grey.clone(),
    ]
    .concat();
    std::fs::write(dir.path().join("m.pgm"), pgm).unwrap();
    dir
}

#[test]
fn any_parameter_can_be_set_from_the_command_line() {
    let dir = floor_plan_pgm();
    let run = |extra: &[&str]| {
        let mut args = vec!["extract", "m.pgm", "--resolution", "0.1"];
        args.extend_from_slice(extra);
        crate::support::nrgdb(dir.path(), &args)
    };
    let ok = run(&["--set", "furniture_max_m=0", "--set", "method=ccl"]);
    assert!(
        ok.status.success(),
        "{}",
        String::from_utf8_lossy(&ok.stderr)
    );
    let unknown = run(&["--set", "furniture_max=0"]);
    assert_eq!(unknown.status.code(), Some(2));
    let err = String::from_utf8_lossy(&unknown.stderr);
    assert!(
        err.contains("furniture_max") && err.contains("no such parameter"),
        "{err}"
    );
    let wrong = run(&["--set", "core_radius_m=wide"]);
    assert_eq!(wrong.status.code(), Some(2));
    let negative = run(&["--set", "core_radius_m=-1"]);
    assert_eq!(negative.status.code(), Some(2));
    // A file and flags are checked together: the file's least door width
    // alone is above the greatest, the flags put them in order.
    std::fs::write(dir.path().join("wide.toml"), "door_width_min_m = 2.0\n").unwrap();
    let alone = run(&["--params", "wide.toml"]);
    assert_eq!(alone.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&alone.stderr).contains("building.door_width_max_m"));
    let ordered = run(&[
        "--params",
        "wide.toml",
        "--set",
        "door_width_max_m=2.5",
        "--set",
        "wall_gap_width_max_m=2.6",
    ]);
    assert!(
        ordered.status.success(),
        "{}",
        String::from_utf8_lossy(&ordered.stderr)
    );
}

#[test]
fn printed_parameters_read_back_as_the_flags_that_made_them() {
    let dir = floor_plan_pgm();
    let run = |args: &[&str]| {
        let out = crate::support::nrgdb(dir.path(), args);
        assert!(
            out.status.success(),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        out.stdout
    };
    let sets = [
        "--set",
        "building.min_room_area_m2=16",
        "--set",
        "internals.door_join_m=0.4",
        "--set",
        "furniture_max_m=0.5",
    ];
    let printed = run(&[&["extract", "--print-params"][..], &sets].concat());
    let text = String::from_utf8(printed).unwrap();
    assert!(
        text.contains("[building]") && text.contains("[internals]"),
        "{text}"
    );
    assert!(text.contains("door_join_m = 0.4") && text.contains("min_room_area_m2 = 16"));
    std::fs::write(dir.path().join("grouped.toml"), &text).unwrap();
    // A file of bare keys, as parameter files were written before the groups.
    std::fs::write(
        dir.path().join("flat.toml"),
        "min_room_area_m2 = 16\ndoor_join_m = 0.4\nfurniture_max_m = 0.5\n",
    )
    .unwrap();
    let extract = |extra: &[&str], json: &str| {
        let base = ["extract", "m.pgm", "--resolution", "0.1", "--json", json];
        run(&[&base[..], extra].concat());
        std::fs::read_to_string(dir.path().join(json)).unwrap()
    };
    let by_flags = extract(&sets, "flags.json");
    assert_eq!(
        extract(&["--params", "grouped.toml"], "grouped.json"),
        by_flags
    );
    assert_eq!(extract(&["--params", "flat.toml"], "flat.json"), by_flags);
    // The 15 m² rooms are now below the smallest room.
    assert_ne!(
        extract(&[], "default.json"),
        by_flags,
        "the parameters took effect"
    );
    // A key in the wrong table is refused by name, and nothing is written.
    std::fs::write(
        dir.path().join("bad.toml"),
        "[building]\ndoor_join_m = 0.4\n",
    )
    .unwrap();
    let bad = crate::support::nrgdb(
        dir.path(),
        &[
            "extract",
            "m.pgm",
            "--resolution",
            "0.1",
            "--params",
            "bad.toml",
            "--json",
            "bad.json",
        ],
    );
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("door_join_m"));
    assert!(!dir.path().join("bad.json").exists());
}

#[test]
fn json_and_label_png_outputs() {
    let x = extract(&floor_plan(0.1), &ExtractParams::default()).unwrap();
    let v: serde_json::Value = serde_json::from_str(&x.to_json()).unwrap();
    let spaces = v["spaces"].as_array().unwrap();
    assert_eq!(spaces.len(), 7);
    assert!(
        spaces
            .iter()
            .all(|s| s["pixel_centroid"].as_array().is_some_and(|c| c.len() == 2))
    );
    let png = x.labels_png().unwrap();
    let img = image::load_from_memory(&png).unwrap().into_luma16();
    assert_eq!(img.dimensions(), (120, 80));
    let max = img.pixels().map(|p| p[0]).max().unwrap();
    assert_eq!(u32::from(max), x.labels.count);
}

#[test]
fn a_lidar_ray_into_unknown_space_is_not_a_room() {
    let mut g = floor_plan(0.05);
    // A 2-pixel-wide ray from the top-right room through the wall into unknown space,
    // fanning out to 3 px.
    let w = g.width as usize;
    for row in 2..40usize {
        for col in 200..(202 + row / 20) {
            g.cells[row * w + col] = Cell::Free;
        }
    }
    for row in 0..2usize {
        for col in 0..w {
            g.cells[row * w + col] = Cell::Unknown;
        }
    }
    check_plan(&g, &ExtractParams::default());
}

/// The shared maps folder, or `None` with a notice (see `support::shared_dir`).
fn shared() -> Option<PathBuf> {
    crate::support::shared_dir("maps").map(|dir| dir.join("maps"))
}

#[test]
fn shared_willow_full_gives_a_connected_sensible_nrg() {
    // No ground truth ships with willow-full, so the checks are what holds
    // for any office building (issue 21: this test used to accept 40 to 400
    // doors and spaces, which garbage passes too).
    let Some(maps) = shared() else { return };
    let grid = load_map(&maps.join("willow-full.yaml"), &LoadOptions::default()).unwrap();
    let x = extract(&grid, &ExtractParams::default()).unwrap();
    let spaces = x.nrg.spaces();
    let doors: Vec<_> = spaces
        .iter()
        .filter(|s| s.kind == SpaceKind::Door)
        .collect();
    // The spaces cover most of the free floor (the rest: specks and
    // rays outside the walls), and little more (doors span their wall).
    let free_m2 = grid.free_count() as f64 * grid.resolution * grid.resolution;
    let area: f64 = spaces.iter().map(|s| s.area_m2).sum();
    assert!(
        area > 0.8 * free_m2 && area <= free_m2 * 1.1,
        "{area} of {free_m2} m²"
    );
    // Every door joins two spaces, and the whole floor is one walkable
    // graph: every space reachable from every other.
    let graph = nrgdb::model::ConnectivityGraph::new(&x.nrg);
    for d in &doors {
        assert!(
            x.nrg
                .connections_of(d.id)
                .filter(|c| c.kind.is_navigable())
                .count()
                >= 2,
            "{}",
            d.label()
        );
    }
    let mut reached = std::collections::HashSet::from([spaces[0].id]);
    let mut stack = vec![spaces[0].id];
    while let Some(id) = stack.pop() {
        for (next, _) in graph.neighbours(id) {
            if reached.insert(next) {
                stack.push(next);
            }
        }
    }
    assert_eq!(
        reached.len(),
        spaces.len(),
        "spaces reachable from the first"
    );
    // Office doors are 0.7 to 1.2 m wide at the median, none wider than
    // the widest doorway gap looked for.
    let mut widths: Vec<f64> = doors.iter().filter_map(|d| d.width_m).collect();
    widths.sort_by(f64::total_cmp);
    assert!(widths.len() >= 40, "{} doors", widths.len());
    let median = widths[widths.len() / 2];
    assert!((0.7..=1.2).contains(&median), "median door width {median}");
    assert!(widths.last().is_some_and(|&w| w <= 2.2), "{widths:?}");
}

/// A shared map with its ground truth, extraction and scores.
struct Scored {
    grid: OccupancyGrid,
    gt: nrgdb::eval::GroundTruth,
    x: nrgdb::extract::Extraction,
    e: nrgdb::eval::Evaluation,
}

/// The shared map `name` (`NAME.yaml`, `NAME_gt.png`) extracted with the
/// defaults and scored against its ground truth; None when the shared data
/// is absent.
fn scored_shared(name: &str) -> Option<Scored> {
    let maps = shared()?;
    let grid = load_map(&maps.join(format!("{name}.yaml")), &LoadOptions::default()).unwrap();
    let gt = nrgdb::eval::load_ground_truth(&maps.join(format!("{name}_gt.png")), &grid).unwrap();
    let x = extract(&grid, &ExtractParams::default()).unwrap();
    let e = nrgdb::eval::evaluate(&gt, &x, grid.resolution);
    Some(Scored { grid, gt, x, e })
}

#[test]
fn shared_freiburg79_scores() {
    let Some(Scored { e, .. }) = scored_shared("Freiburg79_scan") else {
        return;
    };
    assert!(
        e.rooms.recall_micro > 0.85 && e.rooms.precision_micro > 0.95,
        "{e:?}"
    );
    assert!(e.doors.recall > 0.9 && e.doors.precision > 0.9, "{e:?}");
}

/// A real robot map (ROSE²'s FR079): two rooms behind the corridor's south
/// wall, which the sensor saw only in pieces, divided by a partition that
/// stops 2 m short of it. The partition's line ends on the opening along
/// that wall (see `extract/stub_openings.rs`), so the rooms are two spaces,
/// each with its own door to the corridor. Measured 93.48 % and 89.66 %;
/// before that rule 91.16 % and 82.76 %.
#[test]
fn shared_fr079_carmen_rooms_behind_a_broken_wall() {
    let Some(Scored { e, .. }) = scored_shared("rose2_fr079_carmen") else {
        return;
    };
    assert!(e.rooms.precision_micro >= 0.93, "{e:?}");
    assert!(e.connections.recall >= 0.89, "{e:?}");
}

/// Real robot maps (ROSE²'s two maps of the Intel lab): a room opens
/// 2.8–2.95 m wide onto the corridor; the room is a space of its own and
/// the opening its door, as wide as the GT's doorway line (see
/// `GapKind::Opening` in `extract/wall_gaps.rs`).
/// - rose2_intel_map: the front ends above on a short stub hanging from
///   the wall across, a reveal. Measured: connections 79.17 %, the door
///   2.80 m on a 2.80 m line; before the rule, 75.00 % and no door.
/// - rose2_intel_carmen: the front ends below on a wall in line whose
///   first column carries a ragged bump, thicker than the opening's wall.
///   Measured: connections 71.43 %, the door 3.15 m on a 2.95 m line;
///   before, 67.86 % and no door. Since `wall_thickness_max_m` is 0.9 m
///   the same GT lines are found, with two spaces fewer and three wrong
///   doors fewer, and one GT pair is no longer joined: 67.86 %.
#[test]
fn shared_intel_room_fronts_are_doors() {
    for (name, connections, lengths, tolerance) in [
        ("rose2_intel_map", 0.79, 2.6..3.0, 0.1),
        ("rose2_intel_carmen", 0.67, 2.9..3.0, 0.25),
    ] {
        let Some(Scored { grid, gt, x, e }) = scored_shared(name) else {
            return;
        };
        assert!(e.connections.recall >= connections, "{name}: {e:?}");
        let doors = doors_on_lines(&grid, &gt, &x, lengths, tolerance);
        assert_eq!(doors, 1, "{name}");
    }
}

/// How many detected doors match a GT doorway line whose length lies in
/// `lengths` (m) and are as wide as it within `tolerance` (m).
fn doors_on_lines(
    grid: &OccupancyGrid,
    gt: &nrgdb::eval::GroundTruth,
    x: &nrgdb::extract::Extraction,
    lengths: std::ops::Range<f64>,
    tolerance: f64,
) -> usize {
    let report = nrgdb::eval::door_report(gt, x, grid);
    let right = report.right_worst_first();
    eprintln!("matched doors, worst width first: {right:?}");
    right
        .into_iter()
        .filter(|(d, _, truth)| {
            lengths.contains(truth) && d.width_m.is_some_and(|w| (w - truth).abs() <= tolerance)
        })
        .count()
}

/// Issue 19's width target on the shared IPA maps (plain): each door's
/// reported width against the GT doorway line it sits on, median error
/// ≤ 0.10 m and p90 ≤ 0.25 m on every map. The truth is the GT picture,
/// not our extraction.
#[test]
fn shared_ipa_door_widths_match_the_gt_doorways() {
    let Some(maps) = shared() else { return };
    let mut names: Vec<String> = std::fs::read_dir(&maps)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter_map(|n| n.strip_suffix("_gt.png").map(str::to_owned))
        .filter(|n| !n.starts_with("rose2_") && !n.ends_with("_furnitures"))
        .collect();
    names.sort();
    assert!(names.len() >= 10, "{names:?}");
    for name in names {
        let grid = load_map(&maps.join(format!("{name}.yaml")), &LoadOptions::default()).unwrap();
        let gt =
            nrgdb::eval::load_ground_truth(&maps.join(format!("{name}_gt.png")), &grid).unwrap();
        let x = extract(&grid, &ExtractParams::default()).unwrap();
        let w = nrgdb::eval::evaluate(&gt, &x, grid.resolution).widths;
        assert!(w.matched >= 5, "{name}: {w:?}");
        let (median, p90) = (w.median_m.unwrap(), w.p90_m.unwrap());
        assert!(median <= 0.10 && p90 <= 0.25, "{name}: {w:?}");
    }
}
