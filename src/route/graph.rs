//! The adjacency the route algorithms search: navigable spaces and
//! connections, lengths in integer micrometres so costs are totally ordered.

use std::collections::HashMap;

use crate::model::{Nrg, SpaceId};

/// Navigable adjacency of an [`Nrg`], built once per revision and reused.
///
/// Nodes are dense indices; `Adjacent` connections and `Other` spaces are
/// left out. Edge costs are the connections' `length_m` in micrometres.
#[derive(Debug, Clone, Default)]
pub struct RouteGraph {
    ids: Vec<SpaceId>,
    index: HashMap<SpaceId, u32>,
    adjacency: Vec<Vec<(u32, u64)>>,
}

/// Metres to the integer micrometres used as costs.
pub(crate) fn to_micrometres(metres: f64) -> u64 {
    // Lengths are finite (model invariant); negative ones count as 0.
    (metres.max(0.0) * 1e6).round() as u64
}

impl RouteGraph {
    /// Builds the navigable adjacency of `nrg`.
    pub fn new(nrg: &Nrg) -> RouteGraph {
        let mut graph = RouteGraph::default();
        for space in nrg.spaces() {
            let n = graph.ids.len() as u32;
            graph.ids.push(space.id);
            graph.index.insert(space.id, n);
            graph.adjacency.push(Vec::new());
        }
        for c in nrg.connections().iter().filter(|c| c.kind.is_navigable()) {
            if let (Some(&a), Some(&b)) = (graph.index.get(&c.a), graph.index.get(&c.b)) {
                let cost = to_micrometres(c.length_m);
                graph.adjacency[a as usize].push((b, cost));
                graph.adjacency[b as usize].push((a, cost));
            }
        }
        for list in &mut graph.adjacency {
            list.sort_unstable();
        }
        graph
    }

    /// The node of a navigable space.
    pub fn node(&self, id: SpaceId) -> Option<u32> {
        self.index.get(&id).copied()
    }

    /// The space of a node.
    pub fn space(&self, node: u32) -> SpaceId {
        self.ids.get(node as usize).copied().unwrap_or(SpaceId(0))
    }

    /// Neighbours of a node with the cost in micrometres.
    pub fn edges(&self, node: u32) -> &[(u32, u64)] {
        self.adjacency
            .get(node as usize)
            .map_or(&[], |v| v.as_slice())
    }

    /// Number of navigable connections of a space (0 when not navigable).
    pub fn degree(&self, id: SpaceId) -> usize {
        self.node(id).map_or(0, |n| self.edges(n).len())
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.ids.len()
    }

    /// Whether the graph has no nodes.
    pub fn is_empty(&self) -> bool {
        self.ids.is_empty()
    }
}
