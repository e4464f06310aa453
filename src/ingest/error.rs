//! Why files or an upload could not be turned into a model.

use std::path::PathBuf;

use crate::extract::ExtractError;
use crate::format::FormatError;
use crate::grid::GridError;

/// Why [`read`](super::read) or [`read_path`](super::read_path) failed.
/// Every message names the file or the part.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum IngestError {
    /// A file's format could not be told, or a model could not be read.
    #[error(transparent)]
    Format(#[from] FormatError),
    /// A map YAML or its image is not a valid map.
    #[error(transparent)]
    Grid(#[from] GridError),
    /// The image a map YAML names could not be read.
    #[error("{yaml}: cannot read its image: {source}")]
    Image {
        /// The map YAML.
        yaml: PathBuf,
        /// The cause, naming the image.
        source: Box<FormatError>,
    },
    /// The map could not be extracted.
    #[error("{path}: extraction failed: {source}")]
    Extract {
        /// The map YAML.
        path: PathBuf,
        /// The cause.
        source: ExtractError,
    },
    /// A map YAML came without an image.
    #[error("{yaml}: a map YAML needs its image (a PGM or PNG file)")]
    MapWithoutImage {
        /// The map YAML.
        yaml: PathBuf,
    },
    /// An image came without its map YAML.
    #[error("{image}: an image needs its map YAML (resolution and origin); give the .yaml instead")]
    ImageWithoutMap {
        /// The image.
        image: PathBuf,
    },
    /// Two files of a kind there must be one of.
    #[error(
        "{first} and {second}: two {what}s; give one map YAML and its image, or one model file"
    )]
    Twice {
        /// "map YAML", "image" or "model file".
        what: &'static str,
        /// The first.
        first: PathBuf,
        /// The second.
        second: PathBuf,
    },
    /// A map and a model together.
    #[error("{map} and {model}: give either a map YAML and its image or one model file, not both")]
    MapAndModel {
        /// The map YAML or image.
        map: PathBuf,
        /// The model file.
        model: PathBuf,
    },
    /// No file at all.
    #[error("no file given (a map YAML and its PGM or PNG image, or one model file)")]
    Nothing,
}
