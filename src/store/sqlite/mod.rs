//! The SQLite engine, nrgdb's embedded default: one file, WAL (readers
//! never wait for the writer; a killed writer leaves nothing half-done),
//! `BEGIN IMMEDIATE` write transactions, an R*Tree of space bounding boxes
//! for point location. Owns the SQLite schema (`migrations/*.sql`, applied
//! on open). Implements [`crate::store::engine`]; nothing outside this
//! module sees an SQLite type.

mod corrections;
mod fault;
mod georef;
mod read;
mod schema;
mod write;

use std::cell::Cell;
use std::path::{Path, PathBuf};
use std::time::Duration;

use rusqlite::Connection;

use super::engine::{Commit, Committed, Engine, ReadStore, WriteStore};
use super::{
    Correction, CorrectionsKey, DEFAULT_BUSY_TIMEOUT, EncodedGrid, MapInfo, RevisionInfo,
    StoreError,
};
use crate::model::{Georef, Nrg, SpaceId};
use fault::{R, in_file};

pub use schema::SCHEMA_VERSION;

/// An SQLite database file (or an in-memory one).
pub struct SqliteStore {
    conn: Connection,
    path: PathBuf,
    /// Commits made through this connection (SQLite's `data_version`
    /// counts only the others').
    own_commits: Cell<u64>,
}

impl std::fmt::Debug for SqliteStore {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SqliteStore")
            .field("path", &self.path)
            .finish()
    }
}

impl SqliteStore {
    /// Opens (creating if needed) the database at `path`, bringing its
    /// schema up to date. A database from a newer nrgdb is refused with
    /// [`StoreError::TooNew`] and not modified.
    pub fn open(path: &Path) -> Result<SqliteStore, StoreError> {
        let conn = Connection::open(path).map_err(|e| StoreError::Open {
            location: path.display().to_string(),
            source: Box::new(e),
        })?;
        SqliteStore::setup(conn, path.to_path_buf()).map_err(|e| in_file(e.into(), path))
    }

    /// A fresh SQLite database in memory.
    pub fn open_in_memory() -> Result<SqliteStore, StoreError> {
        let conn = Connection::open_in_memory().map_err(|e| StoreError::Open {
            location: ":memory:".into(),
            source: Box::new(e),
        })?;
        Ok(SqliteStore::setup(conn, PathBuf::from(":memory:"))?)
    }

    fn setup(mut conn: Connection, path: PathBuf) -> R<SqliteStore> {
        conn.busy_timeout(DEFAULT_BUSY_TIMEOUT)?;
        schema::prepare(&mut conn, &path)?;
        Ok(SqliteStore {
            conn,
            path,
            own_commits: Cell::new(0),
        })
    }

    /// Runs `f`, naming the file in its error.
    fn run<T>(&self, f: impl FnOnce(&Connection) -> R<T>) -> Result<T, StoreError> {
        f(&self.conn).map_err(|e| in_file(e.into(), &self.path))
    }
}

impl ReadStore for SqliteStore {
    fn location(&self) -> String {
        self.path.display().to_string()
    }
    fn maps(&self) -> Result<Vec<MapInfo>, StoreError> {
        self.run(read::maps)
    }
    fn revisions(&self, map: &str) -> Result<Vec<RevisionInfo>, StoreError> {
        self.run(|c| read::revisions(c, map))
    }
    fn revision(&self, map: &str, rev: Option<u32>) -> Result<RevisionInfo, StoreError> {
        self.run(|c| read::revision(c, map, rev))
    }
    fn load(&self, map: &str, rev: Option<u32>) -> Result<Nrg, StoreError> {
        self.run(|c| read::load(c, map, rev))
    }
    fn locate(
        &self,
        map: &str,
        rev: Option<u32>,
        x: f64,
        y: f64,
    ) -> Result<Option<SpaceId>, StoreError> {
        self.run(|c| read::locate(c, map, rev, x, y))
    }
    fn grid(&self, map: &str, rev: Option<u32>) -> Result<Option<EncodedGrid>, StoreError> {
        self.run(|c| read::grid(c, map, rev))
    }
    fn corrections(&self, map: &str) -> Result<Vec<Correction>, StoreError> {
        self.run(|c| corrections::all(c, map))
    }
    fn corrections_key(&self, map: &str) -> Result<CorrectionsKey, StoreError> {
        self.run(|c| corrections::key_of(c, map))
    }
    fn next_space_id(&self, map: &str) -> Result<SpaceId, StoreError> {
        self.run(|c| write::next_space_id_of(c, map))
    }
    fn georef(&self, map: &str) -> Result<Option<Georef>, StoreError> {
        self.run(|c| georef::get(c, map))
    }
    fn change_token(&self) -> Result<Option<u64>, StoreError> {
        let theirs: i64 = self.run(|c| {
            Ok(c.prepare_cached("PRAGMA data_version")?
                .query_row([], |r| r.get(0))?)
        })?;
        // data_version changes when another connection commits; our own
        // commits are counted apart. Both only grow.
        Ok(Some(
            (u64::try_from(theirs).unwrap_or(0) << 32) ^ self.own_commits.get(),
        ))
    }
}

