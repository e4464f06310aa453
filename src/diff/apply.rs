//! Replaying a change set: `apply(A, diff(A, B)) == B`, and the IndoorGML
//! update (B under A's identifiers).

use std::collections::{BTreeMap, BTreeSet};

use super::change_set::{CHANGESET_FORMAT, ChangeSet, ConnectionChangeKind};
use super::error::DiffError;
use crate::model::{Connection, Nrg, SpaceId};

/// Applies `changes` to `base`, giving the changed model (with B's ids).
/// The base must have exactly the spaces the change set lists as `old`;
/// otherwise [`DiffError::BaseMismatch`].
///
/// ```
/// use nrgdb::diff::{apply, diff, DiffParams};
/// use nrgdb::fixtures::corridor_building;
/// let (a, b) = (corridor_building(5), corridor_building(2));
/// let cs = diff(&a, &b, &DiffParams::default());
/// assert_eq!(apply(&a, &cs)?, b);
/// # Ok::<(), nrgdb::diff::DiffError>(())
/// ```
pub fn apply(base: &Nrg, changes: &ChangeSet) -> Result<Nrg, DiffError> {
    if changes.format != CHANGESET_FORMAT {
        return Err(DiffError::Format {
            found: changes.format.clone(),
            expected: CHANGESET_FORMAT,
        });
    }
    let ids = id_map(base, changes)?;
    let mut spaces = Vec::with_capacity(changes.spaces.len());
    for entry in &changes.spaces {
        let Some(new) = entry.new else { continue };
        let space = match (&entry.space, entry.old) {
            (Some(s), _) => {
                if s.id != new {
                    return Err(DiffError::BadChangeSet {
                        detail: format!("entry for new space {new} carries space {}", s.id),
                    });
                }
                s.clone()
            }
            (None, Some(old)) => {
                let mut s = base
                    .space(old)
                    .ok_or(DiffError::MissingSpace {
                        id: old,
                        side: "base",
                    })?
                    .clone();
                s.id = new;
                s
            }
            (None, None) => {
                return Err(DiffError::BadChangeSet {
                    detail: format!("added space {new} has no geometry"),
                });
            }
        };
        spaces.push(space);
    }
    let mut removed: BTreeSet<(SpaceId, SpaceId)> = BTreeSet::new();
    let mut replaced: BTreeMap<(SpaceId, SpaceId), &Connection> = BTreeMap::new();
    let mut added: Vec<Connection> = Vec::new();
    for c in &changes.connections {
        match (c.change, &c.old, &c.new) {
            (ConnectionChangeKind::Removed, Some(old), _) => {
                removed.insert(old.key());
            }
            (ConnectionChangeKind::Added, _, Some(new)) => added.push(new.clone()),
            (
                ConnectionChangeKind::Rekinded | ConnectionChangeKind::Length,
                Some(old),
                Some(new),
            ) => {
                replaced.insert(old.key(), new);
            }
            _ => {
                return Err(DiffError::BadChangeSet {
                    detail: format!(
                        "connection change '{}' lacks its old or new connection",
                        c.change.as_str()
                    ),
                });
            }
        }
    }
    let mut connections = Vec::with_capacity(base.connections().len() + added.len());
    for c in base.connections() {
        let key = c.key();
        if removed.contains(&key) {
            continue;
        }
        if let Some(new) = replaced.get(&key) {
            connections.push((*new).clone());
            continue;
        }
        let (Some(&a), Some(&b)) = (ids.get(&c.a), ids.get(&c.b)) else {
            return Err(DiffError::BadChangeSet {
                detail: format!(
                    "connection {}-{} of the base joins a space the change set removes, but is not removed itself",
                    c.a, c.b
                ),
            });
        };
        connections.push(Connection { a, b, ..c.clone() });
    }
    connections.extend(added);
    Ok(Nrg::new(spaces, connections)?)
}

/// Old id → new id of every matched space, after checking that the base
/// has exactly the change set's old spaces.
fn id_map(base: &Nrg, changes: &ChangeSet) -> Result<BTreeMap<SpaceId, SpaceId>, DiffError> {
    let mut listed = BTreeSet::new();
    let mut ids = BTreeMap::new();
    for entry in &changes.spaces {
        if let Some(old) = entry.old {
            if !listed.insert(old) {
                return Err(DiffError::BadChangeSet {
                    detail: format!("space {old} of the base is listed twice"),
                });
            }
            if base.space(old).is_none() {
                return Err(DiffError::BaseMismatch {
                    detail: format!("space {old} is not in the base model"),
                });
            }
            if let Some(new) = entry.new {
                ids.insert(old, new);
            }
        }
    }
    if let Some(extra) = base.spaces().iter().find(|s| !listed.contains(&s.id)) {
        return Err(DiffError::BaseMismatch {
            detail: format!(
                "the base has space {} that the change set does not know",
                extra.id
            ),
        });
    }
    Ok(ids)
}

