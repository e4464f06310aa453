//! What SQLite's errors mean to the store (busy, disk full, damaged, a
//! fault), as [`Fault`]s inside the SQLite engine.

use crate::store::StoreError;
pub(crate) use crate::store::fault::{Fault, R, fail};

impl From<rusqlite::Error> for Fault {
    fn from(e: rusqlite::Error) -> Fault {
        Fault(classify(e))
    }
}

/// What an SQLite error means to the store: busy, disk full, or a fault.
fn classify(e: rusqlite::Error) -> StoreError {
    match e.sqlite_error_code() {
        Some(rusqlite::ErrorCode::DatabaseBusy | rusqlite::ErrorCode::DatabaseLocked) => {
            StoreError::Busy
        }
        Some(rusqlite::ErrorCode::DiskFull) => StoreError::DiskFull {
            location: String::new(),
        },
        // The unix VFS reports ENOSPC on the database or WAL file as
        // SQLITE_FULL, but a failed write growing the `-shm` WAL index
        // (the one-byte write that extends it) as SQLITE_IOERR_SHMSIZE,
        // "Error code 4874: disk I/O error" (issue 21, defect 10).
        _ if extended_code(&e) == Some(rusqlite::ffi::SQLITE_IOERR_SHMSIZE) => {
            StoreError::DiskFull {
                location: String::new(),
            }
        }
        Some(rusqlite::ErrorCode::DatabaseCorrupt | rusqlite::ErrorCode::NotADatabase) => {
            StoreError::Corrupt {
                map: String::new(),
                row: 0,
                what: e.to_string(),
            }
        }
        _ => StoreError::Backend {
            engine: "sqlite",
            source: Box::new(e),
        },
    }
}

fn extended_code(e: &rusqlite::Error) -> Option<std::ffi::c_int> {
    match e {
        rusqlite::Error::SqliteFailure(f, _) => Some(f.extended_code),
        _ => None,
    }
}

/// Names the database file in errors that should name it (disk full).
pub(crate) fn in_file(e: StoreError, file: &std::path::Path) -> StoreError {
    match e {
        StoreError::DiskFull { location } if location.is_empty() => StoreError::DiskFull {
            location: file.display().to_string(),
        },
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

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
            let e = in_file(classify(sqlite(code)), Path::new("/data/x.sqlite"));
            assert!(matches!(e, StoreError::DiskFull { .. }), "{code}: {e:?}");
            assert!(
                e.to_string().starts_with("disk full: /data/x.sqlite"),
                "{e}"
            );
        }
        let e = classify(sqlite(rusqlite::ffi::SQLITE_IOERR_READ));
        assert!(matches!(e, StoreError::Backend { .. }), "{e:?}");
        assert!(e.is_fault());
        assert!(matches!(
            classify(sqlite(rusqlite::ffi::SQLITE_BUSY)),
            StoreError::Busy
        ));
    }
}
