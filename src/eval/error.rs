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
    /// The geodesic raster's cell size is not a finite number > 0.
    #[error(
        "geodesic cell size must be a finite number > 0 m, got {cell_m} (0.025 m is a good start)"
    )]
    BadCellSize {
        /// The size given.
        cell_m: f64,
    },
    /// The geodesic raster's gap to bridge is not a finite number >= 0.
    #[error("the gap to bridge between spaces must be a finite number >= 0 m, got {gap_m}")]
    BadGap {
        /// The gap given.
        gap_m: f64,
    },
    /// The model has no space to rasterise.
    #[error("the model has no space, so there is no free space to walk through")]
    NoSpaces,
    /// The geodesic raster would be too large.
    #[error(
        "a geodesic raster of {cells:.0} cells at {cell_m} m is more than the {limit} allowed (use larger cells)"
    )]
    TooManyCells {
        /// Cells the raster would have.
        cells: f64,
        /// The limit, [`GEODESIC_MAX_CELLS`](super::GEODESIC_MAX_CELLS).
        limit: usize,
        /// The cell size asked for.
        cell_m: f64,
    },
}
