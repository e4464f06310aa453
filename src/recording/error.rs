//! Why a recording could not be read.

use std::path::PathBuf;

use super::cdr::CdrError;

/// Why a recording could not be read. Each names the file, and the
/// message where one is at fault.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RecordingError {
    /// The file or folder could not be opened or read.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// Not a recording nrgdb reads.
    #[error(
        "{path}: not a ROS 2 recording (give an .mcap file, a .db3 bag, or a bag folder with metadata.yaml)"
    )]
    NotARecording {
        /// The path.
        path: PathBuf,
    },
    /// The MCAP file is corrupt or truncated.
    #[error("{path}: {source} (is the recording complete? nothing was stored)")]
    Mcap {
        /// The file.
        path: PathBuf,
        /// What the MCAP reader found.
        source: mcap::McapError,
    },
    /// The SQLite bag could not be read.
    #[error("{path}: cannot read the bag: {source} (nothing was stored)")]
    Db3 {
        /// The file.
        path: PathBuf,
        /// The SQLite error.
        source: rusqlite::Error,
    },
    /// The bag folder's `metadata.yaml` is unusable.
    #[error("{path}: {reason}")]
    Metadata {
        /// The metadata file.
        path: PathBuf,
        /// What is wrong.
        reason: String,
    },
    /// No message on the topic.
    #[error("{path}: no messages on {topic}; the recording has {}", topics_list(.topics))]
    NoTopic {
        /// The recording.
        path: PathBuf,
        /// The topic asked for.
        topic: String,
        /// The topics it has.
        topics: Vec<String>,
    },
    /// The topic carries something else than occupancy grids.
    #[error("{path}: {topic} carries {found}, not nav_msgs/msg/OccupancyGrid in CDR")]
    WrongType {
        /// The recording.
        path: PathBuf,
        /// The topic.
        topic: String,
        /// Its schema (or type) and encoding.
        found: String,
    },
    /// A message on the topic could not be decoded.
    #[error("{path}: map message {index} on {topic} (at {time}): {source}")]
    Message {
        /// The recording.
        path: PathBuf,
        /// The topic.
        topic: String,
        /// Its number among the topic's messages, from 1.
        index: usize,
        /// Its log time (RFC 3339).
        time: String,
        /// What is wrong.
        source: Box<CdrError>,
    },
    /// An option is out of range.
    #[error("{name}: {reason}")]
    Option {
        /// The option.
        name: &'static str,
        /// What is wrong.
        reason: String,
    },
}

fn topics_list(topics: &[String]) -> String {
    if topics.is_empty() {
        "no messages at all".into()
    } else {
        format!("topics {}", topics.join(", "))
    }
}
