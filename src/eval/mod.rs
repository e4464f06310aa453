//! Evaluation of an extraction against a ground-truth room image.
//!
//! Owns the metrics: room-segmentation recall/precision exactly as IPA's
//! `evaluation_segmentation.cpp` (BENCHMARK.md §1.1), door recall/precision
//! against the GT's doorway lines, door widths against those lines'
//! lengths (and both item by item: `door_report`), connection
//! recall/precision, room and corridor labels against a simulated plan, and a
//! picture of where extraction and ground truth disagree, the
//! leave-one-building-out judgement of a parameter's value; the free-space
//! geodesic and the route-fidelity harness that measure routes against it.
//! Uses grid, imaging, extract, sim and model; must not use store, server,
//! the terminal, or (for the geodesic) route.

mod door_report;
mod door_widths;
mod error;
mod geodesic;
mod ground_truth;
mod kinds;
mod leave_one_out;
mod metrics;
mod picture;
mod route_fidelity;
mod simulated;
mod transfer;

pub use door_report::{DoorItem, DoorReport, LineItem, door_report};
pub use door_widths::{DoorWidth, WidthScores, door_widths, gt_line_length_px, width_scores};
pub use error::EvalError;
pub use geodesic::{
    FreeSpaceGrid, GEODESIC_MAX_CELLS, GeodesicPath, SIGHT_RADIUS, free_space_geodesic,
    free_space_geodesic_path,
};
pub use ground_truth::{DoorLine, GroundTruth, load_ground_truth};
pub use kinds::{KindScore, kind_score};
pub use leave_one_out::{HeldOut, building_of, leave_one_out, score, tuned_on_all};
pub use metrics::{
    ConnectionPairs, Detection, DoorMatches, Evaluation, RoomScores, connection_pairs,
    connection_scores, door_centroids, door_matches, door_radius_px, door_scores, evaluate,
    room_scores,
};
pub use picture::{DOOR_RIGHT, DOOR_WRONG, LINE_FOUND, LINE_MISSED, evaluation_picture};
pub use route_fidelity::{
    BOUNDARY_TOLERANCE_M, FidelityReport, FidelitySummary, LENGTH_TOLERANCE, PairFidelity, Router,
    SAMPLE_STEP_M, polyline_length, route_fidelity, route_fidelity_with_gap, sample_polyline,
};
pub use simulated::{SimulatedScore, evaluate_simulated};
pub use transfer::transfer_ground_truth;
