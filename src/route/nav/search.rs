//! One walked path between two end points: A* over the gates with the
//! precomputed in-space lengths, then the channel of triangles it implies,
//! straightened by the funnel.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::funnel::{dist, polyline_length};
use super::layer::{Layer, Tree, walk};
use super::mesh::{Mesh, NONE};
use crate::model::Point;
use crate::route::Budget;

/// A point to route from or to, resolved on the mesh.
#[derive(Debug, Clone)]
pub(crate) struct End {
    /// Its space (dense index).
    pub space: u32,
    /// The point.
    pub at: Point,
    /// Its triangle.
    pub tri: u32,
    /// In-space walked length to each gate of its space (in
    /// `Mesh::space_gates` order).
    pub to_gates: Vec<f64>,
    /// How the channel to a gate is found.
    kind: EndKind,
}

#[derive(Debug, Clone)]
enum EndKind {
    /// The anchor of its space: the precomputed table has it.
    Anchor,
    /// Any other point: its own tree.
    Point(Tree),
}

impl End {
    /// The anchor of space `s`.
    pub fn anchor(layer: &Layer, s: u32) -> Option<End> {
        let table = layer.tables.get(s as usize)?;
        let a = table.anchor();
        let (tri, at) = *table.sources.get(a)?;
        let to_gates = (0..a).map(|j| table.cost(a, j)).collect();
        Some(End {
            space: s,
            at,
            tri,
            to_gates,
            kind: EndKind::Anchor,
        })
    }

    /// The point `at` in triangle `tri`.
    pub fn point(mesh: &Mesh, layer: &Layer, at: Point, tri: u32) -> End {
        let space = mesh.tris[tri as usize].space;
        let r = layer.clearance_m;
        let tree = Tree::grow(mesh, &layer.local, space, tri, at, r);
        let table = &layer.tables[space as usize];
        let gates = mesh.space_gates[space as usize].len();
        let to_gates = (0..gates)
            .map(|j| {
                let (gt, gp) = table.sources[j];
                let g = mesh.space_gates[space as usize][j];
                if !layer.gate_open[g as usize] {
                    return f64::INFINITY;
                }
                tree.walk(mesh, &layer.local, gt)
                    .map_or(f64::INFINITY, |mut c| {
                        c.reverse();
                        polyline_length(&walk(mesh, at, gp, &c, r))
                    })
            })
            .collect();
        End {
            space,
            at,
            tri,
            to_gates,
            kind: EndKind::Point(tree),
        }
    }

    /// Triangles from this end to gate source `j` of its space (`outbound`)
    /// or from that gate to this end.
    fn channel(&self, mesh: &Mesh, layer: &Layer, j: usize, outbound: bool) -> Option<Vec<u32>> {
        let table = &layer.tables[self.space as usize];
        match &self.kind {
            EndKind::Anchor => {
                let a = table.anchor();
                if outbound {
                    table.channel(mesh, &layer.local, a, j)
                } else {
                    table.channel(mesh, &layer.local, j, a)
                }
            }
            EndKind::Point(tree) => {
                let mut c = tree.walk(mesh, &layer.local, table.sources.get(j)?.0)?;
                if outbound {
                    c.reverse();
                }
                Some(c)
            }
        }
    }

    /// Triangles from this end to `other` inside their common space.
    fn direct(&self, mesh: &Mesh, layer: &Layer, other: &End) -> Option<Vec<u32>> {
        match (&self.kind, &other.kind) {
            (EndKind::Point(tree), _) => {
                let mut c = tree.walk(mesh, &layer.local, other.tri)?;
                c.reverse();
                Some(c)
            }
            (_, EndKind::Point(tree)) => tree.walk(mesh, &layer.local, self.tri),
            (EndKind::Anchor, EndKind::Anchor) => Some(vec![self.tri]),
        }
    }
}

/// A path found: the polyline, its length, and where it crosses from one
/// space into the next.
#[derive(Debug, Clone)]
pub(crate) struct Walk {
    /// The polyline, start and end included.
    pub points: Vec<Point>,
    /// Its length in metres.
    pub length_m: f64,
    /// The spaces entered, in order (dense indices), start and goal included.
    pub spaces: Vec<u32>,
    /// The gates crossed, in order (one fewer than `spaces`).
    pub gates: Vec<u32>,
}

