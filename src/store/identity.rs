//! Stable identity: a new model's spaces take the ids of the spaces they
//! continue in the parent revision ([`crate::diff::match_spaces_within`]),
//! with their names and attributes. The same on every engine.

use std::collections::BTreeMap;

use super::StoreError;
use crate::diff::{MAX_MATCH_PAIRS, MatchParams, match_spaces_within};
use crate::model::{Connection as Link, Nrg, SpaceId};

/// Renumbers `new` so each space continuing a space of `parent` takes its
/// id, inheriting its name (unless `new` names it) and its attributes
/// (`new`'s values win key by key); unmatched spaces get `next`, `next+1`...
pub(crate) fn continue_identity(
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
