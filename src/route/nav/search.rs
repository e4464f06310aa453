//! One walked path between two end points: A* over the openings with the
//! precomputed in-space lengths, then the channel of triangles it implies,
//! straightened by the funnel.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use super::dead_ends::DeadEnds;
use super::funnel::{dist, polyline_length};
use super::layer::{Layer, SAMPLES, Tree, walk};
use super::mesh::{Mesh, NONE};
use super::visibility::Reach;
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
    /// In-space walked length to each crossing point of each opening of
    /// its space (`Openings::of_space` order, [`SAMPLES`] an opening).
    pub to_crossings: Vec<f64>,
    /// How the channel to a crossing is found.
    kind: EndKind,
}

#[derive(Debug, Clone)]
enum EndKind {
    /// The anchor of its space: the precomputed table has it.
    Anchor,
    /// Any other point: its own tree and, in a space with holes, its
    /// visibility walks where they are shorter.
    Point(Tree, Option<(Reach, Vec<Option<u32>>)>),
}

impl End {
    /// The anchor of space `s`.
    pub fn anchor(mesh: &Mesh, layer: &Layer, s: u32) -> Option<End> {
        let table = layer.table(mesh, s);
        let a = table.anchor();
        let (tri, at) = *table.sources.get(a)?;
        let to_crossings = (0..a).map(|j| table.cost(a, j)).collect();
        Some(End {
            space: s,
            at,
            tri,
            to_crossings,
            kind: EndKind::Anchor,
        })
    }

    /// The point `at` in triangle `tri`.
    pub fn point(mesh: &Mesh, layer: &Layer, at: Point, tri: u32) -> End {
        let space = mesh.tris[tri as usize].space;
        let r = layer.clearance_m;
        let tree = Tree::grow(mesh, &layer.local, space, tri, at, r);
        let table = layer.table(mesh, space);
        let openings = &mesh.openings.of_space[space as usize];
        let mut to_crossings = vec![f64::INFINITY; openings.len() * SAMPLES];
        for (j, o) in openings.iter().enumerate() {
            if !layer.open[*o as usize] {
                continue;
            }
            for k in 0..SAMPLES {
                let (tri, p) = table.sources[j * SAMPLES + k];
                let Some(mut c) = tree.walk(mesh, &layer.local, tri) else {
                    continue;
                };
                c.reverse();
                to_crossings[j * SAMPLES + k] = polyline_length(&walk(mesh, at, p, &c, r));
            }
        }
        let exact = table.exact.as_ref().map(|x| {
            let n = to_crossings.len();
            x.walks_from(mesh, &table.sources[..n], (tri, at), &mut to_crossings, r)
        });
        End {
            space,
            at,
            tri,
            to_crossings,
            kind: EndKind::Point(tree, exact),
        }
    }

    /// Appends the triangles from this end to source `j` (an opening
    /// crossing) of its space (`outbound`) or from there to this end.
    fn channel_into(
        &self,
        mesh: &Mesh,
        layer: &Layer,
        j: usize,
        outbound: bool,
        out: &mut Vec<u32>,
    ) -> Option<()> {
        let table = layer.table(mesh, self.space);
        match &self.kind {
            EndKind::Anchor => {
                let a = table.anchor();
                let (i, j) = if outbound { (a, j) } else { (j, a) };
                table.channel_into(mesh, &layer.local, i, j, out)
            }
            EndKind::Point(tree, exact) => {
                let target = *table.sources.get(j)?;
                if let (Some(x), Some((reach, via))) = (&table.exact, exact)
                    && let Some(Some(last)) = via.get(j)
                {
                    return x
                        .vis
                        .channel_into(mesh, reach, *last, target, outbound, out);
                }
                tree.walk_into(mesh, &layer.local, target.0, outbound, out)
            }
        }
    }

