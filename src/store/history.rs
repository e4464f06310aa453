//! Writing the store, the same on every engine: imports matched to their
//! parent revision, renames, edits kept as corrections, undo. Each adds
//! exactly one revision or nothing, through one [`Commit`].
//!
//! Matching against the parent revision is the expensive part, so it (like
//! encoding the grid) runs before the engine takes its write lock, on the
//! revision read (issue 21, defect 3: it ran under the lock and every
//! other writer got "busy"). The commit checks that the revision matched
//! against is still the latest; if another writer got in first the import
//! is matched again, at most [`MAX_IMPORT_ATTEMPTS`] times, then fails with
//! [`StoreError::MapChanged`].

use super::delta::same_model;
use super::identity::continue_identity;
use super::limits::{check_map_name, check_meta};
use super::{
    Commit, Correction, CorrectionResults, CorrectionState, EncodedGrid, ImportMeta, Imported,
    NewCorrection, RevisionInfo, Store, StoreError,
};
use crate::edit::Rule;
use crate::grid::OccupancyGrid;
use crate::model::{Georef, Nrg, SpaceId};

/// How many times an import matches its spaces again when another writer
/// added a revision meanwhile, before it gives up with
/// [`StoreError::MapChanged`].
pub const MAX_IMPORT_ATTEMPTS: usize = 3;

impl Store {
    /// Stores `nrg` as the next revision of `map` (creating the map on its
    /// first import). Each space is matched to the space it continues in
    /// the parent revision and keeps its stable id, name and attributes
    /// (the new model's own name and attribute values win when set); new
    /// spaces get ids above any the map ever used. The first revision
    /// keeps the model's ids. The same model as the latest revision writes
    /// nothing ([`Imported::unchanged`]). On any error nothing is stored.
    pub fn import(
        &mut self,
        map: &str,
        nrg: &Nrg,
        meta: ImportMeta,
    ) -> Result<Imported, StoreError> {
        self.import_with_grid(map, nrg, meta, None)
    }

    /// [`Store::import`], also keeping the occupancy grid the model was
    /// extracted from (see [`Store::grid`]), in the same commit.
    pub fn import_with_grid(
        &mut self,
        map: &str,
        nrg: &Nrg,
        meta: ImportMeta,
        grid: Option<&OccupancyGrid>,
    ) -> Result<Imported, StoreError> {
        self.import_inner(map, nrg, &meta, grid, None)
    }

    /// [`Store::import_with_grid`] of a model the map's corrections were
    /// applied to, recording each one's result with the revision; refused
    /// with [`StoreError::Stale`] (nothing stored) when the corrections
    /// changed since `reapplied` was computed.
    pub fn import_corrected(
        &mut self,
        map: &str,
        nrg: &Nrg,
        meta: ImportMeta,
        grid: Option<&OccupancyGrid>,
        reapplied: &CorrectionResults,
    ) -> Result<Imported, StoreError> {
        self.import_inner(map, nrg, &meta, grid, Some(reapplied))
    }

    fn import_inner(
        &mut self,
        map: &str,
        nrg: &Nrg,
        meta: &ImportMeta,
        grid: Option<&OccupancyGrid>,
        reapplied: Option<&CorrectionResults>,
    ) -> Result<Imported, StoreError> {
        check_map_name(map)?;
        check_meta(meta)?;
        let grid = grid.map(EncodedGrid::encode).transpose()?;
        for _ in 0..MAX_IMPORT_ATTEMPTS {
            tracing::info!(
                map,
                spaces = nrg.spaces().len(),
                "matching the latest revision"
            );
            let parent = self.latest_model(map)?;
            let (stable, ids) = match &parent {
                Some((_, p)) => {
                    let next = self.engine.next_space_id(map)?;
                    continue_identity(p, nrg, &self.match_params, next.0)?
                }
                None => (
                    nrg.clone(),
                    nrg.spaces().iter().map(|s| (s.id, s.id)).collect(),
                ),
            };
            #[cfg(test)]
            if let Some(hook) = self.before_write_lock.as_mut() {
                hook();
            }
            tracing::info!(map, "writing the revision");
            let unchanged = parent.as_ref().is_some_and(|(_, p)| same_model(p, &stable));
            let commit = Commit {
                map,
                base: parent.as_ref().map_or(0, |p| p.0),
                parent: parent.as_ref().map(|p| &p.1),
                nrg: (!unchanged).then_some(&stable),
                meta,
                grid: grid.as_ref().filter(|_| !unchanged),
                reapplied,
                correction: None,
                drops: None,
            };
            match self.engine.commit(&commit) {
                Ok(done) => {
                    return Ok(Imported {
                        revision: done.revision,
                        unchanged,
                        ids,
                    });
                }
                // Another writer added a revision: match again. When the
                // corrections changed instead, the caller must re-apply
                // them (see `ingest`).
                Err(StoreError::Stale { .. })
                    if reapplied
                        .is_none_or(|r| self.engine.corrections_key(map).ok() == Some(r.key)) => {}
                Err(e) => return Err(e),
            }
        }
        Err(StoreError::MapChanged {
            map: map.to_string(),
            attempts: MAX_IMPORT_ATTEMPTS,
        })
    }

