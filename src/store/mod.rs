//! The versioned store: maps, immutable revisions, stable space identity,
//! corrections, crash-safe imports — on any engine.
//!
//! [`Store`] is what the rest of nrgdb uses (the query language, the
//! server, the CLI, the demo). It holds an engine behind the traits of
//! [`engine`] — [`memory`] (tests, one-off conversions), [`sqlite`] (the
//! embedded default) — and does once, above them, everything that is the
//! same on each: matching a new model's spaces to the parent revision so
//! they keep their stable id, name and attributes; "nothing changed";
//! renames; undo; retries when another writer got in first; limits.
//! Engines keep spaces and connections as rows valid over a revision range
//! `[valid_from, valid_to)` ([`delta`]), so a revision costs only what
//! changed while every revision reads back exactly as it was imported.
//!
//! Uses `model` and `diff`; must not use the terminal, HTTP or XML.
//!
//! ```
//! use nrgdb::model::{Nrg, Space, SpaceId, SpaceKind};
//! use nrgdb::store::{ImportMeta, Store};
//! let room = Space::new(SpaceId(1), SpaceKind::Room, [1.0, 1.0],
//!     vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]);
//! let nrg = Nrg::new(vec![room], vec![])?;
//! let mut store = Store::open_in_memory()?;
//! let done = store.import("lab", &nrg, ImportMeta::new("first map", "ada"))?;
//! assert_eq!(done.revision.seq, 1);
//! assert_eq!(store.load("lab", None)?, nrg);
//! assert_eq!(store.locate("lab", None, 0.5, 0.5)?, Some(SpaceId(1)));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod correction;
pub mod delta;
pub mod engine;
mod error;
mod fault;
mod geometry_blob;
mod georef_json;
mod grid_png;
mod history;
mod identity;
mod limits;
pub mod memory;
#[cfg(feature = "postgres")]
pub mod postgres;
mod read;
pub mod sqlite;

use std::collections::BTreeMap;
use std::path::Path;
use std::time::Duration;

use serde::Serialize;
use sha2::{Digest, Sha256};

use crate::diff::MatchParams;
use crate::model::SpaceId;

pub use correction::{Correction, CorrectionResults, CorrectionState, CorrectionsKey};
pub use engine::{Commit, Committed, Engine, NewCorrection, ReadStore, WriteStore};
pub use error::StoreError;
pub use grid_png::EncodedGrid;
pub use history::MAX_IMPORT_ATTEMPTS;
pub use limits::MAX_MESSAGE_CHARS;
pub use sqlite::SCHEMA_VERSION;

/// How long a writer waits for another writer before [`StoreError::Busy`].
pub const DEFAULT_BUSY_TIMEOUT: Duration = Duration::from_secs(5);

/// An open nrgdb database, on any engine.
pub struct Store {
    engine: Box<dyn Engine>,
    match_params: MatchParams,
    /// Called by an import between matching and taking the write lock
    /// (tests make another writer get in first there).
    #[cfg(test)]
    before_write_lock: Option<Box<dyn FnMut() + Send>>,
}

impl std::fmt::Debug for Store {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Store")
            .field("engine", &self.engine)
            .finish()
    }
}

/// A map and how far its history goes.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct MapInfo {
    /// The map's name.
    pub name: String,
    /// When the map was created (UTC, ISO 8601).
    pub created_at: String,
    /// Its latest revision (0 when it has none).
    pub latest: u32,
}

/// Who made a revision, why and from what.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ImportMeta {
    /// The commit message.
    pub message: String,
    /// Who made the revision.
    pub author: String,
    /// The file the model came from (its name, as given).
    pub source_name: Option<String>,
    /// SHA-256 of that file, lower-case hex.
    pub source_sha256: Option<String>,
    /// Extraction parameters (JSON), when the model was extracted.
    pub params: Option<serde_json::Value>,
    /// When the map was made (RFC 3339 UTC, e.g. a recording's message
    /// time): the revision's time. `None`: when it is stored.
    pub recorded_at: Option<String>,
}

impl ImportMeta {
    /// Meta data with a message and an author only.
    pub fn new(message: impl Into<String>, author: impl Into<String>) -> ImportMeta {
        ImportMeta {
            message: message.into(),
            author: author.into(),
            ..ImportMeta::default()
        }
    }

    /// Records the source file's name and the SHA-256 of its bytes.
    pub fn with_source(mut self, name: impl Into<String>, bytes: &[u8]) -> ImportMeta {
        self.source_name = Some(name.into());
        self.source_sha256 = Some(sha256_hex(bytes));
        self
    }
}

/// Whether `db` names a PostgreSQL database (`postgres://` or
/// `postgresql://`) rather than an SQLite file: the one place that tells.
///
/// ```
/// assert!(nrgdb::store::is_postgres_url("postgres://u@h/db"));
/// assert!(!nrgdb::store::is_postgres_url("maps/nrgdb.sqlite"));
/// ```
pub fn is_postgres_url(db: &str) -> bool {
    db.starts_with("postgres://") || db.starts_with("postgresql://")
}

/// Now, UTC, ISO 8601 with milliseconds (as every engine records times).
pub(crate) fn now_utc() -> String {
    humantime::format_rfc3339_millis(std::time::SystemTime::now()).to_string()
}

/// Lower-case hex SHA-256 of `bytes`.
///
/// ```
/// assert!(nrgdb::store::sha256_hex(b"").starts_with("e3b0c442"));
/// ```
pub fn sha256_hex(bytes: &[u8]) -> String {
    sha256_hex_of(&[bytes])
}

