//! Reading and writing model files for the CLI: IndoorGML, model JSON and
//! GeoJSON by extension (`nrgdb::format`), and occupancy maps (`.yaml`),
//! which are extracted first.

use std::path::Path;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::extract::{ExtractParams, extract};
use nrgdb::format::ModelFormat;
use nrgdb::grid::{LoadOptions, load_map};
use nrgdb::indoorgml::{DEFAULT_MAX_BYTES, WeightFixes};
use nrgdb::model::Nrg;

/// A model read from a file, with the bytes it came from.
pub struct ModelFile {
    /// The model.
    pub nrg: Nrg,
    /// The file's bytes (hashed into the revision record).
    pub bytes: Vec<u8>,
    /// Extraction parameters, when the model was extracted from a map.
    pub params: Option<serde_json::Value>,
    /// The occupancy grid, when the model was extracted from a map.
    pub grid: Option<nrgdb::grid::OccupancyGrid>,
    /// IndoorGML Transitions whose missing or 0 weight was fixed.
    pub weights_fixed: WeightFixes,
}

/// Reads a model: `.gml`/`.xml` (IndoorGML), `.json` (model JSON),
/// `.geojson`, or `.yaml` (a ROS occupancy map, extracted with default
/// parameters).
pub fn load_model(path: &Path) -> miette::Result<ModelFile> {
    let bytes = std::fs::read(path)
        .into_diagnostic()
        .wrap_err_with(|| format!("reading {}", path.display()))?;
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    if ext == "yaml" || ext == "yml" {
        let grid = load_map(path, &LoadOptions::default()).into_diagnostic()?;
        let params = ExtractParams::default();
        let extraction = extract(&grid, &params)
            .into_diagnostic()
            .wrap_err_with(|| format!("extracting the NRG of {}", path.display()))?;
        let params = serde_json::to_value(&params).ok();
        return Ok(ModelFile {
            nrg: extraction.nrg,
            bytes,
            params,
            grid: Some(grid),
            weights_fixed: WeightFixes::default(),
        });
    }
    let (nrg, weights_fixed) =
        nrgdb::format::read_model_fixing(path, DEFAULT_MAX_BYTES).into_diagnostic()?;
    Ok(ModelFile {
        nrg,
        bytes,
        params: None,
        grid: None,
        weights_fixed,
    })
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
