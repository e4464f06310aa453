//! The storage the executor reads: the [`Source`] trait and
//! [`MemorySource`], an in-memory implementation for tests and model files.

use std::collections::BTreeMap;
use std::sync::Arc;

use super::error::SourceError;
use super::index::IndexedRevision;
use super::suggest::suggest;
use crate::edit::Edit;
use crate::grid::OccupancyGrid;
use crate::model::{Nrg, SpaceId};

/// A map and how many revisions it has.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MapInfo {
    /// The map's name.
    pub name: String,
    /// Number of revisions.
    pub revisions: usize,
    /// Newest revision number.
    pub latest: u64,
}

/// One revision of a map.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RevisionInfo {
    /// Revision number (starting at 1, increasing).
    pub revision: u64,
    /// Number of spaces.
    pub spaces: usize,
    /// Number of connections.
    pub connections: usize,
    /// A note saying where it came from ("imported from willow.yaml").
    pub note: String,
}

/// What a correction wrote.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct EditDone {
    /// The revision it made.
    pub revision: u64,
    /// The correction's number, when the source keeps corrections (the
    /// store does; a [`MemorySource`] does not).
    pub correction: Option<u32>,
    /// Spaces it made.
    pub created: Vec<SpaceId>,
    /// Spaces it removed.
    pub removed: Vec<SpaceId>,
}

/// What the query executor needs from storage. `store::Store` implements
/// it for SQLite; [`MemorySource`] holds maps in memory.
///
/// Revisions are numbered from 1 per map and only grow; a revision's model
/// never changes once written. Errors use [`SourceError`]: `NoMap` /
/// `NoRevision` for names and numbers that do not exist (with a suggestion
/// when cheap), `Backend` for anything else.
pub trait Source {
    /// Every map, sorted by name.
    fn maps(&self) -> Result<Vec<MapInfo>, SourceError>;
    /// The revisions of `map`, oldest first.
    fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, SourceError>;
    /// The model of one revision.
    fn load(&self, map: &str, revision: u64) -> Result<Nrg, SourceError>;
    /// The occupancy grid one revision was extracted from, or `None` when
    /// it came from a model file (or the source keeps no grids). `DIFF`
    /// aligns revisions on their grids; without them it falls back to the
    /// outlines of the spaces.
    fn grid(&self, map: &str, revision: u64) -> Result<Option<OccupancyGrid>, SourceError>;
    /// One revision indexed for queries, shared. The default loads and
    /// indexes it; a source with a cache of indexed revisions (the
    /// server's, shared by every endpoint) hands out its copy.
    fn indexed(&self, map: &str, revision: u64) -> Result<Arc<IndexedRevision>, SourceError> {
        let nrg = self.load(map, revision)?;
        Ok(Arc::new(IndexedRevision::new(map, revision, nrg)))
    }
    /// Gives space `id` of `map` at `revision` the name `name`, writing a new
    /// revision (whose model is the old one with that change) and returning
    /// its number. The caller has checked that the space exists.
    fn rename_space(
        &mut self,
        map: &str,
        revision: u64,
        id: SpaceId,
        name: &str,
    ) -> Result<u64, SourceError>;
    /// Applies the correction `edit` (written as `statement`, by `author`)
    /// to `map` at `revision`, which must be its latest, writing a new
    /// revision; a
    /// source that keeps corrections keeps it for later imports. A refused
    /// edit is [`SourceError::Edit`].
    fn edit(
        &mut self,
        map: &str,
        revision: u64,
        edit: &Edit,
        statement: &str,
        author: &str,
    ) -> Result<EditDone, SourceError>;
}

/// Maps held in memory: name → revisions (revision `n` at index `n - 1`).
///
/// ```
/// use nrgdb::query::{MemorySource, Source, demo};
/// let mut source = MemorySource::new();
/// source.insert("demo", demo::building(2));
/// assert_eq!(source.maps().unwrap()[0].latest, 1);
/// ```
#[derive(Debug, Clone, Default)]
pub struct MemorySource {
    maps: BTreeMap<String, Vec<Stored>>,
}

/// One revision held by a [`MemorySource`].
#[derive(Debug, Clone)]
struct Stored {
    nrg: Nrg,
    grid: Option<OccupancyGrid>,
    note: String,
}

impl MemorySource {
    /// An empty source.
    pub fn new() -> MemorySource {
        MemorySource::default()
    }

    /// Adds `nrg` as a new revision of `map` (creating the map); returns the
    /// revision number.
    pub fn insert(&mut self, map: &str, nrg: Nrg) -> u64 {
        self.insert_with_note(map, nrg, "inserted")
    }

    /// Like [`MemorySource::insert`] with a note.
    pub fn insert_with_note(&mut self, map: &str, nrg: Nrg, note: &str) -> u64 {
        self.insert_revision(map, nrg, None, note)
    }

    /// Like [`MemorySource::insert`], keeping the occupancy grid the model
    /// was extracted from (what [`Source::grid`] returns).
    pub fn insert_with_grid(&mut self, map: &str, nrg: Nrg, grid: OccupancyGrid) -> u64 {
        self.insert_revision(map, nrg, Some(grid), "inserted")
    }

    fn insert_revision(
        &mut self,
        map: &str,
        nrg: Nrg,
        grid: Option<OccupancyGrid>,
        note: &str,
    ) -> u64 {
        let revisions = self.maps.entry(map.to_string()).or_default();
        revisions.push(Stored {
            nrg,
            grid,
            note: note.to_string(),
        });
        revisions.len() as u64
    }

    fn map(&self, map: &str) -> Result<&Vec<Stored>, SourceError> {
        self.maps.get(map).ok_or_else(|| SourceError::NoMap {
            name: map.to_string(),
            suggestion: suggest(map, self.maps.keys().map(String::as_str)).map(str::to_string),
        })
    }