impl WriteStore for SqliteStore {
    fn commit(&mut self, commit: &Commit<'_>) -> Result<Committed, StoreError> {
        let done =
            write::commit(&mut self.conn, commit).map_err(|e| in_file(e.into(), &self.path))?;
        self.own_commits.set(self.own_commits.get() + 1);
        Ok(done)
    }
    fn drop_correction(&mut self, map: &str, id: u32) -> Result<Correction, StoreError> {
        let done = corrections::drop(&mut self.conn, map, id)
            .map_err(|e| in_file(e.into(), &self.path))?;
        self.own_commits.set(self.own_commits.get() + 1);
        Ok(done)
    }
    fn set_georef(&mut self, map: &str, g: Option<&Georef>) -> Result<(), StoreError> {
        georef::set(&self.conn, map, g).map_err(|e| in_file(e.into(), &self.path))?;
        self.own_commits.set(self.own_commits.get() + 1);
        Ok(())
    }
}

impl Engine for SqliteStore {
    fn set_busy_timeout(&mut self, timeout: Duration) -> Result<(), StoreError> {
        self.run(|c| Ok(c.busy_timeout(timeout)?))
    }
    fn integrity_check(&self) -> Result<Vec<String>, StoreError> {
        self.run(|c| {
            let mut stmt = c.prepare("PRAGMA integrity_check")?;
            let rows = stmt.query_map([], |r| r.get::<_, String>(0))?;
            Ok(rows.collect::<Result<_, _>>()?)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Issue 21, defect 10: a full disk said "Error code 4874: disk I/O
    /// error". A database that may not grow (`max_page_count`) gives
    /// SQLITE_FULL for real; the error says "disk full" and names the
    /// file, and the import stored nothing.
    #[test]
    fn issue_21_defect_10_a_full_database_says_disk_full() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("db.sqlite");
        let mut store = SqliteStore::open(&path).unwrap();
        let rooms = |n: u32| {
            let spaces = (0..n)
                .map(|i| {
                    let x = f64::from(i) * 3.0;
                    crate::model::Space::new(
                        SpaceId(i + 1),
                        crate::model::SpaceKind::Room,
                        [x + 1.0, 1.0],
                        vec![[x, 0.0], [x + 2.0, 0.0], [x + 2.0, 2.0], [x, 2.0]],
                    )
                })
                .collect();
            Nrg::new(spaces, vec![]).unwrap()
        };
        let meta = crate::store::ImportMeta::new("test", "me");
        let first = rooms(4);
        store
            .commit(&Commit::revision("m", 0, None, &first, &meta))
            .unwrap();
        let pages: i64 = store
            .conn
            .query_row("PRAGMA page_count", [], |r| r.get(0))
            .unwrap();
        store
            .conn
            .pragma_update(None, "max_page_count", pages + 1)
            .unwrap();
        let big = rooms(2_000);
        let e = store
            .commit(&Commit::revision("big", 0, None, &big, &meta))
            .unwrap_err();
        assert!(
            matches!(&e, StoreError::DiskFull { location } if *location == path.display().to_string()),
            "{e:?}"
        );
        assert!(e.to_string().starts_with("disk full: "), "{e}");
        assert!(store.revisions("big").is_err());
        assert_eq!(store.revisions("m").unwrap().len(), 1);
    }
}
