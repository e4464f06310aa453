//! Model files by extension: IndoorGML (`.gml`, `.xml`), the model's JSON
//! form (`.json`) and GeoJSON (`.geojson`). One place decides which reader
//! or writer a path gets, for the CLI, the store and the server.

use std::path::{Path, PathBuf};

use crate::indoorgml::{self, IndoorGmlError};
use crate::model::Nrg;

/// A file format nrgdb reads and writes models in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ModelFormat {
    /// IndoorGML 1.0.3 XML.
    IndoorGml,
    /// The model's JSON form.
    Json,
    /// GeoJSON FeatureCollection.
    GeoJson,
}

/// Why a model file could not be read or written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum FormatError {
    /// The extension names no known format.
    #[error(
        "{0}: unknown format; use .gml or .xml (IndoorGML), .json (model JSON) or .geojson (GeoJSON)"
    )]
    UnknownExtension(PathBuf),
    /// Reading or writing IndoorGML failed.
    #[error("{path}: {source}")]
    IndoorGml {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: IndoorGmlError,
    },
    /// The JSON is not a valid model.
    #[error("{path}: {message}")]
    Json {
        /// The file.
        path: PathBuf,
        /// The cause, with line and column.
        message: String,
    },
    /// The file could not be read or written.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
}

impl ModelFormat {
    /// The format of a path, by its extension.
    pub fn of(path: &Path) -> Result<ModelFormat, FormatError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        match ext.as_deref() {
            Some("gml" | "xml") => Ok(ModelFormat::IndoorGml),
            Some("json") => Ok(ModelFormat::Json),
            Some("geojson") => Ok(ModelFormat::GeoJson),
            _ => Err(FormatError::UnknownExtension(path.to_path_buf())),
        }
    }
}

/// Reads a model file in the format its extension names.
pub fn read_model(path: &Path, max_bytes: u64) -> Result<Nrg, FormatError> {
    let format = ModelFormat::of(path)?;
    let gml = |source| FormatError::IndoorGml {
        path: path.to_path_buf(),
        source,
    };
    if format == ModelFormat::IndoorGml {
        return indoorgml::read_nrg_file(path, max_bytes).map_err(gml);
    }
    let text = indoorgml::read_text(path, max_bytes).map_err(gml)?;
    let json = |message: String| FormatError::Json {
        path: path.to_path_buf(),
        message,
    };
    match format {
        ModelFormat::Json => Nrg::from_json(&text).map_err(|e| json(e.to_string())),
        _ => crate::geojson::from_geojson(&text).map_err(|e| json(e.to_string())),
    }
}

/// Writes a model atomically in the format its extension names.
pub fn write_model(nrg: &Nrg, path: &Path) -> Result<(), FormatError> {
    let text = match ModelFormat::of(path)? {
        ModelFormat::IndoorGml => indoorgml::write_string(&indoorgml::from_nrg(nrg)),
        ModelFormat::Json => nrg.to_json() + "\n",
        ModelFormat::GeoJson => {
            serde_json::to_string_pretty(&crate::geojson::to_geojson(nrg)).unwrap_or_default()
                + "\n"
        }
    };
    crate::atomic::write(path, text.as_bytes()).map_err(|source| FormatError::Io {
        path: path.to_path_buf(),
        source,
    })
}
