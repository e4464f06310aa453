//! The diff overlay from two revisions, by space matching
//! ([`crate::diff::match_spaces`]). A stand-in until the diff module's
//! change sets land: then this becomes a mapping of a `ChangeSet`.

use super::scene::{DiffOverlay, OverlaySpace};
use std::collections::{BTreeMap, BTreeSet};

use crate::diff::{MatchParams, SpaceMatch, match_spaces};
use crate::model::{Nrg, SpaceId};

/// What changed from `old` to `new`, by space matching: unmatched old
/// spaces were removed, unmatched new ones added, and matched ones whose
/// outline (IoU < 0.999), kind or name differ changed.
pub fn diff_overlay(old: &Nrg, new: &Nrg) -> DiffOverlay {
    let matches = match_spaces(old, new, &MatchParams::default());
    let matched_old: BTreeSet<SpaceId> = matches.iter().map(|m| m.old).collect();
    let by_new: BTreeMap<SpaceId, &SpaceMatch> = matches.iter().map(|m| (m.new, m)).collect();
    let mut overlay = DiffOverlay::default();
    for s in old.spaces() {
        if !matched_old.contains(&s.id) {
            overlay.removed.push(OverlaySpace::of(s));
        }
    }
    for s in new.spaces() {
        match by_new.get(&s.id) {
            None => overlay.added.push(OverlaySpace::of(s)),
            Some(m) => {
                let before = old.space(m.old);
                if m.iou < 0.999 || before.is_some_and(|b| b.kind != s.kind || b.name != s.name) {
                    overlay.changed.push(OverlaySpace::of(s));
                }
            }
        }
    }
    overlay
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_new_room_is_added_and_the_longer_corridor_changed() {
        let old = crate::fixtures::corridor_building(2);
        let new = crate::fixtures::corridor_building(3);
        let d = diff_overlay(&old, &new);
        let ids = |v: &Vec<OverlaySpace>| v.iter().map(|o| o.id.0).collect::<Vec<_>>();
        assert_eq!(ids(&d.added), vec![12, 10_002]);
        assert_eq!(ids(&d.changed), vec![1]);
        assert!(d.removed.is_empty());
        assert!(diff_overlay(&new, &new).is_empty());
        assert_eq!(ids(&diff_overlay(&new, &old).removed), vec![12, 10_002]);
    }
}