/// Lower-case hex SHA-256 of `parts` one after the other (a map's YAML,
/// then its image), without joining them.
///
/// ```
/// use nrgdb::store::{sha256_hex, sha256_hex_of};
/// assert_eq!(sha256_hex_of(&[b"ab", b"c"]), sha256_hex(b"abc"));
/// ```
pub fn sha256_hex_of(parts: &[&[u8]]) -> String {
    let mut hash = Sha256::new();
    for part in parts {
        hash.update(part);
    }
    hash.finalize().iter().map(|b| format!("{b:02x}")).collect()
}

/// One revision of a map as recorded in its history.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RevisionInfo {
    /// The map.
    pub map: String,
    /// Sequence number, 1 for the first revision.
    pub seq: u32,
    /// The revision this one was made from.
    pub parent: Option<u32>,
    /// When it was stored (UTC, ISO 8601).
    pub created_at: String,
    /// Source file name.
    pub source_name: Option<String>,
    /// SHA-256 of the source file.
    pub source_sha256: Option<String>,
    /// Extraction parameters (JSON).
    pub params: Option<serde_json::Value>,
    /// The commit message.
    pub message: String,
    /// Who made it.
    pub author: String,
    /// Number of spaces in the revision.
    pub spaces: usize,
    /// Number of connections in the revision.
    pub connections: usize,
    /// Spaces new in this revision.
    pub spaces_added: usize,
    /// Spaces kept from the parent but changed (geometry, name, ...).
    pub spaces_changed: usize,
    /// Spaces of the parent gone in this revision.
    pub spaces_removed: usize,
}

/// The result of [`Store::import`].
#[derive(Debug, Clone, PartialEq)]
pub struct Imported {
    /// The new revision, or the latest one when nothing changed.
    pub revision: RevisionInfo,
    /// Whether the model was the latest revision's exactly, so that no
    /// revision was written ("nothing changed").
    pub unchanged: bool,
    /// Stable id given to each space of the imported model (input id →
    /// stored id).
    pub ids: BTreeMap<SpaceId, SpaceId>,
}

impl Store {
    /// Opens (creating if needed) the SQLite database at `path`, bringing
    /// its schema up to date. A database from a newer nrgdb is refused with
    /// [`StoreError::TooNew`] and not modified.
    pub fn open(path: &Path) -> Result<Store, StoreError> {
        Ok(Store::on(Box::new(sqlite::SqliteStore::open(path)?)))
    }

    /// Opens an existing database, refusing with [`StoreError::NoDatabase`]
    /// when there is no file at `path` (for commands that only read, so a
    /// mistyped path does not leave an empty database behind).
    pub fn open_existing(path: &Path) -> Result<Store, StoreError> {
        if !path.exists() {
            return Err(StoreError::NoDatabase {
                path: path.to_path_buf(),
            });
        }
        Store::open(path)
    }

    /// Opens the database `db`: a `postgres://` (or `postgresql://`) URL
    /// names a PostgreSQL database (with PostGIS; nrgdb creates or
    /// migrates its schema `nrgdb` there), anything else an SQLite file
    /// (created if needed).
    pub fn open_db(db: &str) -> Result<Store, StoreError> {
        #[cfg(feature = "postgres")]
        if is_postgres_url(db) {
            return Ok(Store::on(Box::new(postgres::PostgresStore::open(db)?)));
        }
        #[cfg(not(feature = "postgres"))]
        if is_postgres_url(db) {
            return Err(StoreError::Open {
                location: "the PostgreSQL URL".into(),
                source: "this nrgdb was built without the `postgres` feature".into(),
            });
        }
        Store::open(Path::new(db))
    }

    /// [`Store::open_db`] for commands that only read: an SQLite file must
    /// exist already ([`StoreError::NoDatabase`]).
    pub fn open_existing_db(db: &str) -> Result<Store, StoreError> {
        if is_postgres_url(db) {
            return Store::open_db(db);
        }
        Store::open_existing(Path::new(db))
    }

    /// A fresh, empty database in memory ([`memory::MemoryStore`]: tests,
    /// one-off conversions).
    pub fn open_in_memory() -> Result<Store, StoreError> {
        Ok(Store::on(Box::new(memory::MemoryStore::new())))
    }

    /// A store on `engine`.
    pub fn on(engine: Box<dyn Engine>) -> Store {
        Store {
            engine,
            match_params: MatchParams::default(),
            #[cfg(test)]
            before_write_lock: None,
        }
    }

    /// How long a writer waits for another one before giving up with
    /// [`StoreError::Busy`] (default [`DEFAULT_BUSY_TIMEOUT`]).
    pub fn set_busy_timeout(&mut self, timeout: Duration) -> Result<(), StoreError> {
        self.engine.set_busy_timeout(timeout)
    }

    /// How spaces are matched to their parent revision on import.
    pub fn set_match_params(&mut self, params: MatchParams) {
        self.match_params = params;
    }

    /// Where the data lives (a file path, or a URL without its password).
    pub fn location(&self) -> String {
        self.engine.location()
    }

    /// The engine's consistency check (SQLite's `PRAGMA integrity_check`);
    /// `Ok(vec!["ok"])` when sound.
    pub fn integrity_check(&self) -> Result<Vec<String>, StoreError> {
        self.engine.integrity_check()
    }

    /// The engine, for reading directly.
    pub fn engine(&self) -> &dyn Engine {
        &*self.engine
    }
}
