//! # nrgdb
//!
//! A graph database and query engine for indoor models. nrgdb turns a
//! robot's 2D occupancy grid map into an IndoorGML Node-Relation Graph
//! (rooms, corridors, doors and how they connect), stores its revisions,
//! queries and routes over it, and reads and writes IndoorGML (1.0.3,
//! 1.1, the 2.0 draft's JSON), GeoJSON, Nav2 route graphs and OpenStreetMap
//! indoor tagging; it takes maps from ROS 2 recordings ([`recording`]).
//!
//! Data flows one way: `grid` (and [`recording`]) → `imaging` → `extract`
//! → [`model`] ↔ [`indoorgml`] · `format` · `store` · `query` · `route` ·
//! `diff` · `server`.
//! Every public coordinate is in metres in the map frame (ROS convention:
//! origin at the lower left, y up).

pub mod atomic;
pub mod demo;
pub mod diff;
pub mod edit;
pub mod eval;
pub mod extract;
pub mod fixtures;
pub mod format;
pub mod geojson;
pub mod grid;
pub mod imaging;
pub mod indoorgml;
pub mod ingest;
pub mod model;
pub mod query;
pub mod recording;
pub mod render;
pub mod route;
#[cfg(feature = "server")]
pub mod server;
pub mod sim;
pub mod store;
pub mod wording;
