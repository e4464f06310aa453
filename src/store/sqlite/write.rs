//! Writing the SQLite engine: one [`Commit`] is one `BEGIN IMMEDIATE`
//! transaction that adds exactly one revision (with its grid and
//! corrections) or nothing.
//!
//! A revision is written as a [`Delta`] against its parent: rows of spaces
//! and connections that did not change stay open (`valid_to IS NULL`);
//! changed or removed ones are closed at the new revision and changed or
//! added ones opened from it.

use rusqlite::{Connection, OptionalExtension, TransactionBehavior, params};

use super::corrections::{insert_correction, mark_dropped, record_results};
use super::fault::{R, fail};
use super::read::{latest, load_at, map_id, revision_at};
use crate::model::{Nrg, Space};
use crate::store::delta::{Delta, bounding_box};
use crate::store::geometry_blob;
use crate::store::{Commit, Committed, EncodedGrid, ImportMeta, StoreError};

/// Writes `c` in one write transaction (see [`crate::store::engine`]).
pub(super) fn commit(conn: &mut Connection, c: &Commit<'_>) -> R<Committed> {
    let tx = conn.transaction_with_behavior(TransactionBehavior::Immediate)?;
    let existing: Option<i64> = tx
        .query_row("SELECT id FROM maps WHERE name = ?1", [c.map], |r| r.get(0))
        .optional()?;
    let stale = || {
        fail(StoreError::Stale {
            map: c.map.to_string(),
        })
    };
    let map_id = match existing {
        Some(id) => {
            if latest(&tx, id)? != c.base {
                return stale();
            }
            id
        }
        None if c.base == 0 => {
            tx.execute(
                "INSERT INTO maps (name, created_at) VALUES (?1, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))",
                [c.map],
            )?;
            tx.last_insert_rowid()
        }
        None => return map_id(&tx, c.map).and_then(|_| stale()),
    };
    let seq = match c.nrg {
        Some(nrg) => {
            let seq = c.base + 1;
            // The caller passes the base's model; read it when it did not.
            let loaded = match (c.base, c.parent) {
                (0, _) | (_, Some(_)) => None,
                (base, None) => Some(load_at(&tx, map_id, c.map, base)?),
            };
            let parent = if c.base == 0 {
                None
            } else {
                c.parent.or(loaded.as_ref())
            };
            write_revision(&tx, map_id, seq, c.base, parent, nrg, c.meta)?;
            if let Some(grid) = c.grid {
                insert_grid(&tx, map_id, seq, grid)?;
            }
            seq
        }
        None if c.base == 0 => {
            return fail(StoreError::NoSuchRevision {
                map: c.map.to_string(),
                rev: 1,
                latest: 0,
            });
        }
        None => c.base,
    };
    if let Some(reapplied) = c.reapplied {
        record_results(&tx, c.map, map_id, seq, reapplied)?;
    }
    let correction = match c.correction {
        Some(new) => Some(insert_correction(&tx, map_id, seq, &c.meta.author, new)?),
        None => None,
    };
    if let Some(id) = c.drops {
        mark_dropped(&tx, c.map, map_id, id)?;
    }
    let revision = revision_at(&tx, map_id, c.map, seq)?;
    tx.commit()?;
    Ok(Committed {
        revision,
        correction,
    })
}

/// One above the largest space id `map` ever used (1 for a new map).
pub(super) fn next_space_id_of(conn: &Connection, map: &str) -> R<crate::model::SpaceId> {
    let id: Option<i64> = conn
        .query_row("SELECT id FROM maps WHERE name = ?1", [map], |r| r.get(0))
        .optional()?;
    let Some(map_id) = id else {
        return Ok(crate::model::SpaceId(1));
    };
    let max: Option<u32> = conn.query_row(
        "SELECT MAX(space_id) FROM spaces WHERE map_id = ?1",
        [map_id],
        |r| r.get(0),
    )?;
    Ok(crate::model::SpaceId(
        max.map_or(1, |m| m.saturating_add(1)),
    ))
}

