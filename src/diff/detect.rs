//! The change detector: two models in one frame → a [`ChangeSet`].
//!
//! 1. Overlaps: every pair of spaces (A × B) sharing area, measured exactly
//!    ([`overlaps`]).
//! 2. Identity: the optimal one-to-one matching on IoU ≥ `min_iou`
//!    (Kuhn–Munkres, [`match_overlaps`]), the same rule the store uses to
//!    keep ids, so a split room's largest part continues it; doors by
//!    their doorway line (centres within `door_shift_m`) and the spaces
//!    they join ([`super::door_match`]), whatever their thickness.
//! 3. Splits and merges by overlap fractions (doors: by the share of their
//!    doorway line), independent of the matching ([`super::split_merge`]).
//! 4. Per matched pair: resized (relative and absolute area thresholds,
//!    not reported for split or merged spaces, whose area change the split
//!    or merge explains), re-kinded, renamed, door width
//!    ([`doorway`](crate::model::doorway())).
//! 5. Connections through the matching: removed, added, re-kinded, or a
//!    length change (carried, not reported).

use std::collections::{BTreeSet, HashMap};

use super::change_set::{
    CHANGESET_FORMAT, ChangeSet, ConnectionChange, ConnectionChangeKind, Merge, SpaceChange,
    SpaceChangeKind, Split, Summary,
};
use super::matching::{match_overlaps, overlaps, overlaps_within};
use super::overlaps::Overlaps;
use super::params::{DiffParams, MatchParams};
use super::split_merge::splits_and_merges;
use crate::model::{Connection, Nrg, Space, SpaceId, SpaceKind, doorway};

/// Compares `b` with the base `a` (both in the same frame: align first
/// when they are not). `apply(a, &diff(a, b))`
/// gives `b` back exactly.
///
/// ```
/// use nrgdb::diff::{diff, DiffParams, SpaceChangeKind};
/// use nrgdb::fixtures::corridor_building;
/// let a = corridor_building(3);
/// assert!(diff(&a, &a, &DiffParams::default()).is_empty());
/// let b = corridor_building(4); // one more room, door and links
/// let cs = diff(&a, &b, &DiffParams::default());
/// assert_eq!(cs.summary.added, 2);
/// assert_eq!(nrgdb::diff::apply(&a, &cs)?, b);
/// # Ok::<(), nrgdb::diff::DiffError>(())
/// ```
pub fn diff(a: &Nrg, b: &Nrg, params: &DiffParams) -> ChangeSet {
    let ov = overlaps(a, b);
    diff_with_overlaps(a, b, &ov, params)
}

/// [`diff`], or `None` rather than measure more than `max_pairs` pairs of
/// spaces whose boxes meet (see [`MAX_MATCH_PAIRS`](super::MAX_MATCH_PAIRS))
/// or go on past `deadline`.
pub(crate) fn diff_within(
    a: &Nrg,
    b: &Nrg,
    params: &DiffParams,
    max_pairs: usize,
    deadline: Option<std::time::Instant>,
) -> Option<ChangeSet> {
    let ov = overlaps_within(a, b, max_pairs, deadline)?;
    Some(diff_with_overlaps(a, b, &ov, params))
}

