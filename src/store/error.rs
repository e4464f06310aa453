//! Errors of the store.

use std::path::{Path, PathBuf};

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
    /// The disk holding the database is full (SQLite's `SQLITE_FULL`, or
    /// `SQLITE_IOERR_SHMSIZE`: no room to grow the WAL index next to it);
    /// the transaction was rolled back.
    #[error("disk full: {} (nothing was stored; free some space and retry)", path.display())]
    DiskFull {
        /// The database file (empty until the store names it).
        path: PathBuf,
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
    /// Any other SQLite error.
    #[error("sqlite: {0}")]
    Sqlite(rusqlite::Error),
}

impl StoreError {
    /// Names the database file in errors that should name it (disk full).
    pub(crate) fn in_file(self, file: &Path) -> StoreError {
        match self {
            StoreError::DiskFull { path } if path.as_os_str().is_empty() => StoreError::DiskFull {
                path: file.to_path_buf(),
            },
            other => other,
        }
    }
}

impl From<rusqlite::Error> for StoreError {
    fn from(e: rusqlite::Error) -> Self {
        match e.sqlite_error_code() {
            Some(rusqlite::ErrorCode::DatabaseBusy | rusqlite::ErrorCode::DatabaseLocked) => {
                StoreError::Busy
            }
            Some(rusqlite::ErrorCode::DiskFull) => StoreError::DiskFull {
                path: PathBuf::new(),
            },
            // The unix VFS reports ENOSPC on the database or WAL file as
            // SQLITE_FULL, but a failed write growing the `-shm` WAL index
            // (the one-byte write that extends it) as SQLITE_IOERR_SHMSIZE,
            // "Error code 4874: disk I/O error" (issue 21, defect 10).
            _ if extended_code(&e) == Some(rusqlite::ffi::SQLITE_IOERR_SHMSIZE) => {
                StoreError::DiskFull {
                    path: PathBuf::new(),
                }
            }
            _ => StoreError::Sqlite(e),
        }
    }
}

fn extended_code(e: &rusqlite::Error) -> Option<std::ffi::c_int> {
    match e {
        rusqlite::Error::SqliteFailure(f, _) => Some(f.extended_code),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sqlite(extended_code: std::ffi::c_int) -> rusqlite::Error {
        rusqlite::Error::SqliteFailure(rusqlite::ffi::Error::new(extended_code), None)
    }

    /// Issue 21, defect 10: a full disk said "Error code 4874: disk I/O
    /// error"; SQLITE_FULL and SQLITE_IOERR_SHMSIZE now say "disk full"
    /// and name the file, other I/O errors stay as SQLite put them.
    #[test]
    fn issue_21_defect_10_disk_full_is_named() {
        for code in [
            rusqlite::ffi::SQLITE_FULL,
            rusqlite::ffi::SQLITE_IOERR_SHMSIZE,
        ] {
            let e = StoreError::from(sqlite(code)).in_file(Path::new("/data/x.sqlite"));
            assert!(matches!(e, StoreError::DiskFull { .. }), "{code}: {e:?}");
            assert!(
                e.to_string().starts_with("disk full: /data/x.sqlite"),
                "{e}"
            );
        }
        let e = StoreError::from(sqlite(rusqlite::ffi::SQLITE_IOERR_READ));
        assert!(matches!(e, StoreError::Sqlite(_)), "{e:?}");
        assert!(matches!(
            StoreError::from(sqlite(rusqlite::ffi::SQLITE_BUSY)),
            StoreError::Busy
        ));
    }
}
