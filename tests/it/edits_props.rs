//! Issue 22: applying edits never produces a model `nrgdb check` rejects.
//! Random buildings (corridor pieces, rooms with furniture holes, doors
//! of random widths), random sequences of edits: every edit accepted
//! leaves a model with no findings, splits keep the area, merges hold
//! their members, and refused edits change nothing.

use nrgdb::edit::{Edit, NewDoor, apply};
use nrgdb::model::{ConnectionKind, Nrg, SpaceId, SpaceKind};
use proptest::prelude::*;

use crate::route_building::building;

/// One random edit on `nrg`, picked by `pick` (index, angle, offset...).
fn random_edit(nrg: &Nrg, pick: (u8, usize, f64, f64, f64)) -> Option<Edit> {
    let (what, i, angle, along, width) = pick;
    let spaces = nrg.spaces();
    let s = &spaces[i % spaces.len()];
    let neighbours: Vec<(SpaceId, ConnectionKind)> = nrg
        .connections_of(s.id)
        .filter_map(|c| Some((c.other(s.id)?, c.kind)))
        .collect();
    let nth = |k: usize| neighbours.get(k % neighbours.len().max(1)).copied();
    Some(match what % 5 {
        0 => {
            // A line through the anchor, shifted, long enough to cross.
            let (dx, dy) = (angle.cos(), angle.sin());
            let half = s
                .polygon
                .iter()
                .map(|p| (p[0] - s.anchor[0]).hypot(p[1] - s.anchor[1]))
                .fold(0.0, f64::max)
                + 1.0;
            let c = [s.anchor[0] - dy * along, s.anchor[1] + dx * along];
            let door = (width > 1.2).then_some(NewDoor {
                at: c,
                width_m: Some(width),
            });
            Edit::Split {
                space: s.id,
                line: [
                    [c[0] - dx * half, c[1] - dy * half],
                    [c[0] + dx * half, c[1] + dy * half],
                ],
                door,
            }
        }
        1 => Edit::Merge {
            spaces: vec![s.id, nth(i / 7)?.0],
            name: Some("merged".into()),
        },
        2 => {
            let (other, _) = neighbours
                .iter()
                .copied()
                .find(|(_, k)| *k == ConnectionKind::Adjacent)?;
            let o = nrg.space(other)?;
            let at = [
                (s.anchor[0] + o.anchor[0]) / 2.0 + along,
                (s.anchor[1] + o.anchor[1]) / 2.0,
            ];
            Edit::AddDoor {
                a: s.id,
                b: other,
                at,
                width_m: Some(width),
            }
        }
        3 => {
            let door = spaces
                .iter()
                .filter(|d| d.kind == SpaceKind::Door)
                .nth(i % 5)?;
            Edit::RemoveDoor { door: door.id }
        }
        _ => Edit::SetKind {
            space: s.id,
            kind: if s.kind == SpaceKind::Room {
                SpaceKind::Corridor
            } else {
                SpaceKind::Room
            },
        },
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn accepted_edits_always_pass_the_checker(
        b in building(),
        picks in proptest::collection::vec((0u8..5, 0usize..500, 0.0f64..std::f64::consts::PI, -1.0f64..1.0, 0.5f64..1.6), 1..5),
    ) {
        let mut nrg = b.nrg.clone();
        prop_assert!(nrgdb::ingest::findings(&nrg).is_empty());
        for pick in picks {
            let Some(edit) = random_edit(&nrg, pick) else { continue };
            match apply(&nrg, &edit, nrg.next_id()) {
                Ok(done) => {
                    let findings = nrgdb::ingest::findings(&done.nrg);
                    prop_assert!(findings.is_empty(), "{edit:?}: {findings:?}");
                    let area = |m: &Nrg, id: SpaceId| m.space(id).map_or(0.0, |s| s.area_m2);
                    match &edit {
                        Edit::Split { space, door: None, .. } => {
                            let sum = area(&done.nrg, *space) + area(&done.nrg, done.created[0]);
                            prop_assert!((sum - area(&nrg, *space)).abs() < 1e-6, "{edit:?}: {sum}");
                        }
                        Edit::Merge { spaces, .. } => {
                            let members: f64 = spaces.iter().map(|&id| area(&nrg, id)).sum();
                            let keeper = spaces.iter().copied().find(|&id| nrg.space(id).is_some_and(|s| s.kind != SpaceKind::Door));
                            // (Outlines are snapped to the micrometre before the union.)
                            prop_assert!(area(&done.nrg, keeper.unwrap()) >= members - 1e-4, "{edit:?}");
                        }
                        _ => {}
                    }
                    nrg = done.nrg;
                }
                Err(e) => prop_assert!(!e.to_string().is_empty()),
            }
        }
    }
}
