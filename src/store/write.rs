//! Writing the store: imports and renames, each one transaction (`BEGIN
//! IMMEDIATE`) that adds exactly one revision or nothing.
//!
//! A revision is written as a delta against its parent: rows of spaces and
//! connections that did not change stay open (`valid_to IS NULL`); changed
//! or removed ones are closed at the new revision and changed or added ones
//! opened from it.

use std::collections::BTreeMap;

use rusqlite::{Connection, OptionalExtension, TransactionBehavior, params};

use super::corrections::{CorrectionResults, record_results};
use super::read::{REVISION_COLUMNS, latest, load_at, map_id, revision_info};
use super::{ImportMeta, Imported, RevisionInfo, Store, StoreError, geometry_blob};
use crate::diff::{MAX_MATCH_PAIRS, MatchParams, match_spaces_within};
use crate::model::{Connection as Link, Nrg, Space, SpaceId};

impl Store {
    /// Stores `nrg` as the next revision of `map` (creating the map on its
    /// first import). Each space is matched to the space it continues in
    /// the parent revision and keeps its stable id, name and attributes
    /// (the new model's own name and attribute values win when set); new
    /// spaces get ids above any the map ever used. The first revision
    /// keeps the model's ids. One transaction: on any error nothing is
    /// stored.
    pub fn import(
        &mut self,
        map: &str,
        nrg: &Nrg,
        meta: ImportMeta,
    ) -> Result<Imported, StoreError> {
        self.import_with_grid(map, nrg, meta, None)
    }

    /// [`Store::import`], also keeping the occupancy grid the model was
    /// extracted from (see [`Store::grid`]), in the same transaction.
    ///
    /// Matching against the parent revision is the expensive part, so it
    /// (like encoding the grid) runs before the write lock is taken, on a
    /// snapshot of the map (issue 21, defect 3: it ran inside `BEGIN
    /// IMMEDIATE` and every other writer got "busy"). Under the lock the
    /// import checks that the revision it matched against is still the
    /// latest; if another writer got in first it matches again, at most
    /// [`MAX_IMPORT_ATTEMPTS`] times, then fails with
    /// [`StoreError::MapChanged`].
    pub fn import_with_grid(
        &mut self,
        map: &str,
        nrg: &Nrg,
        meta: ImportMeta,
        grid: Option<&crate::grid::OccupancyGrid>,
    ) -> Result<Imported, StoreError> {
        self.import_inner(map, nrg, meta, grid, None)
    }

    /// [`Store::import_with_grid`] of a model the map's corrections were
    /// applied to, recording each one's result with the revision; refused
    /// with [`StoreError::Stale`] (nothing stored) when the corrections
    /// changed since `reapplied` was computed.
    pub fn import_corrected(
        &mut self,
        map: &str,
        nrg: &Nrg,
        meta: ImportMeta,
        grid: Option<&crate::grid::OccupancyGrid>,
        reapplied: &CorrectionResults,
    ) -> Result<Imported, StoreError> {
        self.import_inner(map, nrg, meta, grid, Some(reapplied))
    }

    fn import_inner(
        &mut self,
        map: &str,
        nrg: &Nrg,
        meta: ImportMeta,
        grid: Option<&crate::grid::OccupancyGrid>,
        reapplied: Option<&CorrectionResults>,
    ) -> Result<Imported, StoreError> {
        check_map_name(map)?;
        check_meta(&meta)?;
        let grid = grid.map(super::grids::encode_grid).transpose()?;
        for _ in 0..MAX_IMPORT_ATTEMPTS {
            tracing::info!(
                map,
                spaces = nrg.spaces().len(),
                "matching the latest revision"
            );
            let prepared = self
                .prepare_import(map, nrg)
                .map_err(|e| e.in_file(&self.path))?;
            tracing::info!(map, "writing the revision");
            #[cfg(test)]
            if let Some(hook) = self.before_write_lock.as_mut() {
                hook();
            }
            let done = self
                .commit_import(map, prepared, &meta, grid.as_ref(), reapplied)
                .map_err(|e| e.in_file(&self.path))?;
            if let Some(imported) = done {
                return Ok(imported);
            }
        }
        Err(StoreError::MapChanged {
            map: map.to_string(),
            attempts: MAX_IMPORT_ATTEMPTS,
        })
    }

