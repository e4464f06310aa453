//! Schema migrations: the SQL files of `migrations/`, embedded, applied on
//! open with `rusqlite_migration` (version in `PRAGMA user_version`).

use std::path::Path;

use rusqlite::{Connection, TransactionBehavior};
use rusqlite_migration::{M, Migrations};

use super::fault::{R, fail};
use crate::store::StoreError;

const MIGRATIONS: &[M<'static>] = &[
    M::up(include_str!("../../../migrations/0001_init.sql")),
    M::up(include_str!("../../../migrations/0002_revision_grids.sql")),
    M::up(include_str!("../../../migrations/0003_doorways.sql")),
    M::up(include_str!("../../../migrations/0004_corrections.sql")),
    M::up(include_str!("../../../migrations/0005_georef.sql")),
    M::up(include_str!("../../../migrations/0006_levels.sql")),
];

/// The newest schema version this build knows (the number of migrations).
pub const SCHEMA_VERSION: i64 = MIGRATIONS.len() as i64;

/// Checks the schema version, refusing (without writing anything) a
/// database newer than this build, then switches to WAL and migrates.
pub(super) fn prepare(conn: &mut Connection, path: &Path) -> R<()> {
    let open_err = |e: rusqlite::Error| StoreError::Open {
        location: path.display().to_string(),
        source: Box::new(e),
    };
    let found = user_version(conn).map_err(open_err)?;
    if found > SCHEMA_VERSION {
        return fail(StoreError::TooNew {
            path: path.display().to_string(),
            found,
            known: SCHEMA_VERSION,
        });
    }
    // WAL: readers never wait for a writer, and a killed writer leaves
    // nothing half-done. NORMAL sync is crash-safe in WAL mode (only a
    // power cut may lose the last commits, never corrupt the file).
    let _mode: String = conn.pragma_update_and_check(None, "journal_mode", "wal", |r| r.get(0))?;
    conn.pragma_update(None, "synchronous", "NORMAL")?;
    conn.pragma_update(None, "foreign_keys", "ON")?;
    if found == SCHEMA_VERSION {
        return Ok(());
    }
    conn.set_transaction_behavior(TransactionBehavior::Immediate);
    let result = Migrations::from_slice(MIGRATIONS).to_latest(conn);
    conn.set_transaction_behavior(TransactionBehavior::Deferred);
    if let Err(e) = result {
        // Another process may have migrated the file meanwhile.
        if user_version(conn).ok() != Some(SCHEMA_VERSION) {
            return fail(StoreError::Migration {
                path: path.display().to_string(),
                known: SCHEMA_VERSION,
                message: e.to_string(),
            });
        }
    }
    Ok(())
}

fn user_version(conn: &Connection) -> rusqlite::Result<i64> {
    conn.pragma_query_value(None, "user_version", |r| r.get(0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn migrations_are_valid() {
        Migrations::from_slice(MIGRATIONS).validate().unwrap();
    }

    #[test]
    fn fresh_database_gets_the_latest_schema() {
        let mut conn = Connection::open_in_memory().unwrap();
        prepare(&mut conn, Path::new(":memory:")).unwrap();
        assert_eq!(user_version(&conn).unwrap(), SCHEMA_VERSION);
        // Opening again is a no-op.
        prepare(&mut conn, Path::new(":memory:")).unwrap();
    }
}
