//! A ROS 2 recording into the store: every map the recording chose
//! ([`crate::recording::scan`]: maps that changed, at most one per
//! interval) extracted, gated and stored through [`ingest`](super::ingest)
//! as its own revision in its own transaction, with the message's time as
//! the revision's time and the recording's name in its message. The
//! whole recording is read once before anything is stored, so a corrupt
//! or truncated one stores nothing. A map that cannot be made into a model
//! (a robot's first maps are often a few square metres: extraction finds
//! no room; or the model fails the geometric gate) is left out and
//! reported with its reason; the store failing stops the import, and the
//! error says which revisions were stored before it.

use std::collections::BTreeSet;

use super::read::from_grid;
use super::{IngestOptions, Ingested, ingest};
use crate::recording::{
    Recording, RecordingError, RecordingOptions, Scan, log_time, read_chosen, scan,
};
use crate::store::{ImportMeta, RevisionInfo, Store, StoreError};

/// What [`import_recording`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordingImport {
    /// The recording's name.
    pub recording: String,
    /// The topic read.
    pub topic: String,
    /// Map messages on the topic.
    pub messages: usize,
    /// Bytes of recording read in the first pass.
    pub bytes_read: u64,
    /// Maps left out as identical to the one before.
    pub identical: usize,
    /// Maps left out by the interval.
    pub thinned: usize,
    /// Chosen maps left out as stored already: a revision of the map has
    /// the same map (hash) at the same time, from an earlier import of
    /// this recording or of one it continues.
    pub already_stored: usize,
    /// One entry per chosen map stored (or found unchanged), in order.
    pub maps: Vec<StoredMap>,
    /// Chosen maps that could not be made into a model: number, time and
    /// why.
    pub unusable: Vec<(usize, String, String)>,
}

/// One chosen map and what became of it.
#[derive(Debug, Clone, PartialEq)]
pub struct StoredMap {
    /// Its number among the topic's messages, from 1.
    pub index: usize,
    /// Its log time (RFC 3339).
    pub time: String,
    /// What ingest did (`imported.unchanged` when the extracted model is
    /// the latest revision's exactly).
    pub ingested: Ingested,
}

impl RecordingImport {
    /// The revisions written (chosen maps whose model changed).
    pub fn revisions(&self) -> impl Iterator<Item = &RevisionInfo> {
        self.maps
            .iter()
            .filter(|m| !m.ingested.imported.unchanged)
            .map(|m| &m.ingested.imported.revision)
    }
}

/// Why [`import_recording`] stopped.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RecordingImportError {
    /// The recording could not be read; nothing was stored.
    #[error(transparent)]
    Read(#[from] RecordingError),
    /// The map's history could not be read; nothing was stored.
    #[error("reading the map's history: {0} (nothing was stored)")]
    History(StoreError),
    /// A map's model could not be stored.
    #[error("map message {index} ({time}): {error}{}", stored_before(*stored))]
    Store {
        /// The message's number.
        index: usize,
        /// Its log time.
        time: String,
        /// Revisions stored before it.
        stored: usize,
        /// The cause.
        error: StoreError,
    },
}

fn stored_before(n: usize) -> String {
    match n {
        0 => " (nothing was stored)".into(),
        n => format!(
            " ({} stored before it, each complete)",
            crate::wording::count(n, "revision", "revisions")
        ),
    }
}

/// Reads `recording` (see [`crate::recording`]) and stores each chosen
/// map as the next revision of `map`, calling `progress` after each. The
/// revisions carry `meta`'s author; their message is `meta`'s message, or
/// when empty one naming the recording, topic and time.
pub fn import_recording(
    store: &mut Store,
    map: &str,
    recording: &Recording,
    options: &RecordingOptions,
    ingest_options: &IngestOptions,
    meta: &ImportMeta,
    mut progress: impl FnMut(&StoredMap),
) -> Result<RecordingImport, RecordingImportError> {
    let found: Scan = scan(recording, options)?;
    let name = recording.name();
    let mut done = RecordingImport {
        recording: name.clone(),
        topic: options.topic.clone(),
        messages: found.seen.len(),
        bytes_read: found.bytes_read,
        identical: found.choice.identical,
        thinned: found.choice.thinned,
        already_stored: 0,
        maps: Vec::with_capacity(found.choice.chosen.len()),
        unusable: Vec::new(),
    };
    let stored_before: BTreeSet<(String, String)> = match store.revisions(map) {
        Ok(list) => list
            .into_iter()
            .filter_map(|r| Some((r.source_sha256?, r.created_at)))
            .collect(),
        Err(StoreError::NoSuchMap { .. }) => BTreeSet::new(),
        Err(source) => return Err(RecordingImportError::History(source)),
    };
    let result = read_chosen(recording, options, &found, |seen, grid| {
        let time = log_time(seen.log_time_ns);
        if stored_before.contains(&(seen.sha256.clone(), time.clone())) {
            done.already_stored += 1;
            return Ok(());
        }
        let stored = done.revisions().count();
        let label = format!("{name} {} #{}", options.topic, seen.index);
        let prepared = match from_grid(
            grid,
            &label,
            label.clone(),
            seen.sha256.clone(),
            ingest_options,
        ) {
            Ok(p) => p,
            Err(e) => {
                done.unusable.push((seen.index, time, e.to_string()));
                return Ok(());
            }
        };
        let message = if meta.message.is_empty() {
            format!("from {name} ({} at {time})", options.topic)
        } else {
            meta.message.clone()
        };
        let mut revision_meta = prepared.meta(message, meta.author.clone());
        revision_meta.recorded_at = Some(time.clone());
        let ingested = ingest(
            store,
            map,
            &prepared.nrg,
            revision_meta,
            prepared.grid.as_ref(),
        )
        .map_err(|error| RecordingImportError::Store {
            index: seen.index,
            time: time.clone(),
            stored,
            error,
        })?;
        let entry = StoredMap {
            index: seen.index,
            time,
            ingested,
        };
        progress(&entry);
        done.maps.push(entry);
        Ok(())
    });
    result.map(|()| done)
}
