//! What makes a route query fast, computed once per revision: inside every
//! space, a shortest-path tree over its triangles from each crossing point
//! ([`SAMPLES`] along each of its openings) and from its anchor, and the
//! walked length (funnel) between every pair of them; in a space with
//! holes, also the walks through the visibility graph of its corners where
//! they are shorter ([`Exact`]). A query then searches only the small graph
//! of opening crossings.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::sync::OnceLock;

use super::clearance::{channel_open, clear_walk, edge_open, traversal_open};
use super::dead_ends::DeadEnds;
use super::funnel::{dist, funnel, polyline_length};
use super::hierarchy::Hierarchy;
use super::mesh::{Across, Mesh, NONE};
use super::visibility::{Reach, Sight, Spot, Visibility};
use crate::model::{Nrg, Point};

/// A shortest-path tree inside one space, from one source.
#[derive(Debug, Clone)]
pub(crate) struct Tree {
    /// Predecessor of each triangle of the space (by local index), NONE at
    /// the root and for triangles not reached.
    pred: Vec<u32>,
    /// Approximate distance (through edge midpoints) of each triangle.
    cost: Vec<f64>,
}

/// Crossing points per opening: both ends of its free part (where a walk
/// that turns round a door jamb crosses, at the clearance kept) and the
/// middle. Samples inset from the ends made every turn at a doorway a few
/// centimetres long, enough to pick a door sequence 1.6 % longer than
/// another (a CI failure of `route_props::via_and_avoid_are_honoured`).
pub(crate) const SAMPLES: usize = 3;

/// Spaces with more openings than this get approximate in-space lengths
/// (tree distances) instead of one funnel per pair of crossing points.
const EXACT_TABLE_OPENINGS: usize = 200;

/// Most segment walks the sources of a space with holes may take to find
/// the corners they see (sources × corners); past it the space keeps the
/// trees' lengths (e.g. 40 openings and 500 corners).
const MAX_SIGHT_WALKS: usize = 60_000;

/// Where along an opening its crossing points lie (fractions of its free
/// part: its length less the clearance at each end that is a wall).
const SAMPLE_AT: [f64; SAMPLES] = [0.0, 0.5, 1.0];

/// The sources of one space: [`SAMPLES`] crossing points of each of its
/// openings in `Openings::of_space` order, then its anchor.
#[derive(Debug, Clone, Default)]
pub(crate) struct SpaceTable {
    /// `(triangle, point)` of each source.
    pub sources: Vec<(u32, Point)>,
    trees: Vec<Tree>,
    /// Walked length between sources `i` and `j` at `i * n + j`
    /// (infinite when not connected inside the space).
    costs: Vec<f64>,
    /// Exact walks when the space has holes.
    pub exact: Option<Box<Exact>>,
}

/// The in-space walks of a space with holes that the trees get wrong: the
/// visibility graph of its corners, and which pairs of sources it walks.
#[derive(Debug, Clone)]
pub(crate) struct Exact {
    /// The space's corners and which see each other.
    pub vis: Visibility,
    /// The corners each source sees.
    sights: Vec<Sight>,
    /// Shortest lengths from each source to every corner.
    reaches: Vec<Reach>,
    /// For sources `i < j` at `i * n + j`: the last corner of the kept
    /// visibility walk (NONE: straight), `None` when the tree's is kept.
    via: Vec<Option<u32>>,
}

impl Exact {
    /// From `start` (a point of the space) to each source: the walk
    /// through the visibility graph where it is shorter than `lengths[j]`
    /// (which it then lowers), as the reach and per-source last corner.
    pub fn walks_from(
        &self,
        mesh: &Mesh,
        sources: &[Spot],
        start: Spot,
        lengths: &mut [f64],
        r: f64,
    ) -> (Reach, Vec<Option<u32>>) {
        let reach = self.vis.reach(start, &self.vis.sight(mesh, start));
        let mut via = vec![None; sources.len()];
        let mut channel = Vec::new();
        let each = sources.iter().zip(lengths.iter_mut()).zip(&self.sights);
        for (j, ((to, than), seen)) in each.enumerate() {
            if let Some((walked, last)) =
                shorter_walk(mesh, &self.vis, &reach, *to, seen, *than, r, &mut channel)
            {
                *than = walked;
                via[j] = Some(last);
            }
        }
        (reach, via)
    }

