//! The versioned SQLite store: maps, immutable revisions, stable space
//! identity, crash-safe imports.
//!
//! Owns the database schema (`migrations/*.sql`, applied on open), the
//! revision history of every map and point location over stored spaces.
//! Spaces and connections are kept as rows valid over a revision range
//! `[valid_from, valid_to)`, so a revision costs only what changed while
//! every revision reads back exactly as it was imported. On import each
//! space is matched to the space it continues in the parent revision
//! ([`crate::diff::match_spaces`]) and keeps its stable id, name and
//! attributes.
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

mod corrections;
mod error;
mod geometry_blob;
mod grids;
mod read;
mod schema;
mod write;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Duration;

use rusqlite::Connection;
use serde::Serialize;
use sha2::{Digest, Sha256};

use crate::diff::MatchParams;
use crate::model::SpaceId;

pub use corrections::{Correction, CorrectionResults, CorrectionState, CorrectionsKey};
pub use error::StoreError;
pub use schema::SCHEMA_VERSION;

/// How long a writer waits for another writer before [`StoreError::Busy`].
pub const DEFAULT_BUSY_TIMEOUT: Duration = Duration::from_secs(5);

/// An open nrgdb database.
pub struct Store {
    conn: Connection,
    path: PathBuf,
    match_params: MatchParams,
    /// Called by an import between matching and taking the write lock
    /// (tests make another writer get in first there).
    #[cfg(test)]
    before_write_lock: Option<Box<dyn FnMut() + Send>>,
}

impl std::fmt::Debug for Store {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Store").field("path", &self.path).finish()
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
    /// Opens (creating if needed) the database at `path`, bringing its
    /// schema up to date. A database from a newer nrgdb is refused with
    /// [`StoreError::TooNew`] and not modified.
    pub fn open(path: &Path) -> Result<Store, StoreError> {
        let conn = Connection::open(path).map_err(|source| StoreError::Open {
            path: path.to_path_buf(),
            source,
        })?;
        Store::setup(conn, path.to_path_buf()).map_err(|e| e.in_file(path))
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

    /// A fresh database in memory (tests, one-off conversions).
    pub fn open_in_memory() -> Result<Store, StoreError> {
        let conn = Connection::open_in_memory()?;
        Store::setup(conn, PathBuf::from(":memory:"))
    }

    fn setup(mut conn: Connection, path: PathBuf) -> Result<Store, StoreError> {
        conn.busy_timeout(DEFAULT_BUSY_TIMEOUT)?;
        schema::prepare(&mut conn, &path)?;
        Ok(Store {
            conn,
            path,
            match_params: MatchParams::default(),
            #[cfg(test)]
            before_write_lock: None,
        })
    }

    /// How long a writer waits for another one before giving up with
    /// [`StoreError::Busy`] (default [`DEFAULT_BUSY_TIMEOUT`]).
    pub fn set_busy_timeout(&mut self, timeout: Duration) -> Result<(), StoreError> {
        self.conn.busy_timeout(timeout)?;
        Ok(())
    }

    /// How spaces are matched to their parent revision on import.
    pub fn set_match_params(&mut self, params: MatchParams) {
        self.match_params = params;
    }

    /// The database file (`:memory:` for an in-memory store).
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Runs `PRAGMA integrity_check`; `Ok(vec!["ok"])` on a sound file.
    pub fn integrity_check(&self) -> Result<Vec<String>, StoreError> {
        let mut stmt = self.conn.prepare("PRAGMA integrity_check")?;
        let rows = stmt.query_map([], |r| r.get::<_, String>(0))?;
        Ok(rows.collect::<Result<_, _>>()?)
    }
}
