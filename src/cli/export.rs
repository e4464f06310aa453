//! `nrgdb export`: write a stored revision to a file.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use miette::{IntoDiagnostic, WrapErr};

use super::db::{DbArg, parse_map_rev};
use super::write_model_as;
use nrgdb::format::Frame;

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
    /// What to write: a model format told by the extension (default), `nav2`: a Nav2 Route
    /// Server graph (GeoJSON for nav2_route's GeoJsonGraphFileLoader), or `osm`: OpenStreetMap
    /// Simple Indoor Tagging for JOSM (needs a georeference).
    #[arg(long, value_enum, default_value_t = ExportFormat::Model)]
    pub format: ExportFormat,
    /// A georeferenced map's GeoJSON or IndoorGML (`nrgdb georef`) in map-frame metres instead
    /// of WGS84 or UTM.
    #[arg(long, conflicts_with = "crs")]
    pub local_frame: bool,
    /// The CRS of a georeferenced map's file: `wgs84` (RFC 7946; GeoJSON's default) or `utm`
    /// (metres in the WGS84 / UTM zone of the map's origin, EPSG:326zz or 327zz, named in
    /// GeoJSON's `crs` member for GDAL and QGIS and as IndoorGML's `srsName`; IndoorGML's
    /// default).
    #[arg(long, value_enum)]
    pub crs: Option<GeoCrs>,
    #[command(flatten)]
    pub db: DbArg,
}

/// The CRS of a georeferenced map's GeoJSON.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum GeoCrs {
    /// WGS84 longitude and latitude (RFC 7946).
    Wgs84,
    /// Metres in the WGS84 / UTM zone of the map's origin.
    Utm,
}

/// What `nrgdb export` writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ExportFormat {
    /// The model, in the format its extension names (.gml, .json, .geojson, .indoor.json).
    Model,
    /// A Nav2 Route Server graph (GeoJSON).
    Nav2,
    /// OpenStreetMap XML in Simple Indoor Tagging, for JOSM (needs `nrgdb georef`).
    Osm,
}

/// Runs `nrgdb export`.
pub fn run(args: Args, out: &mut dyn Write) -> miette::Result<ExitCode> {
    let (map, rev) = parse_map_rev(&args.map)?;
    let store = args.db.open_existing()?;
    let nrg = store
        .load(&map, rev)
        .into_diagnostic()
        .wrap_err_with(|| format!("exporting {}", args.map))?;
    if args.crs.is_some() && args.format != ExportFormat::Model {
        miette::bail!(
            "--crs is for a model's GeoJSON; Nav2 graphs are in map-frame metres and OpenStreetMap files in WGS84"
        );
    }
    if args.format == ExportFormat::Osm {
        let Some(georef) = store.georef(&map).into_diagnostic()? else {
            miette::bail!(
                "map '{map}' has no georeference; OpenStreetMap files are in WGS84: set one with `nrgdb georef {map} --origin LAT,LON --heading DEG`"
            );
        };
        let text = nrgdb::format::osm::to_osm_xml(&nrg, &georef);
        nrgdb::atomic::write(&args.out, text.as_bytes())
            .into_diagnostic()
            .wrap_err_with(|| format!("writing {}", args.out.display()))?;
        return Ok(ExitCode::SUCCESS);
    }
    if args.format == ExportFormat::Nav2 {
        let nav = nrgdb::route::NavMesh::new(std::sync::Arc::new(nrg));
        let graph = nrgdb::format::nav2::to_nav2(&nav);
        nrgdb::format::nav2::check_nav2(&graph)
            .into_diagnostic()
            .wrap_err_with(|| format!("{} makes no Nav2 route graph", args.map))?;
        let text = serde_json::to_string_pretty(&graph).into_diagnostic()? + "\n";
        if args.out == std::path::Path::new("-") {
            out.write_all(text.as_bytes()).into_diagnostic()?;
            return Ok(ExitCode::SUCCESS);
        }
        nrgdb::atomic::write(&args.out, text.as_bytes())
            .into_diagnostic()
            .wrap_err_with(|| format!("writing {}", args.out.display()))?;
        return Ok(ExitCode::SUCCESS);
    }
    let asked = match (args.local_frame, args.crs) {
        (true, _) => Some(Frame::Local),
        (false, Some(GeoCrs::Wgs84)) => Some(Frame::Wgs84),
        (false, Some(GeoCrs::Utm)) => Some(Frame::Utm),
        (false, None) => None,
    };
    if args.out != std::path::Path::new("-") {
        let format = nrgdb::format::ModelFormat::of(&args.out).into_diagnostic()?;
        let georef = store.georef(&map).into_diagnostic()?;
        let frame = nrgdb::format::frame_for(format, asked, georef.is_some())
            .into_diagnostic()
            .wrap_err_with(|| format!("exporting {} to {}", args.map, args.out.display()))?;
        if frame != Frame::Local {
            let walked = nrgdb::route::walked_model(&nrg);
            let text = nrgdb::format::render_in(
                &walked,
                format,
                args.indoorgml_version,
                frame,
                georef.as_ref(),
            );
            nrgdb::atomic::write(&args.out, text.as_bytes())
                .into_diagnostic()
                .wrap_err_with(|| format!("writing {}", args.out.display()))?;
            return Ok(ExitCode::SUCCESS);
        }
    } else if asked.is_some_and(|f| f != Frame::Local) {
        miette::bail!(
            "`--out -` writes model JSON in map-frame metres; --crs needs a .geojson or .gml file"
        );
    }
    write_model_as(&args.out, &nrg, args.indoorgml_version, out)?;
    Ok(ExitCode::SUCCESS)
}
