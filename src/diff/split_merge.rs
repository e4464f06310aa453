//! Splits and merges by overlap shares, independent of the one-to-one
//! matching: a space of A is split when at least two spaces of B each lie
//! mostly (≥ `part_cover` of their own area) inside it; a space of B is a
//! merge when at least two spaces of A each lie mostly inside it. A part
//! must be unmatched or matched to the whole itself, and overlap it by at
//! least `min_part_m2`.
//!
//! Doors are measured by their doorway line, not their area (a door strip
//! a pixel or two deep has none): a door is a part of a space of the other
//! revision when at least `part_cover` of its doorway line lies inside it
//! ([`super::door_match`]). Its share of the whole is then its area times
//! that line share over the whole's area. Door–door pairs are never parts
//! (doors are matched by doorway instead).

use std::collections::{BTreeMap, HashMap};

use super::change_set::{Merge, Part, Split};
use super::overlaps::Overlaps;
use super::params::DiffParams;
use crate::model::SpaceId;

/// The splits (by old id) and merges (by new id) that the overlaps show.
pub(crate) fn splits_and_merges(
    ov: &Overlaps,
    old_to_new: &HashMap<SpaceId, (SpaceId, f64)>,
    new_to_old: &HashMap<SpaceId, SpaceId>,
    params: &DiffParams,
) -> (Vec<Split>, Vec<Merge>) {
    let mut split_parts: BTreeMap<usize, Vec<Part>> = BTreeMap::new();
    let mut merge_parts: BTreeMap<usize, Vec<Part>> = BTreeMap::new();
    let mut add =
        |i: usize, j: usize, inter: f64, door_line: Option<f64>, [split, merge]: [bool; 2]| {
            let (old, new) = (ov.old_ids[i], ov.new_ids[j]);
            // Area pairs must overlap by `min_part_m2`; a door's line share
            // stands in for the area share (see the module doc).
            let covers = |own_area: f64| match door_line {
                Some(share) => share >= params.part_cover,
                None => inter >= params.min_part_m2 && inter >= params.part_cover * own_area,
            };
            // `new` is a part of `old` split.
            let new_free = new_to_old.get(&new).is_none_or(|&o| o == old);
            if split && new_free && covers(ov.new_area[j]) && ov.old_area[i] > 0.0 {
                split_parts.entry(i).or_default().push(Part {
                    id: new,
                    share: inter / ov.old_area[i],
                });
            }
            // `old` is a part of `new` merged.
            let old_free = old_to_new.get(&old).is_none_or(|&(n, _)| n == new);
            if merge && old_free && covers(ov.old_area[i]) && ov.new_area[j] > 0.0 {
                merge_parts.entry(j).or_default().push(Part {
                    id: old,
                    share: inter / ov.new_area[j],
                });
            }
        };
    for &(i, j, inter) in &ov.pairs {
        if !ov.old_is_door(i) && !ov.new_is_door(j) {
            add(i, j, inter, None, [true, true]);
        }
    }
    for &(i, j, share) in &ov.door_shares {
        // A door of A may only be a part of a merge in B, a door of B only
        // a part of a split of A.
        let old_door = ov.old_is_door(i);
        let door_area = if old_door {
            ov.old_area[i]
        } else {
            ov.new_area[j]
        };
        add(i, j, door_area * share, Some(share), [!old_door, old_door]);
    }
    let by_share = |parts: &mut Vec<Part>| {
        parts.sort_by(|x, y| y.share.total_cmp(&x.share).then(x.id.cmp(&y.id)));
    };
    let splits = split_parts
        .into_iter()
        .filter(|(_, p)| p.len() >= 2)
        .map(|(i, mut parts)| {
            by_share(&mut parts);
            Split {
                old: ov.old_ids[i],
                parts,
            }
        })
        .collect();
    let mut merges: Vec<Merge> = merge_parts
        .into_iter()
        .filter(|(_, p)| p.len() >= 2)
        .map(|(j, mut parts)| {
            by_share(&mut parts);
            Merge {
                new: ov.new_ids[j],
                parts,
            }
        })
        .collect();
    merges.sort_by_key(|m| m.new);
    (splits, merges)
}

#[cfg(test)]
mod tests {
    use crate::diff::{DiffParams, diff};
    use crate::model::{Connection, ConnectionKind, Nrg, Space, SpaceId, SpaceKind};

    fn rect(id: u32, kind: SpaceKind, x0: f64, x1: f64) -> Space {
        let poly = vec![[x0, 0.0], [x1, 0.0], [x1, 4.0], [x0, 4.0]];
        Space::new(SpaceId(id), kind, [(x0 + x1) / 2.0, 2.0], poly)
    }

    /// Rooms 1 and 2 and, in the wall between them, door 3 as a line (no
    /// area), as a one-pixel door cut traces.
    fn two_rooms() -> Nrg {
        let door = Space::new(
            SpaceId(3),
            SpaceKind::Door,
            [5.0, 1.45],
            vec![[5.0, 1.0], [5.0, 1.45], [5.0, 1.9], [5.0, 1.45]],
        );
        let link = |a, b| Connection {
            a: SpaceId(a),
            b: SpaceId(b),
            kind: ConnectionKind::Door,
            length_m: 1.0,
        };
        Nrg::new(
            vec![
                rect(1, SpaceKind::Room, 0.0, 4.95),
                rect(2, SpaceKind::Room, 5.05, 10.0),
                door,
            ],
            vec![link(1, 3), link(2, 3)],
        )
        .unwrap()
    }

    #[test]
    fn a_thin_door_in_a_removed_wall_is_a_part_of_the_merge() {
        let a = two_rooms();
        let b = Nrg::new(vec![rect(7, SpaceKind::Room, 0.0, 10.0)], vec![]).unwrap();
        let cs = diff(&a, &b, &DiffParams::default());
        assert_eq!(cs.merges.len(), 1, "{}", cs.table());
        let ids: Vec<u32> = cs.merges[0].parts.iter().map(|p| p.id.0).collect();
        assert_eq!(ids, vec![1, 2, 3]);
        assert_eq!((cs.summary.removed, cs.summary.added), (0, 0));
    }

    #[test]
    fn a_thin_door_walled_up_is_removed_not_merged() {
        let a = two_rooms();
        let (mut spaces, _) = a.clone().into_parts();
        spaces.retain(|s| s.id.0 != 3);
        let b = Nrg::new(spaces, vec![]).unwrap();
        let cs = diff(&a, &b, &DiffParams::default());
        assert!(
            cs.merges.is_empty() && cs.splits.is_empty(),
            "{}",
            cs.table()
        );
        assert_eq!((cs.summary.removed, cs.summary.unchanged), (1, 2));
    }
}
