//! Issue 6: `apply(A, diff(A, B)) == B` on generated models (proptest):
//! B is A with random edits (spaces removed, moved, resized, renamed,
//! re-kinded, added; connections removed, re-kinded, re-measured; ids
//! renumbered), and the change set goes through JSON on the way.

use nrgdb::diff::{ChangeSet, DiffParams, apply, diff};
use nrgdb::fixtures::corridor_building;
use nrgdb::model::{Connection, ConnectionKind, Nrg, Space, SpaceId, SpaceKind};
use proptest::prelude::*;

#[derive(Debug, Clone)]
enum Edit {
    Remove(usize),
    Shift(usize, f64, f64),
    Grow(usize, f64),
    Rename(usize, Option<String>),
    Rekind(usize, usize),
    Add(f64, f64, f64),
    Unlink(usize),
    Relink(usize, usize, f64),
    Renumber(u32),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (0usize..64).prop_map(Edit::Remove),
        (0usize..64, -3.0f64..3.0, -3.0f64..3.0).prop_map(|(i, x, y)| Edit::Shift(i, x, y)),
        (0usize..64, 0.5f64..2.0).prop_map(|(i, f)| Edit::Grow(i, f)),
        (0usize..64, proptest::option::of("[a-zA-Z ]{0,8}")).prop_map(|(i, n)| Edit::Rename(i, n)),
        (0usize..64, 0usize..4).prop_map(|(i, k)| Edit::Rekind(i, k)),
        (-5.0f64..40.0, -5.0f64..10.0, 0.3f64..6.0).prop_map(|(x, y, s)| Edit::Add(x, y, s)),
        (0usize..64).prop_map(Edit::Unlink),
        (0usize..64, 0usize..3, 0.0f64..20.0).prop_map(|(i, k, l)| Edit::Relink(i, k, l)),
        (1u32..5000).prop_map(Edit::Renumber),
    ]
}

fn edited(a: &Nrg, edits: &[Edit]) -> Nrg {
    let (mut spaces, mut links) = a.clone().into_parts();
    for e in edits {
        let n = spaces.len().max(1);
        match e {
            Edit::Remove(i) if !spaces.is_empty() => {
                let id = spaces.remove(i % n).id;
                links.retain(|c| c.a != id && c.b != id);
            }
            Edit::Shift(i, dx, dy) if !spaces.is_empty() => {
                let s = &mut spaces[i % n];
                for p in &mut s.polygon {
                    *p = [p[0] + dx, p[1] + dy];
                }
            }
            Edit::Grow(i, f) if !spaces.is_empty() => {
                let s = &mut spaces[i % n];
                let [cx, cy] = s.anchor;
                for p in &mut s.polygon {
                    *p = [cx + (p[0] - cx) * f, cy + (p[1] - cy) * f];
                }
            }
            Edit::Rename(i, name) if !spaces.is_empty() => spaces[i % n].name = name.clone(),
            Edit::Rekind(i, k) if !spaces.is_empty() => spaces[i % n].kind = SpaceKind::ALL[k % 4],
            Edit::Add(x, y, s) => {
                let id = SpaceId(spaces.iter().map(|s| s.id.0).max().unwrap_or(0) + 1);
                let poly = vec![[*x, *y], [x + s, *y], [x + s, y + s], [*x, y + s]];
                spaces.push(Space::new(
                    id,
                    SpaceKind::Room,
                    [x + s / 2.0, y + s / 2.0],
                    poly,
                ));
                if let Some(other) = spaces.first().map(|s| s.id).filter(|o| *o != id) {
                    links.push(Connection {
                        a: other,
                        b: id,
                        kind: ConnectionKind::Open,
                        length_m: 1.0,
                    });
                }
            }
            Edit::Unlink(i) if !links.is_empty() => {
                let k = i % links.len();
                links.remove(k);
            }
            Edit::Relink(i, k, l) if !links.is_empty() => {
                let k2 = i % links.len();
                links[k2].kind = [
                    ConnectionKind::Door,
                    ConnectionKind::Open,
                    ConnectionKind::Adjacent,
                ][*k];
                links[k2].length_m = *l;
            }
            Edit::Renumber(off) => {
                for s in &mut spaces {
                    s.id = SpaceId(s.id.0 + off);
                }
                for c in &mut links {
                    c.a = SpaceId(c.a.0 + off);
                    c.b = SpaceId(c.b.0 + off);
                }
            }
            _ => {}
        }
    }
    Nrg::new(spaces, links).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn apply_of_diff_gives_the_changed_model(
        rooms in 1usize..8,
        edits in proptest::collection::vec(edit(), 0..8),
    ) {
        let a = corridor_building(rooms);
        let b = edited(&a, &edits);
        let cs = diff(&a, &b, &DiffParams::default());
        let back = ChangeSet::from_json(&cs.to_json()).unwrap();
        prop_assert_eq!(&back, &cs);
        prop_assert_eq!(apply(&a, &back).unwrap(), b.clone());
        // Every space of A and of B has exactly one entry.
        let olds = cs.spaces.iter().filter(|e| e.old.is_some()).count();
        let news = cs.spaces.iter().filter(|e| e.new.is_some()).count();
        prop_assert_eq!((olds, news), (a.spaces().len(), b.spaces().len()));
        if edits.is_empty() {
            prop_assert!(cs.is_empty());
        }
        // The reverse direction replays too.
        prop_assert_eq!(apply(&b, &diff(&b, &a, &DiffParams::default())).unwrap(), a);
    }
}
