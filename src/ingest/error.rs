//! Why files or an upload could not be turned into a model.

use std::path::PathBuf;

use crate::extract::ExtractError;
use crate::format::FormatError;
use crate::grid::GridError;
use crate::indoorgml::Finding;

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
    /// A building manifest that cannot be used.
    #[error("{path}: line {line}: {message}")]
    Manifest {
        /// The manifest.
        path: PathBuf,
        /// The line of the entry concerned (1-based).
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// A building manifest given as bytes: its maps are files beside it.
    #[error(
        "{path}: a building manifest names map files beside it; import it from disk (`nrgdb import building.toml --map NAME`)"
    )]
    ManifestNotFromDisk {
        /// The manifest.
        path: PathBuf,
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
    /// A ROS 2 recording where one model was expected.
    #[error(
        "{path}: a ROS 2 recording holds maps over time, not one model; import it with `nrgdb import {path} --map NAME` (one revision per map that changed)"
    )]
    Recording {
        /// The recording.
        path: PathBuf,
    },
    /// No file at all.
    #[error("no file given (a map YAML and its PGM or PNG image, or one model file)")]
    Nothing,
    /// The model is geometrically invalid and the repairs that keep its
    /// meaning could not fix it (see [`validate`](super::validate)).
    #[error(
        "{source_name}: {} that `nrgdb check` reports {}{}: {}{}; \
         nrgdb does not store or write such a model (cells that overlap by more than a sliver \
         without one lying inside the other, e.g. several floors drawn on one plane, cannot be \
         repaired without guessing; --allow-invalid keeps the model as it is)",
        crate::wording::count(findings.len(), "geometric problem", "geometric problems"),
        if findings.len() == 1 { "remains" } else { "remain" },
        if *repaired > 0 { format!(" after {}", crate::wording::count(*repaired, "repair", "repairs")) } else { String::new() },
        first_findings(findings),
        if findings.len() > SHOWN { format!("; and {} more", findings.len() - SHOWN) } else { String::new() }
    )]
    Invalid {
        /// The file or upload the model came from.
        source_name: String,
        /// How many repairs were made before giving up.
        repaired: usize,
        /// What is still wrong.
        findings: Vec<Finding>,
    },
}

/// How many findings an [`IngestError::Invalid`] message lists.
const SHOWN: usize = 3;

fn first_findings(findings: &[Finding]) -> String {
    findings
        .iter()
        .take(SHOWN)
        .map(|f| format!("{} [{}]: {}", f.element, f.code, f.message))
        .collect::<Vec<_>>()
        .join("; ")
}
