//! Bytes in, a model out: a map YAML and its image (extracted), or one
//! IndoorGML, model JSON or GeoJSON file, each told by
//! [`format::detect`](crate::format::detect). Everything is read and
//! checked here, before anything is stored.

use std::path::Path;

use crate::extract::{ExtractParams, extract};
use crate::format::{self, Declared, FileKind, ModelFormat};
use crate::grid::{LoadOptions, MapYaml, OccupancyGrid, load_map_bytes};
use crate::indoorgml::{DEFAULT_MAX_BYTES, Finding, WeightFixes};
use crate::model::{Georef, Nrg, Repair};
use crate::store::{ImportMeta, sha256_hex_of};

use super::{IngestError, validate};

/// One file handed to [`read`]: its bytes and what is said about it.
#[derive(Debug, Clone, Copy)]
pub struct InputFile<'a> {
    /// Its name, media type or form field, as far as known.
    pub declared: Declared<'a>,
    /// The bytes.
    pub bytes: &'a [u8],
}

impl<'a> InputFile<'a> {
    /// A file known by its name (or path).
    pub fn named(name: &'a str, bytes: &'a [u8]) -> InputFile<'a> {
        InputFile {
            declared: Declared::name(name),
            bytes,
        }
    }

    fn label(&self) -> &'a str {
        self.declared.label()
    }
}

/// How inputs are read.
#[derive(Debug, Clone, PartialEq)]
pub struct IngestOptions {
    /// How map images are read and classified (the pixel limit).
    pub load: LoadOptions,
    /// How maps are extracted.
    pub params: ExtractParams,
    /// Largest file [`read_path`] reads, in bytes (default 1 GiB).
    pub max_bytes: u64,
    /// Keep a model that stays geometrically invalid after repair
    /// instead of refusing it (see [`validate`]; default false).
    pub allow_invalid: bool,
    /// The georeference of the map the model goes to, when it has one: a
    /// model file in a CRS is read into its frame (default none: the
    /// frame the file carries, or one made at its corner).
    pub frame: Option<Georef>,
}

impl Default for IngestOptions {
    fn default() -> IngestOptions {
        IngestOptions {
            load: LoadOptions::default(),
            params: ExtractParams::default(),
            max_bytes: DEFAULT_MAX_BYTES,
            allow_invalid: false,
            frame: None,
        }
    }
}

/// A model read and checked, ready to store, with where it came from.
#[derive(Debug, Clone, PartialEq)]
pub struct Prepared {
    /// The model.
    pub nrg: Nrg,
    /// The occupancy grid, when the model was extracted from a map (kept
    /// with the revision).
    pub grid: Option<OccupancyGrid>,
    /// The extraction parameters, when the model was extracted.
    pub params: Option<ExtractParams>,
    /// IndoorGML Transitions whose missing or 0 weight was fixed.
    pub weights_fixed: WeightFixes,
    /// Geometry repaired on the way in (see [`validate`]).
    pub repairs: Vec<Repair>,
    /// Check findings kept because `allow_invalid` was set.
    pub kept: Vec<Finding>,
    /// The georeference that placed a model file in a CRS (see
    /// [`format::ModelRead::georef`]); stored with the map when it has
    /// none ([`crate::ingest::ingest_prepared`]).
    pub georef: Option<Georef>,
    /// The source's file names (`floor.yaml + floor.pgm` for a map).
    pub source_name: String,
    /// SHA-256 of the source's bytes (a map's YAML, then its image).
    pub source_sha256: String,
}

impl Prepared {
    /// The revision's meta data: `message`, `author`, the source and, for
    /// an extracted map, the parameters.
    pub fn meta(&self, message: impl Into<String>, author: impl Into<String>) -> ImportMeta {
        let mut meta = ImportMeta::new(message, author);
        meta.source_name = Some(self.source_name.clone());
        meta.source_sha256 = Some(self.source_sha256.clone());
        meta.params = self
            .params
            .as_ref()
            .and_then(|p| serde_json::to_value(p).ok());
        meta
    }
}

