#![cfg(test)]
//! nrgdb's integration tests: one binary, one module per concern.

mod hostile_gen;
mod hostile_inputs;
mod indoorgml_bad_input;
mod indoorgml_check;
mod indoorgml_fuzz;
mod indoorgml_json2;
mod indoorgml_roundtrip;
mod indoorgml_samples;
mod indoorgml_versions;
mod indoorgml_walked;
mod sim;
mod sim_accuracy;
mod support;

mod corrections;
mod demo;
mod doorway_formats;
mod edits;
mod edits_props;
mod eval_loo;
mod extract;
mod extract_doors;
mod extract_tiling;
mod extract_valid_props;
mod gdal_reads;
mod georef;
mod georef_import;
mod ingest;
mod ingest_gate;
mod levels;
mod nav2;
mod osm;
mod paper_cuts;
mod query;
mod query_cli;
mod query_golden;
mod query_props;
mod recording;
mod recording_support;
mod route_building;
mod route_fidelity;
mod route_holes;
mod route_props;
mod route_shared;

mod diff_cli;
mod diff_edits;
mod diff_entry_points;
mod diff_props;
mod diff_self;
mod diff_shared;
mod diff_support;
mod render_cli;
mod render_golden;
mod viewer_cdp;
mod viewer_e2e;
mod viewer_levels;

mod store;
mod store_building;
mod store_cli;
mod store_conformance;
mod store_engines;
mod store_killed_writer;
mod store_pgrouting;
mod store_replicas;

mod server_cli;
mod server_client;
mod server_connections;
mod server_diff;
mod server_faults;
mod server_openapi;
mod server_read;
mod server_write;
