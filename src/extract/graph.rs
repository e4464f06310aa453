//! From the labelled spaces to typed nodes and connections: region adjacency
//! (4-adjacency), labelling (paper Tab. 3) and refinement (Tab. 4).

use std::collections::{BTreeMap, BTreeSet};

use crate::imaging::{Labels, region_adjacency};
use crate::model::{ConnectionKind, SpaceKind};

/// Spaces and edges in pixel terms, before geometry.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Topology {
    /// Kind of every label 1..=count (index 0 unused).
    pub kinds: Vec<SpaceKind>,
    /// Edges `(a, b, kind)` with `a < b`.
    pub edges: Vec<(u32, u32, ConnectionKind)>,
}

/// Labels `1..=regions` are rooms or corridors, `regions+1..=labels.count`
/// doors with `door_pairs[k]` the two regions door `regions+1+k` joins.
/// `shape[l]` = (area px, widest inscribed diameter px) of region `l`.
///
/// Edges: door–region for each door and its two regions (RAG edges from a
/// door to a third region are dropped); region–region RAG edges become
/// `Open`; door–door edges are dropped. Where the two regions also share a
/// door, the paper drops the open edge (the corridor–door–corridor cycles
/// of Tab. 4); here it is dropped only when they touch along fewer than
/// `min_open_px` pixels (the pipeline passes the widest door: a border
/// that narrow may be the rest of the doorway beside its door space, and
/// a door-width profile must not walk round a narrow door through it). A
/// corridor cut in two that also meets itself through a door is still
/// walked straight across the cut.
/// A region with ≥ 2 navigable edges whose elongation (area / diameter²;
/// the pipeline passes the diameter with the clutter in the region filled,
/// see `filled`) is at least `min_elongation` is a corridor, every other region a room, so no
/// corridor dangles.
pub(crate) fn topology(
    labels: &Labels,
    regions: u32,
    door_pairs: &[(u32, u32)],
    shape: &[(usize, f64)],
    min_elongation: f64,
    min_open_px: usize,
) -> Topology {
    let rag = region_adjacency(labels);
    let mut edges: BTreeSet<(u32, u32, ConnectionKind)> = BTreeSet::new();
    let door_joined: BTreeSet<(u32, u32)> = door_pairs.iter().copied().collect();
    for (k, &(a, b)) in door_pairs.iter().enumerate() {
        let d = regions + 1 + k as u32;
        edges.insert((a.min(d), a.max(d), ConnectionKind::Door));
        edges.insert((b.min(d), b.max(d), ConnectionKind::Door));
    }
    for (&(a, b), &contact) in &rag {
        let sliver = door_joined.contains(&(a, b)) && contact < min_open_px;
        if a <= regions && b <= regions && !sliver {
            edges.insert((a, b, ConnectionKind::Open));
        }
    }
    let mut degree: BTreeMap<u32, usize> = BTreeMap::new();
    for &(a, b, _) in &edges {
        *degree.entry(a).or_default() += 1;
        *degree.entry(b).or_default() += 1;
    }
    let mut kinds = vec![SpaceKind::Other; labels.count as usize + 1];
    for l in 1..=labels.count {
        kinds[l as usize] = if l > regions {
            SpaceKind::Door
        } else {
            let (area, diam) = shape.get(l as usize).copied().unwrap_or((0, 1.0));
            let elongation = area as f64 / (diam * diam).max(1.0);
            if degree.get(&l).copied().unwrap_or(0) >= 2 && elongation >= min_elongation {
                SpaceKind::Corridor
            } else {
                SpaceKind::Room
            }
        };
    }
    Topology {
        kinds,
        edges: edges.into_iter().collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn corridor_with_two_doors_and_cycle_removed() {
        // 1 = long corridor, 2 and 3 rooms, 4 door 1-2, 5 door 1-3; 1 and 2 also touch.
        let labels = Labels {
            width: 6,
            height: 2,
            data: vec![2, 4, 1, 1, 5, 3, 2, 2, 1, 1, 1, 3],
            count: 5,
        };
        let shape = vec![(0, 1.0), (40, 2.0), (9, 3.0), (9, 3.0)];
        let t = topology(&labels, 3, &[(1, 2), (1, 3)], &shape, 2.5, 3);
        assert_eq!(t.kinds[1], SpaceKind::Corridor);
        assert_eq!(t.kinds[2], SpaceKind::Room);
        assert_eq!(t.kinds[4], SpaceKind::Door);
        assert!(
            !t.edges.iter().any(|e| (e.0, e.1) == (1, 2)),
            "cycle edge removed"
        );
        assert!(t.edges.contains(&(1, 4, ConnectionKind::Door)));
        assert!(t.edges.contains(&(2, 4, ConnectionKind::Door)));
        assert_eq!(t.edges.len(), 4);
    }

    #[test]
    fn regions_sharing_a_door_and_a_wide_border_keep_both() {
        // Corridor pieces 1 and 2 meet along 4 pixels and through door 3.
        let labels = Labels {
            width: 4,
            height: 5,
            data: vec![
                1, 1, 2, 2, //
                1, 1, 2, 2, //
                1, 1, 2, 2, //
                1, 1, 2, 2, //
                1, 3, 3, 2,
            ],
            count: 3,
        };
        let shape = vec![(0, 1.0), (9, 2.0), (9, 2.0)];
        let open = |min_open_px| {
            topology(&labels, 2, &[(1, 2)], &shape, 2.5, min_open_px)
                .edges
                .contains(&(1, 2, ConnectionKind::Open))
        };
        assert!(
            open(4),
            "a border at least as wide as the limit is walked across"
        );
        assert!(!open(5), "a narrower one may be the rest of the doorway");
    }
}
