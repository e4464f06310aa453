//! The PostgreSQL engine's corrections table: the same records as the
//! SQLite engine's (rule as JSON text, state at the last import, dropped).

use postgres::{Client, GenericClient};

use super::fault::{R, fail};
use super::prepared::Prepared;
use super::read::map_id;
use super::write::lock_map;
use crate::edit::Rule;
use crate::store::now_utc;
use crate::store::{
    Correction, CorrectionResults, CorrectionState, CorrectionsKey, NewCorrection, StoreError,
};

const COLUMNS: &str =
    "id, made_on, created_at, author, statement, rule, state, reason, checked_on, dropped_at";

fn map_row(c: &mut impl GenericClient, p: &mut Prepared, map: &str) -> R<Option<i64>> {
    Ok(
        p.query_opt(c, "SELECT id FROM maps WHERE name = $1", &[&map])?
            .map(|r| r.get(0)),
    )
}

/// Every correction of `map`, oldest first (none for an unknown map).
pub(super) fn all(client: &mut Client, p: &mut Prepared, map: &str) -> R<Vec<Correction>> {
    match map_row(client, p, map)? {
        Some(id) => read_corrections(client, p, id, map),
        None => Ok(Vec::new()),
    }
}

/// The key of `map`'s corrections (the default for an unknown map).
pub(super) fn key_of(client: &mut Client, p: &mut Prepared, map: &str) -> R<CorrectionsKey> {
    match map_row(client, p, map)? {
        Some(id) => key(client, p, id),
        None => Ok(CorrectionsKey::default()),
    }
}

/// Marks correction `id` dropped, under the map's write lock.
pub(super) fn drop(client: &mut Client, p: &mut Prepared, map: &str, id: u32) -> R<Correction> {
    let mut tx = client.transaction()?;
    lock_map(&mut tx, p, map)?;
    let map_id = map_id(&mut tx, p, map)?;
    p.execute(&mut tx, "UPDATE corrections SET dropped_at = $3 WHERE map_id = $1 AND id = $2 AND dropped_at IS NULL",
        &[&map_id, &(id as i32), &now_utc()],
    )?;
    let found = read_corrections(&mut tx, p, map_id, map)?
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
pub(super) fn mark_dropped(
    c: &mut impl GenericClient,
    p: &mut Prepared,
    map: &str,
    map_id: i64,
    id: u32,
) -> R<()> {
    let changed = p.execute(c, "UPDATE corrections SET dropped_at = $3 WHERE map_id = $1 AND id = $2 AND dropped_at IS NULL",
        &[&map_id, &(id as i32), &now_utc()],
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
    c: &mut impl GenericClient,
    p: &mut Prepared,
    map_id: i64,
    seq: u32,
    author: &str,
    new: NewCorrection<'_>,
) -> R<u32> {
    let next: i32 = p
        .query_one(
            c,
            "SELECT COALESCE(MAX(id), 0) + 1 FROM corrections WHERE map_id = $1",
            &[&map_id],
        )?
        .get(0);
    p.execute(c, "INSERT INTO corrections (map_id, id, made_on, created_at, author, statement, rule, state, checked_on)
         VALUES ($1, $2, $3, $4, $5, $6, $7, 'applied', $3)",
        &[&map_id, &next, &(seq as i32), &now_utc(), &author, &new.statement, &new.rule_json],
    )?;
    Ok(u32::try_from(next).unwrap_or(0))
}

/// Checks that `map_id`'s corrections are still those `reapplied` was
/// computed from, and records each result at revision `seq`.
pub(super) fn record_results(
    c: &mut impl GenericClient,
    p: &mut Prepared,
    map: &str,
    map_id: i64,
    seq: u32,
    reapplied: &CorrectionResults,
) -> R<()> {
    if key(c, p, map_id)? != reapplied.key {
        return fail(StoreError::Stale {
            map: map.to_string(),
        });
    }
    for (id, result) in &reapplied.results {
        let (state, reason) = match result {
            Ok(()) => ("applied", None),
            Err(reason) => ("failed", Some(reason.as_str())),
        };
        p.execute(c, "UPDATE corrections SET state = $3, reason = $4, checked_on = $5 WHERE map_id = $1 AND id = $2",
            &[&map_id, &(*id as i32), &state, &reason, &(seq as i32)],
        )?;
    }
    Ok(())
}

fn key(c: &mut impl GenericClient, p: &mut Prepared, map_id: i64) -> R<CorrectionsKey> {
    let row = p.query_one(
        c,
        "SELECT COUNT(*), COUNT(dropped_at) FROM corrections WHERE map_id = $1",
        &[&map_id],
    )?;
    Ok(CorrectionsKey {
        made: row.get(0),
        dropped: row.get(1),
    })
}

fn read_corrections(
    c: &mut impl GenericClient,
    p: &mut Prepared,
    map_id: i64,
    map: &str,
) -> R<Vec<Correction>> {
    let rows = p.query(
        c,
        &format!("SELECT {COLUMNS} FROM corrections WHERE map_id = $1 ORDER BY id"),
        &[&map_id],
    )?;
    let mut out = Vec::with_capacity(rows.len());
    for r in rows {
        let id = u32::try_from(r.get::<_, i32>(0)).unwrap_or(0);
        let rule: Rule = serde_json::from_str(r.get(5)).map_err(|e| StoreError::BadCorrection {
            map: map.to_string(),
            id,
            message: e.to_string(),
        })?;
        let dropped: Option<String> = r.get(9);
        let state: &str = r.get(6);
        let state = CorrectionState::from_stored(dropped.is_some(), state);
        out.push(Correction {
            id,
            made_on: u32::try_from(r.get::<_, i32>(1)).unwrap_or(0),
            created_at: r.get(2),
            author: r.get(3),
            statement: r.get(4),
            state,
            reason: r.get(7),
            checked_on: u32::try_from(r.get::<_, i32>(8)).unwrap_or(0),
            rule,
        });
    }
    Ok(out)
}
