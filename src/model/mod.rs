//! The Node-Relation Graph (NRG) of IndoorGML as plain data: [`Space`]s,
//! [`Connection`]s between them and the [`Nrg`] that holds both.
//!
//! Owns the types every other module exchanges, their invariants
//! ([`Nrg::new`] checks them), the public JSON form and the navigable
//! connectivity graph ([`ConnectivityGraph`]), and the one definition of
//! a door's doorway line and width ([`doorway`]). Coordinates are metres in the
//! map frame (x right, y up). Uses nothing from the rest of the crate; must
//! not know about XML, SQL, HTTP or the terminal.

mod connection;
mod crs;
mod doorway;
mod error;
mod geometry;
mod georef;
mod graph;
mod interior_point;
mod level;
mod nrg;
mod repair;
mod space;
mod utm;
pub(crate) mod validity;
mod vertical;

pub use connection::{Connection, ConnectionKind, ConnectionPaths};
pub use crs::{NamedCrs, lowest_corner};
pub use doorway::{Doorway, convex_hull, polygon_doorway};
pub use error::ModelError;
pub use geometry::{
    Point, Ring, bounds, point_in_ring, polygon_area, polygon_centroid, ring_is_ccw,
    segment_distance,
};
pub use georef::{GEOREF_KEY, Georef, GeorefError};
pub use graph::ConnectivityGraph;
pub use interior_point::pole_of_inaccessibility;
pub use level::{Level, LevelError, MAX_ELEVATION_M, MAX_LEVEL_NAME_CHARS, level_name};
pub use nrg::{MAX_COORD_M, MAX_NAME_CHARS, Nrg};
pub use repair::{MAX_OVERLAP_TESTS, MIN_OVERLAP_M2, Repair, RepairKind, repair_geometry};
pub(crate) use repair::{reshaped, to_geo};
pub use space::{Space, SpaceId, SpaceKind, doorway};
pub use utm::UtmZone;
pub use vertical::{
    ELEVATOR_PER_LEVEL_S, ELEVATOR_WAIT_S, STAIRS_M_PER_RISE_M, WALKING_SPEED_M_S,
    elevator_length_m, stairs_length_m,
};