    /// Triangles from this end to `other` inside their common space.
    fn direct(&self, mesh: &Mesh, layer: &Layer, other: &End) -> Option<Vec<u32>> {
        let tree = match (&self.kind, &other.kind) {
            (EndKind::Point(tree, _), _) => {
                tree.walk(mesh, &layer.local, other.tri).map(|mut c| {
                    c.reverse();
                    c
                })
            }
            (_, EndKind::Point(tree, _)) => tree.walk(mesh, &layer.local, self.tri),
            (EndKind::Anchor, EndKind::Anchor) => return Some(vec![self.tri]),
        };
        match &layer.table(mesh, self.space).exact {
            Some(x) => x.better(
                mesh,
                (self.tri, self.at),
                (other.tri, other.at),
                tree,
                layer.clearance_m,
            ),
            None => tree,
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
    /// The gate edges crossed, in order (one fewer than `spaces`).
    pub gates: Vec<u32>,
}

/// The shortest walk from `from` to `to` not entering spaces marked in
/// `banned` (the ends' own spaces are allowed). `None` when there is none
/// or the budget ran out (the caller checks the budget). With nothing
/// banned the level's contraction hierarchy answers; else (or when the
/// level has none) A* over the openings.
pub(crate) fn shortest_walk(
    mesh: &Mesh,
    layer: &Layer,
    from: &End,
    to: &End,
    banned: &[bool],
    budget: &Budget,
) -> Option<Walk> {
    let direct = Direct::new(mesh, layer, from, to);
    if !banned.contains(&true)
        && let Some(hierarchy) = layer.hierarchy(mesh)
    {
        let (seeds_from, seeds_to) = (seeds(mesh, from), seeds(mesh, to));
        let found = hierarchy.shortest(&seeds_from, &seeds_to, direct.length_m, budget);
        if budget.is_expired() || (found.is_none() && !direct.length_m.is_finite()) {
            return None;
        }
        let chain = found.map(|(_, chain)| chain).unwrap_or_default();
        return assemble(mesh, layer, from, to, &chain, &direct);
    }
    search_openings(mesh, layer, from, to, banned, budget, &direct)
}

/// The walk between two ends inside the one space they share, found once
/// per search: its triangles and walked length (none and infinite for ends
/// in different spaces).
pub(crate) struct Direct {
    length_m: f64,
    channel: Option<Vec<u32>>,
}

impl Direct {
    fn new(mesh: &Mesh, layer: &Layer, from: &End, to: &End) -> Direct {
        let channel = (from.space == to.space)
            .then(|| from.direct(mesh, layer, to))
            .flatten();
        let length_m = channel.as_deref().map_or(f64::INFINITY, |c| {
            polyline_length(&walk(mesh, from.at, to.at, c, layer.clearance_m))
        });
        Direct { length_m, channel }
    }
}

/// [`shortest_walk`] by A* over the openings, beating `direct` (the
/// walk inside one space, when the ends share it).
pub(crate) fn search_openings(
    mesh: &Mesh,
    layer: &Layer,
    from: &End,
    to: &End,
    banned: &[bool],
    budget: &Budget,
    direct: &Direct,
) -> Option<Walk> {
    // Nodes are opening crossings: opening o, sample k is node
    // o * SAMPLES + k. A search state is a node and the side of its
    // opening the walk goes on into (state node * 2 + side): the walk
    // never steps back into the space it came from, so a crossing reached
    // first from one side must still be free to carry a walk that comes to
    // it later from the other (a space whose parts no walk can join at the
    // clearance asked is left by one opening and entered again by another).
    let openings = &mesh.openings;
    let nodes = openings.list.len() * SAMPLES;
    let states = 2 * nodes;
    let mut cost = vec![f64::INFINITY; states];
    // Predecessor of a state: the previous state (NONE: the start) and the
    // space walked through.
    let mut pred = vec![(NONE, NONE); states];
    let mut done = vec![false; states];
    let mut heap: BinaryHeap<Reverse<(u64, u32)>> = BinaryHeap::new();
    let point = |st: u32| {
        let n = st as usize / 2;
        layer.samples[n / SAMPLES][n % SAMPLES].1
    };
    let h = |st: u32| dist(point(st), to.at);
    // The state crossing node `n` of opening `o` into the side that is not
    // `from` (None when both sides are `from`).
    let onward = |o: usize, n: u32, from: u32| {
        let sides = openings.list[o].sides;
        (0..2).find(|&i| sides[i] != from).map(|i| n * 2 + i as u32)
    };
    let mut best = direct.length_m;
    // The goal's predecessor state (NONE: direct, inside one space).
    let mut best_pred = NONE;
    let scope = Scope::new(mesh, &layer.dead_ends, &[from.space, to.space]);
    let from_openings = &openings.of_space[from.space as usize];
    scope.for_each_slot(mesh, from.space, |j| {
        let g = from_openings[j];
        for k in 0..SAMPLES {
            let c = from.to_crossings[j * SAMPLES + k];
            let n = g * SAMPLES as u32 + k as u32;
            let Some(st) = onward(g as usize, n, from.space) else {
                continue;
            };
            if c < cost[st as usize] {
                cost[st as usize] = c;
                pred[st as usize] = (NONE, from.space);
                heap.push(Reverse(((c + h(st)).to_bits(), st)));
            }
        }
    });
    while let Some(Reverse((key, st))) = heap.pop() {
        if budget.check() {
            return None;
        }
        let f = f64::from_bits(key);
        if f >= best {
            break;
        }
        // The heuristic is consistent (every in-space length is at least
        // the straight line), so a state's first pop is final.
        if std::mem::replace(&mut done[st as usize], true) {
            continue;
        }
        let d = cost[st as usize];
        let (n, i) = (st as usize / 2, st as usize % 2);
        let (o, k) = (n / SAMPLES, n % SAMPLES);
        let opening = &openings.list[o];
        let t = opening.sides[i];
        if (banned[t as usize] && t != to.space) || !scope.enters(t) {
            continue;
        }
        let list = &openings.of_space[t as usize];
        let table = layer.table(mesh, t);
        let src = opening.slots[i] as usize * SAMPLES + k;
        if t == to.space {
            let goal = d + to.to_crossings[src];
            if goal < best {
                best = goal;
                best_pred = st;
            }
        }
        scope.for_each_slot(mesh, t, |jh| {
            let hgate = list[jh];
            for k2 in 0..SAMPLES {
                let m = hgate * SAMPLES as u32 + k2 as u32;
                let Some(next) = onward(hgate as usize, m, t) else {
                    continue;
                };
                let nd = d + table.cost(src, jh * SAMPLES + k2);
                if nd < cost[next as usize] {
                    let f = nd + h(next);
                    if f >= best {
                        continue;
                    }
                    cost[next as usize] = nd;
                    pred[next as usize] = (st, t);
                    heap.push(Reverse((f.to_bits(), next)));
                }
            }
        });
    }
    if !best.is_finite() {
        return None;
    }
    // States from the goal back to the start.
    let mut chain = Vec::new();
    let mut st = best_pred;
    while st != NONE {
        chain.push(st);
        st = pred[st as usize].0;
        if chain.len() > states {
            return None;
        }
    }
    chain.reverse();
    let chain: Vec<(u32, u32)> = chain
        .iter()
        .map(|st| (st / 2, pred[*st as usize].1))
        .collect();
    assemble(mesh, layer, from, to, &chain, direct)
}

/// The crossings of an end's space with the walked length to each
/// (unreachable ones left out), as hierarchy seeds.
fn seeds(mesh: &Mesh, end: &End) -> Vec<(u32, f64)> {
    let openings = &mesh.openings.of_space[end.space as usize];
    let mut out = Vec::with_capacity(openings.len() * SAMPLES);
    for (j, o) in openings.iter().enumerate() {
        for k in 0..SAMPLES {
            let c = end.to_crossings[j * SAMPLES + k];
            if c.is_finite() {
                out.push((o * SAMPLES as u32 + k as u32, c));
            }
        }
    }
    out
}

/// The triangles of the whole walk through `chain` (crossing nodes, each
/// with the space walked through to reach it from the one before; the
/// first's is ignored), then the funnel.
fn assemble(
    mesh: &Mesh,
    layer: &Layer,
    from: &End,
    to: &End,
    chain: &[(u32, u32)],
    direct: &Direct,
) -> Option<Walk> {
    // The source index of node `n` in space `s`'s table.
    let index_in = |s: u32, n: u32| {
        let (o, k) = (n / SAMPLES as u32, n as usize % SAMPLES);
        mesh.openings.slot(o, s).map(|j| j * SAMPLES + k)
    };
    let mut tris: Vec<u32> = Vec::new();
    if chain.is_empty() {
        tris = direct.channel.clone()?;
    } else {
        tris.reserve(8 * chain.len() + 16);
        let first = chain[0].0;
        from.channel_into(mesh, layer, index_in(from.space, first)?, true, &mut tris)?;
        for w in chain.windows(2) {
            let (g, (h, t)) = (w[0].0, w[1]);
            let table = layer.table(mesh, t);
            let (i, j) = (index_in(t, g)?, index_in(t, h)?);
            table.channel_into(mesh, &layer.local, i, j, &mut tris)?;
        }
        let last = chain.last()?.0;
        to.channel_into(mesh, layer, index_in(to.space, last)?, false, &mut tris)?;
    }
    tris.dedup();
    let (spaces, gates) = crossed(layer, from, to, chain);
    let points = walk(mesh, from.at, to.at, &tris, layer.clearance_m);
    let length_m = polyline_length(&points);
    Some(Walk {
        points,
        length_m,
        spaces,
        gates,
    })
}

/// The spaces a walk through `chain` enters (start and goal included) and
/// the gate edges it crosses between them. A node walked to and from
/// through the same space is touched, not crossed (the hierarchy may route
/// along a doorway's edge without going through): it adds neither.
fn crossed(layer: &Layer, from: &End, to: &End, chain: &[(u32, u32)]) -> (Vec<u32>, Vec<u32>) {
    let mut spaces = Vec::with_capacity(chain.len() + 1);
    let mut gates = Vec::with_capacity(chain.len());
    spaces.push(from.space);
    for (i, (n, _)) in chain.iter().enumerate() {
        let after = chain.get(i + 1).map_or(to.space, |c| c.1);
        if spaces.last() != Some(&after) {
            gates.push(layer.samples[*n as usize / SAMPLES][*n as usize % SAMPLES].0);
            spaces.push(after);
        }
    }
    (spaces, gates)
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
    let openings = &mesh.openings;
    let nodes = openings.list.len() * SAMPLES;
    let mut cost = vec![f64::INFINITY; nodes];
    let mut heap: BinaryHeap<Reverse<(u64, u32)>> = BinaryHeap::new();
    for (j, g) in openings.of_space[from.space as usize].iter().enumerate() {
        for k in 0..SAMPLES {
            let c = from.to_crossings[j * SAMPLES + k];
            let n = *g as usize * SAMPLES + k;
            if c <= bound_m && c < cost[n] {
                cost[n] = c;
                heap.push(Reverse((c.to_bits(), n as u32)));
            }
        }
    }
    let mut out = vec![f64::INFINITY; mesh.space_ids.len()];
    let start_table = layer.table(mesh, from.space);
    out[from.space as usize] = match from.kind {
        EndKind::Anchor => 0.0,
        EndKind::Point(..) => {
            let anchor = End::anchor(mesh, layer, from.space);
            anchor
                .and_then(|a| from.direct(mesh, layer, &a))
                .map_or(f64::INFINITY, |c| {
                    let anchor = start_table.sources[start_table.anchor()].1;
                    polyline_length(&walk(mesh, from.at, anchor, &c, layer.clearance_m))
                })
        }
    };
    while let Some(Reverse((key, n))) = heap.pop() {
        if budget.check() {
            return None;
        }
        let d = f64::from_bits(key);
        if d > cost[n as usize] {
            continue;
        }
        let (o, k) = (n as usize / SAMPLES, n as usize % SAMPLES);
        let opening = &openings.list[o];
        for (i, t) in opening.sides.into_iter().enumerate() {
            if banned[t as usize] {
                continue;
            }
            let list = &openings.of_space[t as usize];
            let table = layer.table(mesh, t);
            let src = opening.slots[i] as usize * SAMPLES + k;
            let to_anchor = d + table.cost(src, table.anchor());
            if to_anchor <= bound_m && to_anchor < out[t as usize] {
                out[t as usize] = to_anchor;
            }
            for (jh, h) in list.iter().enumerate() {
                for k2 in 0..SAMPLES {
                    let nd = d + table.cost(src, jh * SAMPLES + k2);
                    let m = *h as usize * SAMPLES + k2;
                    if nd <= bound_m && nd < cost[m] {
                        cost[m] = nd;
                        heap.push(Reverse((nd.to_bits(), m as u32)));
                    }
                }
            }
        }
    }
    Some(out)
}

/// The part of the opening graph one search may use: the core, and the dead
/// ends on the way out from its end points' spaces.
struct Scope<'a> {
    dead_ends: &'a DeadEnds,
    /// Dead-end spaces the search may enter.
    open: Vec<u32>,
    /// `(core space, slot)` of the openings from the core into `open` spaces.
    doors_in: Vec<(u32, u32)>,
}

impl<'a> Scope<'a> {
    /// The scope of a search between points in spaces `ends`.
    fn new(mesh: &Mesh, dead_ends: &'a DeadEnds, ends: &[u32]) -> Scope<'a> {
        let mut open: Vec<u32> = ends.iter().flat_map(|s| dead_ends.way_out(*s)).collect();
        open.sort_unstable();
        open.dedup();
        let mut doors_in = Vec::new();
        for c in &open {
            let p = dead_ends.parent[*c as usize];
            if p == NONE || dead_ends.dead[p as usize] {
                continue;
            }
            let openings = &mesh.openings;
            for o in &openings.of_space[*c as usize] {
                if openings.other_side(*o, *c) == p
                    && let Some(j) = openings.slot(*o, p)
                {
                    doors_in.push((p, j as u32));
                }
            }
        }
        Scope {
            dead_ends,
            open,
            doors_in,
        }
    }

    /// Whether the search may enter space `s`.
    fn enters(&self, s: u32) -> bool {
        !self.dead_ends.dead[s as usize] || self.open.contains(&s)
    }

    /// Calls `f` with the slot of every opening of `s` leading somewhere
    /// the search may go.
    fn for_each_slot(&self, mesh: &Mesh, s: u32, mut f: impl FnMut(usize)) {
        if self.dead_ends.dead[s as usize] {
            let openings = &mesh.openings;
            for (j, o) in openings.of_space[s as usize].iter().enumerate() {
                if self.enters(openings.other_side(*o, s)) {
                    f(j);
                }
            }
            return;
        }
        for j in &self.dead_ends.core_slots[s as usize] {
            f(*j as usize);
        }
        for (p, j) in &self.doors_in {
            if *p == s {
                f(*j as usize);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use super::*;
    use crate::query::demo;
    use crate::route::{Endpoint, NavMesh, Profile};

    /// The hierarchy finds walks as short as the A* over openings between
    /// every `stride`-th pair of spaces (and points): it is exact on the
    /// crossing graph, which the A* prunes (dead ends, no step back into
    /// the space just left), so now and then it finds a shorter one. Both
    /// choose by lengths through three crossing points a doorway; once
    /// straightened, the hierarchy's walk may come out a little longer,
    /// never by more than 1 %. On willow-full the A* once found no walk
    /// where the hierarchy did: a space whose two parts no walk joins at
    /// the clearance is left by one doorway and entered again by another,
    /// and the A* kept one state per crossing, so a crossing first reached
    /// from inside that space could not carry the walk back into it (its
    /// states are now a crossing and the side walked into).
    fn agree(nav: &NavMesh, profile: Profile, stride: usize) {
        let level = nav.level(&profile);
        let (mesh, layer) = (&level.mesh, &level.layer);
        assert!(layer.hierarchy(mesh).is_some());
        let none = vec![false; mesh.space_ids.len()];
        let budget = Budget::unlimited();
        let mut ends: Vec<Endpoint> = mesh
            .space_ids
            .iter()
            .map(|id| Endpoint::Space(*id))
            .collect();
        ends.push(Endpoint::Point([3.3, 6.1]));
        ends.push(Endpoint::Point([17.9, 5.2]));
        let (mut compared, mut shorter, mut longer) = (0, 0, Vec::new());
        for (i, a) in ends.iter().enumerate() {
            for (j, b) in ends.iter().enumerate() {
                if !(i * ends.len() + j).is_multiple_of(stride) {
                    continue;
                }
                let (Ok(from), Ok(to)) = (nav.end(&level, a), nav.end(&level, b)) else {
                    continue;
                };
                let fast = shortest_walk(mesh, layer, &from, &to, &none, &budget);
                let direct = Direct::new(mesh, layer, &from, &to);
                let slow = search_openings(mesh, layer, &from, &to, &none, &budget, &direct);
                match (fast, slow) {
                    (Some(f), Some(s)) => {
                        assert!(
                            f.spaces.windows(2).all(|w| w[0] != w[1]),
                            "{a:?} -> {b:?}: a space entered twice in a row: {:?}",
                            f.spaces
                        );
                        assert_eq!(f.spaces.len(), f.gates.len() + 1);
                        let d = f.length_m - s.length_m;
                        if d > 0.01 * s.length_m {
                            longer.push((*a, *b, f.length_m, s.length_m));
                        } else if d < -1e-6 {
                            shorter += 1;
                        }
                    }
                    (None, None) => {}
                    (f, s) => panic!("{a:?} -> {b:?}: hierarchy {f:?}, A* {s:?}"),
                }
                compared += 1;
            }
        }
        eprintln!(
            "clearance {}: {compared} pairs, hierarchy shorter on {shorter}, over 1 % longer on {}: {:?}",
            profile.clearance_m,
            longer.len(),
            &longer[..longer.len().min(5)]
        );
        assert!(compared > 100, "{compared} pairs");
        assert!(longer.is_empty());
    }

    #[test]
    fn hierarchy_and_astar_agree_on_willow_full() {
        let Some(nrg) = crate::fixtures::shared_map_nrg("willow-full") else {
            eprintln!("notice: willow-full not found (NRGDB_SHARED); skipped");
            return;
        };
        let nav = NavMesh::new(Arc::new(nrg));
        agree(&nav, Profile::default(), 7);
        agree(&nav, Profile::exact(), 7);
    }

    #[test]
    fn hierarchy_and_astar_agree_on_the_demo_building() {
        let nav = NavMesh::new(Arc::new(demo::building(7)));
        agree(&nav, Profile::default(), 1);
        agree(&nav, Profile::exact(), 1);
        agree(
            &nav,
            Profile {
                clearance_m: 0.5,
                ..Profile::default()
            },
            1,
        );
    }
}
