//! File formats: the one place that decides what a file is ([`detect`]:
//! by its name or declared media type and by its first bytes; see
//! `format/detect.rs` for the rules), and the model formats, IndoorGML
//! (`.gml`, `.xml`), the model's JSON form (`.json`), GeoJSON
//! (`.geojson`) and the IndoorGML 2.0 draft's IndoorJSON2
//! (`.indoor.json`), read from bytes or files and written by extension, for
//! the CLI, the ingest of files and uploads, and the server.
//!
//! Every model written goes through [`render`]: connection lengths are the
//! walked lengths and IndoorGML Transitions and GeoJSON connection lines
//! are the walked paths through the doorways ([`walked_model`]). Reading
//! IndoorGML fixes Transitions with a missing or 0 weight ([`from_document`]).
//! Uses indoorgml, geojson and route; sits above them.

mod detect;
mod frame;
pub mod nav2;
pub mod osm;

use std::io::Read;
use std::path::{Path, PathBuf};

pub use detect::{Declared, FileKind, ImageFormat, RecordingFormat, detect};
pub use frame::{Frame, FrameError, frame_for, render_in};

use crate::indoorgml::{self, Document, IndoorGmlError, IndoorGmlVersion, WeightFixes};
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
    /// IndoorJSON2, the JSON encoding of the IndoorGML 2.0 draft
    /// (`indoorgml::json2`; a draft, not a standard).
    IndoorJson,
}

/// Why a model file could not be read or written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum FormatError {
    /// The extension names no known format.
    #[error(
        "{0}: unknown format; use .gml or .xml (IndoorGML), .json (model JSON), .geojson (GeoJSON) or .indoor.json (IndoorJSON2, IndoorGML 2.0 draft)"
    )]
    UnknownExtension(PathBuf),
    /// Neither the name, the media type nor the bytes tell the format.
    #[error(
        "{path}: cannot tell the format: give a .yaml map (with its .pgm or .png image), .gml or .xml (IndoorGML), .json (model JSON) or .geojson (GeoJSON)"
    )]
    Unrecognised {
        /// The file.
        path: PathBuf,
    },
    /// What was said about the file and its bytes disagree.
    #[error("{path}: {said} but its content is {found} (rename the file or send the right one)")]
    Conflict {
        /// The file.
        path: PathBuf,
        /// What its name or media type says ("its name says model JSON").
        said: String,
        /// What its bytes are.
        found: String,
    },
    /// A model was expected and the file is something else.
    #[error(
        "{path}: this is {kind}, not a model file (.gml, .xml, .json or .geojson); a map is extracted, not read as a model"
    )]
    NotAModel {
        /// The file.
        path: PathBuf,
        /// What it is.
        kind: FileKind,
    },
    /// The file is larger than the limit.
    #[error(
        "{path}: {size} bytes, above the limit of {limit} bytes (raise the limit if the file is genuine)"
    )]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Its size.
        size: u64,
        /// The limit.
        limit: u64,
    },
    /// A text format's bytes are not UTF-8.
    #[error("{path}: line {line}: not UTF-8 text ({kind} is UTF-8 text)")]
    NotUtf8 {
        /// The file.
        path: PathBuf,
        /// The line of the first invalid byte.
        line: usize,
        /// The format expected.
        kind: FileKind,
    },
    /// The extension names no picture format.
    #[error("{0}: unknown picture format (use a .png or .svg file name)")]
    UnknownPicture(PathBuf),
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
    /// The format a path's extension names: how a model is written (an
    /// output has no bytes to look at yet). Reading uses [`detect`].
    pub fn of(path: &Path) -> Result<ModelFormat, FormatError> {
        match FileKind::by_extension(&path.to_string_lossy()) {
            Some(FileKind::Model(format)) => Ok(format),
            _ => Err(FormatError::UnknownExtension(path.to_path_buf())),
        }
    }
}

/// A picture format nrgdb draws in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PictureFormat {
    /// PNG (tiny-skia, feature `render`).
    Png,
    /// SVG.
    Svg,
}