/// Writes `nrg` as revision `seq` of the map, as a delta against `parent`
/// (whose open rows are exactly its model).
fn write_revision(
    conn: &Connection,
    map_id: i64,
    seq: u32,
    base: u32,
    parent: Option<&Nrg>,
    nrg: &Nrg,
    meta: &ImportMeta,
) -> R<()> {
    let empty = Nrg::default();
    let delta = Delta::between(parent.unwrap_or(&empty), nrg);
    let mut close_space = conn.prepare_cached(
        "UPDATE spaces SET valid_to = ?3 WHERE map_id = ?1 AND space_id = ?2 AND valid_to IS NULL",
    )?;
    for id in &delta.close_spaces {
        close_space.execute(params![map_id, id.0, seq])?;
    }
    for s in &delta.open_spaces {
        insert_space(conn, map_id, seq, s)?;
    }
    let mut close_link = conn.prepare_cached(
        "UPDATE connections SET valid_to = ?4 WHERE map_id = ?1 AND a = ?2 AND b = ?3 AND valid_to IS NULL",
    )?;
    for (a, b) in &delta.close_links {
        close_link.execute(params![map_id, a.0, b.0, seq])?;
    }
    let mut insert_link = conn.prepare_cached(
        "INSERT INTO connections (map_id, a, b, valid_from, kind, length_m) VALUES (?1, ?2, ?3, ?4, ?5, ?6)",
    )?;
    for c in &delta.open_links {
        insert_link.execute(params![
            map_id,
            c.a.0,
            c.b.0,
            seq,
            c.kind.as_str(),
            c.length_m
        ])?;
    }
    let params_json = meta.params.as_ref().map(|p| p.to_string());
    conn.execute(
        "INSERT INTO revisions (map_id, seq, parent, created_at, source_name, source_sha256, params,
             message, author, space_count, connection_count, spaces_added, spaces_changed, spaces_removed)
         VALUES (?1, ?2, ?3, COALESCE(?14, strftime('%Y-%m-%dT%H:%M:%fZ', 'now')), ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13)",
        params![
            map_id,
            seq,
            (base > 0).then_some(base),
            meta.source_name,
            meta.source_sha256,
            params_json,
            meta.message,
            meta.author,
            count(nrg.spaces().len()),
            count(nrg.connections().len()),
            count(delta.added),
            count(delta.changed),
            count(delta.removed),
            meta.recorded_at,
        ],
    )?;
    Ok(())
}

fn count(n: usize) -> i64 {
    i64::try_from(n).unwrap_or(i64::MAX)
}

fn insert_space(conn: &Connection, map_id: i64, seq: u32, s: &Space) -> R<()> {
    let attributes = serde_json::Value::Object(s.attributes.clone()).to_string();
    conn.prepare_cached(
        "INSERT INTO spaces (map_id, space_id, valid_from, kind, name, attributes, anchor_x, anchor_y, geometry,
                             doorway_ax, doorway_ay, doorway_bx, doorway_by, level_name, level_elevation)
         VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15)",
    )?
    .execute(params![
        map_id,
        s.id.0,
        seq,
        s.kind.as_str(),
        s.name,
        attributes,
        s.anchor[0],
        s.anchor[1],
        geometry_blob::encode(&s.polygon, &s.holes),
        s.doorway.map(|l| l[0][0]),
        s.doorway.map(|l| l[0][1]),
        s.doorway.map(|l| l[1][0]),
        s.doorway.map(|l| l[1][1]),
        s.level.as_ref().map(|l| l.name.as_str()),
        s.level.as_ref().map(|l| l.elevation_m),
    ])?;
    let row_id = conn.last_insert_rowid();
    let [min_x, max_x, min_y, max_y] = bounding_box(s);
    conn.prepare_cached(
        "INSERT INTO space_boxes (row_id, min_x, max_x, min_y, max_y) VALUES (?1, ?2, ?3, ?4, ?5)",
    )?
    .execute(params![row_id, min_x, max_x, min_y, max_y])?;
    Ok(())
}

/// Stores `grid` as the source of revision `seq`.
fn insert_grid(conn: &Connection, map_id: i64, seq: u32, grid: &EncodedGrid) -> R<()> {
    conn.execute(
        "INSERT INTO revision_grids (map_id, seq, width, height, resolution, origin_x, origin_y, origin_yaw, png)
         VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)",
        params![
            map_id,
            seq,
            grid.width,
            grid.height,
            grid.resolution,
            grid.origin[0],
            grid.origin[1],
            grid.origin[2],
            grid.png
        ],
    )?;
    Ok(())
}
