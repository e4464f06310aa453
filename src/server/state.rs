//! State shared by all requests: the configuration, a small pool of store
//! connections, the revision cache and the metrics.
//!
//! A [`Store`] holds one connection to its engine and is not `Sync`, so
//! every request borrows a store of its own inside `spawn_blocking`;
//! SQLite's WAL lets readers run while one writer imports.
//!
//! Each pooled store remembers the latest revision of the maps it has
//! looked up, valid while the engine's change token (which changes
//! whenever anyone commits, see [`crate::store::ReadStore::change_token`])
//! stays the same: the per-request "which revision is latest" check costs
//! one cheap call, and a new revision is still seen by the next request.
//! An engine without a cheap token is asked for the latest every time.

use std::collections::HashMap;
use std::path::Path;
use std::sync::{Arc, Mutex};

use super::cache::RevisionCache;
use super::config::ServerConfig;
use super::error::ApiError;
use super::metrics::Metrics;
use crate::query::IndexedRevision;
use crate::store::{Store, StoreError};

/// A pooled store and the latest revisions it saw at its change token.
#[derive(Debug)]
pub struct Slot {
    /// The store.
    pub store: Store,
    token: Option<u64>,
    latest: HashMap<String, u32>,
}

impl Slot {
    fn open(db: &str) -> Result<Slot, StoreError> {
        Ok(Slot {
            store: Store::open_db(db)?,
            token: None,
            latest: HashMap::new(),
        })
    }

    /// The latest revision of `map` as remembered, while the database is
    /// unchanged (never for an engine without a change token).
    fn remembered(&mut self, map: &str) -> Result<Option<u32>, StoreError> {
        let token = self.store.change_token()?;
        if token.is_none() || token != self.token {
            self.latest.clear();
            self.token = token;
        }
        Ok(self.latest.get(map).copied())
    }

    /// The latest revision of `map`, from the memo while the database is
    /// unchanged, else from the store.
    fn latest(&mut self, map: &str) -> Result<u32, StoreError> {
        if let Some(seq) = self.remembered(map)? {
            return Ok(seq);
        }
        let seq = self.store.revision(map, None)?.seq;
        if self.token.is_some() {
            self.latest.insert(map.to_string(), seq);
        }
        Ok(seq)
    }
}

/// Idle store connections, opened on demand and kept for reuse.
#[derive(Debug)]
pub struct StorePool {
    db: String,
    idle: Mutex<Vec<Slot>>,
    max_idle: usize,
}

impl StorePool {
    /// Opens the database once (creating it and its schema if needed).
    pub fn open(db: &str, max_idle: usize) -> Result<StorePool, StoreError> {
        let first = Slot::open(db)?;
        Ok(StorePool {
            db: db.to_string(),
            idle: Mutex::new(vec![first]),
            max_idle: max_idle.max(1),
        })
    }

    /// Runs `f` with a connection of its own (blocking: call it off the
    /// async workers).
    pub fn with<R>(&self, f: impl FnOnce(&mut Slot) -> R) -> Result<R, StoreError> {
        let mut slot = match self.take_idle() {
            Some(s) => s,
            None => Slot::open(&self.db)?,
        };
        let out = f(&mut slot);
        self.give_back(slot);
        Ok(out)
    }

    /// An idle connection, if one is open.
    pub fn take_idle(&self) -> Option<Slot> {
        self.idle.lock().unwrap_or_else(|p| p.into_inner()).pop()
    }

    /// Returns a connection to the pool (dropped when the pool is full).
    pub fn give_back(&self, slot: Slot) {
        let mut idle = self.idle.lock().unwrap_or_else(|p| p.into_inner());
        if idle.len() < self.max_idle {
            idle.push(slot);
        }
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
    slot: &'a mut Slot,
    pub(crate) shared: &'a Shared,
    /// Running on an async worker: a revision not yet cached must not be
    /// loaded here ([`AppState::quick`] then retries on the blocking pool).
    inline: bool,
    bailed: bool,
}

impl AppState {
    /// Opens the store at `config.db` and builds empty caches. Without a
    /// token (read-only) the database must exist; with one, uploads may
    /// create it.
    pub fn new(config: ServerConfig) -> Result<AppState, StoreError> {
        let is_file = !crate::store::is_postgres_url(&config.db);
        if config.token.is_none() && is_file && !Path::new(&config.db).exists() {
            // Read-only: nothing could ever fill a database created now.
            return Err(StoreError::NoDatabase {
                path: config.db.clone().into(),
            });
        }
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
            shared.pool.with(|slot| {
                f(&mut Ctx {
                    slot,
                    shared: &shared,
                    inline: false,
                    bailed: false,
                })
            })?
        })
        .await
        .map_err(|e| ApiError::Internal(format!("request task failed: {e}")))?
    }

    /// Like [`AppState::blocking`], but first tries `f` right on the async
    /// worker when it is cheap: an idle connection is at hand and the
    /// revision is already indexed in the cache (a pragma and an in-memory
    /// search, microseconds). Otherwise — a revision to load, no idle
    /// connection — it runs on the blocking pool. Saves two thread hand-offs
    /// per request on the hot path; use it only where `f`'s own work is
    /// small and bounded.
    pub async fn quick<R, F>(&self, f: F) -> Result<R, ApiError>
    where
        R: Send + 'static,
        F: Fn(&mut Ctx<'_>) -> Result<R, ApiError> + Send + 'static,
    {
        let shared = &*self.inner;
        if let Some(mut slot) = shared.pool.take_idle() {
            let mut ctx = Ctx {
                slot: &mut slot,
                shared,
                inline: true,
                bailed: false,
            };
            let out = f(&mut ctx);
            let bailed = ctx.bailed;
            shared.pool.give_back(slot);
            if !bailed {
                return out;
            }
        }
        self.blocking(move |ctx| f(ctx)).await
    }
}

impl Ctx<'_> {
    /// The store connection lent to this request.
    pub fn store(&mut self) -> &mut Store {
        &mut self.slot.store
    }

    /// The store and the revision cache shared by every request (for a
    /// query session, which selects revisions through the cache too).
    pub fn store_and_cache(&mut self) -> (&mut Store, &RevisionCache) {
        (&mut self.slot.store, &self.shared.cache)
    }

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
        if self.inline && rev.is_some() {
            self.bailed = true;
            return Err(ApiError::Busy);
        }
        let seq = match rev {
            Some(r) => self.slot.store.revision(map, Some(r))?.seq,
            // On an async worker only the memo may answer: an engine
            // without a cheap change token (PostgreSQL) is asked on the
            // blocking pool.
            None if self.inline => match self.slot.remembered(map)? {
                Some(seq) => seq,
                None => {
                    self.bailed = true;
                    return Err(ApiError::Busy);
                }
            },
            None => self.slot.latest(map)?,
        };
        if self.inline {
            return match self.shared.cache.get(map, seq) {
                Some(hit) => Ok(hit),
                None => {
                    self.bailed = true;
                    Err(ApiError::Busy)
                }
            };
        }
        let store = &self.slot.store;
        self.shared.cache.get_or_load(map, seq, || {
            let nrg = store.load(map, Some(seq))?;
            Ok::<_, ApiError>(IndexedRevision::new(map, u64::from(seq), nrg))
        })
    }
}
