//! Models entering the database: the one path from a model (extracted from
//! a map, read from a file, uploaded, or made by applying a change set)
//! into the store. Every navigable connection's length becomes its walked
//! length ([`crate::route::walked_model`]) before the model is stored as
//! the next revision, so stored lengths are the lengths exports carry.
//!
//! Uses route and store; sits above both (the store knows nothing of
//! routing). Must not use HTTP or the terminal.
//!
//! ```
//! use nrgdb::ingest::ingest;
//! use nrgdb::store::{ImportMeta, Store};
//! let mut store = Store::open_in_memory()?;
//! let nrg = nrgdb::fixtures::corridor_building(2);
//! let done = ingest(&mut store, "lab", &nrg, ImportMeta::new("first", "ada"), None)?;
//! assert_eq!(done.imported.revision.seq, 1);
//! let stored = store.load("lab", None)?;
//! assert_eq!(stored, nrgdb::route::walked_model(&nrg).nrg);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::grid::OccupancyGrid;
use crate::model::Nrg;
use crate::route::walked_model;
use crate::store::{ImportMeta, Imported, Store, StoreError};

/// What [`ingest`] did.
#[derive(Debug, Clone, PartialEq)]
pub struct Ingested {
    /// The stored revision and the ids its spaces got.
    pub imported: Imported,
    /// How many connection lengths the walked lengths changed (by more
    /// than a millimetre).
    pub lengths_walked: usize,
}

/// Stores `nrg`, with walked connection lengths, as the next revision of
/// `map` (see [`Store::import_with_grid`]), keeping `grid` when given.
pub fn ingest(
    store: &mut Store,
    map: &str,
    nrg: &Nrg,
    meta: ImportMeta,
    grid: Option<&OccupancyGrid>,
) -> Result<Ingested, StoreError> {
    let walked = walked_model(nrg);
    let imported = store.import_with_grid(map, &walked.nrg, meta, grid)?;
    Ok(Ingested {
        imported,
        lengths_walked: walked.lengths_changed,
    })
}
