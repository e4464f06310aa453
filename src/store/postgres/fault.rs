//! PostgreSQL's errors inside the PostgreSQL engine: [`Fault`] carries a
//! store error, so `?` works on both, and becomes a [`StoreError`] (with no
//! client type in it) at the engine's edge.

use postgres::error::SqlState;

use crate::store::StoreError;

/// An error inside the PostgreSQL engine.
#[derive(Debug)]
pub(crate) struct Fault(pub(crate) StoreError);

/// Results inside the PostgreSQL engine.
pub(crate) type R<T> = Result<T, Fault>;

/// `Err(e)` as a [`Fault`].
pub(crate) fn fail<T>(e: StoreError) -> R<T> {
    Err(Fault(e))
}

impl From<StoreError> for Fault {
    fn from(e: StoreError) -> Fault {
        Fault(e)
    }
}

impl From<Fault> for StoreError {
    fn from(f: Fault) -> StoreError {
        f.0
    }
}

impl From<crate::model::ModelError> for Fault {
    fn from(e: crate::model::ModelError) -> Fault {
        Fault(StoreError::Model(e))
    }
}

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
