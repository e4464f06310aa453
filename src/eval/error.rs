//! Errors raised while evaluating.

use std::path::PathBuf;

/// Why an evaluation could not run.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum EvalError {
    /// The ground-truth image cannot be read.
    #[error(transparent)]
    Grid(#[from] crate::grid::GridError),
    /// The ground truth has no room of more than 100 px.
    #[error("{path}: the ground truth has no room (white > 250) of more than 100 px")]
    NoRooms {
        /// The GT file.
        path: PathBuf,
    },
    /// The simulation behind [`evaluate_simulated`](super::evaluate_simulated) failed.
    #[error(transparent)]
    Sim(#[from] crate::sim::SimError),
    /// The extraction being scored failed.
    #[error(transparent)]
    Extract(#[from] crate::extract::ExtractError),
}
