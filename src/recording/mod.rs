//! ROS 2 recordings in: the maps a robot published on `/map`
//! (`nav_msgs/msg/OccupancyGrid`) in a rosbag2 recording — an MCAP file
//! (the default storage since ROS 2 Iron), a SQLite `.db3` bag, or a bag
//! folder with its `metadata.yaml` — read as occupancy grids.
//!
//! Reading is two passes over the recording, each holding one message at
//! a time: [`scan`] reads every file to its end (a corrupt or truncated
//! recording is an error before anything is stored), decodes every map
//! message's fields, hashes it and [`choose`]s which maps become
//! revisions; [`read_chosen`] reads again and hands out the chosen maps
//! as grids, classified with the map saver's thresholds ([`Thresholds`])
//! in the message's frame. Storing them is `ingest::import_recording`'s;
//! this module knows nothing of the store.
//!
//! Uses `mcap`, `rusqlite` (bags) and grid; must not use extract or
//! anything above.

mod cdr;
mod error;
mod select;
mod source;

use std::time::{Duration, UNIX_EPOCH};

pub use cdr::{CdrError, DEFAULT_MAX_CELLS, GridMessage, Thresholds};
pub use error::RecordingError;
pub use select::{Choice, Seen, choose};
pub use source::{OCCUPANCY_GRID, RawMessage, Recording};

use crate::grid::OccupancyGrid;

/// How a recording is read.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordingOptions {
    /// The topic of the maps (default `/map`).
    pub topic: String,
    /// Keep at most one map per this much recording time (the last of
    /// each interval); `None` keeps every map that changed.
    pub every: Option<Duration>,
    /// Cell classification.
    pub thresholds: Thresholds,
    /// Most cells a map message may have (default 64 Mi).
    pub max_cells: u64,
    /// Largest MCAP record or chunk read, bytes (default 256 MiB): bounds
    /// memory whatever the file says.
    pub max_record_bytes: usize,
}

impl Default for RecordingOptions {
    fn default() -> RecordingOptions {
        RecordingOptions {
            topic: "/map".into(),
            every: None,
            thresholds: Thresholds::default(),
            max_cells: DEFAULT_MAX_CELLS,
            max_record_bytes: 256 << 20,
        }
    }
}

/// What [`scan`] found.
#[derive(Debug, Clone, PartialEq)]
pub struct Scan {
    /// Every map message on the topic, in order.
    pub seen: Vec<Seen>,
    /// Which become revisions.
    pub choice: Choice,
    /// Bytes of recording read.
    pub bytes_read: u64,
}

/// A log time as RFC 3339 UTC with milliseconds.
pub fn log_time(ns: u64) -> String {
    humantime::format_rfc3339_millis(UNIX_EPOCH + Duration::from_nanos(ns)).to_string()
}

/// SHA-256 of a map message's map: frame, resolution, size, origin and
/// cells — not its stamps, which change each time a robot publishes the
/// same map again.
fn map_sha256(m: &GridMessage<'_>) -> String {
    use sha2::Digest;
    let mut h = sha2::Sha256::new();
    h.update(m.frame_id.as_bytes());
    h.update([0]);
    h.update(m.resolution.to_le_bytes());
    h.update(m.width.to_le_bytes());
    h.update(m.height.to_le_bytes());
    for v in m.origin {
        h.update(v.to_le_bytes());
    }
    h.update(m.data);
    h.finalize().iter().map(|b| format!("{b:02x}")).collect()
}

/// First pass: reads the whole recording, decodes and hashes every map
/// message on the topic, and chooses the maps to store.
pub fn scan(recording: &Recording, options: &RecordingOptions) -> Result<Scan, RecordingError> {
    let every_ns = match options.every {
        Some(d) if d.is_zero() => {
            return Err(RecordingError::Option {
                name: "--every",
                reason: "must be longer than 0 s".into(),
            });
        }
        Some(d) => Some(u64::try_from(d.as_nanos()).unwrap_or(u64::MAX)),
        None => None,
    };
    let mut seen = Vec::new();
    let bytes_read = recording.for_each(&options.topic, options.max_record_bytes, &mut |m| {
        let index = seen.len() + 1;
        let grid = GridMessage::parse(m.data, options.max_cells)
            .map_err(|source| message_error(recording, options, index, m.log_time_ns, source))?;
        seen.push(Seen {
            index,
            log_time_ns: m.log_time_ns,
            sha256: map_sha256(&grid),
            size: (grid.width, grid.height),
        });
        Ok::<(), RecordingError>(())
    })?;
    let choice = choose(&seen, every_ns);
    Ok(Scan {
        seen,
        choice,
        bytes_read,
    })
}

fn message_error(
    recording: &Recording,
    options: &RecordingOptions,
    index: usize,
    time_ns: u64,
    source: CdrError,
) -> RecordingError {
    RecordingError::Message {
        path: recording.path.clone(),
        topic: options.topic.clone(),
        index,
        time: log_time(time_ns),
        source: Box::new(source),
    }
}

/// Second pass: calls `f` with each chosen map of `scan` as a grid, in
/// order. The recording must be the one scanned: a message whose hash
/// changed meanwhile is an error.
pub fn read_chosen<E: From<RecordingError>>(
    recording: &Recording,
    options: &RecordingOptions,
    scan: &Scan,
    mut f: impl FnMut(&Seen, OccupancyGrid) -> Result<(), E>,
) -> Result<(), E> {
    let mut next = 0;
    let mut index = 0;
    recording.for_each(&options.topic, options.max_record_bytes, &mut |m| {
        index += 1;
        let Some(seen) = scan.choice.chosen.get(next).and_then(|p| scan.seen.get(*p)) else {
            return Ok(());
        };
        if seen.index != index {
            return Ok(());
        }
        next += 1;
        let changed = || {
            E::from(RecordingError::Metadata {
                path: recording.path.clone(),
                reason: format!(
                    "map message {index} changed while it was read (is the recording still being written?)"
                ),
            })
        };
        let message = GridMessage::parse(m.data, options.max_cells)
            .map_err(|source| message_error(recording, options, index, m.log_time_ns, source))?;
        if map_sha256(&message) != seen.sha256 {
            return Err(changed());
        }
        f(seen, message.to_grid(&options.thresholds))
    })?;
    Ok(())
}
