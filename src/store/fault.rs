//! Engine errors inside an engine: [`Fault`] carries a [`StoreError`], so
//! `?` works on the store's errors and (with each engine's own `From`
//! impl for its client's error type) on the engine's, and becomes a plain
//! [`StoreError`] — with no engine type in it — at the engine's edge.

use super::StoreError;

/// An error inside an engine.
#[derive(Debug)]
pub(crate) struct Fault(pub(crate) StoreError);

/// Results inside an engine.
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
