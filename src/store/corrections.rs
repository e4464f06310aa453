//! Corrections kept with a map (issue 22): each edit made on a revision is
//! stored as a rule ([`crate::edit::Rule`]) next to the revision it made,
//! in the same transaction, and every later import records whether it
//! still applied. Dropping a correction keeps its row (with the time) so
//! the history says what was undone.

use rusqlite::{Connection, OptionalExtension, TransactionBehavior, params};
use serde::Serialize;

use super::read::{latest, load_at, map_id};
use super::write::commit_revision;
use super::{ImportMeta, RevisionInfo, Store, StoreError};
use crate::edit::Rule;
use crate::model::{Nrg, SpaceId};

/// What became of a correction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum CorrectionState {
    /// It applied at the last import (or was just made).
    Applied,
    /// It no longer fitted at the last import (see the reason).
    Failed,
    /// Someone dropped it; imports no longer apply it.
    Dropped,
}

impl CorrectionState {
    /// The lower-case name used in listings.
    pub fn as_str(self) -> &'static str {
        match self {
            CorrectionState::Applied => "applied",
            CorrectionState::Failed => "failed",
            CorrectionState::Dropped => "dropped",
        }
    }
}

/// A stored correction.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Correction {
    /// Its number within the map, from 1.
    pub id: u32,
    /// The revision the edit made.
    pub made_on: u32,
    /// When it was made (UTC, ISO 8601).
    pub created_at: String,
    /// Who made it.
    pub author: String,
    /// The statement as written (`MERGE 3, 4 AS "Lobby"`).
    pub statement: String,
    /// Applied, failed or dropped.
    pub state: CorrectionState,
    /// Why it failed at the last import.
    pub reason: Option<String>,
    /// The revision its state was last decided at.
    pub checked_on: u32,
    /// The rule re-applied at each import.
    #[serde(skip)]
    pub rule: Rule,
}

/// What an import did with the map's corrections, to be stored with it.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct CorrectionResults {
    /// The corrections as read before the import ([`Store::corrections_key`]);
    /// the import is refused with [`StoreError::Stale`] when they changed.
    pub key: CorrectionsKey,
    /// Each active correction's result, in order: `Err` with the reason
    /// when it no longer applied.
    pub results: Vec<(u32, Result<(), String>)>,
}

/// Identifies the set of a map's corrections (how many were made and how
/// many dropped), to notice a change between reading and writing.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CorrectionsKey {
    made: i64,
    dropped: i64,
}

const COLUMNS: &str =
    "id, made_on, created_at, author, statement, rule, state, reason, checked_on, dropped_at";

impl Store {
    /// Every correction of `map`, oldest first (none for a map without
    /// any, or one not yet imported).
    pub fn corrections(&self, map: &str) -> Result<Vec<Correction>, StoreError> {
        let Some(id) = self.map_row(map)? else {
            return Ok(Vec::new());
        };
        read_corrections(&self.conn, id, map).map_err(|e| e.in_file(&self.path))
    }

    /// The key of `map`'s corrections now (see [`CorrectionResults::key`]).
    pub fn corrections_key(&self, map: &str) -> Result<CorrectionsKey, StoreError> {
        match self.map_row(map)? {
            Some(id) => key(&self.conn, id),
            None => Ok(CorrectionsKey::default()),
        }
    }

    /// Drops correction `id` of `map`: later imports no longer apply it.
    /// The revisions it made stay as they are.
    pub fn drop_correction(&mut self, map: &str, id: u32) -> Result<Correction, StoreError> {
        let tx = self
            .conn
            .transaction_with_behavior(TransactionBehavior::Immediate)?;
        let map_id = map_id(&tx, map)?;
        let changed = tx.execute(
            "UPDATE corrections SET dropped_at = strftime('%Y-%m-%dT%H:%M:%fZ', 'now')
             WHERE map_id = ?1 AND id = ?2 AND dropped_at IS NULL",
            params![map_id, id],
        )?;
        let all = read_corrections(&tx, map_id, map)?;
        let found = all.into_iter().find(|c| c.id == id);
        match (changed, found) {
            (_, Some(c)) => {
                tx.commit()?;
                Ok(c)
            }
            (_, None) => Err(StoreError::NoSuchCorrection {
                map: map.to_string(),
                id,
            }),
        }
    }