    /// The shorter of `tree` (a channel from `from` to `to`, if any) and
    /// the visibility walk between the two points.
    pub fn better(
        &self,
        mesh: &Mesh,
        from: Spot,
        to: Spot,
        tree: Option<Vec<u32>>,
        r: f64,
    ) -> Option<Vec<u32>> {
        let tree_length = tree.as_deref().map_or(f64::INFINITY, |c| {
            polyline_length(&walk(mesh, from.1, to.1, c, r))
        });
        let reach = self.vis.reach(from, &self.vis.sight(mesh, from));
        let seen = self.vis.sight(mesh, to);
        let mut channel = Vec::new();
        match shorter_walk(
            mesh,
            &self.vis,
            &reach,
            to,
            &seen,
            tree_length,
            r,
            &mut channel,
        ) {
            Some(_) => Some(channel),
            None => tree,
        }
    }
}

/// The visibility walk from the start of `reach` to `to` (which sees
/// `seen`) when, at clearance `r`, it is open and walks shorter than
/// `than`: its length and last corner, its triangles left in `channel`.
#[allow(clippy::too_many_arguments)]
fn shorter_walk(
    mesh: &Mesh,
    vis: &Visibility,
    reach: &Reach,
    to: Spot,
    seen: &Sight,
    than: f64,
    r: f64,
    channel: &mut Vec<u32>,
) -> Option<(f64, u32)> {
    let (length, last) = vis.length_to(mesh, reach, to, seen);
    // The walk with clearance is never shorter than without.
    if !length.is_finite() || length >= than {
        return None;
    }
    channel.clear();
    vis.channel_into(mesh, reach, last, to, true, channel)?;
    if !channel_open(mesh, channel, r) {
        return None;
    }
    let walked = polyline_length(&walk(mesh, reach.start().1, to.1, channel, r));
    (walked < than).then_some((walked, last))
}

impl SpaceTable {
    /// Walked length inside the space between sources `i` and `j`.
    pub fn cost(&self, i: usize, j: usize) -> f64 {
        let n = self.sources.len();
        self.costs.get(i * n + j).copied().unwrap_or(f64::INFINITY)
    }

    /// Index of the anchor source.
    pub fn anchor(&self) -> usize {
        self.sources.len().saturating_sub(1)
    }

    /// Appends the triangles from source `i` to source `j`, both included,
    /// to `out`.
    pub fn channel_into(
        &self,
        mesh: &Mesh,
        local: &[u32],
        i: usize,
        j: usize,
        out: &mut Vec<u32>,
    ) -> Option<()> {
        let n = self.sources.len();
        if let Some(x) = &self.exact
            && let Some(Some(last)) = x.via.get(i.min(j) * n + i.max(j))
        {
            let (a, b) = (i.min(j), i.max(j));
            let (reach, to) = (x.reaches.get(a)?, *self.sources.get(b)?);
            return x.vis.channel_into(mesh, reach, *last, to, i < j, out);
        }
        // The channel the table measured: from the lower source's tree
        // to the higher source (trees are not symmetric: the higher one's
        // tree may pass a hole on the other side).
        let (a, b) = (i.min(j), i.max(j));
        let target = self.sources.get(b)?.0;
        self.trees
            .get(a)?
            .walk_into(mesh, local, target, i == a, out)
    }
}

