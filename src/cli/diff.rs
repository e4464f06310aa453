//! `nrgdb diff`: what changed between two revisions of a map, or between
//! two model files.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr, miette};
use nrgdb::diff::{AlignMode, Comparison, DiffOptions, DiffParams, compare, update_model};
use nrgdb::query::LoadedRevision;

use super::db::DbArg;
use super::load_model;

/// Compare two revisions: spaces added, removed, resized, split, merged,
/// re-kinded, renamed; connections added and removed; door widths.
///
/// `nrgdb diff NAME A B` compares revisions A and B of a stored map;
/// `nrgdb diff OLD NEW` compares two files (.yaml maps are extracted with
/// default parameters; .gml, .json, .geojson models are read). When the
/// two frames differ (fewer than half of either map's walls on the other's), B is
/// aligned to A first and the transform is reported. Exit code 0 when
/// nothing changed, 1 when something did, 2 on error.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// `NAME A B` (a stored map and two revision numbers) or `OLD NEW` (two files).
    #[arg(num_args = 2..=3, required = true, value_name = "TARGET")]
    pub targets: Vec<String>,
    /// Print the change set as JSON (the input of `nrgdb apply`) instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Also write the change set as JSON to this file (atomically).
    #[arg(long, short, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// Write the IndoorGML update: B in which matched spaces keep A's ids and new ones get new ids
    /// (in a building with levels, only the levels that changed).
    #[arg(long, value_name = "FILE")]
    pub gml: Option<PathBuf>,
    /// Always align B to A (default: only when their frames differ).
    #[arg(long, conflicts_with = "no_align")]
    pub align: bool,
    /// Never align: the two share a frame.
    #[arg(long)]
    pub no_align: bool,
    /// Smallest intersection over union for two spaces to be the same space.
    #[arg(long, value_name = "IOU", default_value_t = DiffParams::default().min_iou)]
    pub min_iou: f64,
    /// Relative area change above which a space counts as resized.
    #[arg(long, value_name = "RATIO", default_value_t = DiffParams::default().resize_ratio)]
    pub resize_ratio: f64,
    #[command(flatten)]
    pub db: DbArg,
}

/// Runs `nrgdb diff`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let (a, b) = match args.targets.as_slice() {
        [name, ra, rb] => {
            let store = args.db.open_existing()?;
            let load = |rev: &str| -> miette::Result<LoadedRevision> {
                let seq: u64 = rev.trim_start_matches('@').parse().map_err(|_| {
                    miette!("bad revision '{rev}': expected a revision number (see `nrgdb revisions {name}`)")
                })?;
                LoadedRevision::load(&store, name, seq)
                    .into_diagnostic()
                    .wrap_err_with(|| format!("loading {name}@{seq}"))
            };
            (load(ra)?, load(rb)?)
        }
        [fa, fb] => (load_file(Path::new(fa))?, load_file(Path::new(fb))?),
        _ => return Err(miette!("expected `NAME A B` or `OLD NEW`")),
    };
    let options = DiffOptions {
        align: if args.align {
            AlignMode::Always
        } else if args.no_align {
            AlignMode::Never
        } else {
            AlignMode::Auto
        },
        params: DiffParams {
            min_iou: args.min_iou,
            resize_ratio: args.resize_ratio,
            ..DiffParams::default()
        },
        ..DiffOptions::default()
    };
    let Comparison {
        changes,
        moved,
        alignment,
        ..
    } = compare(a.side(), b.side(), &options)
        .into_diagnostic()
        .wrap_err_with(|| format!("comparing {} with {}", a.label, b.label))?;
    if let Some(path) = &args.output {
        nrgdb::atomic::write(path, changes.to_json().as_bytes())
            .into_diagnostic()
            .wrap_err_with(|| format!("writing {}", path.display()))?;
    }
    // Said after the report: which levels the IndoorGML update covers.
    let mut update_said = None;
    if let Some(path) = &args.gml {
        let (update, levels) = update_model(&a.nrg, &moved, &changes).into_diagnostic()?;
        let text = nrgdb::format::render_model(&update, nrgdb::format::ModelFormat::IndoorGml);
        nrgdb::atomic::write(path, text.as_bytes())
            .into_diagnostic()
            .wrap_err_with(|| format!("writing the IndoorGML update {}", path.display()))?;
        if a.nrg.has_levels() && !args.json {
            let covered = if levels.is_empty() {
                "no level changed".to_string()
            } else {
                format!("level {}", levels.join(", "))
            };
            update_said = Some(format!(
                "IndoorGML update {}: {covered} ({} cells)",
                path.display(),
                update.spaces().len()
            ));
        }
    }
    if args.json {
        writeln!(out, "{}", changes.to_json()).into_diagnostic()?;
    } else {
        writeln!(out, "{} → {}", a.label, b.label).into_diagnostic()?;
        if let Some(al) = alignment {
            writeln!(
                out,
                "alignment quality: {:.0}% of walls within {:.2} m (rms {:.3} m)",
                100.0 * al.inliers,
                al.tolerance_m,
                al.rms_m
            )
            .into_diagnostic()?;
        }
        write!(out, "{}", changes.table()).into_diagnostic()?;
        if let Some(said) = update_said {
            writeln!(out, "{said}").into_diagnostic()?;
        }
    }
    Ok(if changes.is_empty() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// A model file as a side of the comparison, labelled by its file name
/// (a `.yaml` map extracted, keeping its grid).
/// Invalid geometry is no reason not to compare: it is kept (repaired
/// where it can be, and said).
pub fn load_file(path: &Path) -> miette::Result<LoadedRevision> {
    let model = load_model(path, true)?;
    Ok(LoadedRevision {
        label: path.file_name().map_or_else(
            || path.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        ),
        nrg: model.nrg,
        grid: model.grid,
    })
}
