//! Openings: the gates between two spaces joined into the runs a walker
//! sees as one doorway. A doorway whose outline follows pixel edges is a
//! staircase of dozens of short triangle edges; searching over each edge
//! would scan them all at every step, so the search works on openings
//! instead: maximal chains of gate edges between the same two spaces,
//! broken where a wall touches the chain.

use super::funnel::dist;
use super::gate::{GateView, NONE};
use crate::model::Point;

/// One opening between two spaces.
#[derive(Debug, Clone)]
pub(crate) struct Opening {
    /// Its gate edges in order along the chain.
    pub gates: Vec<u32>,
    /// The chain's vertices (one more than `gates`).
    pub vertices: Vec<u32>,
    /// The two spaces it joins (dense indices).
    pub sides: [u32; 2],
    /// This opening's index in `Openings::of_space` of each side's space.
    pub slots: [u32; 2],
}

/// Every opening of a mesh and each space's openings.
#[derive(Debug, Default)]
pub(crate) struct Openings {
    /// All openings.
    pub list: Vec<Opening>,
    /// The openings of each space (dense index).
    pub of_space: Vec<Vec<u32>>,
}

impl Openings {
    /// Joins the gates of `mesh` into openings.
    pub fn new(mesh: &GateView<'_>) -> Openings {
        let pair = |g: u32| {
            let [(_, a), (_, b)] = mesh.gates[g as usize].sides;
            (a.min(b), a.max(b))
        };
        let mut order: Vec<u32> = (0..mesh.gates.len() as u32).collect();
        order.sort_unstable_by_key(|g| (pair(*g), *g));
        let mut list = Vec::new();
        for group in order.chunk_by(|g, h| pair(*g) == pair(*h)) {
            let (a, b) = pair(group[0]);
            for (gates, vertices) in chains(mesh, group) {
                list.push(Opening {
                    gates,
                    vertices,
                    sides: [a, b],
                    slots: [0; 2],
                });
            }
        }
        let mut of_space = vec![Vec::new(); mesh.spaces];
        for (o, opening) in list.iter_mut().enumerate() {
            for side in 0..2 {
                let s = opening.sides[side] as usize;
                opening.slots[side] = of_space[s].len() as u32;
                of_space[s].push(o as u32);
            }
        }
        Openings { list, of_space }
    }

    /// The index of opening `o` in `of_space[s]`, when `s` is one of its
    /// sides.
    pub fn slot(&self, o: u32, s: u32) -> Option<usize> {
        let opening = self.list.get(o as usize)?;
        (0..2)
            .find(|i| opening.sides[*i] == s)
            .map(|i| opening.slots[i] as usize)
    }

    /// The space across opening `o` from `s`.
    pub fn other_side(&self, o: u32, s: u32) -> u32 {
        let [a, b] = self.list[o as usize].sides;
        if a == s { b } else { a }
    }
}

impl Opening {
    /// Its length along the chain.
    pub fn length(&self, mesh: &GateView<'_>) -> f64 {
        self.vertices
            .windows(2)
            .map(|w| dist(mesh.point(w[0]), mesh.point(w[1])))
            .sum()
    }

    /// Whether a disc of radius `r` passes: the chain is at least `r` long
    /// for each end that touches a wall.
    pub fn open(&self, mesh: &GateView<'_>, r: f64) -> bool {
        if r <= 0.0 {
            return true;
        }
        self.length(mesh) >= self.walled_ends(mesh) * r
    }

    fn walled_ends(&self, mesh: &GateView<'_>) -> f64 {
        let end = |v: Option<&u32>| v.is_some_and(|v| mesh.obstacle[*v as usize]);
        f64::from(u8::from(end(self.vertices.first())) + u8::from(end(self.vertices.last())))
    }

    /// The points at fractions `at` of the part of the chain at least `r`
    /// from a walled end, each with the gate edge it lies on.
    pub fn crossings<const N: usize>(
        &self,
        mesh: &GateView<'_>,
        at: [f64; N],
        r: f64,
    ) -> [(u32, Point); N] {
        let points: Vec<Point> = self.vertices.iter().map(|v| mesh.point(*v)).collect();
        let mut cumulative = vec![0.0];
        for w in points.windows(2) {
            let last = cumulative.last().copied().unwrap_or(0.0);
            cumulative.push(last + dist(w[0], w[1]));
        }
        let len = cumulative.last().copied().unwrap_or(0.0);
        let inset = |v: Option<&u32>| {
            if v.is_some_and(|v| mesh.obstacle[*v as usize]) {
                r
            } else {
                0.0
            }
        };
        let (lo, hi) = (
            inset(self.vertices.first()),
            len - inset(self.vertices.last()),
        );
        let (lo, hi) = if lo <= hi {
            (lo, hi)
        } else {
            (len / 2.0, len / 2.0)
        };
        at.map(|f| {
            let s = lo + f * (hi - lo);
            let i = cumulative
                .windows(2)
                .position(|w| s <= w[1])
                .unwrap_or(self.gates.len().saturating_sub(1));
            let (a, b) = (points[i], points[i + 1]);
            let seg = cumulative[i + 1] - cumulative[i];
            let t = if seg > 0.0 {
                ((s - cumulative[i]) / seg).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (
                self.gates[i],
                [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])],
            )
        })
    }
}

/// The chains of `gates` (all between the same two spaces, sorted): edges joined
/// at vertices that no wall touches and that no third edge of the set
/// meets. Each chain as its gates and its vertices in order.
fn chains(mesh: &GateView<'_>, gates: &[u32]) -> Vec<(Vec<u32>, Vec<u32>)> {
    // (vertex, gate) for both ends of every gate, sorted by vertex: the
    // gates meeting at a vertex are one run.
    let mut ends: Vec<(u32, u32)> = gates
        .iter()
        .flat_map(|g| mesh.gates[*g as usize].ends.map(|v| (v, *g)))
        .collect();
    ends.sort_unstable();
    let at_vertex = |v: u32| {
        let lo = ends.partition_point(|e| e.0 < v);
        let hi = ends.partition_point(|e| e.0 <= v);
        &ends[lo..hi]
    };
    let joins = |v: u32| !mesh.obstacle[v as usize] && at_vertex(v).len() == 2;
    // `gates` is sorted (see `Openings::new`).
    let index = |g: u32| gates.binary_search(&g).ok();
    let mut used = vec![false; gates.len()];
    let mut out = Vec::new();
    // Open chains first (from an end that does not join), then loops.
    let starts: Vec<(u32, u32)> = ends
        .iter()
        .filter(|(v, _)| !joins(*v))
        .map(|(v, g)| (*g, *v))
        .chain(gates.iter().map(|g| (*g, mesh.gates[*g as usize].ends[0])))
        .collect();
    for (first, start) in starts {
        let Some(i) = index(first).filter(|i| !used[*i]) else {
            continue;
        };
        used[i] = true;
        let mut chain = vec![first];
        let mut vertices = vec![start];
        let mut g = first;
        let mut v = start;
        loop {
            let [p, q] = mesh.gates[g as usize].ends;
            v = if p == v { q } else { p };
            vertices.push(v);
            if !joins(v) {
                break;
            }
            let next = at_vertex(v)
                .iter()
                .map(|e| e.1)
                .find(|h| *h != g)
                .unwrap_or(NONE);
            let Some(j) = index(next).filter(|j| !used[*j]) else {
                break;
            };
            used[j] = true;
            chain.push(next);
            g = next;
        }
        out.push((chain, vertices));
    }
    out
}
