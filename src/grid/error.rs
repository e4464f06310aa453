//! Errors raised while loading a map.

use std::path::PathBuf;

/// A map that cannot be loaded. Every message names the file and the field.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum GridError {
    /// The file cannot be read.
    #[error("{path}: cannot read the file: {source} (check the path)")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The image a map YAML names cannot be read.
    #[error(
        "{yaml}: cannot read its image {image}: {source} (`image:` is resolved against the \
         YAML's folder)"
    )]
    MapImage {
        /// The map YAML.
        yaml: PathBuf,
        /// The image path, resolved.
        image: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The YAML does not parse.
    #[error("{path}: invalid map yaml: {message}")]
    Yaml {
        /// The YAML file.
        path: PathBuf,
        /// What the parser said.
        message: String,
    },
    /// A required YAML field is missing.
    #[error(
        "{path}: field `{field}` is missing (a ROS map yaml needs image, resolution and origin)"
    )]
    MissingField {
        /// The YAML file.
        path: PathBuf,
        /// The missing field.
        field: &'static str,
    },
    /// A field has a value out of range.
    #[error("{path}: field `{field}` = {value} is out of range: {hint}")]
    BadField {
        /// The file.
        path: PathBuf,
        /// The field.
        field: &'static str,
        /// The value found.
        value: String,
        /// What is expected.
        hint: &'static str,
    },
    /// The image cannot be decoded (truncated, unsupported format).
    #[error("{path}: cannot decode the image: {message} (is it a complete pgm or png?)")]
    Image {
        /// The image file.
        path: PathBuf,
        /// What the decoder said.
        message: String,
    },
    /// The image is larger than the configured pixel limit.
    #[error(
        "{path}: image is {width}x{height} = {pixels} px, above the limit of {limit} px (raise the pixel limit if the map is genuine)"
    )]
    TooLarge {
        /// The image file.
        path: PathBuf,
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
        /// width × height.
        pixels: u64,
        /// The configured limit.
        limit: u64,
    },
    /// The map YAML is larger than a map YAML can sensibly be.
    #[error(
        "{path}: the map yaml is {size} bytes, above the limit of {limit} (is it a map_server yaml?)"
    )]
    YamlTooLarge {
        /// The YAML file.
        path: PathBuf,
        /// Its size.
        size: u64,
        /// The limit.
        limit: u64,
    },
    /// The resolution is so fine that one square metre exceeds the pixel
    /// limit.
    #[error(
        "{path}: field `resolution` = {resolution} m/px is too fine: one square metre would be {per_m2:.3e} px, above the limit of {limit} px (is the resolution in metres per pixel?)"
    )]
    ResolutionTooFine {
        /// The YAML file (or the bare image).
        path: PathBuf,
        /// The resolution, metres per pixel.
        resolution: f64,
        /// Pixels in one square metre at that resolution.
        per_m2: f64,
        /// The configured pixel limit.
        limit: u64,
    },
    /// The image size disagrees with what was expected.
    #[error(
        "{path}: image is {width}x{height} px but {expected_width}x{expected_height} px were expected ({what})"
    )]
    SizeMismatch {
        /// The image file.
        path: PathBuf,
        /// Actual width.
        width: u32,
        /// Actual height.
        height: u32,
        /// Expected width.
        expected_width: u32,
        /// Expected height.
        expected_height: u32,
        /// What the size was compared to.
        what: &'static str,
    },
    /// Every cell is unknown.
    #[error("{path}: every cell of the map is unknown (wrong negate or mode?)")]
    AllUnknown {
        /// The image file.
        path: PathBuf,
    },
    /// No cell is free.
    #[error(
        "{path}: the map has no free cell (free = grey >= {free_min_grey}; check negate or the free threshold)"
    )]
    NoFreeSpace {
        /// The image file.
        path: PathBuf,
        /// The free threshold used.
        free_min_grey: u8,
    },
}
