//! The diff overlay: a [`ChangeSet`] mapped onto the outlines to draw. The
//! renderer never diffs: the change set comes from
//! [`crate::diff::compare`] (through `query::compare_revisions` for stored
//! revisions), the same one `nrgdb diff` and `GET /diff` report.

use super::scene::{DiffOverlay, OverlaySpace};

use crate::diff::{ChangeSet, SpaceChangeKind};
use crate::model::{Nrg, SpaceId};

/// Maps the change set of `old` → `new` onto outlines to draw over `new`
/// (in `new`'s own frame): parts of a split space and the result of a
/// merge with their new outlines; other added spaces with theirs; removed
/// spaces with their old outlines, moved into `new`'s frame when the
/// change set was aligned (the inverse of its `alignment`); spaces
/// resized, re-kinded, renamed or with a new door width with their new
/// outlines. Each space appears once.
///
/// ```
/// use nrgdb::diff::{compare, DiffOptions, Revision};
/// use nrgdb::fixtures::corridor_building;
/// let (old, new) = (corridor_building(2), corridor_building(3));
/// let done = compare(Revision::new(&old), Revision::new(&new), &DiffOptions::default())?;
/// let overlay = nrgdb::render::diff_overlay(&done.changes, &old, &new);
/// assert_eq!(overlay.added.len(), 2); // a room and its door
/// # Ok::<(), nrgdb::diff::DiffError>(())
/// ```
pub fn diff_overlay(changes: &ChangeSet, old: &Nrg, new: &Nrg) -> DiffOverlay {
    let mut overlay = DiffOverlay::default();
    let back = changes.alignment.map(|t| t.inverse());
    let of = |nrg: &Nrg, id: Option<SpaceId>| id.and_then(|id| nrg.space(id)).map(OverlaySpace::of);
    let old_of = |id: Option<SpaceId>| {
        let mut o = of(old, id)?;
        if let Some(t) = back {
            for ring in std::iter::once(&mut o.polygon).chain(o.holes.iter_mut()) {
                for p in ring.iter_mut() {
                    *p = t.apply(*p);
                }
            }
        }
        Some(o)
    };
    for c in &changes.spaces {
        let has = |k: SpaceChangeKind| c.changes.contains(&k);
        let (list, space) = if has(SpaceChangeKind::Split) {
            (&mut overlay.split, of(new, c.new))
        } else if has(SpaceChangeKind::Merged) {
            (&mut overlay.merged, of(new, c.new))
        } else if has(SpaceChangeKind::Removed) {
            (&mut overlay.removed, old_of(c.old))
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

impl DiffOverlay {
    /// Only the changes on level `level` of a building: removed spaces by
    /// their level in `old`, the others by theirs in `new`.
    pub fn on_level(&self, old: &Nrg, new: &Nrg, level: &str) -> DiffOverlay {
        let on = |nrg: &Nrg, o: &OverlaySpace| {
            nrg.space(o.id)
                .and_then(|s| s.level.as_ref())
                .is_some_and(|l| l.name == level)
        };
        let keep = |list: &[OverlaySpace], nrg: &Nrg| -> Vec<OverlaySpace> {
            list.iter().filter(|o| on(nrg, o)).cloned().collect()
        };
        DiffOverlay {
            added: keep(&self.added, new),
            removed: keep(&self.removed, old),
            changed: keep(&self.changed, new),
            split: keep(&self.split, new),
            merged: keep(&self.merged, new),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diff::{DiffParams, RigidTransform, diff};
    use crate::model::{Space, SpaceKind};

    /// The overlay of the plain diff of two models in one frame.
    fn overlay(old: &Nrg, new: &Nrg) -> DiffOverlay {
        diff_overlay(&diff(old, new, &DiffParams::default()), old, new)
    }

    fn ids(v: &[OverlaySpace]) -> Vec<u32> {
        v.iter().map(|o| o.id.0).collect()
    }

    #[test]
    fn a_new_room_is_added_and_the_longer_corridor_changed() {
        let old = crate::fixtures::corridor_building(2);
        let new = crate::fixtures::corridor_building(3);
        let d = overlay(&old, &new);
        assert_eq!(ids(&d.added), vec![12, 10_002]);
        assert_eq!(ids(&d.changed), vec![1]);
        assert!(d.removed.is_empty() && d.split.is_empty() && d.merged.is_empty());
        assert!(overlay(&new, &new).is_empty());
        assert_eq!(ids(&overlay(&new, &old).removed), vec![12, 10_002]);
    }

    #[test]
    fn splits_and_merges_are_their_own_changes() {
        let rect = |id: u32, x0: f64, x1: f64| {
            let poly = vec![[x0, 0.0], [x1, 0.0], [x1, 4.0], [x0, 4.0]];
            Space::new(SpaceId(id), SpaceKind::Room, [(x0 + x1) / 2.0, 2.0], poly)
        };
        let whole = Nrg::new(vec![rect(1, 0.0, 6.0)], vec![]).unwrap();
        let halves = Nrg::new(vec![rect(1, 0.0, 3.0), rect(2, 3.1, 6.0)], vec![]).unwrap();
        let d = overlay(&whole, &halves);
        assert_eq!(ids(&d.split), vec![1, 2]);
        assert!(d.added.is_empty() && d.removed.is_empty() && d.changed.is_empty());
        let d = overlay(&halves, &whole);
        assert_eq!(ids(&d.merged), vec![1]);
        assert!(d.added.is_empty() && d.removed.is_empty() && d.changed.is_empty());
    }

    #[test]
    fn removed_outlines_follow_the_new_frame() {
        // B: A without its last room, turned 25° and moved; the change set
        // as `compare` makes it once aligned (B → A is t⁻¹). The removed
        // room is drawn over B where it was, not where A had it.
        let a = crate::fixtures::corridor_building(4);
        let cut = crate::fixtures::corridor_building(3);
        let t = RigidTransform::from_degrees(25.0, 4.0, -3.0);
        let b = t.apply_to_nrg(&cut).unwrap();
        let mut changes = diff(&a, &cut, &DiffParams::default());
        changes.alignment = Some(t.inverse());
        let d = diff_overlay(&changes, &a, &b);
        assert_eq!(ids(&d.removed), vec![13, 10_003]);
        let room = a.space(SpaceId(13)).unwrap();
        for (got, was) in d.removed[0].polygon.iter().zip(&room.polygon) {
            let want = t.apply(*was);
            assert!(
                (got[0] - want[0]).hypot(got[1] - want[1]) < 0.2,
                "{got:?} vs {want:?}"
            );
        }
    }
}
