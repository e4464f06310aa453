//! Reading the PostgreSQL engine, each call in one repeatable-read
//! snapshot: maps, revisions, a revision as an [`Nrg`], point location
//! (GiST on the PostGIS outline, then point-in-polygon on the exact one),
//! grids, and the consistency check.

use std::str::FromStr;

use postgres::{Client, GenericClient, IsolationLevel, Row, Transaction};

use super::fault::{R, fail};
use super::prepared::Prepared;
use crate::model::{Connection as Link, ConnectionKind, Level, Nrg, Space, SpaceId, SpaceKind};
use crate::store::delta::smallest_containing;
use crate::store::{EncodedGrid, MapInfo, RevisionInfo, StoreError, geometry_blob};

/// A read-only snapshot.
fn snapshot(client: &mut Client) -> R<Transaction<'_>> {
    Ok(client
        .build_transaction()
        .isolation_level(IsolationLevel::RepeatableRead)
        .read_only(true)
        .start()?)
}

/// All maps, by name.
pub(super) fn maps(client: &mut Client, p: &mut Prepared) -> R<Vec<MapInfo>> {
    let rows = p.query(
        client,
        "SELECT m.name, m.created_at, COALESCE(MAX(r.seq), 0)
         FROM maps m LEFT JOIN revisions r ON r.map_id = m.id
         GROUP BY m.id ORDER BY m.name",
        &[],
    )?;
    Ok(rows
        .iter()
        .map(|r| MapInfo {
            name: r.get(0),
            created_at: r.get(1),
            latest: u32_of(r.get(2)),
        })
        .collect())
}

pub(super) const REVISION_COLUMNS: &str = "seq, parent, created_at, source_name, source_sha256, \
     params, message, author, space_count, connection_count, spaces_added, spaces_changed, \
     spaces_removed";

fn u32_of(v: i32) -> u32 {
    u32::try_from(v).unwrap_or(0)
}

fn count(v: i64) -> usize {
    usize::try_from(v).unwrap_or(0)
}

pub(super) fn revision_info(map: &str, r: &Row) -> RevisionInfo {
    let params: Option<String> = r.get(5);
    RevisionInfo {
        map: map.to_string(),
        seq: u32_of(r.get(0)),
        parent: r.get::<_, Option<i32>>(1).map(u32_of),
        created_at: r.get(2),
        source_name: r.get(3),
        source_sha256: r.get(4),
        params: params.and_then(|p| serde_json::from_str(&p).ok()),
        message: r.get(6),
        author: r.get(7),
        spaces: count(r.get(8)),
        connections: count(r.get(9)),
        spaces_added: count(r.get(10)),
        spaces_changed: count(r.get(11)),
        spaces_removed: count(r.get(12)),
    }
}

/// The revisions of `map`, oldest first.
pub(super) fn revisions(client: &mut Client, p: &mut Prepared, map: &str) -> R<Vec<RevisionInfo>> {
    let mut tx = snapshot(client)?;
    let map_id = map_id(&mut tx, p, map)?;
    let rows = p.query(
        &mut tx,
        &format!("SELECT {REVISION_COLUMNS} FROM revisions WHERE map_id = $1 ORDER BY seq"),
        &[&map_id],
    )?;
    Ok(rows.iter().map(|r| revision_info(map, r)).collect())
}

/// One revision's record, the latest when `rev` is `None`.
pub(super) fn revision(
    client: &mut Client,
    p: &mut Prepared,
    map: &str,
    rev: Option<u32>,
) -> R<RevisionInfo> {
    // One round trip when the revision exists (every request of a server
    // asks for the latest); the errors take the slow path below.
    let asked = rev.map_or(0, |r| i32::try_from(r).unwrap_or(i32::MAX));
    if let Some(row) = p.query_opt(client, REVISION, &[&map, &asked])? {
        return Ok(revision_info(map, &row));
    }
    let mut tx = snapshot(client)?;
    let map_id = map_id(&mut tx, p, map)?;
    let seq = resolve(&mut tx, p, map_id, map, rev)?;
    revision_at(&mut tx, p, map_id, map, seq)
}

