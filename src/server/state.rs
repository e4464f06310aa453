//! State shared by all requests: the configuration, a small pool of store
//! connections, the revision cache and the metrics.
//!
//! `Store` (rusqlite) is not `Sync`, so every request borrows a connection
//! of its own inside `spawn_blocking`; SQLite's WAL lets readers run while
//! one writer imports.

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use super::cache::RevisionCache;
use super::config::ServerConfig;
use super::error::ApiError;
use super::metrics::Metrics;
use crate::query::IndexedRevision;
use crate::store::{Store, StoreError};

/// Idle store connections, opened on demand and kept for reuse.
#[derive(Debug)]
pub struct StorePool {
    path: PathBuf,
    idle: Mutex<Vec<Store>>,
    max_idle: usize,
}

impl StorePool {
    /// Opens the database once (creating it and its schema if needed).
    pub fn open(path: &Path, max_idle: usize) -> Result<StorePool, StoreError> {
        let first = Store::open(path)?;
        Ok(StorePool {
            path: path.to_path_buf(),
            idle: Mutex::new(vec![first]),
            max_idle: max_idle.max(1),
        })
    }

    /// Runs `f` with a connection of its own (blocking: call it off the
    /// async workers).
    pub fn with<R>(&self, f: impl FnOnce(&mut Store) -> R) -> Result<R, StoreError> {
        let taken = self.idle.lock().unwrap_or_else(|p| p.into_inner()).pop();
        let mut store = match taken {
            Some(s) => s,
            None => Store::open(&self.path)?,
        };
        let out = f(&mut store);
        let mut idle = self.idle.lock().unwrap_or_else(|p| p.into_inner());
        if idle.len() < self.max_idle {
            idle.push(store);
        }
        Ok(out)
    }
}

/// What the handlers share (cheap to clone).
#[derive(Debug, Clone)]
pub struct AppState {
    inner: Arc<Shared>,
}

#[derive(Debug)]
pub(crate) struct Shared {
    pub config: ServerConfig,
    pub pool: StorePool,
    pub cache: RevisionCache,
    pub metrics: Metrics,
}

/// A request's view inside a blocking task: its store connection and the
/// shared cache.
pub struct Ctx<'a> {
    /// The connection lent to this request.
    pub store: &'a mut Store,
    pub(crate) shared: &'a Shared,
}

impl AppState {
    /// Opens the store at `config.db` and builds empty caches.
    pub fn new(config: ServerConfig) -> Result<AppState, StoreError> {
        let pool = StorePool::open(&config.db, 16)?;
        Ok(AppState {
            inner: Arc::new(Shared {
                cache: RevisionCache::new(config.cache_revisions),
                metrics: Metrics::default(),
                pool,
                config,
            }),
        })
    }

    /// The configuration.
    pub fn config(&self) -> &ServerConfig {
        &self.inner.config
    }

    pub(crate) fn shared(&self) -> &Shared {
        &self.inner
    }

    /// Runs `f` on the blocking pool with a store connection of its own.
    pub async fn blocking<R, F>(&self, f: F) -> Result<R, ApiError>
    where
        R: Send + 'static,
        F: FnOnce(&mut Ctx<'_>) -> Result<R, ApiError> + Send + 'static,
    {
        let shared = Arc::clone(&self.inner);
        tokio::task::spawn_blocking(move || {
            shared.pool.with(|store| {
                f(&mut Ctx {
                    store,
                    shared: &shared,
                })
            })?
        })
        .await
        .map_err(|e| ApiError::Internal(format!("request task failed: {e}")))?
    }
}

impl Ctx<'_> {
    /// Revision `rev` of `map` (the latest when `None`), indexed, from the
    /// cache when there. The latest revision is looked up on every call,
    /// so a new revision is served by the next request.
    pub fn revision(
        &mut self,
        map: &str,
        rev: Option<u32>,
    ) -> Result<Arc<IndexedRevision>, ApiError> {
        if let Some(r) = rev
            && let Some(hit) = self.shared.cache.get(map, r)
        {
            return Ok(hit);
        }
        let seq = self.store.revision(map, rev)?.seq;
        let store = &*self.store;
        self.shared.cache.get_or_load(map, seq, || {
            let nrg = store.load(map, Some(seq))?;
            Ok::<_, ApiError>(IndexedRevision::new(map, u64::from(seq), nrg))
        })
    }
}
