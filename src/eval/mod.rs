//! Evaluation of an extraction against a ground-truth room image.
//!
//! Owns the metrics: room-segmentation recall/precision exactly as IPA's
//! `evaluation_segmentation.cpp` (BENCHMARK.md §1.1), door recall/precision
//! against the GT's doorway lines, and connection recall/precision. Uses
//! grid, imaging, extract, sim and model; must not use store, server or the
//! terminal.

mod error;
mod ground_truth;
mod metrics;
mod simulated;

pub use error::EvalError;
pub use ground_truth::{DoorLine, GroundTruth, load_ground_truth};
pub use metrics::{
    Detection, Evaluation, RoomScores, connection_scores, door_scores, evaluate, room_scores,
};
pub use simulated::{SimulatedScore, evaluate_simulated};
