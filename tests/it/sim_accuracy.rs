//! The accuracy benchmark on simulated buildings as a regression guard: 300
//! buildings (seeds 1..=50, each plain, furnished, cluttered, turned,
//! angled and a house) are simulated,
//! extracted and scored, and the means must stay at or above floors set a
//! little under the figures measured on 2026-11-23 (`cargo run --release
//! --example sim_accuracy -- --count 50` prints the same table):
//!
//! | group     | rooms R / P   | doors R / P   | connections R / P |
//! |-----------|---------------|---------------|-------------------|
//! | plain     | 97.57 / 99.87 | 100.0 / 99.72 | 100.0 / 100.0     |
//! | furnished | 89.19 / 99.87 | 100.0 / 97.43 | 100.0 / 100.0     |
//!
//! Since 2026-11-23 the ground truth draws no line across the open passage
//! between two corridors (it is no doorway; see `sim::ground_truth_image`),
//! so joined corridors are one GT room. That raised door recall (the
//! passage had counted as a missed door), connections (from 64 / 70: the
//! extracted corridor, covering both GT corridors, was mapped to one of
//! them, so every door off the other one counted as wrong) and room
//! precision; room recall fell by 0.08 / 0.51 only because the corridors,
//! each fully recalled, now count once in the mean over GT rooms, and the
//! furnished room-recall floor went from 88.5 to 88.0 with it. The same
//! day three extraction changes (wall pieces between two doorways are no
//! furniture, doors at passage mouths, thin door spaces) raised every
//! figure to the table above, and the floors with them.
//!
//! The cluttered group (2026-12-04, issue 20: shelves with door-wide
//! aisles the robot walks into, desk clusters with chairs, kitchen
//! counters and tables; `FloorPlanParams::clutter`) measured
//! 85.91 / 99.85, doors 99.77 / 99.16, connections 100 / 100, and 12 rooms
//! labelled corridor (of about 850): clutter makes a room look long and
//! narrow, a label fault left to mode 6.
//!
//! The turned group (2026-12-05) is the plain buildings each turned by
//! `sim::spread_heading_deg(seed)` (3°–87°): a robot's map seldom lies
//! square to the walls. Before pieces of wall between two doorways were
//! judged along the building's directions (`extract::furniture`), they
//! were judged along the image's axes, and a turned building lost the
//! pieces between its rooms' two front doors, and those doors with them:
//! rooms 97.46 / 99.11, doors 92.61 / 99.83, connections 95.19 / 99.62 and
//! 27 rooms labelled corridor. Now 97.56 / 99.98, doors 100 / 99.83,
//! connections 100 / 100, as plain.
//!
//! The angled group (2026-12-05) is the plain buildings with wings at
//! 25°–65° to the first (`FloorPlanParams::non_manhattan`). A piece of
//! wall between two doors in such a wing lies off the building's two
//! directions; before it was followed along its own axis as well, the
//! group measured rooms 97.33 / 99.10, doors 92.78 / 99.49, connections
//! 94.51 / 99.92 and 29 rooms labelled corridor; then 97.26 / 99.59,
//! 97.85 / 99.53, 97.54 / 99.93 and 8. Since 2026-12-06 doorway gaps are
//! also scanned along the wings' own wall directions
//! (`imaging::further_wall_directions`), and in a building with such
//! wings a gap needs wall support along its own direction: 97.45 / 99.94,
//! 99.62 / 99.88, 99.66 / 100 and 2.
//!
//! The house group (2026-12-06, issue 20: "simulated furnished houses";
//! `FloorPlanParams::house`) is an open-plan living area 8-12 m by
//! 4.6-6 m with a sofa, a kitchen counter and a dining table with chairs,
//! the bedrooms and bathrooms off it through 0.75-1 m doors, furniture
//! boxes in them. With doors only it measured rooms 86.78 / 99.96, doors
//! 99.00 / 97.93, connections 99.00 / 100 and 1 room (of about 280)
//! labelled corridor: what furnished offices lose (the floor behind boxes
//! near a back wall left out of its room, a box's shadow cutting a room
//! with a door). With one room front in five a 2-3.2 m opening instead of
//! a door (an alcove or a dining nook, as real houses have), it measures
//! rooms 87.80 / 96.90, doors 85.20 / 99.33, connections 84.53 / 100 and 6
//! rooms labelled corridor, each a living area: most of these openings are
//! not found (issue 20's failure modes 1 and 2), so the alcoves join the
//! living area, which grows long. Since openings are scanned with the
//! room's corners square, a stack ends where it steps into the wall, and
//! an opening into a room hardly wider than its front counts between walls
//! the sensor saw (2026-12-06, benches/README.md "Openings into rooms
//! hardly wider than their fronts"): rooms 87.80 / 97.66, doors 88.60 /
//! 99.33, connections 88.10 / 100, none labelled corridor.
//!
//! Everything is deterministic in the seeds, so a drop below a floor is a
//! real change of behaviour, not noise. Needs no shared data.

use std::sync::Mutex;

use nrgdb::eval::{SimulatedScore, evaluate_simulated};
use nrgdb::extract::ExtractParams;
use nrgdb::sim::{FloorPlanParams, SimParams, spread_heading_deg};

const SEEDS: u64 = 50;

/// A group of buildings: (furnished, cluttered, turned, angled, house).
type Group = (bool, bool, bool, bool, bool);

