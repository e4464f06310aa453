//! Simulated buildings and occupancy mapping (the paper's data acquisition,
//! Section 4.1 and Eq. 3), without ROS.
//!
//! Owns the floor-plan generator ([`FloorPlan`]: office floors, and houses
//! with an open-plan living area, [`FloorPlanParams::house`]; exact ground truth as an
//! [`Nrg`](crate::model::Nrg) and an IPA-style `_gt.png`), the LiDAR
//! simulation ([`simulate_scans`]), the known-pose log-odds mapper
//! ([`LogOddsMap`]), the CARMEN log reader ([`read_carmen`]) and the ROS map
//! writer ([`write_map`]). Uses `model` and `atomic`; must not use grid,
//! imaging, extract, store, query or server. Everything is deterministic
//! in its seeds ([`SplitMix64`]).

mod bresenham;
mod carmen;
mod clutter;
mod error;
mod floor_plan;
mod ground_truth;
mod house;
mod layout;
mod lidar;
mod log_odds;
mod map_log;
mod map_writer;
mod prng;
mod ray_cast;
mod robot_path;
mod separation;
mod simulate;
mod storeys;

pub use bresenham::bresenham;
pub use carmen::{DEFAULT_NO_RETURN_M, parse_carmen, read_carmen};
pub use error::SimError;
pub use floor_plan::{
    Door, FloorPlan, FloorPlanParams, Opening, Segment, SpaceRef, spread_heading_deg,
};
pub use ground_truth::ground_truth_image;
pub use lidar::{LidarParams, Scan, simulate_scans};
pub use log_odds::{GreyMap, LogOddsMap, LogOddsParams, MAX_CELLS, OccupancyRule};
pub use map_log::{LogMap, map_carmen_log, map_scans};
pub use map_writer::{encode_grey_png, encode_pgm, map_yaml, write_map};
pub use prng::SplitMix64;
pub use ray_cast::{WallIndex, ray_segment};
pub use robot_path::{Pose, sample_poses};
pub use separation::separation_gap;
pub use simulate::{SimFiles, SimParams, Simulation, simulate, write_simulation};
pub use storeys::{MAX_SIM_LEVELS, STOREY_HEIGHT_M, StoreyFiles, write_storeys};
