//! Writing the PostgreSQL engine: one [`Commit`] is one transaction that
//! first takes the map's advisory lock (writers of one map queue there;
//! `lock_timeout` turns a long wait into [`StoreError::Busy`]), checks the
//! base is still the latest, and writes the revision as a [`Delta`] with
//! its grid and corrections.

use geozero::{CoordDimensions, ToWkb};
use postgres::{Client, GenericClient, Transaction};

use super::corrections::{insert_correction, mark_dropped, record_results};
use super::fault::{R, fail};
use super::prepared::Prepared;
use super::read::{latest, load_at, map_id, revision_at};
use crate::model::{Nrg, Space, SpaceId};
use crate::store::delta::Delta;
use crate::store::now_utc;
use crate::store::{Commit, Committed, EncodedGrid, StoreError, geometry_blob};

/// Takes the write lock of `map` for the rest of the transaction.
pub(super) fn lock_map(tx: &mut Transaction<'_>, p: &mut Prepared, map: &str) -> R<()> {
    p.execute(
        tx,
        "SELECT pg_advisory_xact_lock(hashtextextended('nrgdb map ' || $1, 0))",
        &[&map],
    )?;
    Ok(())
}

/// Writes `c` in one transaction (see [`crate::store::engine`]).
pub(super) fn commit(client: &mut Client, p: &mut Prepared, c: &Commit<'_>) -> R<Committed> {
    let mut tx = client.transaction()?;
    lock_map(&mut tx, p, c.map)?;
    let existing = p.query_opt(&mut tx, "SELECT id FROM maps WHERE name = $1", &[&c.map])?;
    let stale = || {
        fail(StoreError::Stale {
            map: c.map.to_string(),
        })
    };
    let map_id: i64 = match existing {
        Some(row) => {
            let id = row.get(0);
            if latest(&mut tx, p, id)? != c.base {
                return stale();
            }
            id
        }
        None if c.base == 0 => p
            .query_one(
                &mut tx,
                "INSERT INTO maps (name, created_at) VALUES ($1, $2) RETURNING id",
                &[&c.map, &now_utc()],
            )?
            .get(0),
        None => return map_id(&mut tx, p, c.map).and_then(|_| stale()),
    };
    let seq = match c.nrg {
        Some(nrg) => {
            let seq = c.base + 1;
            let loaded = match (c.base, c.parent) {
                (0, _) | (_, Some(_)) => None,
                (base, None) => Some(load_at(&mut tx, p, map_id, c.map, base)?),
            };
            let parent = if c.base == 0 {
                None
            } else {
                c.parent.or(loaded.as_ref())
            };
            write_revision(&mut tx, p, map_id, c, parent, nrg)?;
            if let Some(grid) = c.grid {
                insert_grid(&mut tx, p, map_id, seq, grid)?;
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
        record_results(&mut tx, p, c.map, map_id, seq, reapplied)?;
    }
    let correction = match c.correction {
        Some(new) => Some(insert_correction(
            &mut tx,
            p,
            map_id,
            seq,
            &c.meta.author,
            new,
        )?),
        None => None,
    };
    if let Some(id) = c.drops {
        mark_dropped(&mut tx, p, c.map, map_id, id)?;
    }
    let revision = revision_at(&mut tx, p, map_id, c.map, seq)?;
    tx.commit()?;
    Ok(Committed {
        revision,
        correction,
    })
}

/// One above the largest space id `map` ever used (1 for a new map).
pub(super) fn next_space_id_of(client: &mut Client, p: &mut Prepared, map: &str) -> R<SpaceId> {
    let max: Option<i64> = p
        .query_one(
            client,
            "SELECT MAX(s.space_id) FROM spaces s JOIN maps m ON m.id = s.map_id WHERE m.name = $1",
            &[&map],
        )?
        .get(0);
    let next = max.map_or(1, |m| m.saturating_add(1));
    Ok(SpaceId(u32::try_from(next).unwrap_or(u32::MAX)))
}

/// Writes `nrg` as revision `c.base + 1`, a delta against `parent`.
fn write_revision(
    tx: &mut Transaction<'_>,
    p: &mut Prepared,
    map_id: i64,
    c: &Commit<'_>,
    parent: Option<&Nrg>,
    nrg: &Nrg,
) -> R<()> {
    let (base, meta) = (c.base, c.meta);
    let seq = base + 1;
    let empty = Nrg::default();
    let delta = Delta::between(parent.unwrap_or(&empty), nrg);
    let seq_i = seq as i32;
    if !delta.close_spaces.is_empty() {
        let ids: Vec<i64> = delta.close_spaces.iter().map(|s| i64::from(s.0)).collect();
        p.execute(
            &mut *tx,
            "UPDATE spaces SET valid_to = $3
             WHERE map_id = $1 AND space_id = ANY($2) AND valid_to IS NULL",
            &[&map_id, &ids, &seq_i],
        )?;
    }
    let insert =
        "INSERT INTO spaces (map_id, space_id, valid_from, kind, name, attributes, anchor_x,
             anchor_y, geometry, geom, doorway_ax, doorway_ay, doorway_bx, doorway_by,
             level_name, level_elevation)
         VALUES ($1, $2, $3, $4, $5, $6::text::json, $7, $8, $9, ST_GeomFromWKB($10, 0),
                 $11, $12, $13, $14, $15, $16)";
    for s in &delta.open_spaces {
        let attributes = serde_json::Value::Object(s.attributes.clone()).to_string();
        let wkb = polygon_wkb(s)?;
        p.execute(
            &mut *tx,
            insert,
            &[
                &map_id,
                &i64::from(s.id.0),
                &seq_i,
                &s.kind.as_str(),
                &s.name,
                &attributes,
                &s.anchor[0],
                &s.anchor[1],
                &geometry_blob::encode(&s.polygon, &s.holes),
                &wkb,
                &s.doorway.map(|l| l[0][0]),
                &s.doorway.map(|l| l[0][1]),
                &s.doorway.map(|l| l[1][0]),
                &s.doorway.map(|l| l[1][1]),
                &s.level.as_ref().map(|l| l.name.as_str()),
                &s.level.as_ref().map(|l| l.elevation_m),
            ],
        )?;
    }
    let close = "UPDATE connections SET valid_to = $4
         WHERE map_id = $1 AND a = $2 AND b = $3 AND valid_to IS NULL";
    for (a, b) in &delta.close_links {
        p.execute(
            &mut *tx,
            close,
            &[&map_id, &i64::from(a.0), &i64::from(b.0), &seq_i],
        )?;
    }
    let insert = "INSERT INTO connections (map_id, a, b, valid_from, kind, length_m, geom)
         VALUES ($1, $2, $3, $4, $5, $6, ST_MakeLine(ST_MakePoint($7, $8), ST_MakePoint($9, $10)))";
    for link in &delta.open_links {
        let (pa, pb) = (
            nrg.space(link.a).map_or([0.0; 2], |s| s.anchor),
            nrg.space(link.b).map_or([0.0; 2], |s| s.anchor),
        );
        p.execute(
            &mut *tx,
            insert,
            &[
                &map_id,
                &i64::from(link.a.0),
                &i64::from(link.b.0),
                &seq_i,
                &link.kind.as_str(),
                &link.length_m,
                &pa[0],
                &pa[1],
                &pb[0],
                &pb[1],
            ],
        )?;
    }
    let params_json = meta.params.as_ref().map(|v| v.to_string());
    let n = |v: usize| i64::try_from(v).unwrap_or(i64::MAX);
    p.execute(&mut *tx, "INSERT INTO revisions (map_id, seq, parent, created_at, source_name, source_sha256, params,
             message, author, space_count, connection_count, spaces_added, spaces_changed, spaces_removed)
         VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14)",
        &[
            &map_id,
            &seq_i,
            &(base > 0).then_some(base as i32),
            &meta.recorded_at.clone().unwrap_or_else(now_utc),
            &meta.source_name,
            &meta.source_sha256,
            &params_json,
            &meta.message,
            &meta.author,
            &n(nrg.spaces().len()),
            &n(nrg.connections().len()),
            &n(delta.added),
            &n(delta.changed),
            &n(delta.removed),
        ],
    )?;
    Ok(())
}

