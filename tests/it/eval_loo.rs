//! `nrgdb eval --loo`: a parameter judged leave-one-building-out over a
//! folder of simulated buildings, checked against plain `nrgdb eval` runs
//! of each map under each value and a held-out choice recomputed here.

use std::path::Path;

use nrgdb::sim::{SimParams, simulate, write_simulation};
use serde_json::Value;

use crate::support::nrgdb;

/// Writes simulated building `seed` into `maps` as `<stem>.yaml`,
/// `<stem>.pgm` and `<stem>_gt.png`.
fn write_building(scratch: &Path, maps: &Path, seed: u64, stem: &str) {
    let mut p = SimParams::new(seed);
    p.plan.corridor_length_m = (10.0, 16.0);
    let dir = scratch.join(format!("sim{seed}"));
    let files = write_simulation(&dir, &simulate(&p).unwrap()).unwrap();
    std::fs::copy(&files.pgm, maps.join(format!("{stem}.pgm"))).unwrap();
    std::fs::copy(&files.gt_png, maps.join(format!("{stem}_gt.png"))).unwrap();
    let yaml = std::fs::read_to_string(&files.yaml).unwrap();
    let yaml = yaml.replace("map.pgm", &format!("{stem}.pgm"));
    std::fs::write(maps.join(format!("{stem}.yaml")), yaml).unwrap();
}

/// The mean F1 of rooms, doors and connections of one `nrgdb eval --json`.
fn score(e: &Value) -> f64 {
    let f1 = |r: f64, p: f64| {
        if r + p > 0.0 {
            2.0 * r * p / (r + p)
        } else {
            0.0
        }
    };
    let get = |a: &str, b: &str| e[a][b].as_f64().unwrap();
    (f1(
        get("rooms", "recall_micro"),
        get("rooms", "precision_micro"),
    ) + f1(get("doors", "recall"), get("doors", "precision"))
        + f1(
            get("connections", "recall"),
            get("connections", "precision"),
        ))
        / 3.0
}

#[test]
fn leave_one_building_out_matches_plain_runs() {
    let tmp = tempfile::tempdir().unwrap();
    let maps = tmp.path().join("maps");
    std::fs::create_dir(&maps).unwrap();
    for (seed, stem) in [(1, "b1"), (1, "b1_furnitures"), (2, "b2"), (3, "b3")] {
        write_building(tmp.path(), &maps, seed, stem);
    }
    let values = ["0.6", "1.8"];
    let out = nrgdb(
        tmp.path(),
        &[
            "eval",
            "maps",
            "--loo",
            "door_width_max_m=0.6,1.8",
            "--json",
        ],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: Value = serde_json::from_slice(&out.stdout).unwrap();
    let buildings = report["buildings"].as_array().unwrap();
    let names: Vec<&str> = buildings
        .iter()
        .map(|b| b["building"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["b1", "b2", "b3"], "the furnished copy joins b1");
    assert_eq!(buildings[0]["maps"].as_array().unwrap().len(), 2);
    // Each building's scores are the means of plain runs of its maps.
    let mut table = Vec::new();
    for b in buildings {
        let mut want = Vec::new();
        for value in values {
            let mut sum = 0.0;
            let maps_of = b["maps"].as_array().unwrap();
            for m in maps_of {
                let map = format!("maps/{}.yaml", m.as_str().unwrap());
                let set = format!("door_width_max_m={value}");
                let plain = nrgdb(tmp.path(), &["eval", &map, "--set", &set, "--json"]);
                assert!(plain.status.success());
                sum += score(&serde_json::from_slice(&plain.stdout).unwrap());
            }
            want.push(sum / maps_of.len() as f64);
        }
        let got: Vec<f64> = b["scores"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s.as_f64().unwrap())
            .collect();
        for (g, w) in got.iter().zip(&want) {
            assert!(
                (g - w).abs() < 1e-9,
                "{}: {got:?} vs {want:?}",
                b["building"]
            );
        }
        table.push(want);
    }
    // Held out: the value best on the others (the first on ties).
    for (i, b) in buildings.iter().enumerate() {
        let others = |v: usize| -> f64 {
            table
                .iter()
                .enumerate()
                .filter(|(j, _)| *j != i)
                .map(|(_, s)| s[v])
                .sum()
        };
        let chosen = if others(1) > others(0) { 1 } else { 0 };
        assert_eq!(b["held_out_value"], values[chosen], "{}", b["building"]);
        let held = b["held_out_score"].as_f64().unwrap();
        assert!((held - table[i][chosen]).abs() < 1e-9);
    }
}

#[test]
fn a_bad_spec_is_refused_by_name() {
    let tmp = tempfile::tempdir().unwrap();
    let maps = tmp.path().join("maps");
    std::fs::create_dir(&maps).unwrap();
    write_building(tmp.path(), &maps, 1, "b1");
    write_building(tmp.path(), &maps, 2, "b2");
    for (args, says) in [
        (vec!["--loo", "door_width_max_m=1.2"], "between 2 and"),
        (vec!["--loo", "no_such_knob=1,2"], "no_such_knob"),
        (
            vec!["--loo", "door_width_max_m=1,2", "--picture", "p.png"],
            "--picture",
        ),
    ] {
        let spec = args.join(" ");
        let out = nrgdb(tmp.path(), &[&["eval", "maps"][..], &args].concat());
        assert!(!out.status.success(), "{spec}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(says), "{spec}: {err}");
    }
}
