//! Reading and writing model files for the CLI. Reading is the library's
//! `nrgdb::ingest::read_path` (the same code the server runs on uploads):
//! IndoorGML, model JSON and GeoJSON, told by name and content, and
//! occupancy maps (`.yaml` with their image), which are extracted first.
//! Writing goes by extension (`nrgdb::format`).

use std::path::Path;

use miette::IntoDiagnostic;
use nrgdb::format::ModelFormat;
use nrgdb::indoorgml::{Finding, WeightFixes};
use nrgdb::ingest::{IngestOptions, Prepared, read_path};
use nrgdb::model::{Nrg, Repair};

/// Reads a model: `.gml`/`.xml` (IndoorGML), `.json` (model JSON),
/// `.geojson`, or `.yaml` (a ROS occupancy map with its image, extracted
/// with default parameters), with the grid of a map and where it came from.
/// A model that stays geometrically invalid after repair is refused
/// unless `allow_invalid`; repairs are said on stderr.
pub fn load_model(path: &Path, allow_invalid: bool) -> miette::Result<Prepared> {
    load_model_into(path, allow_invalid, None)
}

/// [`load_model`] into the frame of a map's georeference (a model file
/// in a CRS is read into it; see `IngestOptions::frame`).
pub fn load_model_into(
    path: &Path,
    allow_invalid: bool,
    frame: Option<nrgdb::model::Georef>,
) -> miette::Result<Prepared> {
    let options = IngestOptions {
        allow_invalid,
        frame,
        ..IngestOptions::default()
    };
    // The errors name the file (and the part: its image, a line).
    let model = read_path(path, &options).into_diagnostic()?;
    report_repairs(&path.display().to_string(), &model.repairs, &model.kept);
    Ok(model)
}

/// Says on stderr what the geometric gate repaired in the model read
/// from `source`, and what it kept invalid because that was allowed.
pub fn report_repairs(source: &str, repairs: &[Repair], kept: &[Finding]) {
    for r in repairs {
        eprintln!("warning: {source}: repaired {r}");
    }
    if !kept.is_empty() {
        eprintln!(
            "warning: {source}: kept with {} of `nrgdb check` (--allow-invalid); the first: {}",
            nrgdb::wording::count(kept.len(), "finding", "findings"),
            kept[0]
        );
    }
}

/// Says how many IndoorGML Transition weights were fixed on reading, if any.
pub fn report_fixes(fixes: &WeightFixes, out: &mut dyn std::io::Write) -> miette::Result<()> {
    if fixes.total() == 0 {
        return Ok(());
    }
    let walked = fixes.without_geometry.len();
    let from = match (fixes.from_geometry, walked) {
        (_, 0) => "set from their geometry".to_string(),
        (0, _) => "set from their walked path (no geometry)".to_string(),
        (g, w) => format!("{g} set from their geometry, {w} from their walked path"),
    };
    writeln!(
        out,
        "fixed {} transition weights (missing or 0): {from}",
        fixes.total()
    )
    .into_diagnostic()
}

/// Writes a model atomically in the format its extension names
/// (`.gml`, `.json`, `.geojson`, `.indoor.json`; IndoorGML as `version`);
/// `-` writes JSON to `out`. Either way with
/// walked connection lengths and paths (`nrgdb::format::render_model`).
pub fn write_model_as(
    path: &Path,
    nrg: &Nrg,
    version: nrgdb::indoorgml::IndoorGmlVersion,
    out: &mut dyn std::io::Write,
) -> miette::Result<()> {
    if path == Path::new("-") {
        let json = nrgdb::format::render_model(nrg, ModelFormat::Json);
        return out.write_all(json.as_bytes()).into_diagnostic();
    }
    nrgdb::format::write_model_as(nrg, path, version).into_diagnostic()
}
