//! Reading the store: the engine's read side, with grids decoded.

use super::{Correction, CorrectionsKey, MapInfo, RevisionInfo, Store, StoreError};
use crate::grid::OccupancyGrid;
use crate::model::{Georef, Nrg, SpaceId};

impl Store {
    /// All maps, by name.
    pub fn maps(&self) -> Result<Vec<MapInfo>, StoreError> {
        self.engine.maps()
    }

    /// The revisions of `map`, oldest first.
    pub fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, StoreError> {
        self.engine.revisions(map)
    }

    /// The history of `map`, newest first (what `nrgdb log` prints).
    pub fn log(&self, map: &str) -> Result<Vec<RevisionInfo>, StoreError> {
        let mut revs = self.revisions(map)?;
        revs.reverse();
        Ok(revs)
    }

    /// One revision's record; the latest when `rev` is `None`.
    pub fn revision(&self, map: &str, rev: Option<u32>) -> Result<RevisionInfo, StoreError> {
        self.engine.revision(map, rev)
    }

    /// Revision `rev` of `map` (the latest when `None`) exactly as it was
    /// stored.
    pub fn load(&self, map: &str, rev: Option<u32>) -> Result<Nrg, StoreError> {
        self.engine.load(map, rev)
    }

    /// The space of revision `rev` (latest when `None`) containing the
    /// point `(x, y)` (metres, map frame), holes excluded. Where spaces
    /// overlap, the smallest wins (a door inside a wall gap before the
    /// corridor around it).
    pub fn locate(
        &self,
        map: &str,
        rev: Option<u32>,
        x: f64,
        y: f64,
    ) -> Result<Option<SpaceId>, StoreError> {
        self.engine.locate(map, rev, x, y)
    }

    /// The georeference of `map` (WGS84 origin, heading, level), if it
    /// has one: the same for every revision.
    pub fn georef(&self, map: &str) -> Result<Option<Georef>, StoreError> {
        self.engine.georef(map)
    }

    /// The occupancy grid revision `rev` of `map` was imported from (the
    /// latest revision when `None`), or `None` when it came from a model
    /// file.
    pub fn grid(&self, map: &str, rev: Option<u32>) -> Result<Option<OccupancyGrid>, StoreError> {
        let Some(encoded) = self.engine.grid(map, rev)? else {
            return Ok(None);
        };
        let seq = match rev {
            Some(r) => r,
            None => self.engine.revision(map, None)?.seq,
        };
        encoded.decode(map, seq).map(Some)
    }

    /// Every correction of `map`, oldest first (none for a map without
    /// any, or one not yet imported).
    pub fn corrections(&self, map: &str) -> Result<Vec<Correction>, StoreError> {
        self.engine.corrections(map)
    }

    /// The key of `map`'s corrections now (see
    /// [`super::CorrectionResults::key`]).
    pub fn corrections_key(&self, map: &str) -> Result<CorrectionsKey, StoreError> {
        self.engine.corrections_key(map)
    }

    /// One above the largest space id `map` ever used (1 for a new map):
    /// the first id an edit may give a new space.
    pub fn next_space_id(&self, map: &str) -> Result<SpaceId, StoreError> {
        self.engine.next_space_id(map)
    }

    /// A value that changes whenever anything is committed to the
    /// database by anyone; `None` when the engine has no cheap one (see
    /// [`super::ReadStore::change_token`]).
    pub fn change_token(&self) -> Result<Option<u64>, StoreError> {
        self.engine.change_token()
    }
}
