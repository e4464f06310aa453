//! The accuracy benchmark on simulated buildings: simulates, extracts and
//! evaluates `--count` buildings per group (fixed seeds 1..=count), plain,
//! furnished (boxes), cluttered (shelves, desk clusters, kitchens:
//! `FloorPlanParams::clutter`) and turned (the plain, furnished and
//! cluttered buildings at a heading spread over 3°–87°:
//! `sim::spread_heading_deg`) and angled (plain buildings with wings at
//! 25°–65° to the first: `FloorPlanParams::non_manhattan`) and houses (an
//! open-plan living area with bedrooms off it: `FloorPlanParams::house`), and prints a line per building and
//! the means per group. `kinds` is corridors and rooms labelled as the plan
//! has them / corridors labelled room and rooms labelled corridor. The regression guard over the same figures is the
//! integration test `sim_accuracy` (tests/it/sim_accuracy.rs).
//!
//! ```text
//! cargo run --release --example sim_accuracy [-- --count 50 --params p.toml --group house]
//! ```

use std::time::Instant;

use nrgdb::eval::{SimulatedScore, evaluate_simulated};
use nrgdb::extract::ExtractParams;
use nrgdb::sim::{FloorPlanParams, SimParams};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let mut count = 50u64;
    let mut only: Option<String> = None;
    let mut params = ExtractParams::default();
    while let Some(a) = args.next() {
        match a.as_str() {
            "--count" => count = args.next().unwrap_or_default().parse()?,
            "--group" => only = args.next(),
            "--params" => {
                params = ExtractParams::from_toml(&std::fs::read_to_string(
                    args.next().unwrap_or_default(),
                )?)?
            }
            other => return Err(format!("unknown argument {other:?}").into()),
        }
    }
    let scratch = tempfile::tempdir()?;
    println!(
        "{:<10} {:>6} {:>6} | {:>6} {:>6} | {:>6} {:>6} | {:>7} {:>9} {:>7}",
        "building", "R", "P", "doorR", "doorP", "connR", "connP", "rooms", "kinds", "ms"
    );
    // (group, prefix of its buildings' lines, furnished, cluttered, turned,
    // wings at other angles, a house)
    for (group, prefix, furnished, cluttered, turned, angled, house) in [
        ("plain", "P", false, false, false, false, false),
        ("furnished", "F", true, false, false, false, false),
        ("cluttered", "C", false, true, false, false, false),
        ("turned", "T", false, false, true, false, false),
        ("furn-turned", "FT", true, false, true, false, false),
        ("clut-turned", "CT", false, true, true, false, false),
        ("angled", "A", false, false, false, true, false),
        ("house", "H", true, false, false, false, true),
    ] {
        if only.as_deref().is_some_and(|g| g != group) {
            continue;
        }
        let mut scores = Vec::new();
        for seed in 1..=count {
            let mut sim = SimParams::new(seed);
            if house {
                sim.plan = FloorPlanParams::house(seed);
            }
            sim.plan.furniture = furnished;
            sim.plan.clutter = cluttered;
            sim.plan.non_manhattan = angled;
            if turned {
                sim.plan.heading_deg = nrgdb::sim::spread_heading_deg(seed);
            }
            let t = Instant::now();
            let s = evaluate_simulated(&sim, &params, scratch.path())?;
            let ms = t.elapsed().as_secs_f64() * 1e3;
            let e = &s.evaluation;
            println!(
                "{:<10} {:>6.2} {:>6.2} | {:>6.2} {:>6.2} | {:>6.2} {:>6.2} | {:>7} {:>9} {:>7.0}",
                format!("{prefix}{seed}"),
                100.0 * e.rooms.recall_micro,
                100.0 * e.rooms.precision_micro,
                100.0 * e.doors.recall,
                100.0 * e.doors.precision,
                100.0 * e.connections.recall,
                100.0 * e.connections.precision,
                format!("{}/{}", e.rooms.segments, s.true_rooms),
                format!(
                    "{}+{}/{}+{}",
                    s.kinds.corridor_as_corridor,
                    s.kinds.room_as_room,
                    s.kinds.corridor_as_room,
                    s.kinds.room_as_corridor
                ),
                ms
            );
            scores.push(s);
        }
        print_means(group, &scores);
    }
    Ok(())
}

fn print_means(group: &str, scores: &[SimulatedScore]) {
    let n = scores.len().max(1) as f64;
    let mean = |f: &dyn Fn(&SimulatedScore) -> f64| 100.0 * scores.iter().map(f).sum::<f64>() / n;
    let mut kinds = nrgdb::eval::KindScore::default();
    for s in scores {
        kinds.add(&s.kinds);
    }
    // Door widths against the plan's doorway lines: the worst building's
    // median and 90th percentile error (issue 19 asks for at most 0.10 and
    // 0.25 m on every map).
    let worst = |f: &dyn Fn(&SimulatedScore) -> Option<f64>| {
        scores.iter().filter_map(f).fold(0.0f64, f64::max)
    };
    let widths = format!(
        "widths worst median {:.3} p90 {:.3} m",
        worst(&|s| s.evaluation.widths.median_m),
        worst(&|s| s.evaluation.widths.p90_m)
    );
    println!(
        "mean {group:<10} R {:.2} P {:.2} | doors R {:.2} P {:.2} | connections R {:.2} P {:.2} | kinds {:.2} % (corridors as rooms {}, rooms as corridors {}) | {widths}  ({} buildings)",
        mean(&|s| s.evaluation.rooms.recall_micro),
        mean(&|s| s.evaluation.rooms.precision_micro),
        mean(&|s| s.evaluation.doors.recall),
        mean(&|s| s.evaluation.doors.precision),
        mean(&|s| s.evaluation.connections.recall),
        mean(&|s| s.evaluation.connections.precision),
        100.0 * kinds.accuracy(),
        kinds.corridor_as_room,
        kinds.room_as_corridor,
        scores.len()
    );
}