/// [`diff`] over precomputed overlaps.
pub(crate) fn diff_with_overlaps(
    a: &Nrg,
    b: &Nrg,
    ov: &Overlaps,
    params: &DiffParams,
) -> ChangeSet {
    let matches = match_overlaps(
        ov,
        &MatchParams {
            min_iou: params.min_iou,
            door_shift_m: params.door_shift_m,
        },
    );
    let old_to_new: HashMap<SpaceId, (SpaceId, f64)> =
        matches.iter().map(|m| (m.old, (m.new, m.iou))).collect();
    let new_to_old: HashMap<SpaceId, SpaceId> = matches.iter().map(|m| (m.new, m.old)).collect();
    let (splits, merges) = splits_and_merges(ov, &old_to_new, &new_to_old, params);
    let split_of: BTreeSet<SpaceId> = splits.iter().map(|s| s.old).collect();
    let split_parts: BTreeSet<SpaceId> = splits
        .iter()
        .flat_map(|s| s.parts.iter().map(|p| p.id))
        .collect();
    let merge_of: BTreeSet<SpaceId> = merges.iter().map(|m| m.new).collect();
    let merge_parts: BTreeSet<SpaceId> = merges
        .iter()
        .flat_map(|m| m.parts.iter().map(|p| p.id))
        .collect();

    let mut spaces = Vec::with_capacity(a.spaces().len().max(b.spaces().len()));
    for old in a.spaces() {
        let entry = match old_to_new.get(&old.id) {
            Some(&(new_id, iou)) => match b.space(new_id) {
                Some(new) => {
                    let mut e = matched(old, new, iou, params);
                    if split_of.contains(&old.id) {
                        e.changes.push(SpaceChangeKind::Split);
                    }
                    if merge_of.contains(&new.id) {
                        e.changes.push(SpaceChangeKind::Merged);
                    }
                    if split_of.contains(&old.id) || merge_of.contains(&new.id) {
                        e.changes.retain(|c| *c != SpaceChangeKind::Resized);
                    }
                    e.changes.sort();
                    e
                }
                None => alone(old, false, merge_parts.contains(&old.id)),
            },
            None => alone(old, false, merge_parts.contains(&old.id)),
        };
        spaces.push(entry);
    }
    for new in b.spaces() {
        if !new_to_old.contains_key(&new.id) {
            spaces.push(alone(new, true, split_parts.contains(&new.id)));
        }
    }
    let connections = connection_changes(a, b, &old_to_new);
    let summary = summarise(&spaces, &splits, &merges, &connections);
    ChangeSet {
        format: CHANGESET_FORMAT.to_string(),
        from: None,
        to: None,
        alignment: None,
        summary,
        spaces,
        splits,
        merges,
        connections,
    }
}

/// The entry of a matched pair, with its reported changes.
fn matched(old: &Space, new: &Space, iou: f64, params: &DiffParams) -> SpaceChange {
    let mut changes = Vec::new();
    let delta = new.area_m2 - old.area_m2;
    if delta.abs() > params.resize_ratio * old.area_m2 && delta.abs() >= params.resize_min_m2 {
        changes.push(SpaceChangeKind::Resized);
    }
    if old.kind != new.kind {
        changes.push(SpaceChangeKind::Rekinded);
    }
    let renamed = old.name != new.name;
    if renamed {
        changes.push(SpaceChangeKind::Renamed);
    }
    let mut widths = None;
    if old.kind == SpaceKind::Door && new.kind == SpaceKind::Door {
        let width = |s: &Space| doorway(s).map_or(0.0, |d| d.width_m);
        let (wa, wb) = (width(old), width(new));
        if (wa - wb).abs() > params.door_width_tol_m {
            changes.push(SpaceChangeKind::DoorWidth);
            widths = Some([wa, wb]);
        }
    }
    SpaceChange {
        old: Some(old.id),
        new: Some(new.id),
        changes,
        label: new.label(),
        iou: Some(iou),
        kind: old.kind,
        new_kind: (old.kind != new.kind).then_some(new.kind),
        old_area_m2: Some(old.area_m2),
        new_area_m2: Some(new.area_m2),
        names: renamed.then(|| [old.name.clone(), new.name.clone()]),
        door_width_m: widths,
        level: level_name(new),
        space: (!old.same_but_id(new)).then(|| new.clone()),
    }
}

