//! Reading and writing model files for the CLI. Reading is the library's
//! `nrgdb::ingest::read_path` (the same code the server runs on uploads):
//! IndoorGML, model JSON and GeoJSON, told by name and content, and
//! occupancy maps (`.yaml` with their image), which are extracted first.
//! Writing goes by extension (`nrgdb::format`).

use std::path::Path;

use miette::IntoDiagnostic;
use nrgdb::format::ModelFormat;
use nrgdb::indoorgml::WeightFixes;
use nrgdb::ingest::{IngestOptions, Prepared, read_path};
use nrgdb::model::Nrg;

/// Reads a model: `.gml`/`.xml` (IndoorGML), `.json` (model JSON),
/// `.geojson`, or `.yaml` (a ROS occupancy map with its image, extracted
/// with default parameters), with the grid of a map and where it came from.
pub fn load_model(path: &Path) -> miette::Result<Prepared> {
    // The errors name the file (and the part: its image, a line).
    read_path(path, &IngestOptions::default()).into_diagnostic()
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
/// (`.gml`, `.json`, `.geojson`); `-` writes JSON to `out`. Either way with
/// walked connection lengths and paths (`nrgdb::format::render_model`).
pub fn write_model(path: &Path, nrg: &Nrg, out: &mut dyn std::io::Write) -> miette::Result<()> {
    if path == Path::new("-") {
        let json = nrgdb::format::render_model(nrg, ModelFormat::Json);
        return out.write_all(json.as_bytes()).into_diagnostic();
    }
    nrgdb::format::write_model(nrg, path).into_diagnostic()
}
