//! Errors of the store.

use std::path::PathBuf;

use crate::model::{ModelError, SpaceId};

/// What can go wrong opening, reading or writing an nrgdb database.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum StoreError {
    /// The file could not be opened as an SQLite database.
    #[error("cannot open database {path}: {source} (is it an nrgdb database?)")]
    Open {
        /// The database file.
        path: PathBuf,
        /// What SQLite said.
        source: rusqlite::Error,
    },
    /// The database was written by a newer nrgdb; it was not modified.
    #[error(
        "database {path} has schema version {found}, but this nrgdb knows only up to {known}; \
         it was left untouched (upgrade nrgdb to use it)"
    )]
    TooNew {
        /// The database file.
        path: PathBuf,
        /// `user_version` found in the file.
        found: i64,
        /// The newest schema version this build knows.
        known: i64,
    },
    /// Applying the schema migrations failed.
    #[error("cannot bring database {path} to schema version {known}: {message}")]
    Migration {
        /// The database file.
        path: PathBuf,
        /// The schema version aimed at.
        known: i64,
        /// What went wrong.
        message: String,
    },
    /// Another process holds the write lock past the busy timeout.
    #[error("database is busy (another nrgdb is writing); retry")]
    Busy,
    /// No map of that name.
    #[error("no map named '{name}'; maps are: {known} (see `nrgdb maps`)")]
    NoSuchMap {
        /// The name asked for.
        name: String,
        /// The maps there are, comma separated, or "(none)".
        known: String,
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
    #[error(
        "database is damaged: map '{map}' space row {row}: {what} (run `PRAGMA integrity_check`)"
    )]
    Corrupt {
        /// The map.
        map: String,
        /// The row id in table `spaces` (0 for a connection).
        row: i64,
        /// What is wrong with it.
        what: String,
    },
    /// Any other SQLite error.
    #[error("sqlite: {0}")]
    Sqlite(rusqlite::Error),
}

impl From<rusqlite::Error> for StoreError {
    fn from(e: rusqlite::Error) -> Self {
        match e.sqlite_error_code() {
            Some(rusqlite::ErrorCode::DatabaseBusy | rusqlite::ErrorCode::DatabaseLocked) => {
                StoreError::Busy
            }
            _ => StoreError::Sqlite(e),
        }
    }
}
