//! A contraction hierarchy over the opening crossings of one level
//! (Geisberger, Sanders, Schultes & Delling 2008, "Contraction
//! Hierarchies: faster and simpler hierarchical routing in road
//! networks"), built once per level from the in-space tables and kept with
//! it, so a route query settles a few hundred crossings instead of every
//! crossing nearer than its goal.
//!
//! The graph: a node per crossing point ([`SAMPLES`] per opening), an edge
//! between two crossings of the same space weighted by the walked length
//! between them inside it (the layer's table). Nodes are contracted one by
//! one (fewest shortcuts added first, then the shallowest); contracting a
//! node adds a shortcut between two of its neighbours unless a path of at
//! most the same length avoids it (checked over one and two hops: a missed
//! witness only adds a shortcut, never loses a length). A query is a
//! bidirectional Dijkstra that only climbs (with stall-on-demand), so it is
//! exact: it finds the same length as a Dijkstra over the whole graph.
//!
//! Used by the search when no space is banned (AVOID and door widths need
//! the plain search). Uses the layer's tables; knows nothing of geometry.

use std::cell::RefCell;
use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::layer::{Layer, SAMPLES};
use super::mesh::{Mesh, NONE};
use crate::route::Budget;

/// Spaces with more openings than this make the crossing graph too dense
/// to contract quickly (each is a clique of `SAMPLES` × openings nodes);
/// a level with one is searched by A* alone.
const MAX_OPENINGS: usize = 48;

/// Weights of the contraction priority: shortcuts added, degree, depth
/// (`contraction_statistics` below: on willow-full 158 nodes at zero
/// clearance and 39 at 0.2 m, the smallest of the weights tried; on
/// a 300-column demo building 56 and 50).
const WEIGHTS: [i64; 3] = [1, 1, 2];

/// An edge of the graph being contracted.
#[derive(Debug, Clone, Copy)]
struct Edge {
    cost: f64,
    /// The contracted node a shortcut stands for (NONE: an original edge).
    mid: u32,
    /// The space an original edge is walked through.
    space: u32,
}

/// An edge from a node to a neighbour contracted after it.
#[derive(Debug, Clone, Copy)]
struct Arc {
    head: u32,
    cost: f64,
    mid: u32,
    space: u32,
}

/// The contracted crossing graph of one level.
#[derive(Debug)]
pub(crate) struct Hierarchy {
    /// The upward arcs of node `v` are `arcs[first[v]..first[v + 1]]`,
    /// sorted by head.
    first: Vec<u32>,
    arcs: Vec<Arc>,
    /// For a shortcut arc, the two arcs up from its middle node to its
    /// ends (towards the arc's tail, towards its head); found once here so
    /// unpacking a path does no search.
    halves: Vec<[u32; 2]>,
}

/// The node of sample `k` of opening `o`.
fn node(o: u32, k: usize) -> u32 {
    o * SAMPLES as u32 + k as u32
}

/// The edge to `head` in a neighbour list sorted by head.
fn find(list: &[(u32, Edge)], head: u32) -> Option<&Edge> {
    list.binary_search_by_key(&head, |e| e.0)
        .ok()
        .map(|i| &list[i].1)
}

/// Adds the edge to `head`, or lowers the one there.
fn improve(list: &mut Vec<(u32, Edge)>, head: u32, edge: Edge) {
    match list.binary_search_by_key(&head, |e| e.0) {
        Ok(i) if edge.cost < list[i].1.cost => list[i].1 = edge,
        Ok(_) => {}
        Err(i) => list.insert(i, (head, edge)),
    }
}

/// Whether `u` and `w` are joined by a path of at most `via` that avoids
/// `v` (one or two hops).
fn witness(adj: &[Vec<(u32, Edge)>], v: u32, u: u32, w: u32, via: f64) -> bool {
    let (a, b) = if adj[u as usize].len() <= adj[w as usize].len() {
        (u, w)
    } else {
        (w, u)
    };
    if find(&adj[a as usize], b).is_some_and(|e| e.cost <= via) {
        return true;
    }
    adj[a as usize].iter().any(|(x, ex)| {
        *x != v
            && *x != b
            && ex.cost < via
            && find(&adj[*x as usize], b).is_some_and(|e| ex.cost + e.cost <= via)
    })
}

/// The shortcuts contracting `v` needs, `(u, w, length)`, into `out`.
fn shortcuts(adj: &[Vec<(u32, Edge)>], v: u32, out: &mut Vec<(u32, u32, f64)>) {
    let list = &adj[v as usize];
    for (i, (u, eu)) in list.iter().enumerate() {
        for (w, ew) in &list[i + 1..] {
            let via = eu.cost + ew.cost;
            if !witness(adj, v, *u, *w, via) {
                out.push((*u, *w, via));
            }
        }
    }
}

