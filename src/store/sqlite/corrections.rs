//! The SQLite engine's corrections table (schema 4): each correction's
//! rule (JSON), its state at the last import, and when it was dropped.

use rusqlite::{Connection, OptionalExtension, TransactionBehavior, params};

use super::fault::{R, fail};
use super::read::map_id;
use crate::edit::Rule;
use crate::store::{
    Correction, CorrectionResults, CorrectionState, CorrectionsKey, NewCorrection, StoreError,
};

const COLUMNS: &str =
    "id, made_on, created_at, author, statement, rule, state, reason, checked_on, dropped_at";

/// Every correction of `map`, oldest first (none for an unknown map).
pub(super) fn all(conn: &Connection, map: &str) -> R<Vec<Correction>> {
    match map_row(conn, map)? {
        Some(id) => read_corrections(conn, id, map),
        None => Ok(Vec::new()),
    }
}

/// The key of `map`'s corrections (the default for an unknown map).
pub(super) fn key_of(conn: &Connection, map: &str) -> R<CorrectionsKey> {
    match map_row(conn, map)? {
        Some(id) => key(conn, id),
        None => Ok(CorrectionsKey::default()),
    }
}

/// Marks correction `id` dropped, in a write transaction of its own.
pub(super) fn drop(conn: &mut Connection, map: &str, id: u32) -> R<Correction> {
    let tx = conn.transaction_with_behavior(TransactionBehavior::Immediate)?;
    let map_id = map_id(&tx, map)?;
    tx.execute(
        "UPDATE corrections SET dropped_at = strftime('%Y-%m-%dT%H:%M:%fZ', 'now')
         WHERE map_id = ?1 AND id = ?2 AND dropped_at IS NULL",
        params![map_id, id],
    )?;
    let found = read_corrections(&tx, map_id, map)?
        .into_iter()
        .find(|c| c.id == id);
    match found {
        Some(c) => {
            tx.commit()?;
            Ok(c)
        }
        None => fail(StoreError::NoSuchCorrection {
            map: map.to_string(),
            id,
        }),
    }
}

/// Marks correction `id` dropped inside the caller's transaction (undo).
pub(super) fn mark_dropped(conn: &Connection, map: &str, map_id: i64, id: u32) -> R<()> {
    let changed = conn.execute(
        "UPDATE corrections SET dropped_at = strftime('%Y-%m-%dT%H:%M:%fZ', 'now')
         WHERE map_id = ?1 AND id = ?2 AND dropped_at IS NULL",
        params![map_id, id],
    )?;
    if changed == 0 {
        return fail(StoreError::NoSuchCorrection {
            map: map.to_string(),
            id,
        });
    }
    Ok(())
}

/// Keeps a new correction made by revision `seq`; returns its number.
pub(super) fn insert_correction(
    conn: &Connection,
    map_id: i64,
    seq: u32,
    author: &str,
    new: NewCorrection<'_>,
) -> R<u32> {
    let next: u32 = conn.query_row(
        "SELECT COALESCE(MAX(id), 0) + 1 FROM corrections WHERE map_id = ?1",
        [map_id],
        |r| r.get(0),
    )?;
    conn.execute(
        "INSERT INTO corrections (map_id, id, made_on, created_at, author, statement, rule, state, checked_on)
         VALUES (?1, ?2, ?3, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'), ?4, ?5, ?6, 'applied', ?3)",
        params![map_id, next, seq, author, new.statement, new.rule_json],
    )?;
    Ok(next)
}

/// Checks, under the write lock, that `map_id`'s corrections are still
/// those `reapplied` was computed from, and records each result at
/// revision `seq`.
pub(super) fn record_results(
    conn: &Connection,
    map: &str,
    map_id: i64,
    seq: u32,
    reapplied: &CorrectionResults,
) -> R<()> {
    if key(conn, map_id)? != reapplied.key {
        return fail(StoreError::Stale {
            map: map.to_string(),
        });
    }
    let mut update = conn.prepare_cached(
        "UPDATE corrections SET state = ?3, reason = ?4, checked_on = ?5 WHERE map_id = ?1 AND id = ?2",
    )?;
    for (id, result) in &reapplied.results {
        let (state, reason) = match result {
            Ok(()) => ("applied", None),
            Err(reason) => ("failed", Some(reason.as_str())),
        };
        update.execute(params![map_id, id, state, reason, seq])?;
    }
    Ok(())
}

fn map_row(conn: &Connection, map: &str) -> R<Option<i64>> {
    Ok(conn
        .query_row("SELECT id FROM maps WHERE name = ?1", [map], |r| r.get(0))
        .optional()?)
}

fn key(conn: &Connection, map_id: i64) -> R<CorrectionsKey> {
    Ok(conn.query_row(
        "SELECT COUNT(*), COUNT(dropped_at) FROM corrections WHERE map_id = ?1",
        [map_id],
        |r| {
            Ok(CorrectionsKey {
                made: r.get(0)?,
                dropped: r.get(1)?,
            })
        },
    )?)
}

fn read_corrections(conn: &Connection, map_id: i64, map: &str) -> R<Vec<Correction>> {
    let mut stmt = conn.prepare_cached(&format!(
        "SELECT {COLUMNS} FROM corrections WHERE map_id = ?1 ORDER BY id"
    ))?;
    let rows = stmt.query_map([map_id], |r| {
        Ok((
            r.get::<_, u32>(0)?,
            r.get::<_, u32>(1)?,
            r.get::<_, String>(2)?,
            r.get::<_, String>(3)?,
            r.get::<_, String>(4)?,
            r.get::<_, String>(5)?,
            r.get::<_, String>(6)?,
            r.get::<_, Option<String>>(7)?,
            r.get::<_, u32>(8)?,
            r.get::<_, Option<String>>(9)?,
        ))
    })?;
    let mut out = Vec::new();
    for row in rows {
        let (id, made_on, created_at, author, statement, rule, state, reason, checked_on, dropped) =
            row?;
        let rule: Rule = serde_json::from_str(&rule).map_err(|e| StoreError::BadCorrection {
            map: map.to_string(),
            id,
            message: e.to_string(),
        })?;
        let state = CorrectionState::from_stored(dropped.is_some(), &state);
        out.push(Correction {
            id,
            made_on,
            created_at,
            author,
            statement,
            state,
            reason,
            checked_on,
            rule,
        });
    }
    Ok(out)
}