const PLAIN: Group = (false, false, false, false, false);
const FURNISHED: Group = (true, false, false, false, false);
const CLUTTERED: Group = (false, true, false, false, false);
const TURNED: Group = (false, false, true, false, false);
const ANGLED: Group = (false, false, false, true, false);
const HOUSE: Group = (true, false, false, false, true);
const GROUPS: [Group; 6] = [PLAIN, FURNISHED, CLUTTERED, TURNED, ANGLED, HOUSE];

fn run_all() -> Vec<SimulatedScore> {
    let jobs: Vec<(u64, Group)> = (1..=SEEDS)
        .flat_map(|seed| GROUPS.map(|g| (seed, g)))
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
                    let Some((seed, group)) = job else { break };
                    let (furnished, cluttered, turned, angled, house) = group;
                    let mut sim = SimParams::new(seed);
                    if house {
                        sim.plan = FloorPlanParams::house(seed);
                    }
                    sim.plan.furniture = furnished;
                    sim.plan.clutter = cluttered;
                    sim.plan.non_manhattan = angled;
                    if turned {
                        sim.plan.heading_deg = spread_heading_deg(seed);
                    }
                    let score = evaluate_simulated(&sim, &ExtractParams::default(), scratch.path())
                        .unwrap_or_else(|e| panic!("building {seed} {group:?}: {e}"));
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
fn simulated_buildings_plain_furnished_cluttered_turned_angled_and_houses_stay_above_the_floors() {
    let all = run_all();
    assert_eq!(all.len(), GROUPS.len() * SEEDS as usize);
    // (group, room recall, room precision, door recall, door precision,
    // connection recall, connection precision)
    let floors = [
        (PLAIN, 97.3, 99.5, 99.5, 99.5, 99.5, 99.5),
        (FURNISHED, 88.9, 99.5, 99.5, 97.0, 99.5, 99.5),
        (CLUTTERED, 85.5, 99.5, 99.5, 98.8, 99.5, 99.5),
        (TURNED, 97.3, 99.5, 99.5, 99.5, 99.5, 99.5),
        (ANGLED, 97.2, 99.8, 99.4, 99.7, 99.4, 99.5),
        (HOUSE, 87.5, 97.5, 88.4, 99.0, 87.9, 99.5),
    ];
    let mut report = String::new();
    let mut failed = false;
    let in_group = |s: &SimulatedScore, g: Group| {
        (
            s.furnished,
            s.cluttered,
            s.heading_deg != 0.0,
            s.non_manhattan,
            s.house,
        ) == g
    };
    for (g, r, p, dr, dp, cr, cp) in floors {
        let group: Vec<&SimulatedScore> = all.iter().filter(|s| in_group(s, g)).collect();
        let got = [
            mean(&group, |s| s.evaluation.rooms.recall_micro),
            mean(&group, |s| s.evaluation.rooms.precision_micro),
            mean(&group, |s| s.evaluation.doors.recall),
            mean(&group, |s| s.evaluation.doors.precision),
            mean(&group, |s| s.evaluation.connections.recall),
            mean(&group, |s| s.evaluation.connections.precision),
        ];
        let want = [r, p, dr, dp, cr, cp];
        report += &format!(
            "(furnished, cluttered, turned, angled, house)={g:?}: got {got:.2?}, floors {want:?}\n"
        );
        failed |= got.iter().zip(&want).any(|(g, w)| g < w);
    }
    // Room and corridor labels against the plan's (issue 20, mode 6),
    // summed over each group of 50: on 2026-12-02 plain 1 corridor
    // labelled room and 0 rooms labelled corridor, furnished 1 and 6, and
    // 1 and 2 once widths were taken with the clutter filled
    // (`extract/filled.rs`). Labelling everything a room would make about
    // 50 corridors rooms. On 2026-12-06, with a corridor also long along
    // its walk (`graph::SpaceShape::length_ratio`), rooms labelled
    // corridor fell from 12 to 1 (cluttered), 6 to 0 (house) and 3 to 1
    // (furnished), stayed at 2 (angled) and 0 (plain, turned); corridors
    // labelled room unchanged.
    // (group, most corridors labelled room, most rooms labelled corridor,
    // fewest corridors labelled corridor). Spaces whose anchor lies in no
    // plan space are not counted; in the angled group 44 corridors of 50
    // buildings were counted on 2026-12-05.
    let label_bounds = [
        (PLAIN, 2, 1, 50),
        (FURNISHED, 2, 2, 50),
        (CLUTTERED, 2, 2, 50),
        (TURNED, 2, 1, 50),
        (ANGLED, 2, 3, 42),
        (HOUSE, 0, 1, 0),
    ];
    for (g, corridors_as_rooms, rooms_as_corridors, corridors) in label_bounds {
        let mut kinds = nrgdb::eval::KindScore::default();
        for s in all.iter().filter(|s| in_group(s, g)) {
            kinds.add(&s.kinds);
        }
        report +=
            &format!("(furnished, cluttered, turned, angled, house)={g:?}: labels {kinds:?}\n");
        failed |= kinds.corridor_as_room > corridors_as_rooms
            || kinds.room_as_corridor > rooms_as_corridors
            || kinds.corridor_as_corridor < corridors;
    }
    println!("{report}");
    assert!(!failed, "accuracy fell below a floor:\n{report}");
}
