//! Model files by extension: IndoorGML (`.gml`, `.xml`), the model's JSON
//! form (`.json`) and GeoJSON (`.geojson`). One place decides which reader
//! or writer a path gets, for the CLI, the store and the server.
//!
//! Every model written goes through [`render`]: connection lengths are the
//! walked lengths and IndoorGML Transitions and GeoJSON connection lines
//! are the walked paths through the doorways ([`walked_model`]). Reading
//! IndoorGML fixes Transitions with a missing or 0 weight ([`from_document`]).
//! Uses indoorgml, geojson and route; sits above them.

use std::path::{Path, PathBuf};

use crate::indoorgml::{self, Document, IndoorGmlError, WeightFixes};
use crate::model::Nrg;
use crate::route::{WalkedModel, walked_model};

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
    read_model_fixing(path, max_bytes).map(|(nrg, _)| nrg)
}

/// Reads a model file in the format its extension names, with the
/// IndoorGML Transition weights it had to fix (none for other formats).
pub fn read_model_fixing(path: &Path, max_bytes: u64) -> Result<(Nrg, WeightFixes), FormatError> {
    let format = ModelFormat::of(path)?;
    let gml = |source| FormatError::IndoorGml {
        path: path.to_path_buf(),
        source,
    };
    if format == ModelFormat::IndoorGml {
        let doc = indoorgml::read_file(path, max_bytes).map_err(gml)?;
        return from_document(&doc).map_err(gml);
    }
    let text = indoorgml::read_text(path, max_bytes).map_err(gml)?;
    let json = |message: String| FormatError::Json {
        path: path.to_path_buf(),
        message,
    };
    let nrg = match format {
        ModelFormat::Json => Nrg::from_json(&text).map_err(|e| json(e.to_string()))?,
        _ => crate::geojson::from_geojson(&text).map_err(|e| json(e.to_string()))?,
    };
    Ok((nrg, WeightFixes::default()))
}

/// An IndoorGML document as a model, Transitions with a missing or 0
/// weight fixed: from their LineString's length, or, without one, from
/// the walked length between the two anchors (the navigation layer).
pub fn from_document(doc: &Document) -> Result<(Nrg, WeightFixes), IndoorGmlError> {
    let (nrg, fixes) = indoorgml::to_nrg_fixing(doc)?;
    if fixes.without_geometry.is_empty() {
        return Ok((nrg, fixes));
    }
    let walked = walked_model(&nrg);
    let (spaces, mut connections) = nrg.into_parts();
    for c in &mut connections {
        if fixes.without_geometry.contains(&c.key())
            && let Some(w) = walked.nrg.connection(c.a, c.b)
        {
            c.length_m = w.length_m;
        }
    }
    let nrg = Nrg::new(spaces, connections).map_err(|e| IndoorGmlError::Model(e.to_string()))?;
    Ok((nrg, fixes))
}

/// A model as the text of `format`, with walked connection lengths and
/// paths (see the module docs): what `nrgdb export`, `nrgdb convert`,
/// `nrgdb extract` and the server's export endpoints write.
pub fn render_model(nrg: &Nrg, format: ModelFormat) -> String {
    render(&walked_model(nrg), format)
}

/// [`render_model`] for a model already walked (a cached revision's
/// navigation layer: [`WalkedModel::on`]).
pub fn render(walked: &WalkedModel, format: ModelFormat) -> String {
    let nrg = &walked.nrg;
    match format {
        ModelFormat::IndoorGml => {
            indoorgml::write_string(&indoorgml::from_nrg_with_paths(nrg, &walked.paths))
        }
        ModelFormat::Json => nrg.to_json() + "\n",
        ModelFormat::GeoJson => {
            serde_json::to_string_pretty(&crate::geojson::to_geojson_with_paths(nrg, &walked.paths))
                .unwrap_or_default()
                + "\n"
        }
    }
}

/// Writes a model atomically in the format its extension names, with
/// walked connection lengths and paths ([`render_model`]).
pub fn write_model(nrg: &Nrg, path: &Path) -> Result<(), FormatError> {
    let text = render_model(nrg, ModelFormat::of(path)?);
    crate::atomic::write(path, text.as_bytes()).map_err(|source| FormatError::Io {
        path: path.to_path_buf(),
        source,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transitions_without_weight_or_line_get_the_walked_length() {
        let nrg = crate::fixtures::corridor_building(3);
        let mut doc = indoorgml::from_nrg(&nrg);
        let layers = doc.graph.iter_mut().flat_map(|g| &mut g.layer_groups);
        for l in layers.flat_map(|g| &mut g.layers) {
            for t in &mut l.transitions {
                t.weight = None;
                t.geometry = None;
            }
        }
        let (back, fixes) = from_document(&doc).unwrap();
        let walked = walked_model(&nrg).nrg;
        let navigable = walked
            .connections()
            .iter()
            .filter(|c| c.kind.is_navigable());
        assert_eq!(fixes.without_geometry.len(), navigable.count());
        assert_eq!(fixes.from_geometry, 0);
        assert_eq!(back.connections(), walked.connections());
    }
}
