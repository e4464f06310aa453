//! The diff overlay of two revisions: their [`ChangeSet`] (see
//! [`crate::diff::diff`]) mapped onto the outlines to draw.

use super::scene::{DiffOverlay, OverlaySpace};

use crate::diff::{ChangeSet, DiffParams, SpaceChangeKind, diff};
use crate::model::{Nrg, SpaceId};

/// What changed from `old` to `new` (see [`overlay_of`]), by
/// [`crate::diff::diff`] with default parameters.
pub fn diff_overlay(old: &Nrg, new: &Nrg) -> DiffOverlay {
    overlay_of(&diff(old, new, &DiffParams::default()), old, new)
}

/// Maps a change set of `old` → `new` onto outlines: parts of a split
/// space and the result of a merge with their new outlines; other added
/// spaces with theirs; removed spaces with their old outlines; spaces
/// resized, re-kinded, renamed or with a new door width with their new
/// outlines. Each space appears once.
pub fn overlay_of(changes: &ChangeSet, old: &Nrg, new: &Nrg) -> DiffOverlay {
    let mut overlay = DiffOverlay::default();
    let of = |nrg: &Nrg, id: Option<SpaceId>| id.and_then(|id| nrg.space(id)).map(OverlaySpace::of);
    for c in &changes.spaces {
        let has = |k: SpaceChangeKind| c.changes.contains(&k);
        let (list, space) = if has(SpaceChangeKind::Split) {
            (&mut overlay.split, of(new, c.new))
        } else if has(SpaceChangeKind::Merged) {
            (&mut overlay.merged, of(new, c.new))
        } else if has(SpaceChangeKind::Removed) {
            (&mut overlay.removed, of(old, c.old))
        } else if has(SpaceChangeKind::Added) {
            (&mut overlay.added, of(new, c.new))
        } else if c.changes.is_empty() {
            continue;
        } else {
            (&mut overlay.changed, of(new, c.new))
        };
        if let Some(s) = space {
            list.push(s);
        }
    }
    for list in [
        &mut overlay.added,
        &mut overlay.removed,
        &mut overlay.changed,
        &mut overlay.split,
        &mut overlay.merged,
    ] {
        list.sort_by_key(|s| s.id);
        list.dedup_by_key(|s| s.id);
    }
    overlay
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Space, SpaceKind};

    fn ids(v: &[OverlaySpace]) -> Vec<u32> {
        v.iter().map(|o| o.id.0).collect()
    }

    #[test]
    fn a_new_room_is_added_and_the_longer_corridor_changed() {
        let old = crate::fixtures::corridor_building(2);
        let new = crate::fixtures::corridor_building(3);
        let d = diff_overlay(&old, &new);
        assert_eq!(ids(&d.added), vec![12, 10_002]);
        assert_eq!(ids(&d.changed), vec![1]);
        assert!(d.removed.is_empty() && d.split.is_empty() && d.merged.is_empty());
        assert!(diff_overlay(&new, &new).is_empty());
        assert_eq!(ids(&diff_overlay(&new, &old).removed), vec![12, 10_002]);
    }

    #[test]
    fn splits_and_merges_are_their_own_changes() {
        let rect = |id: u32, x0: f64, x1: f64| {
            let poly = vec![[x0, 0.0], [x1, 0.0], [x1, 4.0], [x0, 4.0]];
            Space::new(SpaceId(id), SpaceKind::Room, [(x0 + x1) / 2.0, 2.0], poly)
        };
        let whole = Nrg::new(vec![rect(1, 0.0, 6.0)], vec![]).unwrap();
        let halves = Nrg::new(vec![rect(1, 0.0, 3.0), rect(2, 3.1, 6.0)], vec![]).unwrap();
        let d = diff_overlay(&whole, &halves);
        assert_eq!(ids(&d.split), vec![1, 2]);
        assert!(d.added.is_empty() && d.removed.is_empty() && d.changed.is_empty());
        let d = diff_overlay(&halves, &whole);
        assert_eq!(ids(&d.merged), vec![1]);
        assert!(d.added.is_empty() && d.removed.is_empty() && d.changed.is_empty());
    }
}
