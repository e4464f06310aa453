//! `nrgdb maps`, `nrgdb revisions` and `nrgdb log`: what the database holds.

use std::io::Write;
use std::process::ExitCode;

use miette::IntoDiagnostic;
use nrgdb::store::RevisionInfo;

use super::db::DbArg;

/// List the maps in the database.
#[derive(Debug, clap::Args)]
pub struct MapsArgs {
    #[command(flatten)]
    pub db: DbArg,
}

/// List the revisions of a map, oldest first.
#[derive(Debug, clap::Args)]
pub struct RevisionsArgs {
    /// The map.
    pub map: String,
    #[command(flatten)]
    pub db: DbArg,
}

/// Show the history of a map, newest first, with messages.
#[derive(Debug, clap::Args)]
pub struct LogArgs {
    /// The map.
    pub map: String,
    #[command(flatten)]
    pub db: DbArg,
}

/// Runs `nrgdb maps`; exit 1 when the database holds no map.
pub fn run_maps(args: MapsArgs, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let maps = args.db.open_existing()?.maps().into_diagnostic()?;
    if maps.is_empty() {
        writeln!(out, "no maps in {}", args.db.shown()).into_diagnostic()?;
        return Ok(ExitCode::from(1));
    }
    writeln!(out, "{:<24} {:>9}  created", "map", "revisions").into_diagnostic()?;
    for m in maps {
        writeln!(out, "{:<24} {:>9}  {}", m.name, m.latest, m.created_at).into_diagnostic()?;
    }
    Ok(ExitCode::SUCCESS)
}

/// Runs `nrgdb revisions`.
pub fn run_revisions(args: RevisionsArgs, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let revs = args
        .db
        .open_existing()?
        .revisions(&args.map)
        .into_diagnostic()?;
    writeln!(
        out,
        "{:>4} {:>6}  {:<24} {:>6} {:>5}  {:<20} message",
        "rev", "parent", "created", "spaces", "conns", "source"
    )
    .into_diagnostic()?;
    for r in revs {
        let parent = r.parent.map_or("-".to_string(), |p| p.to_string());
        let source = r.source_name.clone().unwrap_or_else(|| "-".into());
        writeln!(
            out,
            "{:>4} {:>6}  {:<24} {:>6} {:>5}  {:<20} {}",
            r.seq,
            parent,
            r.created_at,
            r.spaces,
            r.connections,
            source,
            first_line(&r.message)
        )
        .into_diagnostic()?;
    }
    Ok(ExitCode::SUCCESS)
}

/// Runs `nrgdb log`.
pub fn run_log(args: LogArgs, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let revs = args.db.open_existing()?.log(&args.map).into_diagnostic()?;
    for r in revs {
        write_entry(&r, out).into_diagnostic()?;
    }
    Ok(ExitCode::SUCCESS)
}

fn write_entry(r: &RevisionInfo, out: &mut dyn Write) -> std::io::Result<()> {
    let parent = r.parent.map_or(String::new(), |p| format!(" (parent {p})"));
    writeln!(out, "revision {}@{}{parent}", r.map, r.seq)?;
    writeln!(out, "Author: {}", r.author)?;
    writeln!(out, "Date:   {}", r.created_at)?;
    if let Some(src) = &r.source_name {
        let sha = r.source_sha256.as_deref().unwrap_or("-");
        writeln!(out, "Source: {src} (sha256 {sha})")?;
    }
    writeln!(
        out,
        "Spaces: {} (+{} ~{} -{}), connections: {}",
        r.spaces, r.spaces_added, r.spaces_changed, r.spaces_removed, r.connections
    )?;
    writeln!(out)?;
    let message = if r.message.is_empty() {
        "(no message)"
    } else {
        &r.message
    };
    for line in message.lines() {
        writeln!(out, "    {line}")?;
    }
    writeln!(out)
}

fn first_line(text: &str) -> &str {
    text.lines().next().unwrap_or("")
}