    /// Undoes correction `id` of `map`, which must have made the map's
    /// latest revision: writes a revision whose model is the one before
    /// the edit and drops the correction, in one transaction. Returns the
    /// new revision.
    pub fn undo_correction(&mut self, map: &str, id: u32) -> Result<RevisionInfo, StoreError> {
        self.undo_in_lock(map, id)
            .map_err(|e| e.in_file(&self.path))
    }

    fn undo_in_lock(&mut self, map: &str, id: u32) -> Result<RevisionInfo, StoreError> {
        let tx = self
            .conn
            .transaction_with_behavior(TransactionBehavior::Immediate)?;
        let map_id = map_id(&tx, map)?;
        let correction = read_corrections(&tx, map_id, map)?
            .into_iter()
            .find(|c| c.id == id)
            .ok_or_else(|| StoreError::NoSuchCorrection {
                map: map.to_string(),
                id,
            })?;
        let seq = latest(&tx, map_id)?;
        if correction.state == CorrectionState::Dropped || correction.made_on != seq || seq < 2 {
            return Err(StoreError::CannotUndo {
                map: map.to_string(),
                id,
                made_on: correction.made_on,
                latest: seq,
            });
        }
        let before = load_at(&tx, map_id, map, correction.made_on - 1)?;
        let now = load_at(&tx, map_id, map, seq)?;
        let meta = ImportMeta::new(
            format!("undo: {}", correction.statement),
            correction.author.clone(),
        );
        let info = commit_revision(&tx, map_id, map, Some(&(seq, now)), &before, &meta)?;
        tx.execute(
            "UPDATE corrections SET dropped_at = strftime('%Y-%m-%dT%H:%M:%fZ', 'now') WHERE map_id = ?1 AND id = ?2",
            params![map_id, id],
        )?;
        tx.commit()?;
        Ok(info)
    }

    /// One above the largest space id `map` ever used (1 for a new map):
    /// the first id an edit may give a new space.
    pub fn next_space_id(&self, map: &str) -> Result<SpaceId, StoreError> {
        match self.map_row(map)? {
            Some(id) => Ok(SpaceId(super::write::next_space_id(&self.conn, id)?)),
            None => Ok(SpaceId(1)),
        }
    }

    /// Stores `nrg` (revision `base` of `map` with an edit applied, ids as
    /// they are) as the next revision, and the edit as a correction, in
    /// one transaction. Refused with [`StoreError::Stale`] when `base` is no
    /// longer the latest revision. Returns the revision and the
    /// correction's number.
    pub fn commit_edit(
        &mut self,
        map: &str,
        base: u32,
        nrg: &Nrg,
        meta: &ImportMeta,
        statement: &str,
        rule: &Rule,
    ) -> Result<(RevisionInfo, u32), StoreError> {
        let rule_json = serde_json::to_string(rule).map_err(|e| StoreError::BadCorrection {
            map: map.to_string(),
            id: 0,
            message: e.to_string(),
        })?;
        self.commit_edit_in_lock(map, base, nrg, meta, statement, &rule_json)
            .map_err(|e| e.in_file(&self.path))
    }