/// Reads a model from files in memory: a map YAML and its image
/// (extracted with `options.params`), or one model file. Each file's
/// format is told by [`format::detect`]; anything else (an image without
/// its YAML, two models, a map and a model) is an error naming the files.
/// The model passes the geometric gate ([`validate`]): repaired where
/// that keeps its meaning, refused when still invalid (unless
/// `options.allow_invalid`).
///
/// ```
/// use nrgdb::ingest::{IngestOptions, InputFile, read};
/// let nrg = nrgdb::fixtures::corridor_building(2);
/// let json = nrg.to_json();
/// let got = read(&[InputFile::named("lab.json", json.as_bytes())], &IngestOptions::default())?;
/// assert_eq!(got.nrg, nrg);
/// assert_eq!(got.source_name, "lab.json");
/// assert!(read(&[], &IngestOptions::default()).is_err());
/// # Ok::<(), nrgdb::ingest::IngestError>(())
/// ```
pub fn read(files: &[InputFile<'_>], options: &IngestOptions) -> Result<Prepared, IngestError> {
    let mut yaml: Option<&InputFile<'_>> = None;
    let mut image: Option<&InputFile<'_>> = None;
    let mut model: Option<(ModelFormat, &InputFile<'_>)> = None;
    for file in files {
        let (slot, what) = match format::detect(&file.declared, file.bytes)? {
            FileKind::MapYaml => (&mut yaml, "map YAML"),
            FileKind::Image(_) => (&mut image, "image"),
            FileKind::Recording(_) => {
                return Err(IngestError::Recording {
                    path: file.label().into(),
                });
            }
            FileKind::Building => {
                return Err(IngestError::ManifestNotFromDisk {
                    path: file.label().into(),
                });
            }
            FileKind::Model(f) => {
                if let Some((_, first)) = model.replace((f, file)) {
                    return Err(twice("model file", first, file));
                }
                continue;
            }
        };
        if let Some(first) = slot.replace(file) {
            return Err(twice(what, first, file));
        }
    }
    match (yaml, image, model) {
        (Some(y), Some(i), None) => read_map(y, i, options),
        (None, None, Some((format, f))) => read_model(f, format, options),
        (Some(y), None, None) => Err(IngestError::MapWithoutImage {
            yaml: y.label().into(),
        }),
        (None, Some(i), None) => Err(IngestError::ImageWithoutMap {
            image: i.label().into(),
        }),
        (None, None, None) => Err(IngestError::Nothing),
        (y, i, Some((_, m))) => Err(IngestError::MapAndModel {
            map: y.or(i).map_or("map", |f| f.label()).into(),
            model: m.label().into(),
        }),
    }
}

/// Reads a model from a file: a map YAML (with the image it names,
/// extracted) or a model file, each at most `options.max_bytes`; the same
/// as [`read`] on the files' bytes.
pub fn read_path(path: &Path, options: &IngestOptions) -> Result<Prepared, IngestError> {
    tracing::info!(path = %path.display(), "reading");
    let bytes = format::read_bytes(path, options.max_bytes)?;
    let name = path.to_string_lossy();
    let file = InputFile::named(&name, &bytes);
    match format::detect(&file.declared, &bytes)? {
        FileKind::Model(format) => read_model(&file, format, options),
        FileKind::Image(_) => Err(IngestError::ImageWithoutMap { image: path.into() }),
        FileKind::Recording(_) => Err(IngestError::Recording { path: path.into() }),
        FileKind::Building => super::building::read_building(path, options),
        FileKind::MapYaml => {
            let text = format::utf8_text(&bytes, path, FileKind::MapYaml)?;
            let image_path = MapYaml::parse(text, path)?.image;
            let image = format::read_bytes(&image_path, options.max_bytes).map_err(|source| {
                IngestError::Image {
                    yaml: path.into(),
                    source: Box::new(source),
                }
            })?;
            let image_name = image_path.to_string_lossy();
            read_map(&file, &InputFile::named(&image_name, &image), options)
        }
    }
}

fn twice(what: &'static str, first: &InputFile<'_>, second: &InputFile<'_>) -> IngestError {
    IngestError::Twice {
        what,
        first: first.label().into(),
        second: second.label().into(),
    }
}

/// The last part of a label that is a path ("maps/a.yaml" → "a.yaml").
fn file_name(label: &str) -> &str {
    Path::new(label)
        .file_name()
        .and_then(|n| n.to_str())
        .unwrap_or(label)
}

fn read_map(
    yaml: &InputFile<'_>,
    image: &InputFile<'_>,
    options: &IngestOptions,
) -> Result<Prepared, IngestError> {
    let yaml_name = Path::new(yaml.label());
    let grid = load_map_bytes(
        yaml_name,
        yaml.bytes,
        Path::new(image.label()),
        image.bytes,
        &options.load,
    )?;
    from_grid(
        grid,
        yaml.label(),
        format!("{} + {}", file_name(yaml.label()), file_name(image.label())),
        sha256_hex_of(&[yaml.bytes, image.bytes]),
        options,
    )
}

/// A model extracted from `grid` (read from `label`) with
/// `options.params`, through the geometric gate: the one way from a grid
/// to a stored model, for map files and for recordings' maps.
pub(crate) fn from_grid(
    grid: OccupancyGrid,
    label: &str,
    source_name: String,
    source_sha256: String,
    options: &IngestOptions,
) -> Result<Prepared, IngestError> {
    let extraction = extract(&grid, &options.params).map_err(|source| IngestError::Extract {
        path: label.into(),
        source,
    })?;
    let valid = validate(extraction.nrg, label, options.allow_invalid)?;
    Ok(Prepared {
        nrg: valid.nrg,
        grid: Some(grid),
        params: Some(options.params.clone()),
        weights_fixed: WeightFixes::default(),
        repairs: valid.repairs,
        kept: valid.kept,
        georef: None,
        source_name,
        source_sha256,
    })
}

fn read_model(
    file: &InputFile<'_>,
    format: ModelFormat,
    options: &IngestOptions,
) -> Result<Prepared, IngestError> {
    let read = format::model_from_bytes_in(
        file.bytes,
        format,
        Path::new(file.label()),
        options.frame.as_ref(),
    )?;
    let valid = validate(read.nrg, file.label(), options.allow_invalid)?;
    Ok(Prepared {
        nrg: valid.nrg,
        grid: None,
        params: None,
        weights_fixed: read.weights_fixed,
        repairs: valid.repairs,
        kept: valid.kept,
        georef: read.georef,
        source_name: file_name(file.label()).to_string(),
        source_sha256: sha256_hex_of(&[file.bytes]),
    })
}
