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

/// The shape of one region, in pixels.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct SpaceShape {
    /// Its area.
    pub area: usize,
    /// Its widest inscribed diameter (the pipeline passes it with the
    /// clutter standing in the region filled, see `filled`).
    pub diameter: f64,
    /// Its length along itself: the geodesic diameter (see `geodesic`).
    pub length: f64,
}

impl SpaceShape {
    /// Area over the squared widest diameter: how many times longer than
    /// its widest part the region is.
    pub fn elongation(&self) -> f64 {
        self.area as f64 / (self.diameter * self.diameter).max(1.0)
    }

    /// Length over mean width (area / length), i.e. length² / area: how
    /// many times longer than it is wide on average the region is, along
    /// the longest walk inside it. A rectangle L × W scores L/W + W/L
    /// (its walk runs corner to corner); an L-shaped or comb-shaped room
    /// (an alcove off a living area, aisles between shelves) keeps a small
    /// score however narrow its widest circle.
    pub fn length_ratio(&self) -> f64 {
        self.length * self.length / (self.area as f64).max(1.0)
    }
}

/// What makes a region long and narrow enough to be a corridor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct CorridorShape {
    /// Least [`SpaceShape::elongation`].
    pub min_elongation: f64,
    /// Least [`SpaceShape::length_ratio`].
    pub min_length_ratio: f64,
}

impl CorridorShape {
    /// Whether `shape` is long and narrow by both measures.
    fn is_long(&self, shape: &SpaceShape) -> bool {
        shape.elongation() >= self.min_elongation && shape.length_ratio() >= self.min_length_ratio
    }
}

/// Labels `1..=regions` are rooms or corridors, `regions+1..=labels.count`
/// doors with `door_pairs[k]` the two regions door `regions+1+k` joins.
/// `shape[l]` is region `l`'s [`SpaceShape`].
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
/// A region is a corridor when it has ≥ 2 navigable edges (so no corridor
/// dangles) and is long and narrow by both measures of [`CorridorShape`]
/// ([`SpaceShape::elongation`] and [`SpaceShape::length_ratio`]); every
/// other region is a room.
pub(crate) fn topology(
    labels: &Labels,
    regions: u32,
    door_pairs: &[(u32, u32)],
    shape: &[SpaceShape],
    corridor: CorridorShape,
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
            let long = shape.get(l as usize).is_some_and(|s| corridor.is_long(s));
            if degree.get(&l).copied().unwrap_or(0) >= 2 && long {
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

    const CORRIDOR: CorridorShape = CorridorShape {
        min_elongation: 2.5,
        min_length_ratio: 4.0,
    };

    fn shape(area: usize, diameter: f64, length: f64) -> SpaceShape {
        SpaceShape {
            area,
            diameter,
            length,
        }
    }

    #[test]
    fn a_space_narrow_for_its_area_but_with_no_long_walk_is_a_room() {
        // Three spaces joined in a row by doors 4 and 5; the middle one
        // (2) has two doors. Its widest circle is small for its area.
        let labels = Labels {
            width: 5,
            height: 1,
            data: vec![1, 4, 2, 5, 3],
            count: 5,
        };
        let shapes = |length: f64| {
            [
                SpaceShape::default(),
                shape(100, 10.0, 12.0),
                shape(400, 10.0, length),
                shape(100, 10.0, 12.0),
            ]
        };
        let kind = |length: f64| {
            topology(&labels, 3, &[(1, 2), (2, 3)], &shapes(length), CORRIDOR, 3).kinds[2]
        };
        // A 40 x 10 strip: its walk is 40 long, four times its mean width.
        assert_eq!(kind(41.0), SpaceKind::Corridor);
        // An L of two 20 x 10 legs, or a 20 x 20 room with shelves: the
        // same area and the same widest circle, but a walk of 30.
        assert_eq!(kind(30.0), SpaceKind::Room);
        // A long space needs its two doors all the same.
        let dangling = topology(&labels, 3, &[(1, 2)], &shapes(41.0), CORRIDOR, 3);
        assert_eq!(dangling.kinds[2], SpaceKind::Room);
    }

    #[test]
    fn corridor_with_two_doors_and_cycle_removed() {
        // 1 = long corridor, 2 and 3 rooms, 4 door 1-2, 5 door 1-3; 1 and 2 also touch.
        let labels = Labels {
            width: 6,
            height: 2,
            data: vec![2, 4, 1, 1, 5, 3, 2, 2, 1, 1, 1, 3],
            count: 5,
        };
        let shape = [
            SpaceShape::default(),
            shape(40, 2.0, 20.0),
            shape(9, 3.0, 4.0),
            shape(9, 3.0, 4.0),
        ];
        let t = topology(&labels, 3, &[(1, 2), (1, 3)], &shape, CORRIDOR, 3);
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
        let shape = [
            SpaceShape::default(),
            shape(9, 2.0, 4.0),
            shape(9, 2.0, 4.0),
        ];
        let open = |min_open_px| {
            topology(&labels, 2, &[(1, 2)], &shape, CORRIDOR, min_open_px)
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
