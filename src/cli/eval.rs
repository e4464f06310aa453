//! `nrgdb eval`: extraction scored against a ground-truth room image.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::eval::{evaluate, load_ground_truth};
use nrgdb::extract::extract;

use super::extract::MapArgs;

/// Scores an extraction against a ground truth (IPA room-segmentation recall/precision,
/// doors, connections).
#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(flatten)]
    pub map: MapArgs,
    /// Ground-truth image: rooms white (> 250), doorways closed by dark lines (IPA style).
    #[arg(long)]
    pub gt: PathBuf,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
}

/// Runs `nrgdb eval`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let (grid, params) = args.map.load()?;
    let gt = load_ground_truth(&args.gt, &grid).into_diagnostic()?;
    let x = extract(&grid, &params)
        .into_diagnostic()
        .wrap_err_with(|| format!("{}: extraction failed", args.map.map.display()))?;
    let e = evaluate(&gt, &x, grid.resolution);
    if args.json {
        let text = serde_json::to_string_pretty(&e).into_diagnostic()?;
        writeln!(out, "{text}").into_diagnostic()?;
    } else {
        let r = e.rooms;
        writeln!(out, "rooms       recall {:6.2} %  precision {:6.2} %  (per-room mean, IPA \"micro\"; {} GT rooms, {} segments)",
            100.0 * r.recall_micro, 100.0 * r.precision_micro, r.gt_rooms, r.segments).into_diagnostic()?;
        writeln!(
            out,
            "rooms       recall {:6.2} %  precision {:6.2} %  (pixel-weighted, IPA \"macro\")",
            100.0 * r.recall_macro,
            100.0 * r.precision_macro
        )
        .into_diagnostic()?;
        writeln!(
            out,
            "doors       recall {:6.2} %  precision {:6.2} %  ({} GT doorway lines, {} detected)",
            100.0 * e.doors.recall,
            100.0 * e.doors.precision,
            e.doors.gt,
            e.doors.detected
        )
        .into_diagnostic()?;
        writeln!(
            out,
            "connections recall {:6.2} %  precision {:6.2} %  ({} GT, {} detected)",
            100.0 * e.connections.recall,
            100.0 * e.connections.precision,
            e.connections.gt,
            e.connections.detected
        )
        .into_diagnostic()?;
    }
    Ok(ExitCode::SUCCESS)
}
