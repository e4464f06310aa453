//! Where a recording's messages come from: an MCAP file, a SQLite `.db3`
//! bag, or a rosbag2 folder whose `metadata.yaml` lists its files (MCAP
//! or SQLite). Messages of one topic are handed out one at a time, in
//! file order, with their log time; memory holds one MCAP chunk or one
//! SQLite row at a time.

use std::fs::File;
use std::io::{BufReader, Read};
use std::path::{Path, PathBuf};

use serde::Deserialize;

use super::RecordingError;
use crate::format::{Declared, FileKind, RecordingFormat, detect};

/// The ROS 2 type and encoding this reader decodes.
pub const OCCUPANCY_GRID: &str = "nav_msgs/msg/OccupancyGrid";

/// An opened recording: its files, each MCAP or SQLite.
#[derive(Debug, Clone, PartialEq)]
pub struct Recording {
    /// The path given (file or bag folder).
    pub path: PathBuf,
    /// Its files in order.
    pub files: Vec<(RecordingFormat, PathBuf)>,
}

/// One message of the topic read.
#[derive(Debug, Clone, Copy)]
pub struct RawMessage<'a> {
    /// Log time, nanoseconds since the epoch.
    pub log_time_ns: u64,
    /// The serialised message (CDR, encapsulation header included).
    pub data: &'a [u8],
}

/// A rosbag2 folder's `metadata.yaml`, the parts read.
#[derive(Debug, Deserialize)]
struct Metadata {
    rosbag2_bagfile_information: BagInfo,
}

#[derive(Debug, Deserialize)]
struct BagInfo {
    #[serde(default)]
    storage_identifier: String,
    #[serde(default)]
    relative_file_paths: Vec<String>,
    #[serde(default)]
    compression_mode: String,
    #[serde(default)]
    compression_format: String,
}

/// Largest `metadata.yaml` read.
const MAX_METADATA_BYTES: u64 = 4 << 20;

impl Recording {
    /// Opens `path`: an `.mcap` file, a `.db3` bag, or a bag folder.
    pub fn open(path: &Path) -> Result<Recording, RecordingError> {
        let io = |source| RecordingError::Io {
            path: path.into(),
            source,
        };
        if path.is_dir() {
            return Recording::open_folder(path);
        }
        let mut head = [0u8; 16];
        let mut file = File::open(path).map_err(io)?;
        let n = read_head(&mut file, &mut head).map_err(io)?;
        let name = path.to_string_lossy();
        match detect(&Declared::name(&name), &head[..n]) {
            Ok(FileKind::Recording(format)) => Ok(Recording {
                path: path.into(),
                files: vec![(format, path.into())],
            }),
            _ => Err(RecordingError::NotARecording { path: path.into() }),
        }
    }

    fn open_folder(dir: &Path) -> Result<Recording, RecordingError> {
        let meta_path = dir.join("metadata.yaml");
        let bad = |reason: String| RecordingError::Metadata {
            path: meta_path.clone(),
            reason,
        };
        let text = read_limited(&meta_path).map_err(|source| match source.kind() {
            std::io::ErrorKind::NotFound => RecordingError::NotARecording { path: dir.into() },
            _ => RecordingError::Io {
                path: meta_path.clone(),
                source,
            },
        })?;
        let meta: Metadata = serde_yaml_ng::from_str(&text)
            .map_err(|e| bad(format!("not a rosbag2 metadata file: {e}")))?;
        let info = meta.rosbag2_bagfile_information;
        if !info.compression_mode.is_empty() && !info.compression_mode.eq_ignore_ascii_case("none")
        {
            return Err(bad(format!(
                "the bag is compressed ({} {}); decompress it first (`ros2 bag convert`)",
                info.compression_mode, info.compression_format
            )));
        }
        let format = match info.storage_identifier.as_str() {
            "mcap" => RecordingFormat::Mcap,
            "sqlite3" => RecordingFormat::Db3,
            other => {
                return Err(bad(format!(
                    "storage '{other}' is not read (mcap or sqlite3)"
                )));
            }
        };
        if info.relative_file_paths.is_empty() {
            return Err(bad("relative_file_paths lists no files".into()));
        }
        let mut files = Vec::with_capacity(info.relative_file_paths.len());
        for rel in &info.relative_file_paths {
            let rel_path = Path::new(rel);
            // Files of a bag are inside its folder.
            if rel_path.is_absolute()
                || rel_path
                    .components()
                    .any(|c| matches!(c, std::path::Component::ParentDir))
            {
                return Err(bad(format!(
                    "{rel}: a bag's file must be inside its folder"
                )));
            }
            files.push((format, dir.join(rel_path)));
        }
        Ok(Recording {
            path: dir.into(),
            files,
        })
    }

    /// The recording's name: its file or folder name.
    pub fn name(&self) -> String {
        self.path.file_name().map_or_else(
            || self.path.display().to_string(),
            |n| n.to_string_lossy().into(),
        )
    }