/// The IndoorGML update: `changed` (B, as diffed against `base` with
/// `changes`) renumbered so matched spaces keep the base's ids and every
/// other space gets a fresh id above the base's largest. Returns the model
/// and the id given to each space of B.
pub fn with_base_ids(
    base: &Nrg,
    changed: &Nrg,
    changes: &ChangeSet,
) -> Result<(Nrg, BTreeMap<SpaceId, SpaceId>), DiffError> {
    let mut ids: BTreeMap<SpaceId, SpaceId> = changes
        .spaces
        .iter()
        .filter_map(|e| Some((e.new?, e.old?)))
        .collect();
    let mut next = base.next_id().0;
    for s in changed.spaces() {
        if let std::collections::btree_map::Entry::Vacant(v) = ids.entry(s.id) {
            v.insert(SpaceId(next));
            next = next.saturating_add(1);
        }
    }
    let (mut spaces, mut links) = changed.clone().into_parts();
    let id_of = |id: SpaceId| {
        ids.get(&id).copied().ok_or(DiffError::MissingSpace {
            id,
            side: "changed",
        })
    };
    for s in &mut spaces {
        s.id = id_of(s.id)?;
    }
    for c in &mut links {
        c.a = id_of(c.a)?;
        c.b = id_of(c.b)?;
    }
    Ok((Nrg::new(spaces, links)?, ids))
}

/// The IndoorGML update of a change: B under A's ids
/// ([`with_base_ids`]). In a building with levels it covers only the
/// levels with a reported change ([`ChangeSet::changed_levels`]): their
/// spaces and the connections among them, so a receiver replaces those
/// levels and keeps the others. A vertical connection between a changed
/// and an unchanged level is not in it (its other end is not in the
/// document): matched stairs and lifts keep the base's ids, so the
/// receiver's own connection still joins them; a connector added or
/// removed is a change on both its levels, which are then both in it. Returns the model and the levels it
/// covers (empty without levels).
///
/// ```
/// use nrgdb::diff::{diff, update_model, DiffParams};
/// use nrgdb::fixtures::storeys;
/// let a = storeys(3, 2);
/// // B: a room on level 1 renamed.
/// let (mut spaces, links) = a.clone().into_parts();
/// spaces.iter_mut().find(|s| s.id.0 == 100_010).unwrap().name = Some("Lab".into());
/// let b = nrgdb::model::Nrg::new(spaces, links)?;
/// let changes = diff(&a, &b, &DiffParams::default());
/// let (update, levels) = update_model(&a, &b, &changes)?;
/// assert_eq!(levels, ["1"]);
/// assert_eq!(update.spaces().len(), a.level_model("1").unwrap().spaces().len());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn update_model(
    base: &Nrg,
    changed: &Nrg,
    changes: &ChangeSet,
) -> Result<(Nrg, Vec<String>), DiffError> {
    let (update, _) = with_base_ids(base, changed, changes)?;
    if !update.has_levels() {
        return Ok((update, Vec::new()));
    }
    let levels = changes.changed_levels();
    let names: Vec<&str> = levels.iter().map(String::as_str).collect();
    Ok((update.levels_model(&names).unwrap_or_default(), levels))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diff::{DiffParams, diff};
    use crate::fixtures::corridor_building;

    #[test]
    fn applying_to_another_base_is_refused() {
        let (a, b) = (corridor_building(3), corridor_building(4));
        let cs = diff(&a, &b, &DiffParams::default());
        assert!(matches!(
            apply(&b, &cs),
            Err(DiffError::BaseMismatch { .. })
        ));
        let mut bad = cs.clone();
        bad.format = "other/9".into();
        assert!(matches!(apply(&a, &bad), Err(DiffError::Format { .. })));
    }

    #[test]
    fn update_keeps_base_ids() {
        let a = corridor_building(3);
        // B: same building with every id shifted by 1000.
        let (spaces, links) = a.clone().into_parts();
        let spaces = spaces
            .into_iter()
            .map(|mut s| {
                s.id = SpaceId(s.id.0 + 1000);
                s
            })
            .collect();
        let links = links
            .into_iter()
            .map(|c| Connection {
                a: SpaceId(c.a.0 + 1000),
                b: SpaceId(c.b.0 + 1000),
                ..c
            })
            .collect();
        let b = Nrg::new(spaces, links).unwrap();
        let cs = diff(&a, &b, &DiffParams::default());
        assert!(cs.is_empty(), "{:?}", cs.summary);
        assert_eq!(apply(&a, &cs).unwrap(), b);
        let (update, _) = with_base_ids(&a, &b, &cs).unwrap();
        assert_eq!(update, a);
    }
}