/// The shortest walk from `from` to `to` not entering spaces marked in
/// `banned` (the ends' own spaces are allowed). `None` when there is none
/// or the budget ran out (the caller checks the budget).
pub(crate) fn shortest_walk(
    mesh: &Mesh,
    layer: &Layer,
    from: &End,
    to: &End,
    banned: &[bool],
    budget: &Budget,
) -> Option<Walk> {
    let gates = mesh.gates.len();
    let mut cost = vec![f64::INFINITY; gates];
    // Predecessor of a gate: the previous gate (NONE: the start) and the
    // space walked through.
    let mut pred = vec![(NONE, NONE); gates];
    let mut heap: BinaryHeap<Reverse<(u64, u32)>> = BinaryHeap::new();
    let h = |g: u32| dist(mesh.gates[g as usize].mid, to.at);
    let mut best = f64::INFINITY;
    // The goal's predecessor gate (NONE: direct, inside one space).
    let mut best_pred = NONE;
    if from.space == to.space
        && let Some(c) = from.direct(mesh, layer, to)
    {
        best = polyline_length(&walk(mesh, from.at, to.at, &c, layer.clearance_m));
    }
    for (j, g) in mesh.space_gates[from.space as usize].iter().enumerate() {
        let c = from.to_gates[j];
        if c < cost[*g as usize] {
            cost[*g as usize] = c;
            pred[*g as usize] = (NONE, from.space);
            heap.push(Reverse(((c + h(*g)).to_bits(), *g)));
        }
    }
    while let Some(Reverse((key, g))) = heap.pop() {
        if budget.check() {
            return None;
        }
        let f = f64::from_bits(key);
        if f >= best {
            break;
        }
        let d = cost[g as usize];
        if f > d + h(g) + 1e-9 {
            continue;
        }
        let gate = &mesh.gates[g as usize];
        for (_, t) in gate.sides {
            if t == pred[g as usize].1 || (banned[t as usize] && t != to.space) {
                continue;
            }
            let list = &mesh.space_gates[t as usize];
            let table = &layer.tables[t as usize];
            let Some(jg) = list.iter().position(|x| *x == g) else {
                continue;
            };
            if t == to.space {
                let goal = d + to.to_gates[jg];
                if goal < best {
                    best = goal;
                    best_pred = g;
                }
            }
            for (jh, hgate) in list.iter().enumerate() {
                let nd = d + table.cost(jg, jh);
                if nd < cost[*hgate as usize] {
                    cost[*hgate as usize] = nd;
                    pred[*hgate as usize] = (g, t);
                    heap.push(Reverse(((nd + h(*hgate)).to_bits(), *hgate)));
                }
            }
        }
    }
    if !best.is_finite() {
        return None;
    }
    // Gates from the goal back to the start.
    let mut chain = Vec::new();
    let mut g = best_pred;
    while g != NONE {
        chain.push(g);
        g = pred[g as usize].0;
        if chain.len() > gates {
            return None;
        }
    }
    chain.reverse();
    assemble(mesh, layer, from, to, &chain, &pred)
}

/// The triangles of the whole walk through `chain`, then the funnel.
fn assemble(
    mesh: &Mesh,
    layer: &Layer,
    from: &End,
    to: &End,
    chain: &[u32],
    pred: &[(u32, u32)],
) -> Option<Walk> {
    let index_in = |s: u32, g: u32| mesh.space_gates[s as usize].iter().position(|x| *x == g);
    let mut tris: Vec<u32> = Vec::new();
    let mut spaces = vec![from.space];
    if chain.is_empty() {
        tris = from.direct(mesh, layer, to)?;
    } else {
        let first = chain[0];
        tris.extend(from.channel(mesh, layer, index_in(from.space, first)?, true)?);
        for w in chain.windows(2) {
            let (g, h) = (w[0], w[1]);
            let t = pred[h as usize].1;
            spaces.push(t);
            let table = &layer.tables[t as usize];
            let c = table.channel(mesh, &layer.local, index_in(t, g)?, index_in(t, h)?)?;
            tris.extend(c);
        }
        let last = *chain.last()?;
        spaces.push(to.space);
        tris.extend(to.channel(mesh, layer, index_in(to.space, last)?, false)?);
    }
    tris.dedup();
    let points = walk(mesh, from.at, to.at, &tris, layer.clearance_m);
    let length_m = polyline_length(&points);
    Some(Walk {
        points,
        length_m,
        spaces,
        gates: chain.to_vec(),
    })
}

/// Walked length from `from` to the anchor of every space (dense index),
/// not entering `banned` spaces, up to `bound_m` (longer ones are infinite).
/// `None` when the budget ran out.
pub(crate) fn anchor_distances(
    mesh: &Mesh,
    layer: &Layer,
    from: &End,
    banned: &[bool],
    bound_m: f64,
    budget: &Budget,
) -> Option<Vec<f64>> {
    let gates = mesh.gates.len();
    let mut cost = vec![f64::INFINITY; gates];
    let mut heap: BinaryHeap<Reverse<(u64, u32)>> = BinaryHeap::new();
    for (j, g) in mesh.space_gates[from.space as usize].iter().enumerate() {
        let c = from.to_gates[j];
        if c <= bound_m && c < cost[*g as usize] {
            cost[*g as usize] = c;
            heap.push(Reverse((c.to_bits(), *g)));
        }
    }
    let mut out = vec![f64::INFINITY; mesh.space_ids.len()];
    let start_table = &layer.tables[from.space as usize];
    out[from.space as usize] = match from.kind {
        EndKind::Anchor => 0.0,
        EndKind::Point(_) => {
            let anchor = End::anchor(layer, from.space);
            anchor
                .and_then(|a| from.direct(mesh, layer, &a))
                .map_or(f64::INFINITY, |c| {
                    let anchor = start_table.sources[start_table.anchor()].1;
                    polyline_length(&walk(mesh, from.at, anchor, &c, layer.clearance_m))
                })
        }
    };
    while let Some(Reverse((key, g))) = heap.pop() {
        if budget.check() {
            return None;
        }
        let d = f64::from_bits(key);
        if d > cost[g as usize] {
            continue;
        }
        for (_, t) in mesh.gates[g as usize].sides {
            if banned[t as usize] {
                continue;
            }
            let list = &mesh.space_gates[t as usize];
            let table = &layer.tables[t as usize];
            let Some(jg) = list.iter().position(|x| *x == g) else {
                continue;
            };
            let to_anchor = d + table.cost(jg, table.anchor());
            if to_anchor <= bound_m && to_anchor < out[t as usize] {
                out[t as usize] = to_anchor;
            }
            for (jh, h) in list.iter().enumerate() {
                let nd = d + table.cost(jg, jh);
                if nd <= bound_m && nd < cost[*h as usize] {
                    cost[*h as usize] = nd;
                    heap.push(Reverse((nd.to_bits(), *h)));
                }
            }
        }
    }
    Some(out)
}
