//! Carrying a change made on an older revision over onto the latest one
//! (`nrgdb apply --rebase`), so that applying it never undoes the
//! revisions in between: the spaces and connections the change touched
//! are taken from the changed model, everything else from the latest,
//! and a space or connection that both the change and a later revision
//! touched is a conflict, reported instead of guessed.

use std::collections::{BTreeMap, BTreeSet};

use crate::model::{Connection, Nrg, Space, SpaceId};

/// Connections whose lengths differ by less than this (metres) are the
/// same (lengths are walked again when stored).
const SAME_LENGTH_M: f64 = 1e-3;

/// `latest` with the change from `base` to `changed` carried over (all
/// three share stable ids); `Err` lists every conflict.
///
/// ```
/// use nrgdb::diff::rebase;
/// use nrgdb::model::SpaceId;
/// let base = nrgdb::fixtures::corridor_building(3);
/// let rename = |nrg: &nrgdb::model::Nrg, id: u32, name: &str| {
///     let (mut spaces, links) = nrg.clone().into_parts();
///     spaces.iter_mut().find(|s| s.id == SpaceId(id)).unwrap().name = Some(name.into());
///     nrgdb::model::Nrg::new(spaces, links).unwrap()
/// };
/// let changed = rename(&base, 11, "Lab");
/// let latest = rename(&base, 12, "Store");
/// let both = rebase(&base, &changed, &latest).unwrap();
/// assert_eq!(both.space(SpaceId(11)).unwrap().name.as_deref(), Some("Lab"));
/// assert_eq!(both.space(SpaceId(12)).unwrap().name.as_deref(), Some("Store"));
/// assert!(rebase(&base, &changed, &rename(&base, 11, "Office")).is_err());
/// ```
pub fn rebase(base: &Nrg, changed: &Nrg, latest: &Nrg) -> Result<Nrg, Vec<String>> {
    let mut conflicts = Vec::new();
    let ids: BTreeSet<SpaceId> = base
        .spaces()
        .iter()
        .chain(changed.spaces())
        .map(|s| s.id)
        .collect();
    let touched: BTreeSet<SpaceId> = ids
        .into_iter()
        .filter(|&id| !same_space(base.space(id), changed.space(id)))
        .collect();
    for &id in &touched {
        // A later revision that made the same change is no conflict.
        let unchanged_since = same_space(base.space(id), latest.space(id));
        if !unchanged_since && !same_space(changed.space(id), latest.space(id)) {
            let what = match (base.space(id), latest.space(id)) {
                (None, Some(_)) => "is a new space in both",
                (Some(_), None) => "was removed by a later revision",
                _ => "was changed by a later revision too",
            };
            conflicts.push(format!("space {id} {what}"));
        }
    }
    let key = |c: &Connection| c.key();
    let links = |nrg: &Nrg| -> BTreeMap<(SpaceId, SpaceId), Connection> {
        nrg.connections()
            .iter()
            .map(|c| (key(c), c.clone()))
            .collect()
    };
    let (base_links, changed_links, mut out_links) = (links(base), links(changed), links(latest));
    let keys: BTreeSet<(SpaceId, SpaceId)> = base_links
        .keys()
        .chain(changed_links.keys())
        .copied()
        .collect();
    for k in keys {
        let (b, c) = (base_links.get(&k), changed_links.get(&k));
        if same_link(b, c) {
            continue;
        }
        let now = out_links.get(&k);
        if same_link(c, now) {
            continue;
        }
        if !same_link(b, now) {
            conflicts.push(format!(
                "the connection {}–{} was changed by a later revision too",
                k.0, k.1
            ));
            continue;
        }
        match c {
            Some(c) => out_links.insert(k, c.clone()),
            None => out_links.remove(&k),
        };
    }
    if !conflicts.is_empty() {
        return Err(conflicts);
    }
    let mut spaces: Vec<Space> = latest
        .spaces()
        .iter()
        .filter(|s| !touched.contains(&s.id))
        .cloned()
        .collect();
    spaces.extend(
        changed
            .spaces()
            .iter()
            .filter(|s| touched.contains(&s.id))
            .cloned(),
    );
    let present: BTreeSet<SpaceId> = spaces.iter().map(|s| s.id).collect();
    let mut dangling = Vec::new();
    let links: Vec<Connection> = out_links
        .into_values()
        .filter(|c| {
            let ok = present.contains(&c.a) && present.contains(&c.b);
            if !ok {
                dangling.push(format!(
                    "a later revision connects {} and {}, one of which the change removes",
                    c.a, c.b
                ));
            }
            ok
        })
        .collect();
    if !dangling.is_empty() {
        return Err(dangling);
    }
    Nrg::new(spaces, links).map_err(|e| vec![e.to_string()])
}

fn same_space(a: Option<&Space>, b: Option<&Space>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => a.id == b.id && a.same_but_id(b),
        (None, None) => true,
        _ => false,
    }
}

fn same_link(a: Option<&Connection>, b: Option<&Connection>) -> bool {
    match (a, b) {
        (Some(a), Some(b)) => a.kind == b.kind && (a.length_m - b.length_m).abs() < SAME_LENGTH_M,
        (None, None) => true,
        _ => false,
    }
}
