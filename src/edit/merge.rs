//! MERGE: one space from several.

use std::collections::{BTreeMap, BTreeSet};

use geo::{Area, MapCoordsInPlace};

use super::shape::{link, pieces, polygon, reanchored, stronger};
use super::{EditError, Edited, MAX_MERGED};
use crate::model::{ConnectionKind, Nrg, SpaceId, SpaceKind, reshaped};

/// The union of `ids` (and of the doors that join only them) as one space
/// with the first non-door id; see [`super::Edit::Merge`].
pub(super) fn merge(nrg: &Nrg, ids: &[SpaceId], name: Option<&str>) -> Result<Edited, EditError> {
    if ids.len() < 2 {
        return Err(EditError::TooFewSpaces);
    }
    if ids.len() > MAX_MERGED {
        return Err(EditError::TooManySpaces {
            count: ids.len(),
            limit: MAX_MERGED,
        });
    }
    let mut members = BTreeSet::new();
    for &id in ids {
        if !members.insert(id) {
            return Err(EditError::NamedTwice(id));
        }
    }
    let space = |id: SpaceId| nrg.space(id).ok_or(EditError::UnknownSpace(id));
    let keeper = *ids
        .iter()
        .find(|&&id| nrg.space(id).is_some_and(|s| s.kind != SpaceKind::Door))
        .ok_or(EditError::OnlyDoors)?;
    // Doors whose every connection leads into the merged spaces go with them.
    for door in nrg.spaces().iter().filter(|s| s.kind == SpaceKind::Door) {
        let mut ends = nrg.connections_of(door.id).filter_map(|c| c.other(door.id));
        let first = ends.next();
        if first.is_some() && first.into_iter().chain(ends).all(|o| members.contains(&o)) {
            members.insert(door.id);
        }
    }
    // Outlines snapped to the micrometre first: spaces drawn to touch
    // (2.0 and 1.9999999999999998) must union into one piece. One unary
    // union (folding pairwise unions from an empty shape left two pieces
    // of a door and the room it opens into: geo 0.33).
    let mut shapes = Vec::with_capacity(members.len());
    for &id in &members {
        let mut shape = polygon(space(id)?);
        shape.map_coords_in_place(|c| geo::Coord {
            x: (c.x * 1e6).round() / 1e6,
            y: (c.y * 1e6).round() / 1e6,
        });
        shapes.push(shape);
    }
    let parts = pieces(geo::unary_union(&shapes));
    let Some(shape) = parts.first().filter(|_| parts.len() == 1) else {
        let labels: Vec<String> = ids
            .iter()
            .filter_map(|&id| nrg.space(id))
            .map(|s| s.label())
            .collect();
        return Err(EditError::DoNotTouch {
            labels: labels.join(", "),
            pieces: parts.len(),
        });
    };
    let largest = ids
        .iter()
        .filter_map(|&id| nrg.space(id))
        .filter(|s| s.kind != SpaceKind::Door)
        .max_by(|a, b| a.area_m2.total_cmp(&b.area_m2).then(b.id.cmp(&a.id)))
        .ok_or(EditError::OnlyDoors)?;
    let mut merged = reshaped(space(keeper)?, shape);
    merged.kind = largest.kind;
    merged.doorway = None;
    merged.name = name
        .map(str::to_string)
        .or_else(|| ids.iter().find_map(|&id| nrg.space(id)?.name.clone()));
    for &id in ids {
        for (k, v) in &space(id)?.attributes {
            merged
                .attributes
                .entry(k.clone())
                .or_insert_with(|| v.clone());
        }
    }
    let merged = reanchored(&merged);
    debug_assert!(merged.area_m2 > 0.0 || shape.unsigned_area() <= 0.0);

    let mut spaces: Vec<_> = nrg
        .spaces()
        .iter()
        .filter(|s| !members.contains(&s.id))
        .cloned()
        .collect();
    spaces.push(merged);
    // Connections leaving the merged spaces now leave the keeper; of two
    // to the same neighbour the stronger stays.
    let mut outside: BTreeMap<SpaceId, ConnectionKind> = BTreeMap::new();
    let mut kept = Vec::new();
    for c in nrg.connections() {
        match (members.contains(&c.a), members.contains(&c.b)) {
            (true, true) => {}
            (false, false) => kept.push(c.clone()),
            (true, false) | (false, true) => {
                let other = if members.contains(&c.a) { c.b } else { c.a };
                let kind = outside.get(&other).map_or(c.kind, |&k| stronger(k, c.kind));
                outside.insert(other, kind);
            }
        }
    }
    for (other, kind) in outside {
        kept.push(link(&spaces, keeper, other, kind));
    }
    let removed = members.into_iter().filter(|&id| id != keeper).collect();
    Ok(Edited {
        nrg: Nrg::new(spaces, kept)?,
        created: vec![],
        removed,
    })
}
