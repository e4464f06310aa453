//! What a revision changes against its parent, row by row: the one
//! definition every engine writes (spaces and connections kept as rows
//! valid over a revision range; a row that did not change stays open).

use crate::model::{Connection as Link, Nrg, Space, SpaceId};

/// The rows a revision closes and opens.
#[derive(Debug, Default)]
pub struct Delta<'a> {
    /// Spaces of the parent whose open row is closed (changed or removed).
    pub close_spaces: Vec<SpaceId>,
    /// Spaces whose new row is opened (changed or added).
    pub open_spaces: Vec<&'a Space>,
    /// Connections `(a, b)` of the parent closed.
    pub close_links: Vec<(SpaceId, SpaceId)>,
    /// Connections opened.
    pub open_links: Vec<&'a Link>,
    /// Spaces new in this revision.
    pub added: usize,
    /// Spaces kept but changed.
    pub changed: usize,
    /// Spaces gone.
    pub removed: usize,
}

impl<'a> Delta<'a> {
    /// The delta from `old` (the parent, empty for a first revision) to
    /// `new`.
    pub fn between(old: &Nrg, new: &'a Nrg) -> Delta<'a> {
        let mut d = Delta::default();
        for s in old.spaces() {
            match new.space(s.id) {
                Some(n) if same_space(s, n) => {}
                Some(_) => {
                    d.close_spaces.push(s.id);
                    d.changed += 1;
                }
                None => {
                    d.close_spaces.push(s.id);
                    d.removed += 1;
                }
            }
        }
        for s in new.spaces() {
            match old.space(s.id) {
                Some(o) if same_space(o, s) => {}
                Some(_) => d.open_spaces.push(s),
                None => {
                    d.open_spaces.push(s);
                    d.added += 1;
                }
            }
        }
        for c in old.connections() {
            if !new.connection(c.a, c.b).is_some_and(|n| same_link(c, n)) {
                d.close_links.push((c.a, c.b));
            }
        }
        for c in new.connections() {
            if !old.connection(c.a, c.b).is_some_and(|o| same_link(o, c)) {
                d.open_links.push(c);
            }
        }
        d
    }
}

/// Whether two models store the same rows: every space and connection
/// equal bit for bit.
pub fn same_model(a: &Nrg, b: &Nrg) -> bool {
    a.spaces().len() == b.spaces().len()
        && a.connections().len() == b.connections().len()
        && a.spaces()
            .iter()
            .zip(b.spaces())
            .all(|(x, y)| same_space(x, y))
        && a.connections()
            .iter()
            .zip(b.connections())
            .all(|(x, y)| same_link(x, y))
}

/// Bit-exact equality of what a space row stores (see [`Space::same_but_id`]).
fn same_space(a: &Space, b: &Space) -> bool {
    a.id == b.id && a.same_but_id(b)
}

fn same_link(a: &Link, b: &Link) -> bool {
    a.key() == b.key() && a.kind == b.kind && a.length_m.to_bits() == b.length_m.to_bits()
}

/// The smallest of `candidates` (id, outline, holes) containing `p`, holes
/// excluded: point location, the same on every engine (a door inside a
/// wall gap wins over the corridor around it).
pub fn smallest_containing<'a>(
    p: [f64; 2],
    candidates: impl IntoIterator<Item = (SpaceId, &'a crate::model::Ring, &'a [crate::model::Ring])>,
) -> Option<SpaceId> {
    candidates
        .into_iter()
        .filter(|(_, outline, holes)| {
            crate::model::point_in_ring(p, outline)
                && !holes.iter().any(|h| crate::model::point_in_ring(p, h))
        })
        .map(|(id, outline, _)| (crate::model::polygon_area(outline).abs(), id))
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, id)| id)
}

/// The bounding box `[min_x, max_x, min_y, max_y]` of a space's outline
/// (what spatial indexes of every engine hold).
pub fn bounding_box(s: &Space) -> [f64; 4] {
    let (mut min, mut max) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in &s.polygon {
        for k in 0..2 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    [min[0], max[0], min[1], max[1]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_delta_counts_what_changed() {
        let old = crate::fixtures::corridor_building(3);
        let (mut spaces, links) = old.clone().into_parts();
        spaces[0].name = Some("renamed".into());
        let gone = spaces.pop().unwrap().id;
        let links: Vec<_> = links
            .into_iter()
            .filter(|l| l.a != gone && l.b != gone)
            .collect();
        let new = Nrg::new(spaces, links).unwrap();
        let d = Delta::between(&old, &new);
        assert_eq!((d.added, d.changed, d.removed), (0, 1, 1));
        assert_eq!(d.open_spaces.len(), 1);
        assert!(d.close_links.iter().all(|(a, b)| *a == gone || *b == gone));
        assert!(!d.close_links.is_empty() && d.open_links.is_empty());
        assert!(same_model(&old, &old.clone()) && !same_model(&old, &new));
        let first = Delta::between(&Nrg::default(), &old);
        assert_eq!(first.added, old.spaces().len());
    }
}
