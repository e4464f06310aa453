//! Runs `nrgdb eval` over every map in the shared map set that has a ground
//! truth (`<name>_gt.png` next to `<name>.yaml`) and prints a per-map table
//! (with the door width error's median and p90 in metres) and the means,
//! plain and furnished separately, with each group's door width errors
//! pooled over all its matched doors (median and p90, nearest rank).
//!
//! ```text
//! cargo run --release --example eval_maps [-- MAPS_DIR [--method ccl] [--params p.toml] [--pictures OUT_DIR]]
//! ```
//! MAPS_DIR defaults to `$NRGDB_SHARED/maps` (NRGDB_SHARED defaults to `../shared`).
//! `--doors` also prints, from `nrgdb::eval::door_report`, every door matched
//! to a GT doorway line: its id, the middle of its doorway (metres), the width
//! reported and the GT line's length, worst first.
//! It then lists every GT doorway line no door was found at: the middle of its
//! pixels (metres), its length and the GT rooms it joins.
//! `--pictures OUT_DIR` also writes each map's evaluation picture (`<name>_eval.png`, see
//! `nrgdb::eval::evaluation_picture`): found and missed doorway lines, right and wrong doors.

use std::path::{Path, PathBuf};
use std::time::Instant;

use nrgdb::eval::{
    DoorReport, DoorWidth, Evaluation, door_report, evaluate, evaluation_picture,
    load_ground_truth, width_scores,
};
use nrgdb::extract::{ExtractParams, Method, extract};
use nrgdb::grid::{LoadOptions, load_map};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let mut dir: Option<PathBuf> = None;
    let mut params = ExtractParams::default();
    let mut pictures: Option<PathBuf> = None;
    let mut doors = false;
    while let Some(a) = args.next() {
        match a.as_str() {
            "--method" => params.method = args.next().unwrap_or_default().parse::<Method>()?,
            "--params" => {
                params = ExtractParams::from_toml(&std::fs::read_to_string(
                    args.next().unwrap_or_default(),
                )?)?
            }
            "--pictures" => pictures = args.next().map(PathBuf::from),
            "--doors" => doors = true,
            _ => dir = Some(PathBuf::from(a)),
        }
    }
    let dir = dir.unwrap_or_else(|| {
        let shared = std::env::var("NRGDB_SHARED").unwrap_or_else(|_| "../shared".into());
        Path::new(&shared).join("maps")
    });
    let mut names: Vec<String> = std::fs::read_dir(&dir)?
        .filter_map(|e| e.ok())
        .filter_map(|e| e.file_name().to_str().map(str::to_owned))
        .filter_map(|n| n.strip_suffix("_gt.png").map(str::to_owned))
        .filter(|n| dir.join(format!("{n}.yaml")).exists())
        .collect();
    names.sort();
    println!(
        "{:<32} {:>6} {:>6} {:>6} {:>6} | {:>6} {:>6} | {:>6} {:>6} | {:>5} {:>5} | {:>5} {:>7}",
        "map",
        "R",
        "P",
        "Rmac",
        "Pmac",
        "doorR",
        "doorP",
        "connR",
        "connP",
        "wMed",
        "wP90",
        "rooms",
        "ms"
    );
    let metres = |v: Option<f64>| v.map_or_else(|| "-".to_string(), |m| format!("{m:.3}"));
    // Per group: its evaluations, its name, and every door matched to a GT
    // doorway line with its width.
    let mut groups: [(Vec<Evaluation>, &str, Vec<DoorWidth>); 3] = [
        (Vec::new(), "plain (IPA)", Vec::new()),
        (Vec::new(), "furnished (IPA)", Vec::new()),
        (Vec::new(), "rose2", Vec::new()),
    ];
    for name in &names {
        let grid = load_map(&dir.join(format!("{name}.yaml")), &LoadOptions::default())?;
        let gt = match load_ground_truth(&dir.join(format!("{name}_gt.png")), &grid) {
            Ok(gt) => gt,
            Err(e) => {
                println!("{name:<32} skipped: {e}");
                continue;
            }
        };
        let t = Instant::now();
        let x = extract(&grid, &params)?;
        let ms = t.elapsed().as_secs_f64() * 1e3;
        let e = evaluate(&gt, &x, grid.resolution);
        println!(
            "{:<32} {:>6.2} {:>6.2} {:>6.2} {:>6.2} | {:>6.2} {:>6.2} | {:>6.2} {:>6.2} | {:>5} {:>5} | {:>5} {:>7.1}",
            name,
            100.0 * e.rooms.recall_micro,
            100.0 * e.rooms.precision_micro,
            100.0 * e.rooms.recall_macro,
            100.0 * e.rooms.precision_macro,
            100.0 * e.doors.recall,
            100.0 * e.doors.precision,
            100.0 * e.connections.recall,
            100.0 * e.connections.precision,
            metres(e.widths.median_m),
            metres(e.widths.p90_m),
            format!("{}/{}", e.rooms.segments, e.rooms.gt_rooms),
            ms
        );
        let report = door_report(&gt, &x, &grid);
        if doors {
            print_doors(&report);
        }
        if let Some(out) = &pictures {
            std::fs::create_dir_all(out)?;
            evaluation_picture(&grid, &gt, &x).save(out.join(format!("{name}_eval.png")))?;
        }
        let g = if name.starts_with("rose2") {
            2
        } else if name.ends_with("_furnitures") {
            1
        } else {
            0
        };
        groups[g].0.push(e);
        groups[g].2.extend(
            report
                .right_worst_first()
                .iter()
                .filter_map(|&(d, line, truth_m)| {
                    d.width_m.map(|reported_m| DoorWidth {
                        door: d.door,
                        line,
                        reported_m,
                        truth_m,
                    })
                }),
        );
    }
    println!();
    for (evals, label, widths) in &groups {
        if evals.is_empty() {
            continue;
        }
        let n = evals.len() as f64;
        let mean = |f: &dyn Fn(&Evaluation) -> f64| 100.0 * evals.iter().map(f).sum::<f64>() / n;
        // Door width errors: the worst map's.
        let worst = |f: &dyn Fn(&Evaluation) -> Option<f64>| {
            metres(evals.iter().filter_map(f).reduce(f64::max))
        };
        println!(
            "mean {:<27} {:>6.2} {:>6.2} {:>6.2} {:>6.2} | {:>6.2} {:>6.2} | {:>6.2} {:>6.2} | {:>5} {:>5} | n={} (w: worst)",
            label,
            mean(&|e| e.rooms.recall_micro),
            mean(&|e| e.rooms.precision_micro),
            mean(&|e| e.rooms.recall_macro),
            mean(&|e| e.rooms.precision_macro),
            mean(&|e| e.doors.recall),
            mean(&|e| e.doors.precision),
            mean(&|e| e.connections.recall),
            mean(&|e| e.connections.precision),
            worst(&|e| e.widths.median_m),
            worst(&|e| e.widths.p90_m),
            evals.len()
        );
        let pooled = width_scores(widths);
        println!(
            "     door width error pooled over {} doors: median {} m, p90 {} m",
            pooled.matched,
            metres(pooled.median_m),
            metres(pooled.p90_m)
        );
    }
    Ok(())
}

/// Each door matched to a GT doorway line, worst width error first, then
/// each GT doorway line no door was found at.
fn print_doors(r: &DoorReport) {
    for (d, line, truth) in r.right_worst_first() {
        let reported = d.width_m.unwrap_or(0.0);
        println!(
            "    door {:>4} at {:<22} reported {:.3} m, GT line {} {:.3} m, error {:+.3} m",
            d.door,
            format!("({:.2}, {:.2})", d.middle[0], d.middle[1]),
            reported,
            line,
            truth,
            reported - truth
        );
    }
    for l in r.missed() {
        println!(
            "    missed GT line {:>3} at ({:.2}, {:.2}), {:.3} m, rooms {:?}",
            l.line, l.middle[0], l.middle[1], l.length_m, l.rooms
        );
    }
}
