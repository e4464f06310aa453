//! Errors of the simulator, the log-odds mapper and the CARMEN reader.

use std::path::PathBuf;

use crate::model::ModelError;

/// Something the simulator or the mapper could not do.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SimError {
    /// A parameter is out of its valid range.
    #[error("parameter {name} must be {expected}, got {value} ({hint})")]
    BadParameter {
        /// The parameter, as the user spells it (e.g. `--resolution`).
        name: &'static str,
        /// The value given.
        value: String,
        /// What a valid value looks like.
        expected: &'static str,
        /// What to try instead.
        hint: &'static str,
    },
    /// A file could not be read or written.
    #[error("{path}: {source} (check that the path exists and is readable/writable)")]
    Io {
        /// The file concerned.
        path: PathBuf,
        /// The underlying error.
        #[source]
        source: std::io::Error,
    },
    /// A line of a CARMEN log is malformed.
    #[error(
        "{path}:{line}: {message} (expected `FLASER n r1 .. rn x y theta odom_x odom_y odom_theta timestamp host logger_timestamp`)"
    )]
    BadLogLine {
        /// The log file.
        path: PathBuf,
        /// 1-based line number.
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// A log holds no laser scans at all.
    #[error("{path}: no FLASER or ROBOTLASER1 lines found (is this a CARMEN log?)")]
    NoScans {
        /// The log file.
        path: PathBuf,
    },
    /// The map would be too large to hold in memory.
    #[error(
        "a map of {width_m:.1} m x {height_m:.1} m at {resolution} m/px is too large (more than {max_cells} cells); use a coarser --resolution"
    )]
    TooLarge {
        /// Extent in x, metres.
        width_m: f64,
        /// Extent in y, metres.
        height_m: f64,
        /// The requested resolution.
        resolution: f64,
        /// The cell limit.
        max_cells: usize,
    },
    /// An image could not be encoded.
    #[error("{path}: cannot encode image: {source}")]
    Image {
        /// The file concerned.
        path: PathBuf,
        /// The underlying error.
        #[source]
        source: image::ImageError,
    },
    /// The generated ground truth broke a model invariant (a simulator bug).
    #[error("generated ground truth is not a valid model: {0} (please report the seed)")]
    Model(#[from] ModelError),
}
