//! Errors of the store.

use std::path::PathBuf;

use crate::model::{ModelError, SpaceId};

/// What can go wrong opening, reading or writing an nrgdb database.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum StoreError {
    /// A command that only reads was pointed at a database file that does
    /// not exist (it is not created: a typo would leave an empty one).
    #[error("no database at {}; `nrgdb import` creates one", path.display())]
    NoDatabase {
        /// The path given.
        path: PathBuf,
    },
    /// The database could not be opened (not an nrgdb database, no such
    /// server, refused login).
    #[error("cannot open database {location}: {source} (is it an nrgdb database?)")]
    Open {
        /// The database file or URL (without its password).
        location: String,
        /// What the engine said.
        source: Box<dyn std::error::Error + Send + Sync>,
    },
    /// The database was written by a newer nrgdb; it was not modified.
    #[error(
        "database {path} has schema version {found}, but this nrgdb knows only up to {known}; \
         it was left untouched (upgrade nrgdb to use it)"
    )]
    TooNew {
        /// The database file or URL.
        path: String,
        /// `user_version` found in the file.
        found: i64,
        /// The newest schema version this build knows.
        known: i64,
    },
    /// Applying the schema migrations failed.
    #[error("cannot bring database {path} to schema version {known}: {message}")]
    Migration {
        /// The database file or URL.
        path: String,
        /// The schema version aimed at.
        known: i64,
        /// What went wrong.
        message: String,
    },
    /// Another process holds the write lock past the busy timeout.
    #[error("database is busy (another nrgdb is writing); retry")]
    Busy,
    /// No map of that name.
    #[error(
        "no map named '{name}'; {}maps are: {known} (see `nrgdb maps`)",
        suggestion.as_ref().map_or_else(String::new, |s| format!("did you mean '{s}'? "))
    )]
    NoSuchMap {
        /// The name asked for.
        name: String,
        /// The maps there are, comma separated, or "(none)".
        known: String,
        /// The known map closest to `name` when it looks like a typo
        /// (see [`crate::query::suggest`]).
        suggestion: Option<String>,
    },
    /// No revision of that number.
    #[error("revision {rev} of map '{map}' does not exist (latest is {latest})")]
    NoSuchRevision {
        /// The map.
        map: String,
        /// The revision asked for.
        rev: u32,
        /// The latest revision of the map.
        latest: u32,
    },
    /// No space of that id in the revision.
    #[error("map '{map}' has no space {id} in revision {rev} (see `nrgdb export {map}`)")]
    NoSuchSpace {
        /// The map.
        map: String,
        /// The space asked for.
        id: SpaceId,
        /// The revision searched.
        rev: u32,
    },
    /// A map name that cannot be used.
    #[error("bad map name '{name}': {reason}")]
    BadMapName {
        /// The name given.
        name: String,
        /// Why it is refused.
        reason: &'static str,
    },
    /// A revision's message, author or source name is too long to keep.
    #[error("revision {field} has {chars} characters; at most {limit} are allowed")]
    TooLong {
        /// Which field.
        field: &'static str,
        /// Its length in characters.
        chars: usize,
        /// The limit.
        limit: usize,
    },
    /// The model to store breaks an invariant.
    #[error("model refused: {0}")]
    Model(#[from] ModelError),
    /// A stored row could not be decoded.
    #[error("database is damaged: map '{map}' row {row}: {what}")]
    Corrupt {
        /// The map.
        map: String,
        /// The row id in the engine's table of spaces (0 for a connection
        /// or another record).
        row: i64,
        /// What is wrong with it.
        what: String,
    },
    /// The disk holding the database is full (SQLite's `SQLITE_FULL` or
    /// `SQLITE_IOERR_SHMSIZE`, PostgreSQL's `disk_full`); the transaction
    /// was rolled back.
    #[error("disk full: {location} (nothing was stored; free some space and retry)")]
    DiskFull {
        /// The database file or URL.
        location: String,
    },
    /// A correction number the map does not have.
    #[error("map '{map}' has no correction {id}")]
    NoSuchCorrection {
        /// The map.
        map: String,
        /// The number asked for.
        id: u32,
    },
    /// A correction that is not the map's last edit (or already dropped)
    /// cannot be undone.
    #[error(
        "correction {id} of map '{map}' made revision {made_on}, but the latest is {latest} (or it was dropped): only the last edit can be undone; drop it instead (nrgdb corrections {map} --drop {id})"
    )]
    CannotUndo {
        /// The map.
        map: String,
        /// The correction.
        id: u32,
        /// The revision it made.
        made_on: u32,
        /// The latest revision.
        latest: u32,
    },
    /// Another writer changed the map (a revision or a correction) between
    /// reading it and writing; nothing was stored.
    #[error("map '{map}' changed while this change was being prepared; nothing was stored, retry")]
    Stale {
        /// The map.
        map: String,
    },
    /// A stored correction that cannot be read back.
    #[error("correction {id} of map '{map}' is unreadable: {message}")]
    BadCorrection {
        /// The map.
        map: String,
        /// The correction.
        id: u32,
        /// What is wrong.
        message: String,
    },
    /// Another writer added a revision to the map every time this import
    /// had matched its spaces against the latest one; nothing was stored.
    #[error(
        "map '{map}' changed while this import was being matched, {attempts} times in a row; retry"
    )]
    MapChanged {
        /// The map.
        map: String,
        /// How many times the import was matched.
        attempts: usize,
    },
    /// The imported model's spaces overlap the parent revision's too much
    /// to be matched in bounded time (spaces piled on each other).
    #[error(
        "cannot match this model to the map's latest revision: more than {limit} pairs of \
         their spaces overlap (are spaces piled on each other?); nothing was stored"
    )]
    TooManyOverlaps {
        /// The bound on overlapping pairs.
        limit: usize,
    },
    /// Any other fault of the engine (I/O, a lost connection, a bug).
    #[error("{engine}: {source}")]
    Backend {
        /// Which engine ("sqlite", "postgres").
        engine: &'static str,
        /// What it said.
        source: Box<dyn std::error::Error + Send + Sync>,
    },
}

impl StoreError {
    /// [`StoreError::NoSuchMap`] for `name`, listing the maps there are
    /// and suggesting the closest when it looks like a typo.
    pub(crate) fn no_such_map(name: &str, names: &[String]) -> StoreError {
        let known = if names.is_empty() {
            "(none)".to_string()
        } else {
            names.join(", ")
        };
        StoreError::NoSuchMap {
            name: name.to_string(),
            known,
            suggestion: crate::query::suggest(name, names.iter().map(String::as_str))
                .map(str::to_string),
        }
    }

    /// Whether this is a fault of the storage (disk, database, engine)
    /// rather than a mistake in the request: servers answer it 500/503
    /// and log the details.
    pub fn is_fault(&self) -> bool {
        matches!(
            self,
            StoreError::Open { .. }
                | StoreError::TooNew { .. }
                | StoreError::Migration { .. }
                | StoreError::Corrupt { .. }
                | StoreError::DiskFull { .. }
                | StoreError::BadCorrection { .. }
                | StoreError::Backend { .. }
        )
    }
}
