//! The PostgreSQL schema: the SQL files of `migrations/postgres/`,
//! embedded, applied in order on open inside one transaction holding an
//! advisory lock (two processes opening a fresh database at once migrate
//! it once). Versions are recorded in `nrgdb.schema_migrations`.

use postgres::Client;

use super::fault::{R, fail};
use crate::store::StoreError;

const MIGRATIONS: &[&str] = &[
    include_str!("../../../migrations/postgres/0001_init.sql"),
    include_str!("../../../migrations/postgres/0002_georef.sql"),
    include_str!("../../../migrations/postgres/0003_levels.sql"),
];

/// The newest PostgreSQL schema version this build knows.
pub const PG_SCHEMA_VERSION: i32 = MIGRATIONS.len() as i32;

/// An arbitrary constant naming nrgdb's migration lock.
const MIGRATION_LOCK: i64 = 0x6e72_6764_625f_6d69;

/// Brings nrgdb's schema in the database to [`PG_SCHEMA_VERSION`],
/// refusing a newer one untouched; then sets the session's search path.
pub(super) fn prepare(client: &mut Client, location: &str) -> R<()> {
    let mut tx = client.transaction()?;
    tx.execute("SELECT pg_advisory_xact_lock($1)", &[&MIGRATION_LOCK])?;
    let has_postgis: bool = tx
        .query_one(
            "SELECT EXISTS (SELECT 1 FROM pg_extension WHERE extname = 'postgis')",
            &[],
        )?
        .get(0);
    if !has_postgis {
        tx.batch_execute("CREATE EXTENSION IF NOT EXISTS postgis")
            .map_err(|e| StoreError::Migration {
                path: location.to_string(),
                known: i64::from(PG_SCHEMA_VERSION),
                message: format!(
                    "PostGIS is needed and could not be enabled ({e}); a superuser can run \
                     CREATE EXTENSION postgis in that database"
                ),
            })?;
    }
    let known: bool = tx
        .query_one(
            "SELECT to_regclass('nrgdb.schema_migrations') IS NOT NULL",
            &[],
        )?
        .get(0);
    if !known {
        tx.batch_execute(
            "CREATE SCHEMA IF NOT EXISTS nrgdb;
             CREATE TABLE nrgdb.schema_migrations (
                 version INTEGER PRIMARY KEY,
                 applied_at TIMESTAMPTZ NOT NULL DEFAULT now())",
        )?;
    }
    let found: i32 = tx
        .query_one(
            "SELECT COALESCE(MAX(version), 0) FROM nrgdb.schema_migrations",
            &[],
        )?
        .get(0);
    if found > PG_SCHEMA_VERSION {
        return fail(StoreError::TooNew {
            path: location.to_string(),
            found: i64::from(found),
            known: i64::from(PG_SCHEMA_VERSION),
        });
    }
    tx.batch_execute("SET LOCAL search_path TO nrgdb, public")?;
    for (k, sql) in MIGRATIONS.iter().enumerate().skip(found as usize) {
        let version = k as i32 + 1;
        tx.batch_execute(sql).map_err(|e| StoreError::Migration {
            path: location.to_string(),
            known: i64::from(PG_SCHEMA_VERSION),
            message: format!("migration {version}: {e}"),
        })?;
        tx.execute(
            "INSERT INTO nrgdb.schema_migrations (version) VALUES ($1)",
            &[&version],
        )?;
    }
    tx.commit()?;
    client.batch_execute("SET search_path TO nrgdb, public")?;
    Ok(())
}