impl Hierarchy {
    /// Contracts the crossing graph of `layer` (building every space's
    /// table). `None` when a space has too many openings for it.
    pub fn new(mesh: &Mesh, layer: &Layer) -> Option<Hierarchy> {
        Hierarchy::with_weights(mesh, layer, WEIGHTS)
    }

    /// [`Hierarchy::new`] with the priority `w[0] × shortcuts − w[1] ×
    /// degree + w[2] × depth`.
    fn with_weights(mesh: &Mesh, layer: &Layer, w: [i64; 3]) -> Option<Hierarchy> {
        let openings = &mesh.openings;
        if openings.of_space.iter().any(|l| l.len() > MAX_OPENINGS) {
            return None;
        }
        let n = openings.list.len() * SAMPLES;
        let mut adj: Vec<Vec<(u32, Edge)>> = vec![Vec::new(); n];
        for (s, list) in openings.of_space.iter().enumerate() {
            if list.is_empty() {
                continue;
            }
            let table = layer.table(mesh, s as u32);
            let m = list.len() * SAMPLES;
            for i in 0..m {
                let a = node(list[i / SAMPLES], i % SAMPLES);
                for j in i + 1..m {
                    let cost = table.cost(i, j);
                    if !cost.is_finite() {
                        continue;
                    }
                    let b = node(list[j / SAMPLES], j % SAMPLES);
                    let edge = Edge {
                        cost,
                        mid: NONE,
                        space: s as u32,
                    };
                    improve(&mut adj[a as usize], b, edge);
                    improve(&mut adj[b as usize], a, edge);
                }
            }
        }
        let mut depth = vec![0i64; n];
        let mut found = Vec::new();
        let mut priority = |adj: &[Vec<(u32, Edge)>], depth: &[i64], v: u32| {
            found.clear();
            shortcuts(adj, v, &mut found);
            w[0] * found.len() as i64 - w[1] * adj[v as usize].len() as i64
                + w[2] * depth[v as usize]
        };
        let mut heap: BinaryHeap<Reverse<(i64, u32)>> = (0..n as u32)
            .map(|v| Reverse((priority(&adj, &depth, v), v)))
            .collect();
        let mut up: Vec<Vec<Arc>> = vec![Vec::new(); n];
        let mut added = Vec::new();
        while let Some(Reverse((_, v))) = heap.pop() {
            // Lazy update: contract `v` only if it is still the cheapest.
            let now = priority(&adj, &depth, v);
            if let Some(Reverse((next, _))) = heap.peek()
                && now > *next
            {
                heap.push(Reverse((now, v)));
                continue;
            }
            added.clear();
            shortcuts(&adj, v, &mut added);
            let neighbours = std::mem::take(&mut adj[v as usize]);
            for (u, e) in &neighbours {
                let list = &mut adj[*u as usize];
                if let Ok(i) = list.binary_search_by_key(&v, |e| e.0) {
                    list.remove(i);
                }
                depth[*u as usize] = depth[*u as usize].max(depth[v as usize] + 1);
                up[v as usize].push(Arc {
                    head: *u,
                    cost: e.cost,
                    mid: e.mid,
                    space: e.space,
                });
            }
            for (u, w, cost) in added.drain(..) {
                let edge = Edge {
                    cost,
                    mid: v,
                    space: NONE,
                };
                improve(&mut adj[u as usize], w, edge);
                improve(&mut adj[w as usize], u, edge);
            }
        }
        let mut first = Vec::with_capacity(n + 1);
        let mut arcs = Vec::new();
        for list in &mut up {
            first.push(arcs.len() as u32);
            list.sort_unstable_by_key(|a| a.head);
            arcs.append(list);
        }
        first.push(arcs.len() as u32);
        let mut hierarchy = Hierarchy {
            first,
            arcs,
            halves: Vec::new(),
        };
        hierarchy.halves = hierarchy.find_halves()?;
        Some(hierarchy)
    }

    /// [`Hierarchy::halves`]: for each arc from `v` to `head` through `mid`,
    /// the arcs from `mid` up to `v` and to `head` (`[NONE; 2]` for an
    /// original edge). `None` if one is missing (it never is: `mid` was
    /// contracted before both ends, with an arc to each).
    fn find_halves(&self) -> Option<Vec<[u32; 2]>> {
        let mut halves = vec![[NONE; 2]; self.arcs.len()];
        for v in 0..self.first.len().saturating_sub(1) as u32 {
            for i in self.up(v) {
                let Arc { head, mid, .. } = self.arcs[i];
                if mid != NONE {
                    halves[i] = [self.arc(mid, v)? as u32, self.arc(mid, head)? as u32];
                }
            }
        }
        Some(halves)
    }