    fn commit_edit_in_lock(
        &mut self,
        map: &str,
        base: u32,
        nrg: &Nrg,
        meta: &ImportMeta,
        statement: &str,
        rule: &str,
    ) -> Result<(RevisionInfo, u32), StoreError> {
        let tx = self
            .conn
            .transaction_with_behavior(TransactionBehavior::Immediate)?;
        let map_id = map_id(&tx, map)?;
        if latest(&tx, map_id)? != base || base == 0 {
            return Err(StoreError::Stale {
                map: map.to_string(),
            });
        }
        let parent = load_at(&tx, map_id, map, base)?;
        let info = commit_revision(&tx, map_id, map, Some(&(base, parent)), nrg, meta)?;
        let next: u32 = tx.query_row(
            "SELECT COALESCE(MAX(id), 0) + 1 FROM corrections WHERE map_id = ?1",
            [map_id],
            |r| r.get(0),
        )?;
        tx.execute(
            "INSERT INTO corrections (map_id, id, made_on, created_at, author, statement, rule, state, checked_on)
             VALUES (?1, ?2, ?3, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'), ?4, ?5, ?6, 'applied', ?3)",
            params![map_id, next, info.seq, meta.author, statement, rule],
        )?;
        tx.commit()?;
        Ok((info, next))
    }

    fn map_row(&self, map: &str) -> Result<Option<i64>, StoreError> {
        Ok(self
            .conn
            .query_row("SELECT id FROM maps WHERE name = ?1", [map], |r| r.get(0))
            .optional()?)
    }
}

/// Checks, under the write lock, that `map_id`'s corrections are still
/// those `reapplied` was computed from, and records each result at
/// revision `seq`.
pub(super) fn record_results(
    conn: &Connection,
    map: &str,
    map_id: i64,
    seq: u32,
    reapplied: &CorrectionResults,
) -> Result<(), StoreError> {
    if key(conn, map_id)? != reapplied.key {
        return Err(StoreError::Stale {
            map: map.to_string(),
        });
    }
    let mut update = conn.prepare_cached(
        "UPDATE corrections SET state = ?3, reason = ?4, checked_on = ?5 WHERE map_id = ?1 AND id = ?2",
    )?;
    for (id, result) in &reapplied.results {
        let (state, reason) = match result {
            Ok(()) => ("applied", None),
            Err(reason) => ("failed", Some(reason.as_str())),
        };
        update.execute(params![map_id, id, state, reason, seq])?;
    }
    Ok(())
}

fn key(conn: &Connection, map_id: i64) -> Result<CorrectionsKey, StoreError> {
    Ok(conn.query_row(
        "SELECT COUNT(*), COUNT(dropped_at) FROM corrections WHERE map_id = ?1",
        [map_id],
        |r| {
            Ok(CorrectionsKey {
                made: r.get(0)?,
                dropped: r.get(1)?,
            })
        },
    )?)
}

fn read_corrections(
    conn: &Connection,
    map_id: i64,
    map: &str,
) -> Result<Vec<Correction>, StoreError> {
    let mut stmt = conn.prepare_cached(&format!(
        "SELECT {COLUMNS} FROM corrections WHERE map_id = ?1 ORDER BY id"
    ))?;
    let rows = stmt.query_map([map_id], |r| {
        Ok((
            r.get::<_, u32>(0)?,
            r.get::<_, u32>(1)?,
            r.get::<_, String>(2)?,
            r.get::<_, String>(3)?,
            r.get::<_, String>(4)?,
            r.get::<_, String>(5)?,
            r.get::<_, String>(6)?,
            r.get::<_, Option<String>>(7)?,
            r.get::<_, u32>(8)?,
            r.get::<_, Option<String>>(9)?,
        ))
    })?;
    let mut out = Vec::new();
    for row in rows {
        let (id, made_on, created_at, author, statement, rule, state, reason, checked_on, dropped) =
            row?;
        let rule: Rule = serde_json::from_str(&rule).map_err(|e| StoreError::BadCorrection {
            map: map.to_string(),
            id,
            message: e.to_string(),
        })?;
        let state = match (dropped.is_some(), state.as_str()) {
            (true, _) => CorrectionState::Dropped,
            (false, "failed") => CorrectionState::Failed,
            (false, _) => CorrectionState::Applied,
        };
        out.push(Correction {
            id,
            made_on,
            created_at,
            author,
            statement,
            state,
            reason,
            checked_on,
            rule,
        });
    }
    Ok(out)
}