/// [`revision`] in one statement: `$1` the map, `$2` the revision (0:
/// the latest); no row when either does not exist.
const REVISION: &str = "SELECT r.seq, r.parent, r.created_at, r.source_name, r.source_sha256, \
     r.params, r.message, r.author, r.space_count, r.connection_count, r.spaces_added, \
     r.spaces_changed, r.spaces_removed \
     FROM maps m JOIN revisions r ON r.map_id = m.id \
     WHERE m.name = $1 AND r.seq = CASE WHEN $2::int = 0 \
         THEN (SELECT MAX(seq) FROM revisions WHERE map_id = m.id) ELSE $2::int END";

/// The record of revision `seq`.
pub(super) fn revision_at(
    c: &mut impl GenericClient,
    p: &mut Prepared,
    map_id: i64,
    map: &str,
    seq: u32,
) -> R<RevisionInfo> {
    let row = p.query_one(
        c,
        &format!("SELECT {REVISION_COLUMNS} FROM revisions WHERE map_id = $1 AND seq = $2"),
        &[&map_id, &(seq as i32)],
    )?;
    Ok(revision_info(map, &row))
}

/// Revision `rev` of `map` (the latest when `None`).
///
/// One statement (so one snapshot and one round trip): the map's latest
/// revision, then its spaces (`part` 0) and connections (`part` 1).
pub(super) fn load(client: &mut Client, p: &mut Prepared, map: &str, rev: Option<u32>) -> R<Nrg> {
    let asked = rev.map_or(0, |r| i32::try_from(r).unwrap_or(i32::MAX));
    let rows = p.query(client, LOAD, &[&map, &asked])?;
    let Some(first) = rows.first() else {
        // No such map: the slow path names the maps there are.
        map_id(client, p, map)?;
        return fail(StoreError::NoSuchMap {
            name: map.to_string(),
            known: String::new(),
            suggestion: None,
        });
    };
    let latest = u32_of(first.get(1));
    if latest == 0 || rev.is_some_and(|r| r < 1 || r > latest) {
        return fail(StoreError::NoSuchRevision {
            map: map.to_string(),
            rev: rev.unwrap_or(0),
            latest,
        });
    }
    let corrupt = |row: i64, what: String| StoreError::Corrupt {
        map: map.to_string(),
        row,
        what,
    };
    let (mut spaces, mut links) = (Vec::new(), Vec::new());
    for r in &rows {
        let Some(row_id) = r.get::<_, Option<i64>>(2) else {
            continue;
        };
        if r.get::<_, i32>(0) == 0 {
            spaces.push(space_of(map, r, 2).map_err(|e| corrupt(row_id, e))?);
        } else {
            links.push(Link {
                a: space_id(map, 0, r.get(3))?,
                b: space_id(map, 0, r.get(16))?,
                kind: ConnectionKind::from_str(r.get(4)).map_err(|e| corrupt(0, e))?,
                length_m: r.get(17),
            });
        }
    }
    Ok(Nrg::new(spaces, links).map_err(|e| corrupt(0, e.to_string()))?)
}

/// The statement of [`load`]: `$1` the map, `$2` the revision (0: the
/// latest). A map without revisions gives one row with `latest` 0.
const LOAD: &str = "
    WITH q AS (
        SELECT m.id AS map_id, r.latest,
               CASE WHEN $2::int = 0 THEN r.latest ELSE $2::int END AS seq
        FROM maps m,
             LATERAL (SELECT COALESCE(MAX(seq), 0) AS latest FROM revisions WHERE map_id = m.id) r
        WHERE m.name = $1)
    SELECT 0 AS part, q.latest, s.row_id, s.space_id, s.kind, s.name, s.attributes::text,
           s.anchor_x, s.anchor_y, s.geometry, s.doorway_ax, s.doorway_ay, s.doorway_bx,
           s.doorway_by, s.level_name, s.level_elevation, NULL::bigint AS b,
           NULL::float8 AS length_m
    FROM q LEFT JOIN spaces s ON s.map_id = q.map_id AND s.valid_from <= q.seq
                               AND (s.valid_to IS NULL OR s.valid_to > q.seq)
    UNION ALL
    SELECT 1, q.latest, 0, c.a, c.kind, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL,
           NULL, NULL, c.b, c.length_m
    FROM q JOIN connections c ON c.map_id = q.map_id AND c.valid_from <= q.seq
                              AND (c.valid_to IS NULL OR c.valid_to > q.seq)";

