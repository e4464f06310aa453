//! `nrgdb export`: write a stored revision to a file.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};

use super::db::{DbArg, parse_map_rev};
use super::write_model_as;

/// Write a revision of a map to a model file (the latest unless NAME@REV).
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The map, optionally with a revision: `willow` or `willow@3`.
    #[arg(value_name = "NAME[@REV]")]
    pub map: String,
    /// Output file (.gml IndoorGML, .json model JSON, .geojson), written atomically; `-` writes JSON to stdout.
    #[arg(long, short)]
    pub out: PathBuf,
    /// IndoorGML version of a .gml/.xml output: 1.0.3 or 1.1.
    #[arg(long, value_name = "VERSION", default_value_t)]
    pub indoorgml_version: nrgdb::indoorgml::IndoorGmlVersion,
    /// GeoJSON of a georeferenced map (`nrgdb georef`) in map-frame metres instead of WGS84.
    #[arg(long)]
    pub local_frame: bool,
    #[command(flatten)]
    pub db: DbArg,
}

/// Runs `nrgdb export`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let (map, rev) = parse_map_rev(&args.map)?;
    let store = args.db.open_existing()?;
    let nrg = store
        .load(&map, rev)
        .into_diagnostic()
        .wrap_err_with(|| format!("exporting {}", args.map))?;
    let geojson =
        nrgdb::format::ModelFormat::of(&args.out).ok() == Some(nrgdb::format::ModelFormat::GeoJson);
    if geojson && !args.local_frame {
        let georef = store.georef(&map).into_diagnostic()?;
        if let Some(g) = georef {
            nrgdb::format::write_geojson_wgs84(&nrg, &g, &args.out).into_diagnostic()?;
            return Ok(ExitCode::SUCCESS);
        }
    }
    write_model_as(&args.out, &nrg, args.indoorgml_version, out)?;
    Ok(ExitCode::SUCCESS)
}
