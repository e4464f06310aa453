//! Indexed revisions kept in memory per (map, revision). Revisions are
//! immutable, so an entry never goes stale; the least recently used one is
//! dropped when the cache is full.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};

use crate::query::IndexedRevision;

struct Entry {
    revision: Arc<IndexedRevision>,
    used: AtomicU64,
}

/// A bounded map (map, revision) → [`IndexedRevision`] (model, route graph,
/// spatial index), shared by all requests.
pub struct RevisionCache {
    entries: Mutex<HashMap<String, HashMap<u32, Entry>>>,
    capacity: usize,
    clock: AtomicU64,
    hits: AtomicU64,
    misses: AtomicU64,
}

impl std::fmt::Debug for RevisionCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RevisionCache")
            .field("capacity", &self.capacity)
            .field("len", &self.len())
            .finish()
    }
}

impl RevisionCache {
    /// An empty cache holding at most `capacity` revisions (at least 1).
    pub fn new(capacity: usize) -> RevisionCache {
        RevisionCache {
            entries: Mutex::new(HashMap::new()),
            capacity: capacity.max(1),
            clock: AtomicU64::new(0),
            hits: AtomicU64::new(0),
            misses: AtomicU64::new(0),
        }
    }

    /// The cached revision, or the one `load` builds (then cached). `load`
    /// runs without the lock held, so two first requests may both build it.
    pub fn get_or_load<E>(
        &self,
        map: &str,
        rev: u32,
        load: impl FnOnce() -> Result<IndexedRevision, E>,
    ) -> Result<Arc<IndexedRevision>, E> {
        let now = self.clock.fetch_add(1, Ordering::Relaxed);
        if let Some(found) = self.lookup(map, rev, now) {
            self.hits.fetch_add(1, Ordering::Relaxed);
            return Ok(found);
        }
        self.misses.fetch_add(1, Ordering::Relaxed);
        let revision = Arc::new(load()?);
        let mut entries = self.entries.lock().unwrap_or_else(|p| p.into_inner());
        let held: usize = entries.values().map(HashMap::len).sum();
        if held >= self.capacity
            && let Some((m, r)) = entries
                .iter()
                .flat_map(|(m, revs)| revs.iter().map(move |(r, e)| (m, *r, e)))
                .min_by_key(|(_, _, e)| e.used.load(Ordering::Relaxed))
                .map(|(m, r, _)| (m.clone(), r))
            && let Some(revs) = entries.get_mut(&m)
        {
            revs.remove(&r);
            if revs.is_empty() {
                entries.remove(&m);
            }
        }
        entries.entry(map.to_string()).or_default().insert(
            rev,
            Entry {
                revision: Arc::clone(&revision),
                used: AtomicU64::new(now),
            },
        );
        Ok(revision)
    }

    /// The cached revision if present (counted as a hit), without loading.
    pub fn get(&self, map: &str, rev: u32) -> Option<Arc<IndexedRevision>> {
        let now = self.clock.fetch_add(1, Ordering::Relaxed);
        let found = self.lookup(map, rev, now);
        if found.is_some() {
            self.hits.fetch_add(1, Ordering::Relaxed);
        }
        found
    }

    fn lookup(&self, map: &str, rev: u32, now: u64) -> Option<Arc<IndexedRevision>> {
        let entries = self.entries.lock().unwrap_or_else(|p| p.into_inner());
        let e = entries.get(map)?.get(&rev)?;
        e.used.store(now, Ordering::Relaxed);
        Some(Arc::clone(&e.revision))
    }

    /// Revisions held.
    pub fn len(&self) -> usize {
        self.entries
            .lock()
            .map_or(0, |e| e.values().map(HashMap::len).sum())
    }

    /// Whether nothing is cached.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// (hits, misses) since start.
    pub fn stats(&self) -> (u64, u64) {
        (
            self.hits.load(Ordering::Relaxed),
            self.misses.load(Ordering::Relaxed),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::corridor_building;

    fn load(n: usize) -> Result<IndexedRevision, ()> {
        Ok(IndexedRevision::new("m", 1, corridor_building(n)))
    }

    #[test]
    fn hits_misses_and_eviction() {
        let cache = RevisionCache::new(2);
        cache.get_or_load("a", 1, || load(2)).unwrap();
        cache.get_or_load("a", 1, || load(2)).unwrap();
        cache.get_or_load("a", 2, || load(2)).unwrap();
        cache.get_or_load("a", 1, || load(2)).unwrap();
        cache.get_or_load("b", 1, || load(2)).unwrap(); // evicts a@2
        assert_eq!(cache.len(), 2);
        assert_eq!(cache.stats(), (2, 3));
        cache.get_or_load("a", 1, || load(2)).unwrap();
        assert_eq!(cache.stats(), (3, 3));
        assert!(
            cache
                .get_or_load("c", 1, || Err::<IndexedRevision, _>(()))
                .is_err()
        );
    }
}