/// The entry of an unmatched space of A (`in_b` false) or of B.
fn alone(space: &Space, in_b: bool, part: bool) -> SpaceChange {
    let change = match (in_b, part) {
        (true, true) => SpaceChangeKind::Split,
        (true, false) => SpaceChangeKind::Added,
        (false, true) => SpaceChangeKind::Merged,
        (false, false) => SpaceChangeKind::Removed,
    };
    SpaceChange {
        old: (!in_b).then_some(space.id),
        new: in_b.then_some(space.id),
        changes: vec![change],
        label: space.label(),
        iou: None,
        kind: space.kind,
        new_kind: None,
        old_area_m2: (!in_b).then_some(space.area_m2),
        new_area_m2: in_b.then_some(space.area_m2),
        names: None,
        door_width_m: None,
        level: level_name(space),
        space: in_b.then(|| space.clone()),
    }
}

/// The name of a space's level, when it has one.
fn level_name(space: &Space) -> Option<String> {
    space.level.as_ref().map(|l| l.name.clone())
}

/// The levels of a connection's ends in `nrg` (one name when both are on
/// one level; none without levels).
fn link_levels(nrg: &Nrg, c: &Connection) -> Vec<String> {
    let mut levels: Vec<String> = [c.a, c.b]
        .iter()
        .filter_map(|id| nrg.space(*id).and_then(level_name))
        .collect();
    levels.sort();
    levels.dedup();
    levels
}

fn connection_changes(
    a: &Nrg,
    b: &Nrg,
    old_to_new: &HashMap<SpaceId, (SpaceId, f64)>,
) -> Vec<ConnectionChange> {
    let mut out = Vec::new();
    let mut kept: BTreeSet<(SpaceId, SpaceId)> = BTreeSet::new();
    for c in a.connections() {
        let mapped = old_to_new
            .get(&c.a)
            .zip(old_to_new.get(&c.b))
            .and_then(|(x, y)| b.connection(x.0, y.0));
        match mapped {
            Some(n) => {
                kept.insert(n.key());
                let change = if n.kind != c.kind {
                    Some(ConnectionChangeKind::Rekinded)
                } else if n.length_m.to_bits() != c.length_m.to_bits() {
                    Some(ConnectionChangeKind::Length)
                } else {
                    None
                };
                if let Some(change) = change {
                    out.push(ConnectionChange {
                        change,
                        old: Some(c.clone()),
                        new: Some(n.clone()),
                        levels: link_levels(b, n),
                    });
                }
            }
            None => out.push(ConnectionChange {
                change: ConnectionChangeKind::Removed,
                old: Some(c.clone()),
                new: None,
                levels: link_levels(a, c),
            }),
        }
    }
    out.extend(
        b.connections()
            .iter()
            .filter(|n| !kept.contains(&n.key()))
            .map(|n: &Connection| ConnectionChange {
                change: ConnectionChangeKind::Added,
                old: None,
                new: Some(n.clone()),
                levels: link_levels(b, n),
            }),
    );
    out
}