impl PictureFormat {
    /// The format a file's extension names.
    ///
    /// ```
    /// use nrgdb::format::PictureFormat;
    /// assert_eq!(PictureFormat::of("out/A.SVG".as_ref()).ok(), Some(PictureFormat::Svg));
    /// assert!(PictureFormat::of("a.jpg".as_ref()).is_err());
    /// ```
    pub fn of(path: &Path) -> Result<PictureFormat, FormatError> {
        let ext = path.extension().and_then(|e| e.to_str());
        match ext.map(str::to_ascii_lowercase).as_deref() {
            Some("png") => Ok(PictureFormat::Png),
            Some("svg") => Ok(PictureFormat::Svg),
            _ => Err(FormatError::UnknownPicture(path.to_path_buf())),
        }
    }
}

/// The bytes of a file of at most `max_bytes` bytes (a larger file is
/// refused before it is read).
pub fn read_bytes(path: &Path, max_bytes: u64) -> Result<Vec<u8>, FormatError> {
    let io = |source| FormatError::Io {
        path: path.to_path_buf(),
        source,
    };
    let file = std::fs::File::open(path).map_err(io)?;
    let size = file.metadata().map_err(io)?.len();
    let too_large = |size| FormatError::TooLarge {
        path: path.to_path_buf(),
        size,
        limit: max_bytes,
    };
    if size > max_bytes {
        return Err(too_large(size));
    }
    let mut bytes = Vec::with_capacity(usize::try_from(size).unwrap_or(0));
    // A file growing while read is cut at the limit and refused.
    file.take(max_bytes.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > max_bytes {
        return Err(too_large(bytes.len() as u64));
    }
    Ok(bytes)
}

/// The bytes as UTF-8 text of `kind`; the error names the file and the
/// line of the first invalid byte.
pub fn utf8_text<'a>(bytes: &'a [u8], path: &Path, kind: FileKind) -> Result<&'a str, FormatError> {
    std::str::from_utf8(bytes).map_err(|e| {
        let valid = bytes.get(..e.valid_up_to()).unwrap_or_default();
        FormatError::NotUtf8 {
            path: path.to_path_buf(),
            line: 1 + valid.iter().filter(|&&c| c == b'\n').count(),
            kind,
        }
    })
}

/// Reads a model file, its format told by [`detect`] (name and bytes).
pub fn read_model(path: &Path, max_bytes: u64) -> Result<Nrg, FormatError> {
    read_model_fixing(path, max_bytes).map(|(nrg, _)| nrg)
}

/// Reads a model file, its format told by [`detect`], with the IndoorGML
/// Transition weights it had to fix (none for other formats).
pub fn read_model_fixing(path: &Path, max_bytes: u64) -> Result<(Nrg, WeightFixes), FormatError> {
    let bytes = read_bytes(path, max_bytes)?;
    let format = detect_model(&Declared::name(&path.to_string_lossy()), &bytes)?;
    model_from_bytes(&bytes, format, path)
}

/// [`detect`] for a place that takes a model only: anything else (a map
/// YAML, an image) is an error naming the file.
pub fn detect_model(declared: &Declared<'_>, bytes: &[u8]) -> Result<ModelFormat, FormatError> {
    match detect(declared, bytes)? {
        FileKind::Model(format) => Ok(format),
        kind => Err(FormatError::NotAModel {
            path: PathBuf::from(declared.label()),
            kind,
        }),
    }
}

/// A model from the bytes of a file in `format` (`path` names it in
/// errors), with the IndoorGML Transition weights that had to be fixed.
/// A file in a CRS is read into the frame it carries or one made at its
/// corner (see [`model_from_bytes_in`]).
pub fn model_from_bytes(
    bytes: &[u8],
    format: ModelFormat,
    path: &Path,
) -> Result<(Nrg, WeightFixes), FormatError> {
    let read = model_from_bytes_in(bytes, format, path, None)?;
    Ok((read.nrg, read.weights_fixed))
}

/// A model read from a file by [`model_from_bytes_in`].
#[derive(Debug, Clone, PartialEq)]
pub struct ModelRead {
    /// The model, in map-frame metres.
    pub nrg: Nrg,
    /// IndoorGML Transitions whose missing or 0 weight was fixed.
    pub weights_fixed: WeightFixes,
    /// The georeference that placed the file's positions, when the file
    /// was in a CRS (GeoJSON in WGS84 or UTM, IndoorGML with a UTM
    /// `srsName`; see [`crate::model::NamedCrs::frame`]).
    pub georef: Option<crate::model::Georef>,
}