    /// The latest revision of `map` and its model; `None` for a map that
    /// does not exist yet (or has no revision).
    fn latest_model(&self, map: &str) -> Result<Option<(u32, Nrg)>, StoreError> {
        let seq = match self.engine.revision(map, None) {
            Ok(info) => info.seq,
            Err(StoreError::NoSuchMap { .. } | StoreError::NoSuchRevision { .. }) => {
                return Ok(None);
            }
            Err(e) => return Err(e),
        };
        Ok(Some((seq, self.engine.load(map, Some(seq))?)))
    }

    /// Gives space `id` of the latest revision of `map` the name `name`
    /// (`None` clears it), as a new revision.
    pub fn rename_space(
        &mut self,
        map: &str,
        id: SpaceId,
        name: Option<&str>,
        meta: ImportMeta,
    ) -> Result<RevisionInfo, StoreError> {
        check_meta(&meta)?;
        for _ in 0..MAX_IMPORT_ATTEMPTS {
            let (seq, parent) = self.latest_model(map)?.ok_or(StoreError::NoSuchRevision {
                map: map.to_string(),
                rev: 1,
                latest: 0,
            })?;
            if parent.space(id).is_none() {
                return Err(StoreError::NoSuchSpace {
                    map: map.to_string(),
                    id,
                    rev: seq,
                });
            }
            let (mut spaces, links) = parent.clone().into_parts();
            for s in spaces.iter_mut().filter(|s| s.id == id) {
                s.name = name.map(str::to_string);
            }
            let renamed = Nrg::new(spaces, links)?;
            let commit = Commit::revision(map, seq, Some(&parent), &renamed, &meta);
            match self.engine.commit(&commit) {
                Ok(done) => return Ok(done.revision),
                Err(StoreError::Stale { .. }) => {}
                Err(e) => return Err(e),
            }
        }
        Err(StoreError::MapChanged {
            map: map.to_string(),
            attempts: MAX_IMPORT_ATTEMPTS,
        })
    }

    /// Stores `nrg` (the model of revision `base.0` of `map`, `base.1`,
    /// with an edit applied, ids as they are) as the next revision, and the
    /// edit as a correction, in one commit. Refused with
    /// [`StoreError::Stale`] when `base` is no longer the latest revision.
    /// Returns the revision and the correction's number.
    pub fn commit_edit(
        &mut self,
        map: &str,
        (base, parent): (u32, &Nrg),
        nrg: &Nrg,
        meta: &ImportMeta,
        statement: &str,
        rule: &Rule,
    ) -> Result<(RevisionInfo, u32), StoreError> {
        check_meta(meta)?;
        let rule_json = serde_json::to_string(rule).map_err(|e| StoreError::BadCorrection {
            map: map.to_string(),
            id: 0,
            message: e.to_string(),
        })?;
        if base == 0 {
            return Err(StoreError::Stale {
                map: map.to_string(),
            });
        }
        let commit = Commit {
            correction: Some(NewCorrection {
                statement,
                rule_json: &rule_json,
            }),
            ..Commit::revision(map, base, Some(parent), nrg, meta)
        };
        let done = self.engine.commit(&commit)?;
        let id = done.correction.ok_or_else(|| StoreError::BadCorrection {
            map: map.to_string(),
            id: 0,
            message: "the engine kept no correction".into(),
        })?;
        Ok((done.revision, id))
    }

    /// Sets the georeference of `map` (an existing map; [`StoreError::NoSuchMap`]
    /// otherwise), or removes it with `None`. It holds for every revision,
    /// past and future.
    pub fn set_georef(&mut self, map: &str, georef: Option<&Georef>) -> Result<(), StoreError> {
        self.engine.set_georef(map, georef)
    }

