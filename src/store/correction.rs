//! Corrections kept with a map (issue 22): each edit made on a revision is
//! stored as a rule ([`crate::edit::Rule`]) next to the revision it made,
//! in the same commit, and every later import records whether it still
//! applied. Dropping a correction keeps it (with the time) so the history
//! says what was undone. These are the records every engine keeps.

use serde::Serialize;

use crate::edit::Rule;

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
    /// The state as engines store it: a `dropped_at` time wins, else the
    /// stored `state` text (`failed` or `applied`).
    pub(crate) fn from_stored(dropped: bool, state: &str) -> CorrectionState {
        match (dropped, state) {
            (true, _) => CorrectionState::Dropped,
            (false, "failed") => CorrectionState::Failed,
            (false, _) => CorrectionState::Applied,
        }
    }

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
    /// How many corrections were ever made.
    pub made: i64,
    /// How many of them were dropped.
    pub dropped: i64,
}