    /// Reads the map's latest revision (one read transaction, no write
    /// lock) and renumbers `nrg` to continue it.
    fn prepare_import(&self, map: &str, nrg: &Nrg) -> Result<PreparedImport, StoreError> {
        let tx = self.conn.unchecked_transaction()?;
        let map_id: Option<i64> = tx
            .query_row("SELECT id FROM maps WHERE name = ?1", [map], |r| r.get(0))
            .optional()?;
        let parent_seq = match map_id {
            Some(id) => latest(&tx, id)?,
            None => 0,
        };
        let prepared = match map_id {
            Some(id) if parent_seq > 0 => {
                let parent = load_at(&tx, id, map, parent_seq)?;
                let next = next_space_id(&tx, id)?;
                tx.finish()?;
                let (stable, ids) = continue_identity(&parent, nrg, &self.match_params, next)?;
                PreparedImport {
                    map_id,
                    stable,
                    ids,
                    parent: Some((parent_seq, parent)),
                }
            }
            _ => {
                tx.finish()?;
                PreparedImport {
                    map_id,
                    stable: nrg.clone(),
                    ids: nrg.spaces().iter().map(|s| (s.id, s.id)).collect(),
                    parent: None,
                }
            }
        };
        Ok(prepared)
    }

    /// Takes the write lock and writes `prepared` if the revision it was
    /// matched against is still the map's latest; `Ok(None)` (nothing
    /// written) when another writer got in first.
    fn commit_import(
        &mut self,
        map: &str,
        prepared: PreparedImport,
        meta: &ImportMeta,
        grid: Option<&super::grids::EncodedGrid<'_>>,
        reapplied: Option<&CorrectionResults>,
    ) -> Result<Option<Imported>, StoreError> {
        let tx = self
            .conn
            .transaction_with_behavior(TransactionBehavior::Immediate)?;
        let existing: Option<i64> = tx
            .query_row("SELECT id FROM maps WHERE name = ?1", [map], |r| r.get(0))
            .optional()?;
        let parent_seq = prepared.parent.as_ref().map_or(0, |p| p.0);
        let map_id = match existing {
            Some(id) => {
                let same_map = prepared.map_id.is_none_or(|m| m == id);
                if !same_map || latest(&tx, id)? != parent_seq {
                    return Ok(None);
                }
                id
            }
            None if prepared.map_id.is_some() => return Ok(None),
            None => {
                tx.execute(
                    "INSERT INTO maps (name, created_at) VALUES (?1, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'))",
                    [map],
                )?;
                tx.last_insert_rowid()
            }
        };
        // The same model again (a map re-imported unchanged): no revision.
        if let Some((seq, _)) = prepared
            .parent
            .as_ref()
            .filter(|(_, p)| same_model(p, &prepared.stable))
        {
            if let Some(reapplied) = reapplied {
                record_results(&tx, map, map_id, *seq, reapplied)?;
            }
            let revision = tx.query_row(
                &format!("SELECT {REVISION_COLUMNS} FROM revisions WHERE map_id = ?1 AND seq = ?2"),
                params![map_id, seq],
                |r| revision_info(map, r),
            )?;
            tx.commit()?;
            return Ok(Some(Imported {
                revision,
                unchanged: true,
                ids: prepared.ids,
            }));
        }
        let revision = commit_revision(
            &tx,
            map_id,
            map,
            prepared.parent.as_ref(),
            &prepared.stable,
            meta,
        )?;
        if let Some(grid) = grid {
            super::grids::insert_grid(&tx, map_id, revision.seq, grid)?;
        }
        if let Some(reapplied) = reapplied {
            record_results(&tx, map, map_id, revision.seq, reapplied)?;
        }
        tx.commit()?;
        Ok(Some(Imported {
            revision,
            unchanged: false,
            ids: prepared.ids,
        }))
    }