/// A space from a row whose columns from `at` on are `row_id, space_id,
/// kind, name, attributes, anchor_x, anchor_y, geometry, doorway_ax,
/// doorway_ay, doorway_bx, doorway_by, level_name, level_elevation`.
fn space_of(map: &str, r: &Row, at: usize) -> Result<Space, String> {
    let row_id: i64 = r.get(at);
    let kind = SpaceKind::from_str(r.get(at + 2))?;
    let attributes = serde_json::from_str(r.get(at + 4)).map_err(|e| e.to_string())?;
    let (polygon, holes) = geometry_blob::decode(r.get(at + 7))?;
    let id = space_id(map, row_id, r.get(at + 1)).map_err(|e| e.0.to_string())?;
    let mut space = Space::new(id, kind, [r.get(at + 5), r.get(at + 6)], polygon);
    space.name = r.get(at + 3);
    space.holes = holes;
    space.attributes = attributes;
    let line: [Option<f64>; 4] = [r.get(at + 8), r.get(at + 9), r.get(at + 10), r.get(at + 11)];
    if let [Some(ax), Some(ay), Some(bx), Some(by)] = line {
        space.doorway = Some([[ax, ay], [bx, by]]);
    }
    let level: (Option<String>, Option<f64>) = (r.get(at + 12), r.get(at + 13));
    if let (Some(name), Some(elevation_m)) = level {
        space.level = Some(Level { name, elevation_m });
    }
    Ok(space)
}

/// The smallest space of the revision containing `(x, y)`.
pub(super) fn locate(
    client: &mut Client,
    p: &mut Prepared,
    map: &str,
    rev: Option<u32>,
    x: f64,
    y: f64,
) -> R<Option<SpaceId>> {
    let mut tx = snapshot(client)?;
    let map_id = map_id(&mut tx, p, map)?;
    let seq = resolve(&mut tx, p, map_id, map, rev)? as i32;
    // The GiST index finds the outlines whose box holds the point; the
    // exact test is the same as every other engine's.
    let rows = p.query(
        &mut tx,
        "SELECT row_id, space_id, geometry FROM spaces
         WHERE map_id = $1 AND valid_from <= $2 AND (valid_to IS NULL OR valid_to > $2)
           AND geom && ST_MakePoint($3, $4)",
        &[&map_id, &seq, &x, &y],
    )?;
    let mut candidates = Vec::with_capacity(rows.len());
    for row in rows {
        let row_id: i64 = row.get(0);
        let (outline, holes) =
            geometry_blob::decode(row.get(2)).map_err(|what| StoreError::Corrupt {
                map: map.to_string(),
                row: row_id,
                what,
            })?;
        candidates.push((space_id(map, row_id, row.get(1))?, outline, holes));
    }
    Ok(smallest_containing(
        [x, y],
        candidates.iter().map(|(id, o, h)| (*id, o, h.as_slice())),
    ))
}

fn space_id(map: &str, row: i64, v: i64) -> R<SpaceId> {
    match u32::try_from(v) {
        Ok(id) => Ok(SpaceId(id)),
        Err(_) => fail(StoreError::Corrupt {
            map: map.to_string(),
            row,
            what: format!("space id {v} out of range"),
        }),
    }
}

/// The grid stored with revision `rev` (latest when `None`).
pub(super) fn grid(
    client: &mut Client,
    p: &mut Prepared,
    map: &str,
    rev: Option<u32>,
) -> R<Option<EncodedGrid>> {
    let mut tx = snapshot(client)?;
    let map_id = map_id(&mut tx, p, map)?;
    let seq = resolve(&mut tx, p, map_id, map, rev)? as i32;
    let row = p.query_opt(
        &mut tx,
        "SELECT width, height, resolution, origin_x, origin_y, origin_yaw, png
         FROM revision_grids WHERE map_id = $1 AND seq = $2",
        &[&map_id, &seq],
    )?;
    Ok(row.map(|r| EncodedGrid {
        width: u32::try_from(r.get::<_, i64>(0)).unwrap_or(0),
        height: u32::try_from(r.get::<_, i64>(1)).unwrap_or(0),
        resolution: r.get(2),
        origin: [r.get(3), r.get(4), r.get(5)],
        png: r.get(6),
    }))
}