impl Tree {
    /// Dijkstra over the triangles of one space from `(root, at)`, moving
    /// through the midpoints of shared edges wide enough for clearance `r`.
    pub fn grow(mesh: &Mesh, local: &[u32], space: u32, root: u32, at: Point, r: f64) -> Tree {
        let n = mesh.space_tris[space as usize].len();
        let mut cost = vec![f64::INFINITY; n];
        let mut arrive = vec![[0.0f64; 2]; n];
        let mut pred = vec![NONE; n];
        // The edge each triangle was entered by (3: the root).
        let mut entry = vec![3u8; n];
        let first = local[root as usize] as usize;
        cost[first] = 0.0;
        arrive[first] = at;
        let mut heap = BinaryHeap::new();
        heap.push(Reverse((0u64, root)));
        while let Some(Reverse((key, t))) = heap.pop() {
            let lt = local[t as usize] as usize;
            if key > cost[lt].to_bits() {
                continue;
            }
            let tri = &mesh.tris[t as usize];
            for i in 0..3 {
                let Across::Inside(u) = tri.across[i] else {
                    continue;
                };
                if r > 0.0
                    && (!edge_open(mesh, tri.v[i], tri.v[(i + 1) % 3], r)
                        || !traversal_open(mesh, t, usize::from(entry[lt]), i, r))
                {
                    continue;
                }
                let (a, b) = (mesh.point(tri.v[i]), mesh.point(tri.v[(i + 1) % 3]));
                let mid = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
                let nd = cost[lt] + dist(arrive[lt], mid);
                let lu = local[u as usize] as usize;
                if nd < cost[lu] {
                    cost[lu] = nd;
                    arrive[lu] = mid;
                    pred[lu] = t;
                    // The edge of u shared with t.
                    entry[lu] = (0..3u8)
                        .find(|k| {
                            mesh.tris[u as usize].across[usize::from(*k)] == Across::Inside(t)
                        })
                        .unwrap_or(3);
                    heap.push(Reverse((nd.to_bits(), u)));
                }
            }
        }
        Tree { pred, cost }
    }

    /// A tree that reaches nothing (from a closed opening).
    pub fn unreached(n: usize) -> Tree {
        Tree {
            pred: vec![NONE; n],
            cost: vec![f64::INFINITY; n],
        }
    }

    /// The triangles from `target` back to the root, or `None` when the
    /// tree does not reach it.
    pub fn walk(&self, mesh: &Mesh, local: &[u32], target: u32) -> Option<Vec<u32>> {
        let mut out = Vec::new();
        self.walk_into(mesh, local, target, false, &mut out)?;
        Some(out)
    }

    /// Appends the triangles between the root and `target` to `out`, from
    /// the root when `from_root`, else from `target`; `None` when the tree
    /// does not reach it.
    pub fn walk_into(
        &self,
        mesh: &Mesh,
        local: &[u32],
        target: u32,
        from_root: bool,
        out: &mut Vec<u32>,
    ) -> Option<()> {
        let lt = *local.get(target as usize)? as usize;
        if !self.cost.get(lt)?.is_finite() {
            return None;
        }
        let start = out.len();
        out.push(target);
        let mut t = target;
        while self.pred[local[t as usize] as usize] != NONE {
            t = self.pred[local[t as usize] as usize];
            out.push(t);
            if out.len() - start > mesh.tris.len() {
                return None;
            }
        }
        if from_root {
            out[start..].reverse();
        }
        Some(())
    }
}

/// The portals of a channel of triangles, `(right, left)` in walking order.
pub(crate) fn portals(mesh: &Mesh, channel: &[u32]) -> Vec<(Point, Point)> {
    let mut out = Vec::with_capacity(channel.len());
    out.extend(channel.windows(2).filter_map(|w| mesh.portal(w[0], w[1])));
    out
}

/// The walked polyline from `from` to `to` through a channel, keeping
/// clearance `r` from obstacle corners.
pub(crate) fn walk(mesh: &Mesh, from: Point, to: Point, channel: &[u32], r: f64) -> Vec<Point> {
    if r <= 0.0 {
        return funnel(from, to, &portals(mesh, channel));
    }
    let mut ends: Vec<(u32, u32)> = Vec::with_capacity(channel.len());
    ends.extend(
        channel
            .windows(2)
            .filter_map(|w| mesh.portal_vertices(w[0], w[1])),
    );
    clear_walk(mesh, from, to, &ends, r)
}