    /// Gives space `id` of the latest revision of `map` the name `name`
    /// (`None` clears it), as a new revision.
    pub fn rename_space(
        &mut self,
        map: &str,
        id: SpaceId,
        name: Option<&str>,
        meta: ImportMeta,
    ) -> Result<RevisionInfo, StoreError> {
        self.rename_in_lock(map, id, name, &meta)
            .map_err(|e| e.in_file(&self.path))
    }

    /// [`Store::rename_space`] in one write transaction (renaming matches
    /// nothing, so it is cheap enough to do under the lock).
    fn rename_in_lock(
        &mut self,
        map: &str,
        id: SpaceId,
        name: Option<&str>,
        meta: &ImportMeta,
    ) -> Result<RevisionInfo, StoreError> {
        let tx = self
            .conn
            .transaction_with_behavior(TransactionBehavior::Immediate)?;
        let map_id = map_id(&tx, map)?;
        let seq = latest(&tx, map_id)?;
        if seq == 0 {
            return Err(StoreError::NoSuchRevision {
                map: map.to_string(),
                rev: 1,
                latest: 0,
            });
        }
        let parent = load_at(&tx, map_id, map, seq)?;
        if parent.space(id).is_none() {
            return Err(StoreError::NoSuchSpace {
                map: map.to_string(),
                id,
                rev: seq,
            });
        }
        let (mut spaces, links) = parent.clone().into_parts();
        for s in spaces.iter_mut().filter(|s| s.id == id) {
            s.name = name.map(str::to_string);
        }
        let renamed = Nrg::new(spaces, links)?;
        let info = commit_revision(&tx, map_id, map, Some(&(seq, parent)), &renamed, meta)?;
        tx.commit()?;
        Ok(info)
    }
}

/// How many times an import matches its spaces again when another writer
/// added a revision meanwhile, before it gives up with
/// [`StoreError::MapChanged`].
pub const MAX_IMPORT_ATTEMPTS: usize = 3;
/// An import matched against its parent revision, ready to be written
/// (made without the write lock).
struct PreparedImport {
    /// The map's row id when it existed.
    map_id: Option<i64>,
    /// The model renumbered to continue the parent's ids.
    stable: Nrg,
    /// Input id → stored id.
    ids: BTreeMap<SpaceId, SpaceId>,
    /// The revision matched against and its model.
    parent: Option<(u32, Nrg)>,
}

/// Longest revision message kept, in characters (issue 21: a 20 MB
/// upload message was stored and sent back in every revisions listing).
pub const MAX_MESSAGE_CHARS: usize = 4_096;

/// Longest author or source file name kept, in characters.
const MAX_LABEL_CHARS: usize = 256;

fn check_meta(meta: &ImportMeta) -> Result<(), StoreError> {
    let fields = [
        ("message", Some(meta.message.as_str()), MAX_MESSAGE_CHARS),
        ("author", Some(meta.author.as_str()), MAX_LABEL_CHARS),
        ("source", meta.source_name.as_deref(), MAX_LABEL_CHARS),
    ];
    for (field, text, limit) in fields {
        let chars = text.map_or(0, |t| t.chars().count());
        if chars > limit {
            return Err(StoreError::TooLong {
                field,
                chars,
                limit,
            });
        }
    }
    Ok(())
}

fn check_map_name(name: &str) -> Result<(), StoreError> {
    let reason = if name.trim().is_empty() {
        Some("it is empty")
    } else if name.contains('@') {
        Some("'@' separates a map from a revision (NAME@REV); choose another name")
    } else if name.chars().any(char::is_control) {
        Some("it contains control characters")
    } else if name.len() > 200 {
        Some("it is longer than 200 bytes")
    } else {
        None
    };
    match reason {
        Some(reason) => Err(StoreError::BadMapName {
            name: name.to_string(),
            reason,
        }),
        None => Ok(()),
    }
}

/// One above the largest space id the map ever used.
pub(super) fn next_space_id(conn: &Connection, map_id: i64) -> Result<u32, StoreError> {
    let max: Option<u32> = conn.query_row(
        "SELECT MAX(space_id) FROM spaces WHERE map_id = ?1",
        [map_id],
        |r| r.get(0),
    )?;
    Ok(max.map_or(1, |m| m.saturating_add(1)))
}

