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
}
