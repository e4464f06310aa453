//! Extraction: an [`OccupancyGrid`](crate::grid::OccupancyGrid) in, an
//! [`Nrg`](crate::model::Nrg) of room, corridor and door spaces in metres out.
//!
//! Owns the pipeline order and [`ExtractParams`]; uses grid, imaging and
//! model. Must not use store, indoorgml, server or the terminal. Pixels never
//! leave this module except as the label image of an [`Extraction`].
//!
//! Stages (see `pipeline.rs`): free space cleaned of LiDAR rays and islands
//! (`clean`), doorway gaps in straight walls closed (`wall_gaps`), exact
//! distance transform, segmentation (`segment`: distance markers + Meyer
//! watershed, or `ccl`: the paper's Experiment I), merging of tiny regions
//! (`merge`), door spaces cut across doorway gaps and narrow borders,
//! each spanning its opening from one face of the wall to the other, with
//! its doorway line at the opening's narrowest chord (`doors`,
//! `doorway`), unknown pockets and specks joined to their spaces
//! (`interior`), each space made one 4-connected piece without diagonal
//! pinches (`tidy`), region adjacency, labelling and refinement (`graph`),
//! outlines along pixel edges that tile the spaces exactly (`polygon`:
//! arcs between junctions from `boundaries`, each simplified once by
//! `simplify`, topology kept by `conflicts`).

mod boundaries;
mod ccl;
mod clean;
mod conflicts;
mod doors;
mod doorway;
mod error;
mod filled;
mod furniture;
mod graph;
mod interior;
mod joins;
mod merge;
mod output;
mod params;
mod passages;
mod pipeline;
mod polygon;
mod resample;
mod segment;
mod simplify;
mod skeleton_doors;
mod stubs;
mod tidy;
mod wall_gaps;

pub use error::ExtractError;
pub use params::{DoorRule, ExtractParams, Method};
pub use pipeline::{Extraction, extract};