/// Renumbers `new` so each space continuing a space of `parent` takes its
/// id, inheriting its name (unless `new` names it) and its attributes
/// (`new`'s values win key by key); unmatched spaces get `next`, `next+1`...
fn continue_identity(
    parent: &Nrg,
    new: &Nrg,
    params: &MatchParams,
    mut next: u32,
) -> Result<(Nrg, BTreeMap<SpaceId, SpaceId>), StoreError> {
    let matches = match_spaces_within(parent, new, params, MAX_MATCH_PAIRS).ok_or(
        StoreError::TooManyOverlaps {
            limit: MAX_MATCH_PAIRS,
        },
    )?;
    let mut ids: BTreeMap<SpaceId, SpaceId> = matches.into_iter().map(|m| (m.new, m.old)).collect();
    for s in new.spaces() {
        if let std::collections::btree_map::Entry::Vacant(e) = ids.entry(s.id) {
            e.insert(SpaceId(next));
            next = next.saturating_add(1);
        }
    }
    let mut spaces = Vec::with_capacity(new.spaces().len());
    for s in new.spaces() {
        let mut space = s.clone();
        space.id = ids.get(&s.id).copied().unwrap_or(s.id);
        if let Some(old) = parent.space(space.id) {
            if space.name.is_none() {
                space.name.clone_from(&old.name);
            }
            let mut attributes = old.attributes.clone();
            for (k, v) in &s.attributes {
                attributes.insert(k.clone(), v.clone());
            }
            space.attributes = attributes;
        }
        spaces.push(space);
    }
    let links = new
        .connections()
        .iter()
        .map(|c| Link {
            a: ids.get(&c.a).copied().unwrap_or(c.a),
            b: ids.get(&c.b).copied().unwrap_or(c.b),
            ..c.clone()
        })
        .collect();
    Ok((Nrg::new(spaces, links)?, ids))
}

/// Writes `nrg` as revision `parent + 1` of the map, as a delta against
/// the parent (whose open rows are exactly `parent`'s model).
pub(super) fn commit_revision(
    conn: &Connection,
    map_id: i64,
    map: &str,
    parent: Option<&(u32, Nrg)>,
    nrg: &Nrg,
    meta: &ImportMeta,
) -> Result<RevisionInfo, StoreError> {
    check_meta(meta)?;
    let parent_seq = parent.map(|p| p.0);
    let seq = parent_seq.unwrap_or(0) + 1;
    let empty = Nrg::default();
    let old = parent.map_or(&empty, |p| &p.1);
    let (mut added, mut changed, mut removed) = (0usize, 0usize, 0usize);

    let mut close_space = conn.prepare_cached(
        "UPDATE spaces SET valid_to = ?3 WHERE map_id = ?1 AND space_id = ?2 AND valid_to IS NULL",
    )?;
    for s in old.spaces() {
        match nrg.space(s.id) {
            Some(n) if same_space(s, n) => {}
            Some(_) => {
                close_space.execute(params![map_id, s.id.0, seq])?;
                changed += 1;
            }
            None => {
                close_space.execute(params![map_id, s.id.0, seq])?;
                removed += 1;
            }
        }
    }
    for s in nrg.spaces() {
        match old.space(s.id) {
            Some(o) if same_space(o, s) => {}
            Some(_) => insert_space(conn, map_id, seq, s)?,
            None => {
                insert_space(conn, map_id, seq, s)?;
                added += 1;
            }
        }
    }

    let mut close_link = conn.prepare_cached(
        "UPDATE connections SET valid_to = ?4 WHERE map_id = ?1 AND a = ?2 AND b = ?3 AND valid_to IS NULL",
    )?;
    for c in old.connections() {
        if !nrg.connection(c.a, c.b).is_some_and(|n| same_link(c, n)) {
            close_link.execute(params![map_id, c.a.0, c.b.0, seq])?;
        }
    }
    let mut insert_link = conn.prepare_cached(
        "INSERT INTO connections (map_id, a, b, valid_from, kind, length_m) VALUES (?1, ?2, ?3, ?4, ?5, ?6)",
    )?;
    for c in nrg.connections() {
        if !old.connection(c.a, c.b).is_some_and(|o| same_link(o, c)) {
            insert_link.execute(params![
                map_id,
                c.a.0,
                c.b.0,
                seq,
                c.kind.as_str(),
                c.length_m
            ])?;
        }
    }

    let params_json = meta.params.as_ref().map(|p| p.to_string());
    conn.execute(
        "INSERT INTO revisions (map_id, seq, parent, created_at, source_name, source_sha256, params,
             message, author, space_count, connection_count, spaces_added, spaces_changed, spaces_removed)
         VALUES (?1, ?2, ?3, strftime('%Y-%m-%dT%H:%M:%fZ', 'now'), ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13)",
        params![
            map_id,
            seq,
            parent_seq,
            meta.source_name,
            meta.source_sha256,
            params_json,
            meta.message,
            meta.author,
            count(nrg.spaces().len()),
            count(nrg.connections().len()),
            count(added),
            count(changed),
            count(removed),
        ],
    )?;
    let info = conn.query_row(
        &format!("SELECT {REVISION_COLUMNS} FROM revisions WHERE map_id = ?1 AND seq = ?2"),
        params![map_id, seq],
        |r| revision_info(map, r),
    )?;
    Ok(info)
}