    fn revision(&self, map: &str, revision: u64) -> Result<&Stored, SourceError> {
        let revisions = self.map(map)?;
        revision
            .checked_sub(1)
            .and_then(|i| revisions.get(usize::try_from(i).ok()?))
            .ok_or_else(|| SourceError::NoRevision {
                map: map.to_string(),
                revision,
            })
    }
}

impl Source for MemorySource {
    fn maps(&self) -> Result<Vec<MapInfo>, SourceError> {
        Ok(self
            .maps
            .iter()
            .map(|(name, revs)| MapInfo {
                name: name.clone(),
                revisions: revs.len(),
                latest: revs.len() as u64,
            })
            .collect())
    }

    fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, SourceError> {
        Ok(self
            .map(map)?
            .iter()
            .enumerate()
            .map(|(i, stored)| RevisionInfo {
                revision: i as u64 + 1,
                spaces: stored.nrg.spaces().len(),
                connections: stored.nrg.connections().len(),
                note: stored.note.clone(),
            })
            .collect())
    }

    fn load(&self, map: &str, revision: u64) -> Result<Nrg, SourceError> {
        Ok(self.revision(map, revision)?.nrg.clone())
    }

    fn grid(&self, map: &str, revision: u64) -> Result<Option<OccupancyGrid>, SourceError> {
        Ok(self.revision(map, revision)?.grid.clone())
    }

    fn rename_space(
        &mut self,
        map: &str,
        revision: u64,
        id: SpaceId,
        name: &str,
    ) -> Result<u64, SourceError> {
        let latest = self.map(map)?.len() as u64;
        if revision != latest {
            return Err(SourceError::NotLatest {
                map: map.to_string(),
                revision,
                latest,
            });
        }
        let (mut spaces, connections) = self.revision(map, revision)?.nrg.clone().into_parts();
        for s in spaces.iter_mut().filter(|s| s.id == id) {
            s.name = Some(name.to_string());
        }
        let nrg = Nrg::new(spaces, connections).map_err(|e| SourceError::Backend(Box::new(e)))?;
        let note = format!("renamed space {id} to '{name}' (from revision {revision})");
        Ok(self.insert_with_note(map, nrg, &note))
    }

    fn edit(
        &mut self,
        map: &str,
        revision: u64,
        edit: &Edit,
        statement: &str,
        author: &str,
    ) -> Result<EditDone, SourceError> {
        let latest = self.map(map)?.len() as u64;
        if revision != latest {
            return Err(SourceError::NotLatest {
                map: map.to_string(),
                revision,
                latest,
            });
        }
        let nrg = &self.revision(map, revision)?.nrg;
        // New spaces take ids above any the map ever used.
        let next = self
            .map(map)?
            .iter()
            .map(|s| s.nrg.next_id())
            .max()
            .unwrap_or(SpaceId(1));
        let done = crate::edit::apply(nrg, edit, next)?;
        let walked = crate::route::walked_model(&done.nrg).nrg;
        let note = format!("{statement} (by {author}, on revision {revision})");
        Ok(EditDone {
            revision: self.insert_with_note(map, walked, &note),
            correction: None,
            created: done.created,
            removed: done.removed,
        })
    }
}

impl<S: Source + ?Sized> Source for Box<S> {
    fn maps(&self) -> Result<Vec<MapInfo>, SourceError> {
        (**self).maps()
    }
    fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, SourceError> {
        (**self).revisions(map)
    }
    fn load(&self, map: &str, revision: u64) -> Result<Nrg, SourceError> {
        (**self).load(map, revision)
    }
    fn grid(&self, map: &str, revision: u64) -> Result<Option<OccupancyGrid>, SourceError> {
        (**self).grid(map, revision)
    }
    fn indexed(&self, map: &str, revision: u64) -> Result<Arc<IndexedRevision>, SourceError> {
        (**self).indexed(map, revision)
    }
    fn rename_space(
        &mut self,
        map: &str,
        revision: u64,
        id: SpaceId,
        name: &str,
    ) -> Result<u64, SourceError> {
        (**self).rename_space(map, revision, id, name)
    }
    fn edit(
        &mut self,
        map: &str,
        revision: u64,
        edit: &Edit,
        statement: &str,
        author: &str,
    ) -> Result<EditDone, SourceError> {
        (**self).edit(map, revision, edit, statement, author)
    }
}

/// A borrowed source (a session over a store the caller keeps).
impl<S: Source + ?Sized> Source for &mut S {
    fn maps(&self) -> Result<Vec<MapInfo>, SourceError> {
        (**self).maps()
    }
    fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, SourceError> {
        (**self).revisions(map)
    }
    fn load(&self, map: &str, revision: u64) -> Result<Nrg, SourceError> {
        (**self).load(map, revision)
    }
    fn grid(&self, map: &str, revision: u64) -> Result<Option<OccupancyGrid>, SourceError> {
        (**self).grid(map, revision)
    }
    fn indexed(&self, map: &str, revision: u64) -> Result<Arc<IndexedRevision>, SourceError> {
        (**self).indexed(map, revision)
    }
    fn rename_space(
        &mut self,
        map: &str,
        revision: u64,
        id: SpaceId,
        name: &str,
    ) -> Result<u64, SourceError> {
        (**self).rename_space(map, revision, id, name)
    }
    fn edit(
        &mut self,
        map: &str,
        revision: u64,
        edit: &Edit,
        statement: &str,
        author: &str,
    ) -> Result<EditDone, SourceError> {
        (**self).edit(map, revision, edit, statement, author)
    }
}
