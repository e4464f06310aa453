//! The storage engine interface: what a backend (memory, SQLite,
//! PostgreSQL) must do, and nothing more.
//!
//! In the manner of gluesql's `Store`/`StoreMut` and oxigraph's storage
//! layer, an engine offers a read side ([`ReadStore`]) and a write side
//! ([`WriteStore`]) of plain primitives over revisions, corrections and
//! grids. Everything that is the same on every engine — matching spaces to
//! their parent revision (stable identity), "nothing changed", renames,
//! undo, retries when another writer got in first, size limits — lives
//! once above them in [`super::Store`]. One conformance suite
//! (`tests/it/store_conformance.rs`) runs against every engine.
//!
//! Every write is one [`Commit`]: under the engine's write lock for the
//! map, it checks that `base` is still the map's latest revision (else
//! [`StoreError::Stale`], nothing written), then writes the revision as a
//! delta against `parent` ([`super::delta::Delta`]), the grid, the
//! corrections' results, a new correction and a dropped one, all in one
//! transaction. The expensive parts (matching, encoding the grid) are done
//! by the caller before.

use std::fmt::Debug;
use std::time::Duration;

use super::grid_png::EncodedGrid;
use super::{
    Correction, CorrectionResults, CorrectionsKey, ImportMeta, MapInfo, RevisionInfo, StoreError,
};
use crate::model::{Georef, Nrg, SpaceId};

/// The read side of an engine.
pub trait ReadStore {
    /// Where the data lives, for messages (a file path, a URL without its
    /// password).
    fn location(&self) -> String;
    /// All maps, by name.
    fn maps(&self) -> Result<Vec<MapInfo>, StoreError>;
    /// The revisions of `map`, oldest first ([`StoreError::NoSuchMap`]
    /// when there is no such map).
    fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, StoreError>;
    /// One revision's record, the latest when `rev` is `None`.
    fn revision(&self, map: &str, rev: Option<u32>) -> Result<RevisionInfo, StoreError>;
    /// Revision `rev` of `map` (the latest when `None`) exactly as stored.
    fn load(&self, map: &str, rev: Option<u32>) -> Result<Nrg, StoreError>;
    /// The smallest space of the revision containing `(x, y)` (metres,
    /// map frame; holes excluded).
    fn locate(
        &self,
        map: &str,
        rev: Option<u32>,
        x: f64,
        y: f64,
    ) -> Result<Option<SpaceId>, StoreError>;
    /// The grid a revision was extracted from, as stored.
    fn grid(&self, map: &str, rev: Option<u32>) -> Result<Option<EncodedGrid>, StoreError>;
    /// Every correction of `map`, oldest first (none for an unknown map).
    fn corrections(&self, map: &str) -> Result<Vec<Correction>, StoreError>;
    /// The key of `map`'s corrections now.
    fn corrections_key(&self, map: &str) -> Result<CorrectionsKey, StoreError>;
    /// One above the largest space id `map` ever used (1 for a new map).
    fn next_space_id(&self, map: &str) -> Result<SpaceId, StoreError>;
    /// A value that changes whenever anything is committed to the
    /// database, by this handle or any other (another connection, another
    /// process); `None` when the engine has no cheap one, so that callers
    /// must ask for the latest revision every time.
    fn change_token(&self) -> Result<Option<u64>, StoreError>;
    /// The georeference of `map`, if it has one.
    fn georef(&self, map: &str) -> Result<Option<Georef>, StoreError>;
}

/// A new correction to keep with a commit.
#[derive(Debug, Clone, Copy)]
pub struct NewCorrection<'a> {
    /// The statement as written.
    pub statement: &'a str,
    /// The rule, as JSON ([`crate::edit::Rule`]).
    pub rule_json: &'a str,
}

/// One write: a revision and what goes with it, all or nothing.
#[derive(Debug, Clone, Copy)]
pub struct Commit<'a> {
    /// The map (created when `base` is 0 and it does not exist).
    pub map: &'a str,
    /// The revision this commit continues: must still be the map's latest
    /// (0 for a map without revisions).
    pub base: u32,
    /// `base`'s model (the rows the delta is taken against); `None` when
    /// `base` is 0.
    pub parent: Option<&'a Nrg>,
    /// The new revision's model; `None` to write no revision (an import
    /// that changed nothing still records its corrections' results).
    pub nrg: Option<&'a Nrg>,
    /// Who, why and from what.
    pub meta: &'a ImportMeta,
    /// The grid the model was extracted from.
    pub grid: Option<&'a EncodedGrid>,
    /// The results of re-applying the map's corrections; refused with
    /// [`StoreError::Stale`] when the corrections changed since.
    pub reapplied: Option<&'a CorrectionResults>,
    /// A correction made by this revision.
    pub correction: Option<NewCorrection<'a>>,
    /// A correction this revision undoes (dropped with it).
    pub drops: Option<u32>,
}

impl<'a> Commit<'a> {
    /// A commit of `nrg` on `base` with nothing else.
    pub fn revision(
        map: &'a str,
        base: u32,
        parent: Option<&'a Nrg>,
        nrg: &'a Nrg,
        meta: &'a ImportMeta,
    ) -> Commit<'a> {
        Commit {
            map,
            base,
            parent,
            nrg: Some(nrg),
            meta,
            grid: None,
            reapplied: None,
            correction: None,
            drops: None,
        }
    }
}

/// What a commit wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct Committed {
    /// The new revision (the base's record when no revision was written).
    pub revision: RevisionInfo,
    /// The number of the correction kept with it.
    pub correction: Option<u32>,
}

/// The write side of an engine.
pub trait WriteStore: ReadStore {
    /// Writes `commit` in one transaction (see the module doc).
    fn commit(&mut self, commit: &Commit<'_>) -> Result<Committed, StoreError>;
    /// Marks correction `id` of `map` dropped (kept for the record);
    /// returns it.
    fn drop_correction(&mut self, map: &str, id: u32) -> Result<Correction, StoreError>;
    /// Sets (or with `None` removes) the georeference of `map`, kept for
    /// all its revisions.
    fn set_georef(&mut self, map: &str, georef: Option<&Georef>) -> Result<(), StoreError>;
}

/// A whole engine, as [`super::Store`] holds it.
pub trait Engine: WriteStore + Send + Debug {
    /// How long a writer waits for another one before
    /// [`StoreError::Busy`].
    fn set_busy_timeout(&mut self, timeout: Duration) -> Result<(), StoreError>;
    /// The engine's own consistency check; `["ok"]` when sound.
    fn integrity_check(&self) -> Result<Vec<String>, StoreError>;
}
