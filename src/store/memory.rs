//! The memory engine: every map and revision held in memory, behind a
//! mutex so that clones of one [`MemoryStore`] share it (several writers,
//! as with a database). For tests, one-off conversions and the conformance
//! suite's reference. Nothing is kept when the last clone is dropped.

use std::collections::BTreeMap;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Duration;

use super::delta::{Delta, smallest_containing};
use super::engine::{Commit, Committed, Engine, ReadStore, WriteStore};
use super::{
    Correction, CorrectionState, CorrectionsKey, EncodedGrid, MapInfo, RevisionInfo, StoreError,
    now_utc,
};
use crate::edit::Rule;
use crate::model::{Georef, Nrg, SpaceId};

/// Maps held in memory; clones share them.
#[derive(Debug, Clone, Default)]
pub struct MemoryStore {
    data: Arc<Mutex<Data>>,
}

#[derive(Debug, Default)]
struct Data {
    maps: BTreeMap<String, MapData>,
    commits: u64,
}

#[derive(Debug)]
struct MapData {
    created_at: String,
    revisions: Vec<Stored>,
    corrections: Vec<Correction>,
    /// The largest space id ever stored.
    max_space_id: u32,
    georef: Option<Georef>,
}

#[derive(Debug)]
struct Stored {
    info: RevisionInfo,
    nrg: Arc<Nrg>,
    grid: Option<EncodedGrid>,
}

impl MemoryStore {
    /// An empty store.
    pub fn new() -> MemoryStore {
        MemoryStore::default()
    }

    fn data(&self) -> MutexGuard<'_, Data> {
        self.data.lock().unwrap_or_else(|p| p.into_inner())
    }
}

impl Data {
    fn map(&self, map: &str) -> Result<&MapData, StoreError> {
        self.maps.get(map).ok_or_else(|| {
            let names: Vec<String> = self.maps.keys().cloned().collect();
            StoreError::no_such_map(map, &names)
        })
    }

    fn stored(&self, map: &str, rev: Option<u32>) -> Result<&Stored, StoreError> {
        let m = self.map(map)?;
        let latest = m.revisions.len() as u32;
        let seq = match rev {
            None if latest > 0 => latest,
            Some(r) if r >= 1 && r <= latest => r,
            _ => {
                return Err(StoreError::NoSuchRevision {
                    map: map.to_string(),
                    rev: rev.unwrap_or(0),
                    latest,
                });
            }
        };
        Ok(&m.revisions[(seq - 1) as usize])
    }
}

impl ReadStore for MemoryStore {
    fn location(&self) -> String {
        ":memory:".to_string()
    }

    fn maps(&self) -> Result<Vec<MapInfo>, StoreError> {
        Ok(self
            .data()
            .maps
            .iter()
            .map(|(name, m)| MapInfo {
                name: name.clone(),
                created_at: m.created_at.clone(),
                latest: m.revisions.len() as u32,
            })
            .collect())
    }

    fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, StoreError> {
        let data = self.data();
        Ok(data
            .map(map)?
            .revisions
            .iter()
            .map(|s| s.info.clone())
            .collect())
    }

    fn revision(&self, map: &str, rev: Option<u32>) -> Result<RevisionInfo, StoreError> {
        Ok(self.data().stored(map, rev)?.info.clone())
    }

    fn load(&self, map: &str, rev: Option<u32>) -> Result<Nrg, StoreError> {
        Ok((*self.data().stored(map, rev)?.nrg).clone())
    }

    fn locate(
        &self,
        map: &str,
        rev: Option<u32>,
        x: f64,
        y: f64,
    ) -> Result<Option<SpaceId>, StoreError> {
        let nrg = Arc::clone(&self.data().stored(map, rev)?.nrg);
        Ok(smallest_containing(
            [x, y],
            nrg.spaces()
                .iter()
                .map(|s| (s.id, &s.polygon, s.holes.as_slice())),
        ))
    }

    fn grid(&self, map: &str, rev: Option<u32>) -> Result<Option<EncodedGrid>, StoreError> {
        Ok(self.data().stored(map, rev)?.grid.clone())
    }

    fn corrections(&self, map: &str) -> Result<Vec<Correction>, StoreError> {
        Ok(self
            .data()
            .maps
            .get(map)
            .map(|m| m.corrections.clone())
            .unwrap_or_default())
    }

    fn corrections_key(&self, map: &str) -> Result<CorrectionsKey, StoreError> {
        Ok(self
            .data()
            .maps
            .get(map)
            .map(|m| key(&m.corrections))
            .unwrap_or_default())
    }

    fn next_space_id(&self, map: &str) -> Result<SpaceId, StoreError> {
        Ok(SpaceId(self.data().maps.get(map).map_or(1, |m| {
            if m.revisions.is_empty() {
                1
            } else {
                m.max_space_id.saturating_add(1)
            }
        })))
    }

    fn change_token(&self) -> Result<Option<u64>, StoreError> {
        Ok(Some(self.data().commits))
    }

    fn georef(&self, map: &str) -> Result<Option<Georef>, StoreError> {
        Ok(self.data().map(map)?.georef.clone())
    }
}

fn key(corrections: &[Correction]) -> CorrectionsKey {
    CorrectionsKey {
        made: corrections.len() as i64,
        dropped: corrections
            .iter()
            .filter(|c| c.state == CorrectionState::Dropped)
            .count() as i64,
    }
}

