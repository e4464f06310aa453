//! Extraction: an [`OccupancyGrid`](crate::grid::OccupancyGrid) in, an
//! [`Nrg`](crate::model::Nrg) of room, corridor and door spaces in metres out.
//!
//! Owns the pipeline order and [`ExtractParams`]; uses grid, imaging and
//! model. Must not use store, indoorgml, server or the terminal. Pixels never
//! leave this module except as the label image of an [`Extraction`].
//!
//! Parameters ([`ExtractParams`]) come in three groups: what the building
//! and sensor are like ([`BuildingPriors`]), how spaces are drawn
//! ([`OutputShape`]) and the method's thresholds ([`MethodInternals`]);
//! `params_file` reads them by name, `pixel_config` turns them into pixels
//! once per map.
//!
//! Stages (named in `pipeline.rs`, over one `regions::Regions`): free space cleaned of LiDAR rays and islands
//! (`clean`), doorway gaps in straight walls closed (`wall_gaps`), exact
//! distance transform, segmentation (`segment`: distance markers + Meyer
//! watershed, or `ccl`: the paper's Experiment I), merging of tiny regions
//! (`merge`), narrow passages split off (`stubs`), open joins (`joins`),
//! the doors chosen (`door_choice`), door spaces cut across doorway gaps and narrow borders,
//! each spanning its opening from one face of the wall to the other, with
//! its doorway line at the opening's narrowest chord (`doors`,
//! `doorway`), unknown pockets and specks joined to their spaces
//! (`interior`), each space made one 4-connected piece without diagonal
//! pinches (`tidy`), region adjacency, labelling and refinement (`graph`),
//! the model built (`build`), with outlines along pixel edges that tile the
//! spaces exactly (`polygon`:
//! arcs between junctions from `boundaries`, each simplified once by
//! `simplify`, topology kept by `conflicts`).

mod along_wall;
mod boundaries;
mod build;
mod ccl;
mod chord_pixels;
mod clean;
mod clear_width;
mod clutter;
mod conflicts;
mod door_choice;
mod doors;
mod doorway;
mod error;
mod filled;
mod furniture;
mod geodesic;
mod graph;
mod interior;
mod joins;
mod merge;
mod output;
mod params;
mod params_file;
mod passages;
mod pipeline;
mod pixel_config;
mod polygon;
mod regions;
mod resample;
mod seen_walls;
mod segment;
mod simplify;
mod skeleton_doors;
mod stub_openings;
mod stubs;
mod tidy;
mod wall_gaps;
mod wall_runs;
mod wall_stubs;
mod wall_support;
mod wandering_doors;

pub use error::ExtractError;
pub use params::{BuildingPriors, DoorRule, ExtractParams, Method, MethodInternals, OutputShape};
pub use pipeline::{Extraction, extract};
