//! Reading the SQLite engine: maps, revision histories, a revision as an
//! [`Nrg`], point location (R*Tree, then point-in-polygon) and grids.

use std::str::FromStr;

use rusqlite::{Connection, OptionalExtension, Row, params};

use super::fault::{R, fail};
use crate::model::{Connection as Link, ConnectionKind, Level, Nrg, Space, SpaceId, SpaceKind};
use crate::store::delta::smallest_containing;
use crate::store::geometry_blob;
use crate::store::{EncodedGrid, MapInfo, RevisionInfo, StoreError};

/// All maps, by name.
pub(super) fn maps(conn: &Connection) -> R<Vec<MapInfo>> {
    let mut stmt = conn.prepare(
        "SELECT m.name, m.created_at, COALESCE(MAX(r.seq), 0)
         FROM maps m LEFT JOIN revisions r ON r.map_id = m.id
         GROUP BY m.id ORDER BY m.name",
    )?;
    let rows = stmt.query_map([], |r| {
        Ok(MapInfo {
            name: r.get(0)?,
            created_at: r.get(1)?,
            latest: r.get(2)?,
        })
    })?;
    Ok(rows.collect::<Result<_, _>>()?)
}

/// The revisions of `map`, oldest first.
pub(super) fn revisions(conn: &Connection, map: &str) -> R<Vec<RevisionInfo>> {
    let tx = conn.unchecked_transaction()?;
    let map_id = map_id(&tx, map)?;
    let mut stmt = tx.prepare(&format!(
        "SELECT {REVISION_COLUMNS} FROM revisions WHERE map_id = ?1 ORDER BY seq"
    ))?;
    let rows = stmt.query_map([map_id], |r| revision_info(map, r))?;
    Ok(rows.collect::<Result<_, _>>()?)
}

/// One revision's record; the latest when `rev` is `None`.
pub(super) fn revision(conn: &Connection, map: &str, rev: Option<u32>) -> R<RevisionInfo> {
    let tx = conn.unchecked_transaction()?;
    let map_id = map_id(&tx, map)?;
    let seq = resolve(&tx, map_id, map, rev)?;
    revision_at(&tx, map_id, map, seq)
}

/// The record of revision `seq`.
pub(super) fn revision_at(conn: &Connection, map_id: i64, map: &str, seq: u32) -> R<RevisionInfo> {
    Ok(conn.query_row(
        &format!("SELECT {REVISION_COLUMNS} FROM revisions WHERE map_id = ?1 AND seq = ?2"),
        params![map_id, seq],
        |r| revision_info(map, r),
    )?)
}

/// Revision `rev` of `map` (the latest when `None`).
pub(super) fn load(conn: &Connection, map: &str, rev: Option<u32>) -> R<Nrg> {
    let tx = conn.unchecked_transaction()?;
    let map_id = map_id(&tx, map)?;
    let seq = resolve(&tx, map_id, map, rev)?;
    load_at(&tx, map_id, map, seq)
}

/// The smallest space of the revision containing `(x, y)`: the R*Tree of
/// bounding boxes, then point-in-polygon (holes excluded).
pub(super) fn locate(
    conn: &Connection,
    map: &str,
    rev: Option<u32>,
    x: f64,
    y: f64,
) -> R<Option<SpaceId>> {
    let tx = conn.unchecked_transaction()?;
    let map_id = map_id(&tx, map)?;
    let seq = resolve(&tx, map_id, map, rev)?;
    let mut stmt = tx.prepare_cached(
        "SELECT s.row_id, s.space_id, s.geometry
         FROM space_boxes b JOIN spaces s ON s.row_id = b.row_id
         WHERE b.min_x <= ?3 AND b.max_x >= ?3 AND b.min_y <= ?4 AND b.max_y >= ?4
           AND s.map_id = ?1 AND s.valid_from <= ?2
           AND (s.valid_to IS NULL OR s.valid_to > ?2)",
    )?;
    let mut rows = stmt.query(params![map_id, seq, x, y])?;
    let mut candidates = Vec::new();
    while let Some(row) = rows.next()? {
        let row_id: i64 = row.get(0)?;
        let blob: Vec<u8> = row.get(2)?;
        let (outline, holes) =
            geometry_blob::decode(&blob).map_err(|what| StoreError::Corrupt {
                map: map.to_string(),
                row: row_id,
                what,
            })?;
        candidates.push((SpaceId(row.get(1)?), outline, holes));
    }
    Ok(smallest_containing(
        [x, y],
        candidates.iter().map(|(id, o, h)| (*id, o, h.as_slice())),
    ))
}

