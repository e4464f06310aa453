//! Subcommands of the `nrgdb` binary: each turns its clap arguments into
//! library parameters, calls the library and writes to a `Write`.
//!
//! Exit codes: 0 success, 1 "no result" or findings (e.g. `check`), 2 error.

mod apply;
mod check;
mod convert;
mod demo;

use std::io::Write;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod corrections;
mod db;
mod diff;
pub mod eval;
pub mod eval_loo;
mod export;
pub mod extract;
mod georef;
mod import;
mod import_recording;
mod map_log;
mod maps;
mod model_file;
mod name;
mod progress;
pub mod query;
pub mod render;
pub mod repl;
mod serve;
mod simulate;

pub use model_file::{load_model, load_model_into, report_fixes, report_repairs, write_model_as};

/// The command line.
#[derive(Debug, Parser)]
#[command(
    name = "nrgdb",
    version,
    about = "A graph database and query engine for indoor models (IndoorGML Node-Relation Graphs)",
    long_about = "nrgdb extracts IndoorGML Node-Relation Graphs (rooms, corridors, doors and how they \
connect) from occupancy grid maps, stores their revisions, queries and routes over them, and reads, \
writes and checks IndoorGML 1.0.3.\n\nAll coordinates are metres in the map frame (origin lower left, y up).",
    propagate_version = true
)]
pub struct Cli {
    /// More log output (-v info, -vv debug); logs go to stderr.
    #[arg(short, long, global = true, action = clap::ArgAction::Count)]
    pub verbose: u8,
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Run the whole pipeline on a simulated building (the place to start).
    Demo(demo::Args),
    /// Check a model file (IndoorGML, model JSON, GeoJSON, IndoorJSON2): references, duality, geometry, schema.
    Check(check::Args),
    /// Convert between IndoorGML (.gml/.xml), model JSON (.json), GeoJSON (.geojson) and IndoorJSON2 (.indoor.json).
    Convert(convert::Args),
    /// Simulate a building, a LiDAR robot mapping it, and its ground truth.
    Simulate(simulate::Args),
    /// Build an occupancy map from a CARMEN laser log with corrected poses.
    MapLog(map_log::Args),
    /// Run query statements (ROUTE, FIND, NEIGHBOURS, …) against a model.
    Query(query::Args),
    /// Interactive query shell with history, completion and highlighting.
    Repl(repl::Args),
    /// Extract an NRG (rooms, corridors, doors, connections) from an occupancy grid map.
    Extract(extract::Args),
    /// Score an extraction against a ground-truth room image.
    Eval(eval::Args),
    /// Store a model file as the next revision of a map.
    Import(import::Args),
    /// List the maps in the database.
    Maps(maps::MapsArgs),
    /// List the revisions of a map.
    Revisions(maps::RevisionsArgs),
    /// Write a revision of a map to a file.
    Export(export::Args),
    /// Name a space (a new revision).
    Name(name::Args),
    /// Show, set or remove where a map lies on the Earth (WGS84 origin, heading, level).
    Georef(georef::Args),
    /// List a map's corrections and their state; drop one.
    Corrections(corrections::Args),
    /// Show the history of a map with messages.
    Log(maps::LogArgs),
    /// Draw a model as a picture (PNG or SVG): spaces by kind over the map, graph, route, diff.
    Render(render::Args),
    /// Serve the database as an HTTP JSON navigation API.
    Serve(serve::Args),
    /// Compare two revisions (or two files): what was added, removed, split, merged, renamed.
    Diff(diff::Args),
    /// Apply a change set from `nrgdb diff --json` to a revision, giving a new revision.
    Apply(apply::Args),
}

/// Runs one subcommand, writing its report to `out`.
pub fn run(command: Command, out: &mut dyn Write) -> miette::Result<ExitCode> {
    match command {
        Command::Demo(args) => demo::run(args, out),
        Command::Check(args) => check::run(args, out),
        Command::Convert(args) => convert::run(args, out),
        Command::Simulate(args) => simulate::run(args, out),
        Command::MapLog(args) => map_log::run(args, out),
        Command::Query(args) => query::run(args, out),
        Command::Repl(args) => repl::run(args, out),
        Command::Extract(args) => extract::run(args, out),
        Command::Eval(args) => eval::run(args, out),
        Command::Import(args) => import::run(args, out),
        Command::Maps(args) => maps::run_maps(args, out),
        Command::Revisions(args) => maps::run_revisions(args, out),
        Command::Export(args) => export::run(args, out),
        Command::Name(args) => name::run(args, out),
        Command::Georef(args) => georef::run(args, out),
        Command::Corrections(args) => corrections::run(args, out),
        Command::Log(args) => maps::run_log(args, out),
        Command::Render(args) => render::run(args, out),
        Command::Serve(args) => serve::run(args, out),
        Command::Diff(args) => diff::run(args, out),
        Command::Apply(args) => apply::run(args, out),
    }
}

/// Sends `tracing` output to stderr at a level chosen by `-v` or `RUST_LOG`.
pub fn init_logging(verbose: u8) {
    let default = match verbose {
        0 => "warn",
        1 => "info",
        _ => "debug",
    };
    let filter = tracing_subscriber::EnvFilter::try_from_default_env()
        .unwrap_or_else(|_| tracing_subscriber::EnvFilter::new(default));
    let builder = tracing_subscriber::fmt()
        .with_env_filter(filter)
        .with_writer(std::io::stderr);
    // Without -v only warnings show: plain "WARN message" lines for people,
    // not timestamps and module paths.
    let _ = if verbose == 0 {
        builder.without_time().with_target(false).try_init()
    } else {
        builder.try_init()
    };
}