/// Precomputed tables of every space.
#[derive(Debug)]
pub(crate) struct Layer {
    /// The clearance kept, metres.
    pub clearance_m: f64,
    /// The crossing points of each opening, each with the gate it lies on.
    pub samples: Vec<[(u32, Point); SAMPLES]>,
    /// Whether each opening is wide enough for it.
    pub open: Vec<bool>,

    /// Local index of each triangle within its space.
    pub local: Vec<u32>,
    /// The dead ends of the opening graph at this clearance.
    pub dead_ends: DeadEnds,
    /// The anchor of each space: its triangle and point.
    anchors: Vec<(u32, Point)>,
    /// One table per space (dense index), built when a route first needs
    /// it: a revision that is only listed, located or diffed never pays
    /// for them.
    tables: Vec<OnceLock<SpaceTable>>,
    /// The contracted crossing graph, built (with every table) when a
    /// route first needs it; `None` when the level is too dense for it.
    hierarchy: OnceLock<Option<Hierarchy>>,
}

impl Layer {
    /// Builds the tables of every space of `mesh`.
    pub fn new(mesh: &Mesh, nrg: &Nrg, clearance_m: f64) -> Layer {
        let mut local = vec![NONE; mesh.tris.len()];
        for tris in &mesh.space_tris {
            for (i, t) in tris.iter().enumerate() {
                local[*t as usize] = i as u32;
            }
        }
        let openings = &mesh.openings.list;
        let open: Vec<bool> = openings
            .iter()
            .map(|o| o.open(&mesh.gate_view(), clearance_m))
            .collect();
        let samples: Vec<[(u32, Point); SAMPLES]> = openings
            .iter()
            .map(|o| o.crossings(&mesh.gate_view(), SAMPLE_AT, clearance_m))
            .collect();
        let anchors = (0..mesh.space_ids.len() as u32)
            .map(|s| anchor(mesh, nrg, s))
            .collect();
        Layer {
            clearance_m,
            samples,
            dead_ends: DeadEnds::new(mesh, &open),
            open,
            local,
            anchors,
            tables: (0..mesh.space_ids.len()).map(|_| OnceLock::new()).collect(),
            hierarchy: OnceLock::new(),
        }
    }

    /// The contraction hierarchy of this level, built on first use.
    pub fn hierarchy(&self, mesh: &Mesh) -> Option<&Hierarchy> {
        self.hierarchy
            .get_or_init(|| Hierarchy::new(mesh, self))
            .as_ref()
    }

    /// The table of space `s`, built on first use.
    pub fn table(&self, mesh: &Mesh, s: u32) -> &SpaceTable {
        static EMPTY: SpaceTable = SpaceTable {
            sources: Vec::new(),
            trees: Vec::new(),
            costs: Vec::new(),
            exact: None,
        };
        let (Some(cell), Some(anchor)) =
            (self.tables.get(s as usize), self.anchors.get(s as usize))
        else {
            return &EMPTY;
        };
        cell.get_or_init(|| {
            table(
                mesh,
                &self.local,
                s,
                self.clearance_m,
                &self.open,
                &self.samples,
                *anchor,
            )
        })
    }
}

/// The anchor of space `s` on the mesh: the model's anchor when it lies in
/// the space, else the centroid of its first triangle.
fn anchor(mesh: &Mesh, nrg: &Nrg, s: u32) -> (u32, Point) {
    let tris = &mesh.space_tris[s as usize];
    let Some(first) = tris.first() else {
        return (NONE, [0.0, 0.0]);
    };
    nrg.space(mesh.space_ids[s as usize])
        .map(|sp| sp.anchor)
        .and_then(|p| mesh.locate(p, Some(s)).map(|t| (t, p)))
        .filter(|(t, _)| mesh.tris[*t as usize].space == s)
        .unwrap_or_else(|| (*first, mesh.centroid(*first)))
}

