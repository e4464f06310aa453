//! `nrgdb demo`: the whole pipeline on a simulated building, in seconds.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use miette::IntoDiagnostic;
use nrgdb::demo::{DemoOptions, run as run_demo};

/// Arguments of `nrgdb demo`.
#[derive(Debug, clap::Args)]
#[command(
    after_help = "Simulates a building and a LiDAR robot mapping it, extracts its NRG, stores it \
as a revision, shuts a door on a route and stores the re-mapped building as a second revision, \
prints the route in both and the changes, and writes IndoorGML and a picture."
)]
pub struct Args {
    /// Folder for the map, ground truth, IndoorGML and picture.
    #[arg(long, default_value = "nrgdb-demo")]
    pub dir: PathBuf,
    /// The database: an SQLite file (created when missing) or a
    /// PostgreSQL URL `postgres://user@host/db`.
    #[arg(long, env = "NRGDB_DB", default_value = "nrgdb.sqlite")]
    pub db: String,
    /// Seed of the simulated building.
    #[arg(long, default_value_t = 7)]
    pub seed: u64,
}

/// Runs `nrgdb demo`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let opts = DemoOptions {
        dir: args.dir,
        db: args.db,
        seed: args.seed,
        ..DemoOptions::default()
    };
    run_demo(&opts, out).into_diagnostic()?;
    Ok(ExitCode::SUCCESS)
}