impl WriteStore for MemoryStore {
    fn commit(&mut self, c: &Commit<'_>) -> Result<Committed, StoreError> {
        let mut data = self.data();
        let stale = || StoreError::Stale {
            map: c.map.to_string(),
        };
        match data.maps.get(c.map) {
            Some(m) if m.revisions.len() as u32 != c.base => return Err(stale()),
            Some(_) => {}
            None if c.base == 0 => {}
            None => return data.map(c.map).map(|_| ()).and(Err(stale())),
        }
        // Check everything before changing anything: all or nothing.
        let correction_rule: Option<Rule> = match c.correction {
            Some(new) => Some(serde_json::from_str(new.rule_json).map_err(|e| {
                StoreError::BadCorrection {
                    map: c.map.to_string(),
                    id: 0,
                    message: e.to_string(),
                }
            })?),
            None => None,
        };
        if let Some(reapplied) = c.reapplied {
            let now = data
                .maps
                .get(c.map)
                .map(|m| key(&m.corrections))
                .unwrap_or_default();
            if now != reapplied.key {
                return Err(stale());
            }
        }
        if let Some(id) = c.drops {
            let live = data
                .maps
                .get(c.map)
                .and_then(|m| m.corrections.iter().find(|k| k.id == id))
                .is_some_and(|k| k.state != CorrectionState::Dropped);
            if !live {
                return Err(StoreError::NoSuchCorrection {
                    map: c.map.to_string(),
                    id,
                });
            }
        }
        if c.nrg.is_none() && c.base == 0 {
            return Err(StoreError::NoSuchRevision {
                map: c.map.to_string(),
                rev: 1,
                latest: 0,
            });
        }
        let now = now_utc();
        let m = data
            .maps
            .entry(c.map.to_string())
            .or_insert_with(|| MapData {
                created_at: now.clone(),
                revisions: Vec::new(),
                corrections: Vec::new(),
                max_space_id: 0,
                georef: None,
            });
        let seq = match c.nrg {
            Some(nrg) => {
                let empty = Nrg::default();
                let parent = match c.base {
                    0 => &empty,
                    b => &*m.revisions[(b - 1) as usize].nrg,
                };
                let delta = Delta::between(parent, nrg);
                let seq = c.base + 1;
                let info = RevisionInfo {
                    map: c.map.to_string(),
                    seq,
                    parent: (c.base > 0).then_some(c.base),
                    created_at: c.meta.recorded_at.clone().unwrap_or_else(|| now.clone()),
                    source_name: c.meta.source_name.clone(),
                    source_sha256: c.meta.source_sha256.clone(),
                    params: c.meta.params.clone(),
                    message: c.meta.message.clone(),
                    author: c.meta.author.clone(),
                    spaces: nrg.spaces().len(),
                    connections: nrg.connections().len(),
                    spaces_added: delta.added,
                    spaces_changed: delta.changed,
                    spaces_removed: delta.removed,
                };
                if let Some(max) = nrg.spaces().iter().map(|s| s.id.0).max() {
                    m.max_space_id = m.max_space_id.max(max);
                }
                m.revisions.push(Stored {
                    info,
                    nrg: Arc::new(nrg.clone()),
                    grid: c.grid.cloned(),
                });
                seq
            }
            None => c.base,
        };
        if let Some(reapplied) = c.reapplied {
            for (id, result) in &reapplied.results {
                if let Some(k) = m.corrections.iter_mut().find(|k| k.id == *id) {
                    k.state = if result.is_ok() {
                        CorrectionState::Applied
                    } else {
                        CorrectionState::Failed
                    };
                    k.reason = result.as_ref().err().cloned();
                    k.checked_on = seq;
                }
            }
        }
        let correction = match (c.correction, correction_rule) {
            (Some(new), Some(rule)) => {
                let id = m.corrections.len() as u32 + 1;
                m.corrections.push(Correction {
                    id,
                    made_on: seq,
                    created_at: now.clone(),
                    author: c.meta.author.clone(),
                    statement: new.statement.to_string(),
                    state: CorrectionState::Applied,
                    reason: None,
                    checked_on: seq,
                    rule,
                });
                Some(id)
            }
            _ => None,
        };
        if let Some(id) = c.drops
            && let Some(k) = m.corrections.iter_mut().find(|k| k.id == id)
        {
            k.state = CorrectionState::Dropped;
        }
        let revision = m.revisions[(seq - 1) as usize].info.clone();
        data.commits += 1;
        Ok(Committed {
            revision,
            correction,
        })
    }

    fn drop_correction(&mut self, map: &str, id: u32) -> Result<Correction, StoreError> {
        let mut data = self.data();
        data.map(map)?;
        let m = data
            .maps
            .get_mut(map)
            .ok_or_else(|| StoreError::NoSuchCorrection {
                map: map.to_string(),
                id,
            })?;
        let k = m
            .corrections
            .iter_mut()
            .find(|k| k.id == id)
            .ok_or_else(|| StoreError::NoSuchCorrection {
                map: map.to_string(),
                id,
            })?;
        k.state = CorrectionState::Dropped;
        let out = k.clone();
        data.commits += 1;
        Ok(out)
    }

    fn set_georef(&mut self, map: &str, georef: Option<&Georef>) -> Result<(), StoreError> {
        let mut data = self.data();
        data.map(map)?;
        if let Some(m) = data.maps.get_mut(map) {
            m.georef = georef.cloned();
        }
        data.commits += 1;
        Ok(())
    }
}

impl Engine for MemoryStore {
    fn set_busy_timeout(&mut self, _timeout: Duration) -> Result<(), StoreError> {
        Ok(())
    }

    fn integrity_check(&self) -> Result<Vec<String>, StoreError> {
        Ok(vec!["ok".to_string()])
    }
}
