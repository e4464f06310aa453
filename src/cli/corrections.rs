//! `nrgdb corrections MAP`: the corrections kept with a map (issue 22),
//! with their state at the last import; `--drop N` drops one.

use std::io::Write;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};

use super::db::DbArg;

/// List a map's corrections (MERGE, SPLIT, ADD DOOR, … made through
/// queries) with their state: applied, failed (and why) or dropped.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The map.
    pub map: String,
    /// Drop correction N: later imports no longer apply it (the revisions
    /// it made stay).
    #[arg(long, value_name = "N")]
    pub drop: Option<u32>,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub db: DbArg,
}

/// Runs the subcommand.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let mut store = args.db.open_existing()?;
    // The map must exist (a typo gets its suggestion).
    store
        .revision(&args.map, None)
        .into_diagnostic()
        .wrap_err_with(|| format!("listing the corrections of map '{}'", args.map))?;
    if let Some(id) = args.drop {
        let c = store
            .drop_correction(&args.map, id)
            .into_diagnostic()
            .wrap_err_with(|| format!("dropping correction {id} of map '{}'", args.map))?;
        writeln!(out, "dropped correction {}: {}", c.id, c.statement).into_diagnostic()?;
        return Ok(ExitCode::SUCCESS);
    }
    let list = store.corrections(&args.map).into_diagnostic()?;
    if args.json {
        writeln!(
            out,
            "{}",
            serde_json::to_string_pretty(&list).into_diagnostic()?
        )
        .into_diagnostic()?;
        return Ok(ExitCode::SUCCESS);
    }
    if list.is_empty() {
        writeln!(out, "map '{}' has no corrections", args.map).into_diagnostic()?;
        return Ok(ExitCode::SUCCESS);
    }
    writeln!(
        out,
        "{:>3}  {:<8} {:>5} {:>7}  {:<16} statement",
        "id", "state", "made", "checked", "author"
    )
    .into_diagnostic()?;
    for c in &list {
        writeln!(
            out,
            "{:>3}  {:<8} {:>5} {:>7}  {:<16} {}",
            c.id,
            c.state.as_str(),
            format!("@{}", c.made_on),
            format!("@{}", c.checked_on),
            c.author,
            c.statement
        )
        .into_diagnostic()?;
        if let Some(reason) = c
            .reason
            .as_deref()
            .filter(|_| c.state == nrgdb::store::CorrectionState::Failed)
        {
            writeln!(out, "     no longer applies: {reason}").into_diagnostic()?;
        }
    }
    Ok(ExitCode::SUCCESS)
}