/// The grid stored with revision `rev` (latest when `None`).
pub(super) fn grid(conn: &Connection, map: &str, rev: Option<u32>) -> R<Option<EncodedGrid>> {
    let tx = conn.unchecked_transaction()?;
    let id = map_id(&tx, map)?;
    let seq = resolve(&tx, id, map, rev)?;
    Ok(tx
        .query_row(
            "SELECT width, height, resolution, origin_x, origin_y, origin_yaw, png
             FROM revision_grids WHERE map_id = ?1 AND seq = ?2",
            params![id, seq],
            |r| {
                Ok(EncodedGrid {
                    width: r.get(0)?,
                    height: r.get(1)?,
                    resolution: r.get(2)?,
                    origin: [r.get(3)?, r.get(4)?, r.get(5)?],
                    png: r.get(6)?,
                })
            },
        )
        .optional()?)
}

pub(super) const REVISION_COLUMNS: &str = "seq, parent, created_at, source_name, source_sha256, \
     params, message, author, space_count, connection_count, spaces_added, spaces_changed, \
     spaces_removed";

pub(super) fn revision_info(map: &str, r: &Row<'_>) -> rusqlite::Result<RevisionInfo> {
    let params: Option<String> = r.get(5)?;
    let count = |i| r.get::<_, i64>(i).map(|v| usize::try_from(v).unwrap_or(0));
    Ok(RevisionInfo {
        map: map.to_string(),
        seq: r.get(0)?,
        parent: r.get(1)?,
        created_at: r.get(2)?,
        source_name: r.get(3)?,
        source_sha256: r.get(4)?,
        params: params.and_then(|p| serde_json::from_str(&p).ok()),
        message: r.get(6)?,
        author: r.get(7)?,
        spaces: count(8)?,
        connections: count(9)?,
        spaces_added: count(10)?,
        spaces_changed: count(11)?,
        spaces_removed: count(12)?,
    })
}

/// The row id of map `name`, or [`StoreError::NoSuchMap`] listing the maps.
pub(super) fn map_id(conn: &Connection, name: &str) -> R<i64> {
    let id = conn
        .query_row("SELECT id FROM maps WHERE name = ?1", [name], |r| r.get(0))
        .optional()?;
    match id {
        Some(id) => Ok(id),
        None => {
            let mut stmt = conn.prepare("SELECT name FROM maps ORDER BY name")?;
            let names: Vec<String> = stmt
                .query_map([], |r| r.get(0))?
                .collect::<Result<_, _>>()?;
            fail(StoreError::no_such_map(name, &names))
        }
    }
}

/// The latest revision of a map, 0 when it has none.
pub(super) fn latest(conn: &Connection, map_id: i64) -> R<u32> {
    Ok(conn.query_row(
        "SELECT COALESCE(MAX(seq), 0) FROM revisions WHERE map_id = ?1",
        [map_id],
        |r| r.get(0),
    )?)
}

/// `rev` checked against the map's history (the latest when `None`).
fn resolve(conn: &Connection, map_id: i64, map: &str, rev: Option<u32>) -> R<u32> {
    let last = latest(conn, map_id)?;
    match rev {
        None if last > 0 => Ok(last),
        Some(r) if r >= 1 && r <= last => Ok(r),
        _ => fail(StoreError::NoSuchRevision {
            map: map.to_string(),
            rev: rev.unwrap_or(0),
            latest: last,
        }),
    }
}