    /// Calls `f` with every message on `topic`, in order, after checking
    /// that the topic carries OccupancyGrid in CDR; reads every file to
    /// its end, so a corrupt or truncated file is an error even after
    /// the topic's last message. Returns the bytes read.
    pub fn for_each<E: From<RecordingError>>(
        &self,
        topic: &str,
        max_record_bytes: usize,
        f: &mut dyn FnMut(RawMessage<'_>) -> Result<(), E>,
    ) -> Result<u64, E> {
        let mut seen = Vec::new();
        let mut found = false;
        let mut bytes = 0;
        for (format, path) in &self.files {
            bytes += match format {
                RecordingFormat::Mcap => {
                    mcap_messages(path, topic, max_record_bytes, &mut seen, &mut found, f)?
                }
                RecordingFormat::Db3 => db3_messages(path, topic, &mut seen, &mut found, f)?,
            };
        }
        if !found {
            seen.sort();
            seen.dedup();
            return Err(RecordingError::NoTopic {
                path: self.path.clone(),
                topic: topic.into(),
                topics: seen,
            }
            .into());
        }
        Ok(bytes)
    }
}

fn read_head(file: &mut File, head: &mut [u8]) -> std::io::Result<usize> {
    let mut n = 0;
    while n < head.len() {
        match file.read(&mut head[n..])? {
            0 => break,
            k => n += k,
        }
    }
    Ok(n)
}

fn read_limited(path: &Path) -> std::io::Result<String> {
    let mut text = String::new();
    File::open(path)?
        .take(MAX_METADATA_BYTES)
        .read_to_string(&mut text)?;
    Ok(text)
}

/// Counts the bytes read through it.
struct Counted<R> {
    inner: R,
    bytes: u64,
}

impl<R: Read> Read for Counted<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.bytes += n as u64;
        Ok(n)
    }
}

fn mcap_messages<E: From<RecordingError>>(
    path: &Path,
    topic: &str,
    max_record_bytes: usize,
    seen: &mut Vec<String>,
    found: &mut bool,
    f: &mut dyn FnMut(RawMessage<'_>) -> Result<(), E>,
) -> Result<u64, E> {
    let file = File::open(path).map_err(|source| RecordingError::Io {
        path: path.into(),
        source,
    })?;
    let mut counted = Counted {
        inner: BufReader::with_capacity(1 << 20, file),
        bytes: 0,
    };
    let options = mcap::sans_io::LinearReaderOptions::default()
        .with_validate_chunk_crcs(true)
        .with_record_length_limit(max_record_bytes);
    let reader = mcap::io::MessageReader::new_with_options(&mut counted, options);
    let mcap_error = |source| RecordingError::Mcap {
        path: path.into(),
        source,
    };
    let mut checked: Option<u16> = None;
    for message in reader {
        let message = message.map_err(mcap_error)?;
        let channel = &message.channel;
        if channel.topic != topic {
            if !seen.contains(&channel.topic) {
                seen.push(channel.topic.clone());
            }
            continue;
        }
        if checked != Some(channel.id) {
            let schema = channel.schema.as_ref().map(|s| s.name.as_str());
            if schema != Some(OCCUPANCY_GRID) || channel.message_encoding != "cdr" {
                return Err(E::from(RecordingError::WrongType {
                    path: path.into(),
                    topic: topic.into(),
                    found: format!(
                        "{} in {}",
                        schema.unwrap_or("messages without a schema"),
                        channel.message_encoding
                    ),
                }));
            }
            checked = Some(channel.id);
        }
        *found = true;
        f(RawMessage {
            log_time_ns: message.log_time,
            data: &message.data,
        })?;
    }
    Ok(counted.bytes)
}

fn db3_messages<E: From<RecordingError>>(
    path: &Path,
    topic: &str,
    seen: &mut Vec<String>,
    found: &mut bool,
    f: &mut dyn FnMut(RawMessage<'_>) -> Result<(), E>,
) -> Result<u64, E> {
    use rusqlite::{Connection, OpenFlags, OptionalExtension};
    let err = |source| RecordingError::Db3 {
        path: path.into(),
        source,
    };
    if !path.is_file() {
        return Err(E::from(RecordingError::Io {
            path: path.into(),
            source: std::io::Error::new(std::io::ErrorKind::NotFound, "no such file"),
        }));
    }
    let conn = Connection::open_with_flags(
        path,
        OpenFlags::SQLITE_OPEN_READ_ONLY | OpenFlags::SQLITE_OPEN_NO_MUTEX,
    )
    .map_err(err)?;
    let topic_row: Option<(i64, String, String)> = conn
        .query_row(
            "SELECT id, type, serialization_format FROM topics WHERE name = ?1",
            [topic],
            |r| Ok((r.get(0)?, r.get(1)?, r.get(2)?)),
        )
        .optional()
        .map_err(err)?;
    let Some((id, kind, encoding)) = topic_row else {
        let mut names = conn.prepare("SELECT name FROM topics").map_err(err)?;
        let rows = names
            .query_map([], |r| r.get::<_, String>(0))
            .map_err(err)?;
        for name in rows {
            seen.push(name.map_err(err)?);
        }
        return Ok(0);
    };
    if kind != OCCUPANCY_GRID || encoding != "cdr" {
        return Err(E::from(RecordingError::WrongType {
            path: path.into(),
            topic: topic.into(),
            found: format!("{kind} in {encoding}"),
        }));
    }
    let mut bytes = 0u64;
    let mut statement = conn
        .prepare("SELECT timestamp, data FROM messages WHERE topic_id = ?1 ORDER BY timestamp, id")
        .map_err(err)?;
    let mut rows = statement.query([id]).map_err(err)?;
    while let Some(row) = rows.next().map_err(err)? {
        let time: i64 = row.get(0).map_err(err)?;
        let data = row
            .get_ref(1)
            .map_err(err)?
            .as_blob()
            .map_err(|e| err(e.into()))?;
        bytes += data.len() as u64;
        *found = true;
        f(RawMessage {
            log_time_ns: u64::try_from(time).unwrap_or(0),
            data,
        })?;
    }
    Ok(bytes)
}