fn count(n: usize) -> i64 {
    i64::try_from(n).unwrap_or(i64::MAX)
}

fn insert_space(conn: &Connection, map_id: i64, seq: u32, s: &Space) -> Result<(), StoreError> {
    let attributes = serde_json::Value::Object(s.attributes.clone()).to_string();
    conn.prepare_cached(
        "INSERT INTO spaces (map_id, space_id, valid_from, kind, name, attributes, anchor_x, anchor_y, geometry,
                             doorway_ax, doorway_ay, doorway_bx, doorway_by)
         VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13)",
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
    ])?;
    let row_id = conn.last_insert_rowid();
    let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in &s.polygon {
        for k in 0..2 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    conn.prepare_cached(
        "INSERT INTO space_boxes (row_id, min_x, max_x, min_y, max_y) VALUES (?1, ?2, ?3, ?4, ?5)",
    )?
    .execute(params![row_id, min[0], max[0], min[1], max[1]])?;
    Ok(())
}

/// Whether two models store the same rows: every space and connection
/// equal bit for bit.
fn same_model(a: &Nrg, b: &Nrg) -> bool {
    a.spaces().len() == b.spaces().len()
        && a.connections().len() == b.connections().len()
        && a.spaces()
            .iter()
            .zip(b.spaces())
            .all(|(x, y)| same_space(x, y))
        && a.connections()
            .iter()
            .zip(b.connections())
            .all(|(x, y)| same_link(x, y))
}

/// Bit-exact equality of what a space row stores (see [`Space::same_but_id`]).
fn same_space(a: &Space, b: &Space) -> bool {
    a.id == b.id && a.same_but_id(b)
}

