//! Accuracy on simulated buildings: simulate (plan → LiDAR → log-odds map),
//! write the map and its ground truth as `nrgdb simulate` does, read them
//! back as `nrgdb eval` does, extract and score. The files go through disk
//! on purpose, so the figures are those a user gets from the two commands.

use std::path::Path;

use super::kinds::{KindScore, kind_score};
use super::{EvalError, Evaluation, evaluate, load_ground_truth};
use crate::extract::{ExtractParams, extract};
use crate::grid::{LoadOptions, load_map};
use crate::sim::{SimParams, simulate, write_simulation};

/// The scores of one simulated building.
#[derive(Debug, Clone)]
pub struct SimulatedScore {
    /// The building's seed.
    pub seed: u64,
    /// Whether rooms were furnished (boxes).
    pub furnished: bool,
    /// Whether rooms hold real-map clutter (shelves, desk clusters,
    /// kitchens; `FloorPlanParams::clutter`).
    pub cluttered: bool,
    /// The building's heading in the map, degrees
    /// (`FloorPlanParams::heading_deg`).
    pub heading_deg: f64,
    /// Whether wings meet at other angles than a quarter turn
    /// (`FloorPlanParams::non_manhattan`).
    pub non_manhattan: bool,
    /// Whether the building is a house (`FloorPlanParams::house`).
    pub house: bool,
    /// Rooms in the true plan.
    pub true_rooms: usize,
    /// The scores against the plan's ground truth.
    pub evaluation: Evaluation,
    /// The room and corridor labels against the plan's.
    pub kinds: KindScore,
}

/// Simulates the building of `sim`, writes it into `scratch` (a directory,
/// created if missing, overwritten), extracts it with `params` and scores it.
///
/// ```no_run
/// use nrgdb::eval::evaluate_simulated;
/// use nrgdb::extract::ExtractParams;
/// use nrgdb::sim::SimParams;
/// let dir = tempfile::tempdir()?;
/// let s = evaluate_simulated(&SimParams::new(7), &ExtractParams::default(), dir.path())?;
/// println!("room recall {:.3}", s.evaluation.rooms.recall_micro);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn evaluate_simulated(
    sim: &SimParams,
    params: &ExtractParams,
    scratch: &Path,
) -> Result<SimulatedScore, EvalError> {
    let building = simulate(sim)?;
    let rooms = building.plan.true_rooms();
    let files = write_simulation(scratch, &building)?;
    let grid = load_map(&files.yaml, &LoadOptions::default())?;
    let gt = load_ground_truth(&files.gt_png, &grid)?;
    let x = extract(&grid, params)?;
    let kinds = kind_score(&x.nrg, building.plan.true_corridors(), &rooms);
    Ok(SimulatedScore {
        seed: sim.plan.seed,
        furnished: sim.plan.furniture,
        cluttered: sim.plan.clutter,
        heading_deg: sim.plan.heading_deg,
        non_manhattan: sim.plan.non_manhattan,
        house: sim.plan.house,
        true_rooms: rooms.len(),
        evaluation: evaluate(&gt, &x, grid.resolution),
        kinds,
    })
}

#[cfg(test)]
mod tests {
    use crate::eval::GroundTruth;
    use crate::model::point_in_ring;
    use crate::sim::{FloorPlan, FloorPlanParams, GreyMap, ground_truth_image};

    /// A perfect map of `plan` at 0.1 m/px: spaces and doorways free (254),
    /// the rest occupied.
    fn perfect_map(plan: &FloorPlan) -> GreyMap {
        let (b, r) = (plan.bounds(), 0.1);
        let origin_m = [b[0] - 1.0, b[1] - 1.0];
        let width = ((b[2] - b[0] + 2.0) / r).ceil() as u32;
        let height = ((b[3] - b[1] + 2.0) / r).ceil() as u32;
        let rings: Vec<_> = plan
            .corridors
            .iter()
            .chain(&plan.rooms)
            .chain(plan.doors.iter().map(|d| &d.polygon))
            .collect();
        let mut grey = vec![0u8; (width * height) as usize];
        for (i, g) in grey.iter_mut().enumerate() {
            let (col, row) = (i as u32 % width, i as u32 / width);
            let p = [
                origin_m[0] + (f64::from(col) + 0.5) * r,
                origin_m[1] + (f64::from(height - 1 - row) + 0.5) * r,
            ];
            if rings.iter().any(|ring| point_in_ring(p, ring)) {
                *g = 254;
            }
        }
        GreyMap {
            width,
            height,
            resolution_m: r,
            origin_m,
            grey,
        }
    }

    #[test]
    fn simulated_ground_truth_has_a_doorway_line_per_door_and_none_elsewhere() {
        for seed in 1..=4 {
            let mut params = FloorPlanParams::new(seed);
            params.wings = (2, 3);
            let plan = FloorPlan::generate(&params).unwrap();
            assert!(!plan.openings.is_empty(), "seed {seed}");
            let map = perfect_map(&plan);
            let img = ground_truth_image(&plan, &map);
            let gt = GroundTruth::from_grey(map.width, map.height, &img, &map.grey);
            // Corridors joined by open passages are one GT room: the
            // connection GT has no corridor-corridor pair that no door can
            // ever match, and a space that covers both corridors maps to it.
            assert_eq!(gt.rooms.count as usize, plan.rooms.len() + 1, "seed {seed}");
            assert_eq!(gt.doors.len(), plan.doors.len(), "seed {seed}");
            for line in &gt.doors {
                assert_eq!(line.rooms.len(), 2, "seed {seed}");
            }
        }
    }
}