    fn up(&self, v: u32) -> std::ops::Range<usize> {
        self.first[v as usize] as usize..self.first[v as usize + 1] as usize
    }

    /// The index of the arc from `v` up to `head`.
    fn arc(&self, v: u32, head: u32) -> Option<usize> {
        let range = self.up(v);
        let start = range.start;
        self.arcs[range]
            .binary_search_by_key(&head, |a| a.head)
            .ok()
            .map(|i| start + i)
    }

    /// The shortest path from any node of `from` to any node of `to`, each
    /// with the length already walked to (or still to walk from) it,
    /// shorter than `bound`: its length and its nodes in order, each with
    /// the space walked through to reach it (NONE for the first). `None`
    /// when there is none or the budget ran out.
    pub fn shortest(
        &self,
        from: &[(u32, f64)],
        to: &[(u32, f64)],
        bound: f64,
        budget: &Budget,
    ) -> Option<(f64, Vec<(u32, u32)>)> {
        SCRATCH.with(|cell| {
            let mut scratch = cell.borrow_mut();
            scratch.prepare(self.first.len().saturating_sub(1));
            let found = self.search(&mut scratch, from, to, bound, budget);
            let path = found
                .and_then(|(length, meet)| self.path(&scratch, meet).map(|nodes| (length, nodes)));
            scratch.reset();
            path
        })
    }

    fn search(
        &self,
        s: &mut Scratch,
        from: &[(u32, f64)],
        to: &[(u32, f64)],
        bound: f64,
        budget: &Budget,
    ) -> Option<(f64, u32)> {
        for (dir, seeds) in [from, to].into_iter().enumerate() {
            for &(v, c) in seeds {
                if c < s.dist[dir][v as usize] {
                    s.set(dir, v, c, (NONE, NONE));
                    s.heap[dir].push(Reverse((c.to_bits(), v)));
                }
            }
        }
        let mut best = bound;
        let mut meet = NONE;
        loop {
            if budget.check() {
                return None;
            }
            let top = |d: usize| s.heap[d].peek().map(|Reverse((k, _))| f64::from_bits(*k));
            let dir = match (top(0), top(1)) {
                (Some(a), Some(b)) if a.min(b) < best => usize::from(b < a),
                (Some(a), None) if a < best => 0,
                (None, Some(b)) if b < best => 1,
                _ => break,
            };
            let Some(Reverse((key, v))) = s.heap[dir].pop() else {
                break;
            };
            let d = f64::from_bits(key);
            if d > s.dist[dir][v as usize] {
                continue;
            }
            let other = s.dist[1 - dir][v as usize];
            if d + other < best {
                best = d + other;
                meet = v;
            }
            let range = self.up(v);
            // Stall-on-demand: a higher node already reached more cheaply
            // leads here; nothing above is reached best through `v`.
            if self.arcs[range.clone()]
                .iter()
                .any(|a| s.dist[dir][a.head as usize] + a.cost < d)
            {
                continue;
            }
            for i in range {
                let a = self.arcs[i];
                let nd = d + a.cost;
                if nd < s.dist[dir][a.head as usize] && nd < best {
                    s.set(dir, a.head, nd, (v, i as u32));
                    s.heap[dir].push(Reverse((nd.to_bits(), a.head)));
                }
            }
        }
        (meet != NONE).then_some((best, meet))
    }

    /// The nodes from a `from` seed through `meet` to a `to` seed, with the
    /// space walked to reach each.
    fn path(&self, s: &Scratch, meet: u32) -> Option<Vec<(u32, u32)>> {
        // Arcs of the upward climbs as (lower node, arc), from the seeds.
        let climb = |dir: usize| {
            let mut arcs = Vec::new();
            let mut v = meet;
            while let Some(&(prev, arc)) = s.pred[dir].get(v as usize) {
                if prev == NONE || arcs.len() > self.arcs.len() {
                    break;
                }
                arcs.push((prev, arc));
                v = prev;
            }
            (v, arcs)
        };
        let (start, mut forward) = climb(0);
        forward.reverse();
        let (_, backward) = climb(1);
        let mut out = vec![(start, NONE)];
        for (prev, arc) in forward {
            let head = self.arcs.get(arc as usize)?.head;
            self.unpack(prev, head, arc as usize, &mut out)?;
        }
        for (prev, arc) in backward {
            // Walked downward: from the arc's head to `prev`.
            let head = self.arcs.get(arc as usize)?.head;
            self.unpack(head, prev, arc as usize, &mut out)?;
        }
        Some(out)
    }