/// [`model_from_bytes`] into the frame of the map the model goes to: a
/// file in a CRS is read into `stored` (the map's georeference) when
/// given, so every revision shares one frame.
pub fn model_from_bytes_in(
    bytes: &[u8],
    format: ModelFormat,
    path: &Path,
    stored: Option<&crate::model::Georef>,
) -> Result<ModelRead, FormatError> {
    let text = utf8_text(bytes, path, FileKind::Model(format))?;
    let gml = |source| FormatError::IndoorGml {
        path: path.to_path_buf(),
        source,
    };
    let json = |message: String| FormatError::Json {
        path: path.to_path_buf(),
        message,
    };
    let (nrg, georef) = match format {
        ModelFormat::IndoorGml => {
            let mut doc = indoorgml::read_str(text).map_err(gml)?;
            let georef = indoorgml::placed::into_map_frame(&mut doc, stored).map_err(gml)?;
            let (nrg, weights_fixed) = from_document(&doc).map_err(gml)?;
            return Ok(ModelRead {
                nrg,
                weights_fixed,
                georef,
            });
        }
        ModelFormat::Json => (Nrg::from_json(text).map_err(|e| json(e.to_string()))?, None),
        ModelFormat::GeoJson => {
            crate::geojson::from_geojson_in(text, stored).map_err(|e| json(e.to_string()))?
        }
        ModelFormat::IndoorJson => (
            indoorgml::json2::read_str(text).map_err(|e| json(format!("IndoorJSON2: {e}")))?,
            None,
        ),
    };
    Ok(ModelRead {
        nrg,
        weights_fixed: WeightFixes::default(),
        georef,
    })
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
    render_as(walked, format, IndoorGmlVersion::default())
}

/// [`render`], IndoorGML written as `version` (other formats have one).
pub fn render_as(walked: &WalkedModel, format: ModelFormat, version: IndoorGmlVersion) -> String {
    let nrg = &walked.nrg;
    match format {
        ModelFormat::IndoorGml => {
            indoorgml::write_string_as(&indoorgml::from_nrg_with_paths(nrg, &walked.paths), version)
        }
        ModelFormat::IndoorJson => indoorgml::json2::write_string(nrg, &walked.paths),
        ModelFormat::Json => nrg.to_json() + "\n",
        ModelFormat::GeoJson => {
            serde_json::to_string_pretty(&crate::geojson::to_geojson_with_paths(nrg, &walked.paths))
                .unwrap_or_default()
                + "\n"
        }
    }
}

/// GeoJSON of a walked model in WGS84, placed by `georef` (RFC 7946; see
/// [`crate::geojson::to_wgs84`]).
pub fn render_geojson_wgs84(walked: &WalkedModel, georef: &crate::model::Georef) -> String {
    let doc = crate::geojson::to_geojson_with_paths(&walked.nrg, &walked.paths);
    serde_json::to_string_pretty(&crate::geojson::to_wgs84(doc, georef)).unwrap_or_default() + "\n"
}

/// GeoJSON of a walked model in the WGS84 / UTM zone of `georef`'s
/// origin, the CRS named (see [`crate::geojson::to_utm`]).
pub fn render_geojson_utm(walked: &WalkedModel, georef: &crate::model::Georef) -> String {
    let doc = crate::geojson::to_geojson_with_paths(&walked.nrg, &walked.paths);
    serde_json::to_string_pretty(&crate::geojson::to_utm(doc, georef)).unwrap_or_default() + "\n"
}

fn write_text(path: &Path, text: &str) -> Result<(), FormatError> {
    crate::atomic::write(path, text.as_bytes()).map_err(|source| FormatError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// Writes a model atomically in the format its extension names, with
/// walked connection lengths and paths ([`render_model`]).
pub fn write_model(nrg: &Nrg, path: &Path) -> Result<(), FormatError> {
    write_model_as(nrg, path, IndoorGmlVersion::default())
}

/// [`write_model`], IndoorGML written as `version`.
pub fn write_model_as(
    nrg: &Nrg,
    path: &Path,
    version: IndoorGmlVersion,
) -> Result<(), FormatError> {
    write_text(
        path,
        &render_as(&walked_model(nrg), ModelFormat::of(path)?, version),
    )
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