/// A space's outline with its holes as WKB, rings closed as WKB wants.
fn polygon_wkb(s: &Space) -> R<Vec<u8>> {
    let ring =
        |r: &[[f64; 2]]| geo::LineString::from(r.iter().map(|p| (p[0], p[1])).collect::<Vec<_>>());
    let polygon = geo::Polygon::new(ring(&s.polygon), s.holes.iter().map(|h| ring(h)).collect());
    geo::Geometry::Polygon(polygon)
        .to_wkb(CoordDimensions::xy())
        .or_else(|e| {
            fail(StoreError::Backend {
                engine: "postgres",
                source: Box::new(e),
            })
        })
}

fn insert_grid(
    c: &mut impl GenericClient,
    p: &mut Prepared,
    map_id: i64,
    seq: u32,
    grid: &EncodedGrid,
) -> R<()> {
    p.execute(c, "INSERT INTO revision_grids (map_id, seq, width, height, resolution, origin_x, origin_y, origin_yaw, png)
         VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9)",
        &[
            &map_id,
            &(seq as i32),
            &i64::from(grid.width),
            &i64::from(grid.height),
            &grid.resolution,
            &grid.origin[0],
            &grid.origin[1],
            &grid.origin[2],
            &grid.png,
        ],
    )?;
    Ok(())
}
