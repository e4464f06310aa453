//! `nrgdb georef`: show, set or remove where a map lies on the Earth.

use std::io::Write;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::model::Georef;

use super::db::DbArg;

/// Show, set or remove a map's georeference: the WGS84 position of its
/// frame's origin, the compass bearing of its +y axis and its level. It
/// holds for every revision; GeoJSON exports are then WGS84 (RFC 7946)
/// and OpenStreetMap exports possible.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The map.
    pub map: String,
    /// Latitude and longitude of the map frame's origin (0, 0), degrees WGS84: `52.5163,13.3777`.
    #[arg(long, value_name = "LAT,LON", allow_hyphen_values = true)]
    pub origin: Option<String>,
    /// Compass bearing of the map's +y axis ("up" in its picture), degrees clockwise from north.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub heading: f64,
    /// The building level the map shows (OpenStreetMap `level`: 0, 1, -1, …).
    #[arg(long, default_value = "0", allow_hyphen_values = true)]
    pub level: String,
    /// Remove the georeference.
    #[arg(long, conflicts_with = "origin")]
    pub clear: bool,
    #[command(flatten)]
    pub db: DbArg,
}

fn parse_origin(text: &str) -> miette::Result<(f64, f64)> {
    let bad = || {
        miette::miette!(
            "--origin {text:?}: give latitude,longitude in degrees, e.g. 52.5163,13.3777"
        )
    };
    let (lat, lon) = text.split_once(',').ok_or_else(bad)?;
    let lat: f64 = lat.trim().parse().map_err(|_| bad())?;
    let lon: f64 = lon.trim().parse().map_err(|_| bad())?;
    Ok((lat, lon))
}

/// Runs `nrgdb georef`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let mut store = args.db.open_existing()?;
    let context = || format!("georeferencing map '{}'", args.map);
    if args.clear {
        store
            .set_georef(&args.map, None)
            .into_diagnostic()
            .wrap_err_with(context)?;
        writeln!(out, "{}: georeference removed", args.map).into_diagnostic()?;
        return Ok(ExitCode::SUCCESS);
    }
    let Some(origin) = &args.origin else {
        let current = store.georef(&args.map).into_diagnostic()?;
        match current {
            Some(g) => writeln!(out, "{}: {}", args.map, describe(&g)),
            None => writeln!(
                out,
                "{}: no georeference (set one with --origin LAT,LON --heading DEG)",
                args.map
            ),
        }
        .into_diagnostic()?;
        return Ok(ExitCode::SUCCESS);
    };
    let (lat, lon) = parse_origin(origin)?;
    let g = Georef::new(lat, lon, args.heading, &args.level)
        .into_diagnostic()
        .wrap_err_with(context)?;
    store
        .set_georef(&args.map, Some(&g))
        .into_diagnostic()
        .wrap_err_with(context)?;
    writeln!(out, "{}: {}", args.map, describe(&g)).into_diagnostic()?;
    Ok(ExitCode::SUCCESS)
}

fn describe(g: &Georef) -> String {
    format!(
        "origin {:.7}, {:.7} (WGS84), +y at {}° from north, level {}",
        g.lat, g.lon, g.heading_deg, g.level
    )
}