/// Revision `seq` of a map, rebuilt from the rows valid in it.
pub(super) fn load_at(conn: &Connection, map_id: i64, map: &str, seq: u32) -> R<Nrg> {
    let corrupt = |row: i64, what: String| StoreError::Corrupt {
        map: map.to_string(),
        row,
        what,
    };
    // The latest revision is exactly the open rows (an index lookup);
    // older ones filter the map's rows by their validity range.
    let is_latest = seq == latest(conn, map_id)?;
    let mut stmt = conn.prepare_cached(if is_latest {
        "SELECT row_id, space_id, kind, name, attributes, anchor_x, anchor_y, geometry,
                doorway_ax, doorway_ay, doorway_bx, doorway_by, level_name, level_elevation
         FROM spaces WHERE map_id = ?1 AND valid_to IS NULL AND ?2 > 0"
    } else {
        "SELECT row_id, space_id, kind, name, attributes, anchor_x, anchor_y, geometry,
                doorway_ax, doorway_ay, doorway_bx, doorway_by, level_name, level_elevation
         FROM spaces WHERE map_id = ?1 AND valid_from <= ?2
           AND (valid_to IS NULL OR valid_to > ?2)"
    })?;
    let mut rows = stmt.query(params![map_id, seq])?;
    let mut spaces = Vec::new();
    while let Some(r) = rows.next()? {
        let row_id: i64 = r.get(0)?;
        let kind: String = r.get(2)?;
        let kind = SpaceKind::from_str(&kind).map_err(|e| corrupt(row_id, e))?;
        let attributes: String = r.get(4)?;
        let attributes =
            serde_json::from_str(&attributes).map_err(|e| corrupt(row_id, e.to_string()))?;
        let blob = r
            .get_ref(7)?
            .as_blob()
            .map_err(|e| corrupt(row_id, e.to_string()))?;
        let (polygon, holes) = geometry_blob::decode(blob).map_err(|e| corrupt(row_id, e))?;
        let mut space = Space::new(SpaceId(r.get(1)?), kind, [r.get(5)?, r.get(6)?], polygon);
        space.name = r.get(3)?;
        space.holes = holes;
        space.attributes = attributes;
        let line: [Option<f64>; 4] = [r.get(8)?, r.get(9)?, r.get(10)?, r.get(11)?];
        if let [Some(ax), Some(ay), Some(bx), Some(by)] = line {
            space.doorway = Some([[ax, ay], [bx, by]]);
        }
        let level: (Option<String>, Option<f64>) = (r.get(12)?, r.get(13)?);
        if let (Some(name), Some(elevation_m)) = level {
            space.level = Some(Level { name, elevation_m });
        }
        spaces.push(space);
    }
    let mut stmt = conn.prepare_cached(if is_latest {
        "SELECT a, b, kind, length_m FROM connections
         WHERE map_id = ?1 AND valid_to IS NULL AND ?2 > 0"
    } else {
        "SELECT a, b, kind, length_m FROM connections WHERE map_id = ?1 AND valid_from <= ?2
           AND (valid_to IS NULL OR valid_to > ?2)"
    })?;
    let mut rows = stmt.query(params![map_id, seq])?;
    let mut links = Vec::new();
    while let Some(r) = rows.next()? {
        let kind: String = r.get(2)?;
        links.push(Link {
            a: SpaceId(r.get(0)?),
            b: SpaceId(r.get(1)?),
            kind: ConnectionKind::from_str(&kind).map_err(|e| corrupt(0, e))?,
            length_m: r.get(3)?,
        });
    }
    Ok(Nrg::new(spaces, links).map_err(|e| corrupt(0, e.to_string()))?)
}