fn summarise(
    spaces: &[SpaceChange],
    splits: &[Split],
    merges: &[Merge],
    connections: &[ConnectionChange],
) -> Summary {
    let has = |k: SpaceChangeKind| spaces.iter().filter(|s| s.changes.contains(&k)).count();
    let links = |k: ConnectionChangeKind| connections.iter().filter(|c| c.change == k).count();
    Summary {
        unchanged: spaces
            .iter()
            .filter(|s| s.old.is_some() && s.new.is_some() && s.changes.is_empty())
            .count(),
        added: has(SpaceChangeKind::Added),
        removed: has(SpaceChangeKind::Removed),
        resized: has(SpaceChangeKind::Resized),
        split: splits.len(),
        merged: merges.len(),
        rekinded: has(SpaceChangeKind::Rekinded),
        renamed: has(SpaceChangeKind::Renamed),
        door_width: has(SpaceChangeKind::DoorWidth),
        connections_added: links(ConnectionChangeKind::Added),
        connections_removed: links(ConnectionChangeKind::Removed),
        connections_rekinded: links(ConnectionChangeKind::Rekinded),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diff::apply;
    use crate::model::{ConnectionKind, SpaceKind};

    fn rect(id: u32, kind: SpaceKind, x0: f64, y0: f64, x1: f64, y1: f64) -> Space {
        let poly = vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
        Space::new(SpaceId(id), kind, [(x0 + x1) / 2.0, (y0 + y1) / 2.0], poly)
    }

    fn link(a: u32, b: u32, kind: ConnectionKind) -> Connection {
        Connection {
            a: SpaceId(a),
            b: SpaceId(b),
            kind,
            length_m: 1.0,
        }
    }

    /// Issue 21, defect 8, in the diff path: spaces whose boxes all meet
    /// (thin diagonal strips, valid and disjoint) make every pair a
    /// candidate; past the bound the diff gives up instead of measuring.
    #[test]
    fn issue_21_a_diff_of_piled_boxes_stops_at_its_bound() {
        let strips = |n: u32, shift: f64| {
            let spaces = (0..n)
                .map(|i| {
                    let x = f64::from(i) * 0.5 + shift;
                    let poly = vec![[x, 0.0], [x + 0.4, 0.0], [x + 40.4, 40.0], [x + 40.0, 40.0]];
                    Space::new(SpaceId(i + 1), SpaceKind::Room, [x + 20.2, 20.0], poly)
                })
                .collect();
            Nrg::new(spaces, vec![]).unwrap()
        };
        let (a, b) = (strips(40, 0.0), strips(40, 0.05));
        let params = DiffParams::default();
        assert!(diff_within(&a, &b, &params, 100, None).is_none());
        let whole = diff_within(&a, &b, &params, 40 * 40, None).unwrap();
        // A deadline already past stops it at its first look at the clock
        // (after 1 024 of the 1 600 pairs).
        let past = Some(std::time::Instant::now());
        assert!(diff_within(&a, &b, &params, 40 * 40, past).is_none());
        assert_eq!(whole, diff(&a, &b, &DiffParams::default()));
    }

    /// Two rooms 1 and 2 joined by door 3 (0.9 m wide).
    fn two_rooms() -> Nrg {
        Nrg::new(
            vec![
                rect(1, SpaceKind::Room, 0.0, 0.0, 5.0, 4.0),
                rect(2, SpaceKind::Room, 5.2, 0.0, 10.0, 4.0),
                rect(3, SpaceKind::Door, 5.0, 1.0, 5.2, 1.9),
            ],
            vec![
                link(1, 3, ConnectionKind::Door),
                link(2, 3, ConnectionKind::Door),
            ],
        )
        .unwrap()
    }

    fn check_roundtrip(a: &Nrg, b: &Nrg) -> ChangeSet {
        let cs = diff(a, b, &DiffParams::default());
        let json = cs.to_json();
        let back = ChangeSet::from_json(&json).unwrap();
        assert_eq!(back, cs);
        assert_eq!(apply(a, &back).unwrap(), *b);
        cs
    }

    #[test]
    fn self_diff_is_empty_and_carries_nothing() {
        let a = two_rooms();
        let cs = check_roundtrip(&a, &a);
        assert!(cs.is_empty());
        assert_eq!(cs.summary.unchanged, 3);
        assert!(cs.spaces.iter().all(|s| s.space.is_none()));
        assert!(cs.connections.is_empty());
        assert!(cs.table().starts_with("no changes (3 unchanged)"));
    }

    #[test]
    fn door_shut_removes_door_and_links() {
        let a = two_rooms();
        let (spaces, _) = a.clone().into_parts();
        let b = Nrg::new(spaces.into_iter().filter(|s| s.id.0 != 3).collect(), vec![]).unwrap();
        let cs = check_roundtrip(&a, &b);
        let s = &cs.summary;
        assert_eq!(
            (s.removed, s.added, s.unchanged, s.connections_removed),
            (1, 0, 2, 2)
        );
        assert_eq!(cs.changed_spaces().next().unwrap().old, Some(SpaceId(3)));
    }

    #[test]
    fn wall_removed_merges_rooms() {
        let a = two_rooms();
        let b = Nrg::new(vec![rect(7, SpaceKind::Room, 0.0, 0.0, 10.0, 4.0)], vec![]).unwrap();
        let cs = check_roundtrip(&a, &b);
        assert_eq!(cs.merges.len(), 1);
        let ids: Vec<u32> = cs.merges[0].parts.iter().map(|p| p.id.0).collect();
        assert_eq!(ids, vec![1, 2, 3]);
        let s = &cs.summary;
        assert_eq!((s.merged, s.removed, s.added, s.resized), (1, 0, 0, 0));
        assert_eq!(s.connections_removed, 2);
        assert!(cs.table().contains("merged"));
    }

    #[test]
    fn wall_added_splits_room() {
        let a = two_rooms();
        let (mut spaces, links) = a.clone().into_parts();
        spaces.retain(|s| s.id.0 != 1);
        spaces.push(rect(1, SpaceKind::Room, 0.0, 0.0, 3.0, 4.0));
        spaces.push(rect(9, SpaceKind::Room, 3.1, 0.0, 5.0, 4.0));
        let b = Nrg::new(spaces, links).unwrap();
        let cs = check_roundtrip(&a, &b);
        assert_eq!(cs.splits.len(), 1);
        assert_eq!(cs.splits[0].old, SpaceId(1));
        let parts: Vec<u32> = cs.splits[0].parts.iter().map(|p| p.id.0).collect();
        assert_eq!(parts, vec![1, 9]);
        let s = &cs.summary;
        assert_eq!(
            (s.split, s.added, s.removed, s.resized, s.unchanged),
            (1, 0, 0, 0, 2)
        );
    }

    #[test]
    fn resize_rekind_rename_and_door_width() {
        let a = two_rooms();
        let (mut spaces, mut links) = a.clone().into_parts();
        spaces[0] = rect(1, SpaceKind::Corridor, 0.0, 0.0, 5.0, 4.0); // rekinded
        spaces[1] = rect(2, SpaceKind::Room, 5.2, 0.0, 12.0, 4.0); // resized
        spaces[1].name = Some("Lab".into()); // renamed
        spaces[2] = rect(3, SpaceKind::Door, 5.0, 1.0, 5.2, 2.4); // 1.4 m wide
        links[0].kind = ConnectionKind::Open;
        let b = Nrg::new(spaces, links).unwrap();
        let cs = check_roundtrip(&a, &b);
        let s = &cs.summary;
        assert_eq!(
            (
                s.rekinded,
                s.resized,
                s.renamed,
                s.door_width,
                s.connections_rekinded
            ),
            (1, 1, 1, 1, 1)
        );
        assert_eq!((s.added, s.removed, s.unchanged), (0, 0, 0));
        let door = cs
            .spaces
            .iter()
            .find(|e| e.old == Some(SpaceId(3)))
            .unwrap();
        let [wa, wb] = door.door_width_m.unwrap();
        assert!((wa - 0.9).abs() < 1e-9 && (wb - 1.4).abs() < 1e-9);
        let table = cs.table();
        for word in [
            "rekinded",
            "resized",
            "renamed",
            "door_width",
            "link_rekinded",
        ] {
            assert!(table.contains(word), "{word} missing in\n{table}");
        }
    }

    #[test]
    fn small_jitter_is_carried_not_reported() {
        let a = two_rooms();
        let (mut spaces, mut links) = a.clone().into_parts();
        spaces[0] = rect(1, SpaceKind::Room, 0.0, 0.0, 5.05, 4.0);
        links[0].length_m = 1.1;
        let b = Nrg::new(spaces, links).unwrap();
        let cs = check_roundtrip(&a, &b);
        assert!(cs.is_empty(), "{}", cs.table());
        assert!(cs.spaces[0].space.is_some());
    }

    #[test]
    fn bad_params_are_named() {
        let p = DiffParams {
            part_cover: 1.5,
            ..DiffParams::default()
        };
        let e = p.validate().unwrap_err().to_string();
        assert!(e.contains("part_cover"), "{e}");
    }
}