/// Maps whose history is not a line 1..n, or whose latest revision's row
/// count disagrees with its record; `["ok"]` when there are none.
pub(super) fn integrity(client: &mut Client, p: &mut Prepared) -> R<Vec<String>> {
    let rows = p.query(
        client,
        "SELECT m.name, COUNT(r.seq), COALESCE(MAX(r.seq), 0),
                (SELECT COUNT(*) FROM spaces s WHERE s.map_id = m.id AND s.valid_to IS NULL),
                (SELECT r2.space_count FROM revisions r2 WHERE r2.map_id = m.id
                 ORDER BY r2.seq DESC LIMIT 1)
         FROM maps m LEFT JOIN revisions r ON r.map_id = m.id GROUP BY m.id, m.name",
        &[],
    )?;
    let mut problems = Vec::new();
    for r in rows {
        let (name, n, max): (String, i64, i32) = (r.get(0), r.get(1), r.get(2));
        if n != i64::from(max) {
            problems.push(format!(
                "map '{name}': {n} revisions but the latest is {max}"
            ));
        }
        let (open, recorded): (i64, Option<i64>) = (r.get(3), r.get(4));
        if recorded.is_some_and(|c| c != open) {
            problems.push(format!(
                "map '{name}': the latest revision records {} spaces, {open} rows are open",
                recorded.unwrap_or(0)
            ));
        }
    }
    if problems.is_empty() {
        problems.push("ok".into());
    }
    Ok(problems)
}

/// The id of map `name`, or [`StoreError::NoSuchMap`] listing the maps.
pub(super) fn map_id(c: &mut impl GenericClient, p: &mut Prepared, name: &str) -> R<i64> {
    if let Some(row) = p.query_opt(c, "SELECT id FROM maps WHERE name = $1", &[&name])? {
        return Ok(row.get(0));
    }
    let names: Vec<String> = c
        .query("SELECT name FROM maps ORDER BY name", &[])?
        .iter()
        .map(|r| r.get(0))
        .collect();
    fail(StoreError::no_such_map(name, &names))
}

/// The latest revision of a map, 0 when it has none.
pub(super) fn latest(c: &mut impl GenericClient, p: &mut Prepared, map_id: i64) -> R<u32> {
    let v: i32 = p
        .query_one(
            c,
            "SELECT COALESCE(MAX(seq), 0) FROM revisions WHERE map_id = $1",
            &[&map_id],
        )?
        .get(0);
    Ok(u32_of(v))
}

fn resolve(
    c: &mut impl GenericClient,
    p: &mut Prepared,
    map_id: i64,
    map: &str,
    rev: Option<u32>,
) -> R<u32> {
    let last = latest(c, p, map_id)?;
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
pub(super) fn load_at(
    c: &mut impl GenericClient,
    p: &mut Prepared,
    map_id: i64,
    map: &str,
    seq: u32,
) -> R<Nrg> {
    let corrupt = |row: i64, what: String| StoreError::Corrupt {
        map: map.to_string(),
        row,
        what,
    };
    let seq = seq as i32;
    let rows = p.query(
        c,
        "SELECT row_id, space_id, kind, name, attributes::text, anchor_x, anchor_y, geometry,
                doorway_ax, doorway_ay, doorway_bx, doorway_by, level_name, level_elevation
         FROM spaces WHERE map_id = $1 AND valid_from <= $2
           AND (valid_to IS NULL OR valid_to > $2)",
        &[&map_id, &seq],
    )?;
    let mut spaces = Vec::with_capacity(rows.len());
    for r in &rows {
        let row_id: i64 = r.get(0);
        spaces.push(space_of(map, r, 0).map_err(|e| corrupt(row_id, e))?);
    }
    let rows = p.query(
        c,
        "SELECT a, b, kind, length_m FROM connections WHERE map_id = $1 AND valid_from <= $2
           AND (valid_to IS NULL OR valid_to > $2)",
        &[&map_id, &seq],
    )?;
    let mut links = Vec::with_capacity(rows.len());
    for r in rows {
        links.push(Link {
            a: space_id(map, 0, r.get(0))?,
            b: space_id(map, 0, r.get(1))?,
            kind: ConnectionKind::from_str(r.get(2)).map_err(|e| corrupt(0, e))?,
            length_m: r.get(3),
        });
    }
    Ok(Nrg::new(spaces, links).map_err(|e| corrupt(0, e.to_string()))?)
}
