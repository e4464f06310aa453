//! The store as the query engine's [`Source`]: queries, `USE`, `NAME …
//! AS …` and the corrections run against SQLite revisions. It sits here,
//! above the store, because a correction is written through the one edit
//! path ([`super::edit`]: connection lengths walked on the navigation
//! layer, the correction kept), which the store must not know about.

use crate::edit::Edit;
use crate::grid::OccupancyGrid;
use crate::model::{Nrg, SpaceId};
use crate::query::EditDone;
use crate::query::{MapInfo, RevisionInfo, Source, SourceError};
use crate::store::{ImportMeta, Store, StoreError};

fn to_source(e: StoreError) -> SourceError {
    match e {
        StoreError::NoSuchMap {
            name, suggestion, ..
        } => SourceError::NoMap { name, suggestion },
        StoreError::NoSuchRevision { map, rev, .. } => SourceError::NoRevision {
            map,
            revision: u64::from(rev),
        },
        other => SourceError::Backend(Box::new(other)),
    }
}

fn revision_u32(map: &str, revision: u64) -> Result<u32, SourceError> {
    u32::try_from(revision).map_err(|_| SourceError::NoRevision {
        map: map.to_string(),
        revision,
    })
}

impl Source for Store {
    fn maps(&self) -> Result<Vec<MapInfo>, SourceError> {
        let maps = Store::maps(self).map_err(to_source)?;
        Ok(maps
            .into_iter()
            .map(|m| MapInfo {
                name: m.name,
                revisions: m.latest as usize,
                latest: u64::from(m.latest),
            })
            .collect())
    }

    fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, SourceError> {
        let revs = Store::revisions(self, map).map_err(to_source)?;
        Ok(revs
            .into_iter()
            .map(|r| RevisionInfo {
                revision: u64::from(r.seq),
                spaces: r.spaces,
                connections: r.connections,
                note: if r.message.is_empty() {
                    r.source_name.unwrap_or_default()
                } else {
                    r.message
                },
            })
            .collect())
    }

    fn load(&self, map: &str, revision: u64) -> Result<Nrg, SourceError> {
        Store::load(self, map, Some(revision_u32(map, revision)?)).map_err(to_source)
    }

    fn grid(&self, map: &str, revision: u64) -> Result<Option<OccupancyGrid>, SourceError> {
        Store::grid(self, map, Some(revision_u32(map, revision)?)).map_err(to_source)
    }

    fn rename_space(
        &mut self,
        map: &str,
        revision: u64,
        id: SpaceId,
        name: &str,
    ) -> Result<u64, SourceError> {
        let rev = revision_u32(map, revision)?;
        let latest = Store::revision(self, map, None).map_err(to_source)?.seq;
        if rev != latest {
            return Err(SourceError::NotLatest {
                map: map.to_string(),
                revision,
                latest: u64::from(latest),
            });
        }
        let meta = ImportMeta::new(format!("name space {id} \"{name}\""), "nrgdb query");
        let info = Store::rename_space(self, map, id, Some(name), meta).map_err(to_source)?;
        Ok(u64::from(info.seq))
    }

    fn edit(
        &mut self,
        map: &str,
        revision: u64,
        edit: &Edit,
        statement: &str,
        author: &str,
    ) -> Result<EditDone, SourceError> {
        let latest = Store::revision(self, map, None).map_err(to_source)?.seq;
        if revision != u64::from(latest) {
            return Err(SourceError::NotLatest {
                map: map.to_string(),
                revision,
                latest: u64::from(latest),
            });
        }
        let meta = ImportMeta::new(statement, author);
        match super::edit(self, map, edit, statement, meta) {
            Ok(done) => Ok(EditDone {
                revision: u64::from(done.revision.seq),
                correction: Some(done.correction),
                created: done.created,
                removed: done.removed,
            }),
            Err(super::CorrectError::Edit(e)) => Err(SourceError::Edit(e)),
            Err(super::CorrectError::Store(e)) => Err(to_source(e)),
        }
    }
}
