//! The PostgreSQL/PostGIS engine (`--db postgres://…`): for campuses and
//! fleets, several writers and several stateless servers on one database.
//!
//! The records are those of the SQLite engine, in the schema `nrgdb`
//! (`migrations/postgres/*.sql`, applied on open under an advisory lock),
//! with each space's outline also as a PostGIS polygon (GiST-indexed:
//! `LOCATE` uses it) and each connection as a line, plus views for GIS
//! tools (`latest_spaces`, `latest_connections`) and pgRouting
//! (`route_edges`). Writers of one map serialise on a transaction-level
//! advisory lock, so its history stays a line; reads run in a
//! repeatable-read snapshot. No client type leaves this module.

mod corrections;
mod fault;
mod georef;
mod prepared;
mod read;
mod schema;
mod write;

use std::cell::RefCell;
use std::str::FromStr;
use std::time::Duration;

use postgres::{Client, Config, NoTls};

use super::engine::{Commit, Committed, Engine, ReadStore, WriteStore};
use super::{
    Correction, CorrectionsKey, DEFAULT_BUSY_TIMEOUT, EncodedGrid, MapInfo, RevisionInfo,
    StoreError,
};
use crate::model::{Georef, Nrg, SpaceId};
use fault::R;
use prepared::Prepared;

pub use schema::PG_SCHEMA_VERSION;

/// A connection to a PostgreSQL database with PostGIS.
pub struct PostgresStore {
    /// The connection and its prepared statements; `None` only while
    /// being dropped.
    client: RefCell<Option<(Client, Prepared)>>,
    location: String,
}

/// Runs `f` where the blocking client may run: the synchronous client
/// drives a runtime of its own, which cannot start on a thread that is
/// inside another tokio runtime (an async function). Opening and closing
/// a connection, which may happen there (a server starting, a pooled
/// store dropped), run on a scoped thread of their own then. Queries run
/// on the caller's thread: callers inside a runtime use it through
/// `spawn_blocking` (the server does; those threads may block), as a
/// thread per query would cost more than the query.
fn off_runtime<T: Send>(f: impl FnOnce() -> T + Send) -> T {
    if tokio::runtime::Handle::try_current().is_err() {
        return f();
    }
    std::thread::scope(|scope| match scope.spawn(f).join() {
        Ok(out) => out,
        Err(panic) => std::panic::resume_unwind(panic),
    })
}

impl Drop for PostgresStore {
    fn drop(&mut self) {
        // Closing the connection blocks too.
        if let Some((client, _)) = self.client.get_mut().take() {
            off_runtime(move || drop(client));
        }
    }
}

impl std::fmt::Debug for PostgresStore {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PostgresStore")
            .field("location", &self.location)
            .finish()
    }
}

impl PostgresStore {
    /// Connects to `url` (`postgres://user[:password]@host[:port]/db`),
    /// creating or migrating nrgdb's schema. A database whose nrgdb schema
    /// is newer than this build is refused and left untouched.
    pub fn open(url: &str) -> Result<PostgresStore, StoreError> {
        let mut config = Config::from_str(url).map_err(|e| StoreError::Open {
            location: "the PostgreSQL URL".into(),
            source: Box::new(e),
        })?;
        let location = describe(&config);
        if config.get_connect_timeout().is_none() {
            config.connect_timeout(Duration::from_secs(10));
        }
        config.application_name("nrgdb");
        let client = off_runtime(|| {
            let mut client = config.connect(NoTls).map_err(|e| StoreError::Open {
                location: location.clone(),
                source: Box::new(e),
            })?;
            schema::prepare(&mut client, &location).map_err(StoreError::from)?;
            client
                .batch_execute(&lock_timeout(DEFAULT_BUSY_TIMEOUT))
                .map_err(|e| StoreError::from(fault::Fault::from(e)))?;
            Ok::<_, StoreError>(client)
        })?;
        Ok(PostgresStore {
            client: RefCell::new(Some((client, Prepared::default()))),
            location,
        })
    }

    fn set_lock_timeout(&self, timeout: Duration) -> Result<(), StoreError> {
        self.run(|c, _| {
            c.batch_execute(&format!(
                "SET lock_timeout = {}",
                timeout.as_millis().max(1)
            ))?;
            Ok(())
        })
    }

