//! Models entering the database, in two steps used by both the CLI and
//! the server:
//!
//! 1. [`read`]: bytes in (a ROS map YAML and its PGM/PNG image, an
//!    IndoorGML document, model JSON or GeoJSON; each file's format told
//!    by [`crate::format::detect`]), a [`Prepared`] model out, with the
//!    occupancy grid a map was extracted from, in memory: an upload is
//!    never written to disk to be read back. [`read_path`] reads the files
//!    (a map YAML and the image it names) and does the same. Sizes from
//!    the input are bounded (file bytes, image pixels, resolution) and
//!    errors name the file or part. The model passes the geometric gate
//!    ([`validate`]: what `nrgdb check` checks, repaired where that keeps
//!    the model's meaning, refused otherwise). Nothing is stored by this
//!    step.
//! 2. [`ingest`]: the one path from a model (read as above, or made by
//!    applying a change set) into the store. Every navigable connection's
//!    length becomes its walked length ([`crate::route::walked_model`])
//!    before the model is stored as the next revision in one transaction,
//!    so stored lengths are the lengths exports carry.
//!
//! A ROS 2 recording ([`import_recording`]) is many maps over time: each
//! chosen map takes the same two steps (extracted and gated as a map
//! file's grid, then [`ingest`]) as its own revision.
//!
//! Uses format, grid, extract, route and store; sits above them (the store
//! knows nothing of routing). Must not use HTTP or the terminal.
//!
//! ```
//! use nrgdb::ingest::ingest;
//! use nrgdb::store::{ImportMeta, Store};
//! let mut store = Store::open_in_memory()?;
//! let nrg = nrgdb::fixtures::corridor_building(2);
//! let done = ingest(&mut store, "lab", &nrg, ImportMeta::new("first", "ada"), None)?;
//! assert_eq!(done.imported.revision.seq, 1);
//! let stored = store.load("lab", None)?;
//! assert_eq!(stored, nrgdb::route::walked_model(&nrg).nrg);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod building;
mod correct;
mod error;
mod read;
mod recording;
mod source;
mod valid;

pub use building::{MAX_CONNECTORS, MAX_LEVELS};
pub use correct::{CorrectError, Corrected, edit};
pub use error::IngestError;
pub use read::{IngestOptions, InputFile, Prepared, read, read_path};
pub use recording::{RecordingImport, RecordingImportError, StoredMap, import_recording};
pub use valid::{Validated, findings, validate};

use crate::grid::OccupancyGrid;
use crate::model::{Georef, Nrg};
use crate::route::walked_model;
use crate::store::{CorrectionResults, CorrectionState, ImportMeta, Imported, Store, StoreError};

/// What [`ingest`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct Ingested {
    /// The stored revision and the ids its spaces got.
    pub imported: Imported,
    /// How many connection lengths the walked lengths changed (by more
    /// than a millimetre).
    pub lengths_walked: usize,
    /// The map's corrections applied again to this model: numbers of
    /// those that applied.
    pub corrections_applied: Vec<u32>,
    /// Those that no longer applied: number, statement and reason.
    pub corrections_failed: Vec<(u32, String, String)>,
    /// The georeference stored with the map because the model came in a
    /// CRS and the map had none ([`ingest_prepared`]).
    pub georef_set: Option<Georef>,
}

/// How many times [`ingest`] reads the corrections again when another
/// writer changed them meanwhile.
const MAX_ATTEMPTS: usize = 3;

/// The georeference model files for `map` are read into
/// ([`IngestOptions::frame`]): the map's, None for a map without one or
/// not made yet.
pub fn map_frame(store: &Store, map: &str) -> Result<Option<Georef>, StoreError> {
    match store.georef(map) {
        Err(StoreError::NoSuchMap { .. }) => Ok(None),
        other => other,
    }
}

/// [`ingest`] of a model [`read`] (read with [`map_frame`] as its frame),
/// with its grid. A model that came in a CRS (GeoJSON in WGS84 or UTM,
/// IndoorGML with a UTM `srsName`) leaves its georeference with the map
/// when the map has none, so exports place it again.
pub fn ingest_prepared(
    store: &mut Store,
    map: &str,
    prepared: &Prepared,
    meta: ImportMeta,
) -> Result<Ingested, StoreError> {
    let mut done = ingest(store, map, &prepared.nrg, meta, prepared.grid.as_ref())?;
    if let Some(g) = &prepared.georef
        && store.georef(map)?.is_none()
    {
        store.set_georef(map, Some(g))?;
        done.georef_set = Some(g.clone());
    }
    Ok(done)
}

/// Stores `nrg`, with walked connection lengths, as the next revision of
/// `map` (see [`Store::import_with_grid`]), keeping `grid` when given.
///
/// The map's corrections (issue 22) are applied to `nrg` first, oldest
/// first, each on the result of the one before: a re-mapped revision keeps
/// the merges, splits, doors and attributes people made, and each
/// correction's result (applied, or failed with the reason) is stored with
/// the revision.
pub fn ingest(
    store: &mut Store,
    map: &str,
    nrg: &Nrg,
    meta: ImportMeta,
    grid: Option<&OccupancyGrid>,
) -> Result<Ingested, StoreError> {
    let mut attempt = 0;
    loop {
        attempt += 1;
        let key = store.corrections_key(map)?;
        let mut model = nrg.clone();
        let mut results = Vec::new();
        let corrections = store.corrections(map)?;
        for c in &corrections {
            if c.state == CorrectionState::Dropped {
                continue;
            }
            match c.rule.reapply(&model, model.next_id()) {
                Ok(done) => {
                    model = done.edited.nrg;
                    results.push((c.id, Ok(())));
                }
                Err(reason) => results.push((c.id, Err(reason))),
            }
        }
        let walked = walked_model(&model);
        let reapplied = CorrectionResults { key, results };
        match store.import_corrected(map, &walked.nrg, meta.clone(), grid, &reapplied) {
            Ok(imported) => {
                let (ok, failed): (Vec<_>, Vec<_>) =
                    reapplied.results.into_iter().partition(|(_, r)| r.is_ok());
                return Ok(Ingested {
                    imported,
                    lengths_walked: walked.lengths_changed,
                    corrections_applied: ok.into_iter().map(|(id, _)| id).collect(),
                    corrections_failed: failed
                        .into_iter()
                        .filter_map(|(id, r)| {
                            let statement =
                                corrections.iter().find(|c| c.id == id)?.statement.clone();
                            r.err().map(|e| (id, statement, e))
                        })
                        .collect(),
                    georef_set: None,
                });
            }
            Err(StoreError::Stale { .. }) if attempt < MAX_ATTEMPTS => continue,
            Err(e) => return Err(e),
        }
    }
}
