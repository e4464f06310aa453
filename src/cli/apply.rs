//! `nrgdb apply`: replay a change set on a stored revision, as a new
//! revision.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::diff::{ChangeSet, apply};
use nrgdb::store::ImportMeta;

use super::db::{DbArg, author, parse_map_rev};

/// Apply a change set (from `nrgdb diff --json`) to a revision of a map
/// (the latest unless NAME@REV), storing the result as the next revision.
/// The change set must have been computed from that revision's model.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The map, optionally with the revision to apply to: `willow` or `willow@3`.
    #[arg(value_name = "NAME[@REV]")]
    pub map: String,
    /// The change set (JSON written by `nrgdb diff --json` or `--output`).
    #[arg(value_name = "CHANGESET.json")]
    pub changes: PathBuf,
    /// Commit message recorded with the revision.
    #[arg(short, long, default_value = "applied a change set")]
    pub message: String,
    /// When NAME@REV is not the latest revision: carry the change over
    /// onto the latest instead of refusing (conflicts are reported and
    /// nothing is stored).
    #[arg(long)]
    pub rebase: bool,
    /// Author recorded with the revision [default: $USER].
    #[arg(long, env = "NRGDB_AUTHOR")]
    pub author: Option<String>,
    #[command(flatten)]
    pub db: DbArg,
}

/// Runs `nrgdb apply`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let (map, rev) = parse_map_rev(&args.map)?;
    let text = std::fs::read_to_string(&args.changes)
        .into_diagnostic()
        .wrap_err_with(|| format!("reading {}", args.changes.display()))?;
    let changes = ChangeSet::from_json(&text)
        .into_diagnostic()
        .wrap_err_with(|| format!("{}: not a change set", args.changes.display()))?;
    let mut store = args.db.open()?;
    let latest = store
        .revision(&map, None)
        .into_diagnostic()
        .wrap_err_with(|| format!("loading {}", args.map))?
        .seq;
    let base_seq = rev.unwrap_or(latest);
    // A change set computed from a stored revision names it; applying it
    // to another would put its changes on the wrong model.
    if let Some((from_map, from_rev)) = changes.from.as_deref().and_then(|f| f.rsplit_once('@'))
        && let Ok(from_rev) = from_rev.parse::<u32>()
        && (from_map != map || from_rev != base_seq)
    {
        miette::bail!(
            "{} was computed from {from_map}@{from_rev}, not {map}@{base_seq}; nothing was stored",
            args.changes.display()
        );
    }
    let base = store
        .load(&map, Some(base_seq))
        .into_diagnostic()
        .wrap_err_with(|| format!("loading {}", args.map))?;
    let mut result = apply(&base, &changes)
        .into_diagnostic()
        .wrap_err_with(|| format!("applying {} to {}", args.changes.display(), args.map))?;
    if base_seq != latest {
        if !args.rebase {
            miette::bail!(
                "{map}@{base_seq} is not the latest revision ({latest}): storing the change on it would undo revisions {} to {latest}; pass --rebase to carry it over onto {map}@{latest}; nothing was stored",
                base_seq + 1
            );
        }
        let now = store.load(&map, Some(latest)).into_diagnostic()?;
        result = nrgdb::diff::rebase(&base, &result, &now).map_err(|conflicts| {
            miette::miette!(
                "cannot carry the change from {map}@{base_seq} over onto {map}@{latest}; nothing was stored:\n  {}",
                conflicts.join("\n  ")
            )
        })?;
        writeln!(out, "rebased from {map}@{base_seq} onto {map}@{latest}").into_diagnostic()?;
    }
    let name = args.changes.file_name().map_or_else(
        || args.changes.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let meta =
        ImportMeta::new(args.message, author(args.author)).with_source(name, text.as_bytes());
    let done = nrgdb::ingest::ingest(&mut store, &map, &result, meta, None)
        .into_diagnostic()
        .wrap_err_with(|| format!("storing the result in map '{map}'"))?;
    let r = &done.imported.revision;
    if done.imported.unchanged {
        writeln!(
            out,
            "nothing changed: {}@{} already is the result",
            r.map, r.seq
        )
        .into_diagnostic()?;
        return Ok(ExitCode::SUCCESS);
    }
    writeln!(
        out,
        "{}@{}: {} spaces ({} new, {} changed, {} gone), {} connections",
        r.map, r.seq, r.spaces, r.spaces_added, r.spaces_changed, r.spaces_removed, r.connections
    )
    .into_diagnostic()?;
    Ok(ExitCode::SUCCESS)
}
