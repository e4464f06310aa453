//! `nrgdb import`: store a model file as the next revision of a map.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};

use super::db::{DbArg, author};
use super::{load_model_into, report_fixes};

/// Store a model as the next revision of a map (the map is created on its
/// first import). Spaces continuing spaces of the previous revision keep
/// their ids and names; connection lengths are stored as walked lengths.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The model: .gml/.xml (IndoorGML), .json, .geojson, .yaml (a ROS occupancy map, extracted
    /// first), .toml (a building manifest: each level's map, its elevation, the stairs and lifts),
    /// or a ROS 2 recording (.mcap, .db3, or a bag folder with metadata.yaml: one revision per map
    /// that changed).
    pub file: PathBuf,
    /// The map to add a revision to.
    #[arg(long, value_name = "NAME")]
    pub map: String,
    /// Commit message recorded with the revision.
    #[arg(short, long, default_value = "")]
    pub message: String,
    /// Author recorded with the revision [default: $USER].
    #[arg(long, env = "NRGDB_AUTHOR")]
    pub author: Option<String>,
    /// Store the model even when it stays geometrically invalid after
    /// repair (`nrgdb check` would report it); refused by default.
    #[arg(long)]
    pub allow_invalid: bool,
    /// Recordings: the topic of the maps (nav_msgs/msg/OccupancyGrid).
    #[arg(long, default_value = "/map", value_name = "TOPIC")]
    pub topic: String,
    /// Recordings: keep at most one map per interval of recording time, the last of each
    /// (e.g. `30s`, `5min`); by default every map that changed.
    #[arg(long, value_name = "DURATION", value_parser = parse_every)]
    pub every: Option<std::time::Duration>,
    #[command(flatten)]
    pub db: DbArg,
}

fn parse_every(text: &str) -> Result<std::time::Duration, String> {
    let d = humantime::parse_duration(text).map_err(|e| format!("{e} (e.g. 30s, 5min)"))?;
    if d.is_zero() {
        return Err("must be longer than 0 s".into());
    }
    Ok(d)
}

/// Runs `nrgdb import`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    if super::import_recording::is_recording(&args.file) {
        return super::import_recording::run(args, out);
    }
    // A spinner on a terminal for big files (reading and storing take a while).
    let bytes = std::fs::metadata(&args.file).map_or(0, |m| m.len());
    let spinner = if bytes > 1 << 20 {
        super::progress::spinner(format!(
            "reading {} ({:.1} MB)",
            args.file.display(),
            bytes as f64 / 1e6
        ))
    } else {
        indicatif::ProgressBar::hidden()
    };
    let mut store = args.db.open()?;
    let frame = nrgdb::ingest::map_frame(&store, &args.map).into_diagnostic()?;
    let model = load_model_into(&args.file, args.allow_invalid, frame)?;
    spinner.set_message(format!("storing {} spaces", model.nrg.spaces().len()));
    let meta = model.meta(args.message, author(args.author));
    let done = nrgdb::ingest::ingest_prepared(&mut store, &args.map, &model, meta)
        .into_diagnostic()
        .wrap_err_with(|| format!("importing {} into map '{}'", args.file.display(), args.map))?;
    spinner.finish_and_clear();
    report_fixes(&model.weights_fixed, out)?;
    if let Some(g) = &done.georef_set {
        writeln!(
            out,
            "georeferenced from the file's CRS: origin {:.7}, {:.7}, heading {:.3}° (change it with `nrgdb georef {}`)",
            g.lat, g.lon, g.heading_deg, args.map
        )
        .into_diagnostic()?;
    }
    let r = &done.imported.revision;
    if done.imported.unchanged {
        writeln!(
            out,
            "nothing changed: the model is {}@{} exactly; no revision was written",
            r.map, r.seq
        )
        .into_diagnostic()?;
        report_corrections(&done, out)?;
        return Ok(ExitCode::SUCCESS);
    }
    writeln!(
        out,
        "{}@{}: {} spaces ({} new, {} changed, {} gone), {} connections",
        r.map, r.seq, r.spaces, r.spaces_added, r.spaces_changed, r.spaces_removed, r.connections
    )
    .into_diagnostic()?;
    report_corrections(&done, out)?;
    Ok(ExitCode::SUCCESS)
}

/// Says how many of the map's corrections were applied again, and which
/// no longer applied.
pub(super) fn report_corrections(
    done: &nrgdb::ingest::Ingested,
    out: &mut dyn Write,
) -> miette::Result<()> {
    let (applied, failed) = (
        done.corrections_applied.len(),
        done.corrections_failed.len(),
    );
    if applied + failed == 0 {
        return Ok(());
    }
    writeln!(
        out,
        "corrections: {applied} re-applied, {failed} no longer apply"
    )
    .into_diagnostic()?;
    for (id, statement, reason) in &done.corrections_failed {
        writeln!(
            out,
            "  correction {id} ({statement}) no longer applies: {reason}"
        )
        .into_diagnostic()?;
    }
    Ok(())
}