#[allow(clippy::too_many_arguments)]
fn table(
    mesh: &Mesh,
    local: &[u32],
    s: u32,
    r: f64,
    open: &[bool],
    samples: &[[(u32, Point); SAMPLES]],
    anchor: (u32, Point),
) -> SpaceTable {
    let tris = &mesh.space_tris[s as usize];
    if tris.is_empty() {
        return SpaceTable::default();
    }
    let openings = &mesh.openings.of_space[s as usize];
    // Each crossing point in the triangle on this space's side of its gate.
    let mut sources: Vec<(u32, Point)> = openings
        .iter()
        .flat_map(|o| {
            samples[*o as usize].map(|(g, p)| {
                let gate = &mesh.gates[g as usize];
                let side = if gate.sides[0].1 == s {
                    gate.sides[0].0
                } else {
                    gate.sides[1].0
                };
                (side, p)
            })
        })
        .collect();
    sources.push(anchor);
    let n = sources.len();
    let anchor = n - 1;
    // A closed opening is a source nothing reaches.
    let reached = |i: usize| i == anchor || open[openings[i / SAMPLES] as usize];
    let trees: Vec<Tree> = (0..n)
        .map(|i| {
            if reached(i) {
                Tree::grow(mesh, local, s, sources[i].0, sources[i].1, r)
            } else {
                Tree::unreached(tris.len())
            }
        })
        .collect();
    let mut costs = vec![f64::INFINITY; n * n];
    for i in 0..n {
        costs[i * n + i] = 0.0;
        for j in i + 1..n {
            if !reached(i) || !reached(j) {
                continue;
            }
            if openings.len() > EXACT_TABLE_OPENINGS {
                // A hall with hundreds of doors: n² funnels would take
                // minutes, so the search uses the tree's distance through
                // edge midpoints (never below the straight line); the route
                // it picks is still straightened exactly.
                let lt = local[sources[j].0 as usize] as usize;
                let through = trees[i].cost.get(lt).copied().unwrap_or(f64::INFINITY);
                let length = through.max(dist(sources[i].1, sources[j].1));
                costs[i * n + j] = length;
                costs[j * n + i] = length;
                continue;
            }
            let channel = trees[i].walk(mesh, local, sources[j].0).map(|mut c| {
                c.reverse();
                c
            });
            if let Some(c) = channel {
                let length = polyline_length(&walk(mesh, sources[i].1, sources[j].1, &c, r));
                costs[i * n + j] = length;
                costs[j * n + i] = length;
            }
        }
    }
    let exact = Visibility::new(mesh, s)
        .filter(|vis| n * vis.corner_count() <= MAX_SIGHT_WALKS)
        .map(|vis| Box::new(exact(mesh, vis, &sources, &mut costs, r, reached)));
    SpaceTable {
        sources,
        trees,
        costs,
        exact,
    }
}

/// The visibility walks between the sources of a space with holes, kept
/// (in `costs`) where shorter than the trees'.
fn exact(
    mesh: &Mesh,
    vis: Visibility,
    sources: &[Spot],
    costs: &mut [f64],
    r: f64,
    reached: impl Fn(usize) -> bool,
) -> Exact {
    let n = sources.len();
    let sights: Vec<Sight> = (0..n)
        .map(|i| {
            if reached(i) {
                vis.sight(mesh, sources[i])
            } else {
                Vec::new()
            }
        })
        .collect();
    let reaches: Vec<Reach> = (0..n).map(|i| vis.reach(sources[i], &sights[i])).collect();
    let mut via = vec![None; n * n];
    let mut channel = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            if !reached(i) || !reached(j) {
                continue;
            }
            let than = costs[i * n + j];
            let (to, seen) = (sources[j], &sights[j]);
            if let Some((walked, last)) =
                shorter_walk(mesh, &vis, &reaches[i], to, seen, than, r, &mut channel)
            {
                costs[i * n + j] = walked;
                costs[j * n + i] = walked;
                via[i * n + j] = Some(last);
            }
        }
    }
    Exact {
        vis,
        sights,
        reaches,
        via,
    }
}
