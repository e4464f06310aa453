//! The one path of an edit into the store (issue 22): the edit applied to
//! the map's latest revision and validated ([`crate::edit::apply`]), its
//! connection lengths walked as for any import, then stored as the next
//! revision together with the correction that re-applies it to later
//! imports, in one transaction. The edit is computed without the write
//! lock; if another writer got in first it is computed again on the new
//! latest revision, a bounded number of times.

use crate::edit::{Edit, EditError, Rule, apply};
use crate::route::walked_model;
use crate::store::{ImportMeta, RevisionInfo, Store, StoreError};

/// An edit stored.
#[derive(Debug, Clone, PartialEq)]
pub struct Corrected {
    /// The revision it made.
    pub revision: RevisionInfo,
    /// The correction's number within the map.
    pub correction: u32,
    /// Spaces it made (ids in the new revision).
    pub created: Vec<crate::model::SpaceId>,
    /// Spaces it removed.
    pub removed: Vec<crate::model::SpaceId>,
}

/// Why an edit was not stored.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum CorrectError {
    /// The edit itself is refused (the reason names the space).
    #[error(transparent)]
    Edit(#[from] EditError),
    /// The store failed or the map does not exist.
    #[error(transparent)]
    Store(#[from] StoreError),
}

/// How many times an edit is computed again when another writer changed
/// the map meanwhile.
const MAX_ATTEMPTS: usize = 3;

/// Applies `edit` to the latest revision of `map` and stores the result
/// and the correction (written as `statement`); see the module doc.
///
/// ```
/// use nrgdb::edit::Edit;
/// use nrgdb::model::{SpaceId, SpaceKind};
/// use nrgdb::store::{ImportMeta, Store};
/// let mut store = Store::open_in_memory()?;
/// let nrg = nrgdb::fixtures::corridor_building(2);
/// nrgdb::ingest::ingest(&mut store, "lab", &nrg, ImportMeta::new("first", "ada"), None)?;
/// let edit = Edit::SetKind { space: SpaceId(10), kind: SpaceKind::Corridor };
/// let done = nrgdb::ingest::edit(&mut store, "lab", &edit, "SET 10 KIND corridor", ImportMeta::new("a passage", "ada"))?;
/// assert_eq!((done.revision.seq, done.correction), (2, 1));
/// assert_eq!(store.load("lab", None)?.space(SpaceId(10)).unwrap().kind, SpaceKind::Corridor);
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn edit(
    store: &mut Store,
    map: &str,
    edit: &Edit,
    statement: &str,
    meta: ImportMeta,
) -> Result<Corrected, CorrectError> {
    let mut attempt = 0;
    loop {
        attempt += 1;
        let base = store.revision(map, None)?.seq;
        let nrg = store.load(map, Some(base))?;
        let next = store.next_space_id(map)?;
        let edited = apply(&nrg, edit, next)?;
        let rule = Rule::record(&nrg, edit)?;
        let walked = walked_model(&edited.nrg);
        match store.commit_edit(map, (base, &nrg), &walked.nrg, &meta, statement, &rule) {
            Ok((revision, correction)) => {
                return Ok(Corrected {
                    revision,
                    correction,
                    created: edited.created,
                    removed: edited.removed,
                });
            }
            Err(StoreError::Stale { .. }) if attempt < MAX_ATTEMPTS => continue,
            Err(e) => return Err(e.into()),
        }
    }
}