    /// Drops correction `id` of `map`: later imports no longer apply it.
    /// The revisions it made stay as they are.
    pub fn drop_correction(&mut self, map: &str, id: u32) -> Result<Correction, StoreError> {
        self.engine.drop_correction(map, id)
    }

    /// Undoes correction `id` of `map`, which must have made the map's
    /// latest revision: writes a revision whose model is the one before
    /// the edit and drops the correction, in one commit. Returns the new
    /// revision.
    pub fn undo_correction(&mut self, map: &str, id: u32) -> Result<RevisionInfo, StoreError> {
        let correction = self
            .engine
            .corrections(map)?
            .into_iter()
            .find(|c| c.id == id);
        // An unknown map says so before an unknown correction does.
        let seq = self.engine.revision(map, None)?.seq;
        let correction = correction.ok_or_else(|| StoreError::NoSuchCorrection {
            map: map.to_string(),
            id,
        })?;
        if correction.state == CorrectionState::Dropped || correction.made_on != seq || seq < 2 {
            return Err(StoreError::CannotUndo {
                map: map.to_string(),
                id,
                made_on: correction.made_on,
                latest: seq,
            });
        }
        let before = self.engine.load(map, Some(correction.made_on - 1))?;
        let now = self.engine.load(map, Some(seq))?;
        let meta = ImportMeta::new(
            format!("undo: {}", correction.statement),
            correction.author.clone(),
        );
        let commit = Commit {
            drops: Some(id),
            ..Commit::revision(map, seq, Some(&now), &before, &meta)
        };
        Ok(self.engine.commit(&commit)?.revision)
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;
    use std::sync::atomic::{AtomicUsize, Ordering};

    use super::*;
    use crate::model::{Space, SpaceKind};

    /// `n` square rooms of 2 m in a row, ids 1.., shifted `dx` metres.
    fn rooms(n: u32, dx: f64) -> Nrg {
        let spaces = (0..n)
            .map(|i| {
                let x = f64::from(i) * 3.0 + dx;
                Space::new(
                    SpaceId(i + 1),
                    SpaceKind::Room,
                    [x + 1.0, 1.0],
                    vec![[x, 0.0], [x + 2.0, 0.0], [x + 2.0, 2.0], [x, 2.0]],
                )
            })
            .collect();
        Nrg::new(spaces, vec![]).unwrap()
    }

    fn meta() -> ImportMeta {
        ImportMeta::new("test", "me")
    }

    /// A store on a file in a fresh directory, with map `m` at revision 1.
    fn store_with_map() -> (tempfile::TempDir, std::path::PathBuf, Store) {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("db.sqlite");
        let mut store = Store::open(&path).unwrap();
        store.import("m", &rooms(4, 0.0), meta()).unwrap();
        (dir, path, store)
    }

    /// A second writer on the same file that gives up at once when the
    /// write lock is held.
    fn impatient_writer(path: &std::path::Path) -> Store {
        let mut other = Store::open(path).unwrap();
        other.set_busy_timeout(std::time::Duration::ZERO).unwrap();
        other
    }

    /// Issue 21, defect 3: identity matching ran inside `BEGIN IMMEDIATE`,
    /// so every other writer got "busy" while a large import was matched.
    /// Right after matching, another connection that refuses to wait for
    /// the lock can still write.
    #[test]
    fn issue_21_defect_3_matching_runs_without_the_write_lock() {
        let (_dir, path, mut store) = store_with_map();
        let calls = Arc::new(AtomicUsize::new(0));
        let seen = Arc::clone(&calls);
        let mut other = impatient_writer(&path);
        store.before_write_lock = Some(Box::new(move || {
            seen.fetch_add(1, Ordering::SeqCst);
            other
                .import("elsewhere", &rooms(2, 0.0), meta())
                .expect("the write lock is free while matching");
        }));
        let done = store.import("m", &rooms(4, 0.5), meta()).unwrap();
        assert_eq!(calls.load(Ordering::SeqCst), 1);
        assert_eq!((done.revision.seq, done.revision.parent), (2, Some(1)));
        assert_eq!(store.revision("elsewhere", None).unwrap().seq, 1);
    }

    /// Issue 21, defect 3: when another writer adds a revision between
    /// matching and the lock, the import is matched again against the new
    /// latest revision instead of being written over a stale parent.
    #[test]
    fn issue_21_defect_3_stale_parent_is_matched_again() {
        let (_dir, path, mut store) = store_with_map();
        let mut other = impatient_writer(&path);
        let calls = Arc::new(AtomicUsize::new(0));
        let seen = Arc::clone(&calls);
        store.before_write_lock = Some(Box::new(move || {
            if seen.fetch_add(1, Ordering::SeqCst) == 0 {
                // A fifth room: the next import must continue this one.
                other.import("m", &rooms(5, 0.0), meta()).unwrap();
            }
        }));
        let done = store.import("m", &rooms(5, 0.25), meta()).unwrap();
        assert_eq!(calls.load(Ordering::SeqCst), 2);
        assert_eq!((done.revision.seq, done.revision.parent), (3, Some(2)));
        // Matched against revision 2, the fifth room continues room 5
        // (matched against revision 1 it would count as added).
        assert_eq!(done.revision.spaces_added, 0);
        assert_eq!(done.revision.spaces_changed, 5);
    }

    /// Issue 21, defect 3: a map that changes before every attempt fails
    /// with a clear "retry" after a bounded number of attempts, storing
    /// nothing.
    #[test]
    fn issue_21_defect_3_a_map_that_keeps_changing_fails_clearly() {
        let (_dir, path, mut store) = store_with_map();
        let mut other = impatient_writer(&path);
        let mut dx = 0.0;
        store.before_write_lock = Some(Box::new(move || {
            // A different model each time (the same one again would
            // write nothing).
            dx += 0.1;
            other.import("m", &rooms(4, dx), meta()).unwrap();
        }));
        let e = store.import("m", &rooms(4, 0.5), meta()).unwrap_err();
        assert!(
            matches!(e, StoreError::MapChanged { attempts, .. } if attempts == MAX_IMPORT_ATTEMPTS),
            "{e:?}"
        );
        assert!(e.to_string().contains("retry"), "{e}");
        let revs = store.revisions("m").unwrap();
        assert_eq!(revs.len(), 1 + MAX_IMPORT_ATTEMPTS);
        assert!(revs.iter().all(|r| r.message == "test"));
    }

    /// Issue 21, defect 8: 20 000 piled cells imported over a revision of
    /// piled cells took 11 min and 4.5 GB to match; past
    /// [`MAX_MATCH_PAIRS`] overlapping pairs the import is refused at once,
    /// storing nothing.
    #[test]
    fn issue_21_defect_8_a_pile_over_a_pile_is_refused() {
        let pile = |n: u32, dx: f64| {
            let square = vec![[dx, 0.0], [dx + 2.0, 0.0], [dx + 2.0, 2.0], [dx, 2.0]];
            let spaces = (1..=n)
                .map(|k| Space::new(SpaceId(k), SpaceKind::Room, [dx + 1.0, 1.0], square.clone()))
                .collect();
            Nrg::new(spaces, vec![]).unwrap()
        };
        let mut store = Store::open_in_memory().unwrap();
        store.import("piles", &pile(1_500, 0.0), meta()).unwrap();
        let e = store
            .import("piles", &pile(1_500, 0.1), meta())
            .unwrap_err();
        assert!(matches!(e, StoreError::TooManyOverlaps { .. }), "{e:?}");
        assert!(e.to_string().contains("piled"), "{e}");
        assert_eq!(store.revisions("piles").unwrap().len(), 1);
    }
}

#[cfg(test)]
mod unchanged_tests {
    use crate::store::{ImportMeta, Store};

    /// Issue 22: re-importing the latest revision's model writes nothing
    /// and says so; a different one writes the next revision.
    #[test]
    fn an_identical_import_makes_no_revision() {
        let mut store = Store::open_in_memory().unwrap();
        let nrg = crate::fixtures::corridor_building(3);
        let first = store.import("m", &nrg, ImportMeta::new("a", "me")).unwrap();
        assert!(!first.unchanged);
        let again = store.import("m", &nrg, ImportMeta::new("b", "me")).unwrap();
        assert!(again.unchanged);
        assert_eq!(again.revision.seq, 1);
        assert_eq!(store.revisions("m").unwrap().len(), 1);
        let other = crate::fixtures::corridor_building(4);
        let next = store
            .import("m", &other, ImportMeta::new("c", "me"))
            .unwrap();
        assert!(!next.unchanged);
        assert_eq!(next.revision.seq, 2);
    }
}
