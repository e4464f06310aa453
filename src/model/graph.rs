//! The navigable connectivity graph of an NRG, built on petgraph.

use std::collections::HashMap;

use petgraph::graph::{NodeIndex, UnGraph};

use super::{Nrg, SpaceId};

/// Undirected graph of the spaces, weighted by connection length in metres.
/// Only navigable connections (`Door`, `Open`) are edges; `Adjacent` ones
/// are left out.
#[derive(Debug, Clone)]
pub struct ConnectivityGraph {
    /// The petgraph graph: node weight = space id, edge weight = metres.
    pub graph: UnGraph<SpaceId, f64>,
    index: HashMap<SpaceId, NodeIndex>,
}

impl ConnectivityGraph {
    /// Builds the graph of `nrg`'s navigable spaces and connections.
    pub fn new(nrg: &Nrg) -> ConnectivityGraph {
        let mut graph = UnGraph::with_capacity(nrg.spaces().len(), nrg.connections().len());
        let mut index = HashMap::with_capacity(nrg.spaces().len());
        for space in nrg.spaces() {
            index.insert(space.id, graph.add_node(space.id));
        }
        for c in nrg.connections().iter().filter(|c| c.kind.is_navigable()) {
            if let (Some(&a), Some(&b)) = (index.get(&c.a), index.get(&c.b)) {
                graph.add_edge(a, b, c.length_m);
            }
        }
        ConnectivityGraph { graph, index }
    }

    /// The node of a space.
    pub fn node(&self, id: SpaceId) -> Option<NodeIndex> {
        self.index.get(&id).copied()
    }

    /// The space of a node.
    pub fn space_id(&self, node: NodeIndex) -> Option<SpaceId> {
        self.graph.node_weight(node).copied()
    }

    /// Navigable neighbours of a space, with the connection length.
    pub fn neighbours(&self, id: SpaceId) -> Vec<(SpaceId, f64)> {
        let Some(node) = self.node(id) else {
            return Vec::new();
        };
        let mut out: Vec<(SpaceId, f64)> = self
            .graph
            .edges(node)
            .filter_map(|e| {
                use petgraph::visit::EdgeRef;
                let other = if e.source() == node {
                    e.target()
                } else {
                    e.source()
                };
                self.space_id(other).map(|s| (s, *e.weight()))
            })
            .collect();
        out.sort_by_key(|(s, _)| *s);
        out
    }
}
