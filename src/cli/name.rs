//! `nrgdb name`: name a space, as a new revision.

use std::io::Write;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::model::SpaceId;
use nrgdb::store::ImportMeta;

use super::db::{DbArg, author};

/// Give a space of the latest revision a name (recorded as a new
/// revision). Names survive later re-imports of the map.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The map.
    pub map: String,
    /// The space: its id (see `nrgdb export`), or its current name.
    pub space: String,
    /// The new name; an empty string removes the name.
    pub name: String,
    /// Commit message [default: "name SPACE 'NAME'"].
    #[arg(short, long)]
    pub message: Option<String>,
    /// Author recorded with the revision [default: $USER].
    #[arg(long, env = "NRGDB_AUTHOR")]
    pub author: Option<String>,
    #[command(flatten)]
    pub db: DbArg,
}

/// Runs `nrgdb name`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let mut store = args.db.open()?;
    let id = match args.space.parse::<u32>() {
        Ok(id) => SpaceId(id),
        Err(_) => {
            let nrg = store.load(&args.map, None).into_diagnostic()?;
            let mut found = nrg
                .spaces()
                .iter()
                .filter(|s| s.name.as_deref() == Some(args.space.as_str()));
            match (found.next(), found.next()) {
                (Some(s), None) => s.id,
                (Some(_), Some(_)) => miette::bail!(
                    "several spaces of map '{}' are named '{}'; give the id instead",
                    args.map,
                    args.space
                ),
                (None, _) => miette::bail!(
                    "map '{}' has no space named '{}'; give a space id (see `nrgdb export {} --out -`)",
                    args.map,
                    args.space,
                    args.map
                ),
            }
        }
    };
    let name = (!args.name.is_empty()).then_some(args.name.as_str());
    let message = args
        .message
        .unwrap_or_else(|| format!("name space {id} '{}'", args.name));
    let info = store
        .rename_space(
            &args.map,
            id,
            name,
            ImportMeta::new(message, author(args.author)),
        )
        .into_diagnostic()
        .wrap_err_with(|| format!("naming space {id} of map '{}'", args.map))?;
    writeln!(
        out,
        "{}@{}: space {id} named '{}'",
        info.map, info.seq, args.name
    )
    .into_diagnostic()?;
    Ok(ExitCode::SUCCESS)
}
