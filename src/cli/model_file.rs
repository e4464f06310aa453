//! Reading and writing model files: the one place that knows which file
//! formats the CLI accepts (the lead extends these two functions with
//! IndoorGML and occupancy maps).

use std::path::Path;

use miette::{IntoDiagnostic, WrapErr};
use nrgdb::model::Nrg;

/// A model read from a file, with the bytes it came from.
pub struct ModelFile {
    /// The model.
    pub nrg: Nrg,
    /// The file's bytes (hashed into the revision record).
    pub bytes: Vec<u8>,
    /// Extraction parameters, when the model was extracted from a map.
    pub params: Option<serde_json::Value>,
}

/// Reads a model file: `.json` (the model's JSON form).
pub fn load_model(path: &Path) -> miette::Result<ModelFile> {
    let bytes = std::fs::read(path)
        .into_diagnostic()
        .wrap_err_with(|| format!("reading {}", path.display()))?;
    let ext = extension(path);
    match ext.as_str() {
        "json" => {
            let text = std::str::from_utf8(&bytes)
                .into_diagnostic()
                .wrap_err_with(|| format!("{}: not UTF-8 text", path.display()))?;
            let nrg = Nrg::from_json(text)
                .into_diagnostic()
                .wrap_err_with(|| format!("{}: not a valid nrgdb model JSON", path.display()))?;
            Ok(ModelFile {
                nrg,
                bytes,
                params: None,
            })
        }
        _ => Err(miette::miette!(
            "{}: unknown model format '.{ext}' (expected .json)",
            path.display()
        )),
    }
}

/// Writes a model file atomically, in the format its extension names
/// (`.json`); `-` writes JSON to `out`.
pub fn write_model(path: &Path, nrg: &Nrg, out: &mut dyn std::io::Write) -> miette::Result<()> {
    if path == Path::new("-") {
        return writeln!(out, "{}", nrg.to_json()).into_diagnostic();
    }
    let ext = extension(path);
    match ext.as_str() {
        "json" => nrgdb::atomic::write(path, nrg.to_json().as_bytes())
            .into_diagnostic()
            .wrap_err_with(|| format!("writing {}", path.display())),
        _ => Err(miette::miette!(
            "{}: unknown output format '.{ext}' (expected .json)",
            path.display()
        )),
    }
}

fn extension(path: &Path) -> String {
    path.extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase()
}
