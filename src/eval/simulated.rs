//! Accuracy on simulated buildings: simulate (plan → LiDAR → log-odds map),
//! write the map and its ground truth as `nrgdb simulate` does, read them
//! back as `nrgdb eval` does, extract and score. The files go through disk
//! on purpose, so the figures are those a user gets from the two commands.

use std::path::Path;

use super::{EvalError, Evaluation, evaluate, load_ground_truth};
use crate::extract::{ExtractParams, extract};
use crate::grid::{LoadOptions, load_map};
use crate::sim::{SimParams, simulate, write_simulation};

/// The scores of one simulated building.
#[derive(Debug, Clone)]
pub struct SimulatedScore {
    /// The building's seed.
    pub seed: u64,
    /// Whether rooms were furnished (cluttered).
    pub furnished: bool,
    /// Rooms in the true plan.
    pub true_rooms: usize,
    /// The scores against the plan's ground truth.
    pub evaluation: Evaluation,
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
    let true_rooms = building.plan.rooms.len();
    let files = write_simulation(scratch, &building)?;
    let grid = load_map(&files.yaml, &LoadOptions::default())?;
    let gt = load_ground_truth(&files.gt_png, &grid)?;
    let x = extract(&grid, params)?;
    Ok(SimulatedScore {
        seed: sim.plan.seed,
        furnished: sim.plan.furniture,
        true_rooms,
        evaluation: evaluate(&gt, &x, grid.resolution),
    })
}
