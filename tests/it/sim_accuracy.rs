//! The accuracy benchmark on simulated buildings as a regression guard: 100
//! buildings (seeds 1..=50, each plain and furnished) are simulated,
//! extracted and scored, and the means must stay at or above floors set a
//! little under the figures measured on 2026-11-22 (`cargo run --release
//! --example sim_accuracy -- --count 50` prints the same table):
//!
//! | group     | rooms R / P   | doors R / P   |
//! |-----------|---------------|---------------|
//! | plain     | 96.99 / 97.10 | 89.36 / 100.0 |
//! | furnished | 89.11 / 97.16 | 88.23 / 96.79 |
//!
//! Everything is deterministic in the seeds, so a drop below a floor is a
//! real change of behaviour, not noise. Needs no shared data.

use std::sync::Mutex;

use nrgdb::eval::{SimulatedScore, evaluate_simulated};
use nrgdb::extract::ExtractParams;
use nrgdb::sim::SimParams;

const SEEDS: u64 = 50;

fn run_all() -> Vec<SimulatedScore> {
    let jobs: Vec<(u64, bool)> = (1..=SEEDS)
        .flat_map(|seed| [(seed, false), (seed, true)])
        .collect();
    let next = Mutex::new(0usize);
    let results = Mutex::new(Vec::new());
    let threads = std::thread::available_parallelism().map_or(2, |n| n.get());
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                let scratch = tempfile::tempdir().unwrap();
                loop {
                    let job = {
                        let mut n = next.lock().unwrap();
                        *n += 1;
                        jobs.get(*n - 1).copied()
                    };
                    let Some((seed, furnished)) = job else { break };
                    let mut sim = SimParams::new(seed);
                    sim.plan.furniture = furnished;
                    let score = evaluate_simulated(&sim, &ExtractParams::default(), scratch.path())
                        .unwrap_or_else(|e| panic!("building {seed} (furnished {furnished}): {e}"));
                    results.lock().unwrap().push(score);
                }
            });
        }
    });
    results.into_inner().unwrap()
}

fn mean(scores: &[&SimulatedScore], f: impl Fn(&SimulatedScore) -> f64) -> f64 {
    100.0 * scores.iter().map(|s| f(s)).sum::<f64>() / scores.len() as f64
}

#[test]
fn hundred_simulated_buildings_stay_above_the_floors() {
    let all = run_all();
    assert_eq!(all.len(), 2 * SEEDS as usize);
    // (furnished, room recall, room precision, door recall, door precision)
    let floors = [
        (false, 96.5, 96.5, 86.0, 97.0),
        (true, 88.5, 96.0, 85.0, 93.0),
    ];
    let mut report = String::new();
    let mut failed = false;
    for (furnished, r, p, dr, dp) in floors {
        let group: Vec<&SimulatedScore> = all.iter().filter(|s| s.furnished == furnished).collect();
        let got = [
            mean(&group, |s| s.evaluation.rooms.recall_micro),
            mean(&group, |s| s.evaluation.rooms.precision_micro),
            mean(&group, |s| s.evaluation.doors.recall),
            mean(&group, |s| s.evaluation.doors.precision),
        ];
        let want = [r, p, dr, dp];
        report += &format!("furnished={furnished}: got {got:.2?}, floors {want:?}\n");
        failed |= got.iter().zip(&want).any(|(g, w)| g < w);
    }
    println!("{report}");
    assert!(!failed, "accuracy fell below a floor:\n{report}");
}
