//! What PostgreSQL's errors mean to the store (busy, disk full, damaged,
//! a fault), as [`Fault`]s inside the PostgreSQL engine.

use postgres::error::SqlState;

use crate::store::StoreError;
pub(crate) use crate::store::fault::{Fault, R, fail};

impl From<postgres::Error> for Fault {
    fn from(e: postgres::Error) -> Fault {
        Fault(classify(e))
    }
}

/// What a PostgreSQL error means to the store: busy (lock timeout,
/// serialization failure, deadlock), disk full, damaged data, or a fault.
pub(crate) fn classify(e: postgres::Error) -> StoreError {
    let code = e.code().cloned();
    match code {
        Some(c)
            if c == SqlState::LOCK_NOT_AVAILABLE
                || c == SqlState::T_R_SERIALIZATION_FAILURE
                || c == SqlState::T_R_DEADLOCK_DETECTED
                || c == SqlState::TOO_MANY_CONNECTIONS =>
        {
            StoreError::Busy
        }
        Some(c) if c == SqlState::DISK_FULL => StoreError::DiskFull {
            location: String::new(),
        },
        Some(c) if c == SqlState::DATA_CORRUPTED || c == SqlState::INDEX_CORRUPTED => {
            StoreError::Corrupt {
                map: String::new(),
                row: 0,
                what: e.to_string(),
            }
        }
        _ => StoreError::Backend {
            engine: "postgres",
            source: Box::new(e),
        },
    }
}