fn same_link(a: &Link, b: &Link) -> bool {
    a.key() == b.key() && a.kind == b.kind && a.length_m.to_bits() == b.length_m.to_bits()
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;
    use std::sync::atomic::{AtomicUsize, Ordering};

    use super::*;
    use crate::model::SpaceKind;

    /// `n` square rooms of 2 m in a row, ids 1.., shifted `dx` metres.
    fn rooms(n: u32, dx: f64) -> Nrg {
        let spaces = (0..n)
            .map(|i| {
                let x = f64::from(i) * 3.0 + dx;
                Space::new(
                    SpaceId(i + 1),
                    SpaceKind::Room,
                    [x + 1.0, 1.0],
                    vec![[x, 0.0], [x + 2.0, 0.0], [x + 2.0, 2.0], [x, 2.0]],
                )
            })
            .collect();
        Nrg::new(spaces, vec![]).unwrap()
    }

    fn meta() -> ImportMeta {
        ImportMeta::new("test", "me")
    }

    /// A store on a file in a fresh directory, with map `m` at revision 1.
    fn store_with_map() -> (tempfile::TempDir, std::path::PathBuf, Store) {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("db.sqlite");
        let mut store = Store::open(&path).unwrap();
        store.import("m", &rooms(4, 0.0), meta()).unwrap();
        (dir, path, store)
    }

    /// A second writer on the same file that gives up at once when the
    /// write lock is held.
    fn impatient_writer(path: &std::path::Path) -> Store {
        let mut other = Store::open(path).unwrap();
        other.set_busy_timeout(std::time::Duration::ZERO).unwrap();
        other
    }

    /// Issue 21, defect 3: identity matching ran inside `BEGIN IMMEDIATE`,
    /// so every other writer got "busy" while a large import was matched.
    /// Right after matching, another connection that refuses to wait for
    /// the lock can still write.
    #[test]
    fn issue_21_defect_3_matching_runs_without_the_write_lock() {
        let (_dir, path, mut store) = store_with_map();
        let calls = Arc::new(AtomicUsize::new(0));
        let seen = Arc::clone(&calls);
        let mut other = impatient_writer(&path);
        store.before_write_lock = Some(Box::new(move || {
            seen.fetch_add(1, Ordering::SeqCst);
            other
                .import("elsewhere", &rooms(2, 0.0), meta())
                .expect("the write lock is free while matching");
        }));
        let done = store.import("m", &rooms(4, 0.5), meta()).unwrap();
        assert_eq!(calls.load(Ordering::SeqCst), 1);
        assert_eq!((done.revision.seq, done.revision.parent), (2, Some(1)));
        assert_eq!(store.revision("elsewhere", None).unwrap().seq, 1);
    }

    /// Issue 21, defect 3: when another writer adds a revision between
    /// matching and the lock, the import is matched again against the new
    /// latest revision instead of being written over a stale parent.
    #[test]
    fn issue_21_defect_3_stale_parent_is_matched_again() {
        let (_dir, path, mut store) = store_with_map();
        let mut other = impatient_writer(&path);
        let calls = Arc::new(AtomicUsize::new(0));
        let seen = Arc::clone(&calls);
        store.before_write_lock = Some(Box::new(move || {
            if seen.fetch_add(1, Ordering::SeqCst) == 0 {
                // A fifth room: the next import must continue this one.
                other.import("m", &rooms(5, 0.0), meta()).unwrap();
            }
        }));
        let done = store.import("m", &rooms(5, 0.25), meta()).unwrap();
        assert_eq!(calls.load(Ordering::SeqCst), 2);
        assert_eq!((done.revision.seq, done.revision.parent), (3, Some(2)));
        // Matched against revision 2, the fifth room continues room 5
        // (matched against revision 1 it would count as added).
        assert_eq!(done.revision.spaces_added, 0);
        assert_eq!(done.revision.spaces_changed, 5);
    }

    /// Issue 21, defect 3: a map that changes before every attempt fails
    /// with a clear "retry" after a bounded number of attempts, storing
    /// nothing.
    #[test]
    fn issue_21_defect_3_a_map_that_keeps_changing_fails_clearly() {
        let (_dir, path, mut store) = store_with_map();
        let mut other = impatient_writer(&path);
        let mut dx = 0.0;
        store.before_write_lock = Some(Box::new(move || {
            // A different model each time (the same one again would
            // write nothing).
            dx += 0.1;
            other.import("m", &rooms(4, dx), meta()).unwrap();
        }));
        let e = store.import("m", &rooms(4, 0.5), meta()).unwrap_err();
        assert!(
            matches!(e, StoreError::MapChanged { attempts, .. } if attempts == MAX_IMPORT_ATTEMPTS),
            "{e:?}"
        );
        assert!(e.to_string().contains("retry"), "{e}");
        let revs = store.revisions("m").unwrap();
        assert_eq!(revs.len(), 1 + MAX_IMPORT_ATTEMPTS);
        assert!(revs.iter().all(|r| r.message == "test"));
    }

    /// Issue 21, defect 8: 20 000 piled cells imported over a revision of
    /// piled cells took 11 min and 4.5 GB to match; past
    /// [`MAX_MATCH_PAIRS`] overlapping pairs the import is refused at once,
    /// storing nothing.
    #[test]
    fn issue_21_defect_8_a_pile_over_a_pile_is_refused() {
        let pile = |n: u32, dx: f64| {
            let square = vec![[dx, 0.0], [dx + 2.0, 0.0], [dx + 2.0, 2.0], [dx, 2.0]];
            let spaces = (1..=n)
                .map(|k| Space::new(SpaceId(k), SpaceKind::Room, [dx + 1.0, 1.0], square.clone()))
                .collect();
            Nrg::new(spaces, vec![]).unwrap()
        };
        let mut store = Store::open_in_memory().unwrap();
        store.import("piles", &pile(1_500, 0.0), meta()).unwrap();
        let e = store
            .import("piles", &pile(1_500, 0.1), meta())
            .unwrap_err();
        assert!(matches!(e, StoreError::TooManyOverlaps { .. }), "{e:?}");
        assert!(e.to_string().contains("piled"), "{e}");
        assert_eq!(store.revisions("piles").unwrap().len(), 1);
    }

    /// Issue 21, defect 10: a full disk said "Error code 4874: disk I/O
    /// error". A database that may not grow (`max_page_count`) gives
    /// SQLITE_FULL for real; the error says "disk full" and names the
    /// file, and the import stored nothing.
    #[test]
    fn issue_21_defect_10_a_full_database_says_disk_full() {
        let (_dir, path, mut store) = store_with_map();
        let pages: i64 = store
            .conn
            .query_row("PRAGMA page_count", [], |r| r.get(0))
            .unwrap();
        store
            .conn
            .pragma_update(None, "max_page_count", pages + 1)
            .unwrap();
        let e = store.import("big", &rooms(2_000, 0.0), meta()).unwrap_err();
        assert!(
            matches!(&e, StoreError::DiskFull { path: p } if *p == path),
            "{e:?}"
        );
        assert!(e.to_string().starts_with("disk full: "), "{e}");
        assert!(store.revisions("big").is_err());
        assert_eq!(store.revisions("m").unwrap().len(), 1);
    }

    /// Issue 21, defect 6: a 20 MB message was stored and returned in
    /// every revisions listing; now it is refused, naming the field.
    #[test]
    fn long_messages_are_refused() {
        let mut meta = ImportMeta::new("x".repeat(MAX_MESSAGE_CHARS), "me");
        assert!(check_meta(&meta).is_ok());
        meta.message.push('y');
        let e = check_meta(&meta).unwrap_err().to_string();
        assert!(e.contains("message has 4097 characters"), "{e}");
        let meta = ImportMeta::new("ok", "a".repeat(300));
        assert!(matches!(
            check_meta(&meta),
            Err(StoreError::TooLong {
                field: "author",
                ..
            })
        ));
    }

    #[test]
    fn map_names_are_checked() {
        assert!(check_map_name("willow").is_ok());
        for bad in ["", "  ", "a@b", "x\ny"] {
            assert!(check_map_name(bad).is_err(), "{bad:?}");
        }
    }
}

#[cfg(test)]
mod unchanged_tests {
    use super::*;
    use crate::store::ImportMeta;

    /// Issue 22: re-importing the latest revision's model writes nothing
    /// and says so; a different one writes the next revision.
    #[test]
    fn an_identical_import_makes_no_revision() {
        let mut store = Store::open_in_memory().unwrap();
        let nrg = crate::fixtures::corridor_building(3);
        let first = store.import("m", &nrg, ImportMeta::new("a", "me")).unwrap();
        assert!(!first.unchanged);
        let again = store.import("m", &nrg, ImportMeta::new("b", "me")).unwrap();
        assert!(again.unchanged);
        assert_eq!(again.revision.seq, 1);
        assert_eq!(store.revisions("m").unwrap().len(), 1);
        let other = crate::fixtures::corridor_building(4);
        let next = store
            .import("m", &other, ImportMeta::new("c", "me"))
            .unwrap();
        assert!(!next.unchanged);
        assert_eq!(next.revision.seq, 2);
    }
}