    /// Appends the original edges of arc `arc` (between `a` and `b`),
    /// walked from `a` to `b`: each node reached with its space.
    fn unpack(&self, a: u32, b: u32, arc: usize, out: &mut Vec<(u32, u32)>) -> Option<()> {
        let mut stack = vec![(a, b, arc)];
        while let Some((a, b, arc)) = stack.pop() {
            let Arc { mid, space, .. } = *self.arcs.get(arc)?;
            if mid == NONE {
                out.push((b, space));
                continue;
            }
            // `mid` was contracted before both ends: both arcs go up from
            // it, the arc's tail half first (the arc may be walked either
            // way).
            let [to_tail, to_head] = *self.halves.get(arc)?;
            let tail_is_a = self.arcs.get(to_head as usize)?.head == b;
            let (to_a, to_b) = if tail_is_a {
                (to_tail, to_head)
            } else {
                (to_head, to_tail)
            };
            stack.push((mid, b, to_b as usize));
            stack.push((a, mid, to_a as usize));
            if stack.len() > self.arcs.len() {
                return None;
            }
        }
        Some(())
    }
}

/// Per-thread search state, reused across queries: distances stay
/// infinite except where the current query has set them.
#[derive(Debug, Default)]
struct Scratch {
    dist: [Vec<f64>; 2],
    /// `(lower node, arc index)` each node was reached by.
    pred: [Vec<(u32, u32)>; 2],
    heap: [BinaryHeap<Reverse<(u64, u32)>>; 2],
    touched: Vec<(usize, u32)>,
}

impl Scratch {
    fn prepare(&mut self, n: usize) {
        for d in 0..2 {
            if self.dist[d].len() < n {
                self.dist[d].resize(n, f64::INFINITY);
                self.pred[d].resize(n, (NONE, NONE));
            }
            self.heap[d].clear();
        }
    }

    fn set(&mut self, dir: usize, v: u32, d: f64, pred: (u32, u32)) {
        if self.dist[dir][v as usize].is_infinite() {
            self.touched.push((dir, v));
        }
        self.dist[dir][v as usize] = d;
        self.pred[dir][v as usize] = pred;
    }

    fn reset(&mut self) {
        for (dir, v) in self.touched.drain(..) {
            self.dist[dir][v as usize] = f64::INFINITY;
            self.pred[dir][v as usize] = (NONE, NONE);
        }
        for h in &mut self.heap {
            h.clear();
        }
    }
}

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use super::*;
    use crate::route::{NavMesh, Profile};

    /// Average upward search space (nodes settled, arcs scanned) from
    /// every 7th node.
    fn search_space(h: &Hierarchy) -> (f64, f64) {
        let n = h.first.len() - 1;
        let (mut settled, mut scanned, mut runs) = (0usize, 0usize, 0usize);
        for s in (0..n as u32).step_by(7) {
            let mut dist = std::collections::HashMap::new();
            let mut heap = BinaryHeap::new();
            dist.insert(s, 0.0f64);
            heap.push(Reverse((0u64, s)));
            while let Some(Reverse((k, v))) = heap.pop() {
                let d = f64::from_bits(k);
                if d > dist[&v] {
                    continue;
                }
                settled += 1;
                for a in &h.arcs[h.up(v)] {
                    scanned += 1;
                    let nd = d + a.cost;
                    if dist.get(&a.head).is_none_or(|x| nd < *x) {
                        dist.insert(a.head, nd);
                        heap.push(Reverse((nd.to_bits(), a.head)));
                    }
                }
            }
            runs += 1;
        }
        (settled as f64 / runs as f64, scanned as f64 / runs as f64)
    }

    #[test]
    #[ignore = "prints contraction statistics for tuning"]
    fn contraction_statistics() {
        let nets = [
            (
                "willow-full",
                crate::fixtures::shared_map_nrg("willow-full"),
            ),
            ("demo-300", Some(crate::query::demo::building(300))),
        ];
        for (name, nrg) in nets {
            let Some(nrg) = nrg else { continue };
            let nav = NavMesh::new(Arc::new(nrg));
            for profile in [Profile::exact(), Profile::default()] {
                let level = nav.level(&profile);
                for w in [
                    [1, 1, 1],
                    [2, 1, 1],
                    [1, 1, 0],
                    [2, 2, 1],
                    [1, 1, 2],
                    [1, 0, 1],
                ] {
                    let t = std::time::Instant::now();
                    let Some(h) = Hierarchy::with_weights(&level.mesh, &level.layer, w) else {
                        continue;
                    };
                    let took = t.elapsed();
                    let (settled, scanned) = search_space(&h);
                    eprintln!(
                        "{name} r={} w={w:?}: {} nodes, {} arcs, {took:?}; up search {settled:.0} nodes {scanned:.0} arcs",
                        profile.clearance_m,
                        h.first.len() - 1,
                        h.arcs.len()
                    );
                }
            }
        }
    }
}