    /// Runs `f` on the connection, naming the database in its error.
    fn run<T>(&self, f: impl FnOnce(&mut Client, &mut Prepared) -> R<T>) -> Result<T, StoreError> {
        let mut guard = self.client.borrow_mut();
        let Some((client, prepared)) = guard.as_mut() else {
            return Err(StoreError::Backend {
                engine: "postgres",
                source: "the connection is closed".into(),
            });
        };
        f(client, prepared).map_err(|e| match StoreError::from(e) {
            StoreError::DiskFull { .. } => StoreError::DiskFull {
                location: self.location.clone(),
            },
            other => other,
        })
    }
}

/// The statement setting how long a writer waits for a lock.
fn lock_timeout(timeout: Duration) -> String {
    format!("SET lock_timeout = {}", timeout.as_millis().max(1))
}

/// `postgres://user@host:port/db`, without the password.
fn describe(config: &Config) -> String {
    let host = match config.get_hosts().first() {
        Some(postgres::config::Host::Tcp(h)) => h.clone(),
        #[cfg(unix)]
        Some(postgres::config::Host::Unix(p)) => p.display().to_string(),
        None => "localhost".into(),
    };
    let port = config.get_ports().first().copied().unwrap_or(5432);
    format!(
        "postgres://{}@{host}:{port}/{}",
        config.get_user().unwrap_or(""),
        config.get_dbname().unwrap_or("")
    )
}

impl ReadStore for PostgresStore {
    fn location(&self) -> String {
        self.location.clone()
    }
    fn maps(&self) -> Result<Vec<MapInfo>, StoreError> {
        self.run(read::maps)
    }
    fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, StoreError> {
        self.run(|c, p| read::revisions(c, p, map))
    }
    fn revision(&self, map: &str, rev: Option<u32>) -> Result<RevisionInfo, StoreError> {
        self.run(|c, p| read::revision(c, p, map, rev))
    }
    fn load(&self, map: &str, rev: Option<u32>) -> Result<Nrg, StoreError> {
        self.run(|c, p| read::load(c, p, map, rev))
    }
    fn locate(
        &self,
        map: &str,
        rev: Option<u32>,
        x: f64,
        y: f64,
    ) -> Result<Option<SpaceId>, StoreError> {
        self.run(|c, p| read::locate(c, p, map, rev, x, y))
    }
    fn grid(&self, map: &str, rev: Option<u32>) -> Result<Option<EncodedGrid>, StoreError> {
        self.run(|c, p| read::grid(c, p, map, rev))
    }
    fn corrections(&self, map: &str) -> Result<Vec<Correction>, StoreError> {
        self.run(|c, p| corrections::all(c, p, map))
    }
    fn corrections_key(&self, map: &str) -> Result<CorrectionsKey, StoreError> {
        self.run(|c, p| corrections::key_of(c, p, map))
    }
    fn next_space_id(&self, map: &str) -> Result<SpaceId, StoreError> {
        self.run(|c, p| write::next_space_id_of(c, p, map))
    }
    /// No cheap token: several servers share the database, and asking for
    /// the latest revision is one indexed query, so callers ask every time
    /// and never serve a stale "latest".
    fn change_token(&self) -> Result<Option<u64>, StoreError> {
        Ok(None)
    }
    fn georef(&self, map: &str) -> Result<Option<Georef>, StoreError> {
        self.run(|c, p| georef::get(c, p, map))
    }
}

impl WriteStore for PostgresStore {
    fn commit(&mut self, commit: &Commit<'_>) -> Result<Committed, StoreError> {
        self.run(|c, p| write::commit(c, p, commit))
    }
    fn drop_correction(&mut self, map: &str, id: u32) -> Result<Correction, StoreError> {
        self.run(|c, p| corrections::drop(c, p, map, id))
    }
    fn set_georef(&mut self, map: &str, g: Option<&Georef>) -> Result<(), StoreError> {
        self.run(|c, p| georef::set(c, p, map, g))
    }
}

impl Engine for PostgresStore {
    fn set_busy_timeout(&mut self, timeout: Duration) -> Result<(), StoreError> {
        self.set_lock_timeout(timeout)
    }
    fn integrity_check(&self) -> Result<Vec<String>, StoreError> {
        self.run(read::integrity)
    }
}
