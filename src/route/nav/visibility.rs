//! Exact shortest paths inside one space with holes (furniture, a
//! courtyard, a pillar). Between two points of such a space there is more
//! than one channel of triangles, and the shortest-path tree over triangles
//! (through edge midpoints, see `layer`) can take the longer way round a
//! hole. Here a walk bends only at the space's reflex corners: Dijkstra over
//! the visibility graph of those corners (an edge wherever the straight
//! segment stays in the space and is tangent at its corner ends, Lozano-Pérez
//! & Wesley 1979), and each straight segment's triangles come from walking
//! it through the mesh with exact orientation tests (`robust`). At zero
//! clearance the result is the geodesic; with a clearance the layer keeps
//! whichever of this channel and the tree's walks shorter.
//!
//! Spaces without holes never get here: the triangles of a simply connected
//! space form a tree, so the channel between two triangles is unique.

use std::cmp::Reverse;
use std::collections::{BinaryHeap, HashMap};

use robust::{Coord, orient2d};

use super::funnel::dist;
use super::mesh::{Across, Mesh, NONE};
use crate::model::Point;

/// A point of the space with the triangle it lies in.
pub(crate) type Spot = (u32, Point);

/// The corners of one space with holes and which of them see each other.
#[derive(Debug, Clone)]
pub(crate) struct Visibility {
    space: u32,
    /// Reflex corners of the space's boundary (mesh vertices).
    corners: Vec<u32>,
    /// Their positions.
    points: Vec<Point>,
    /// The two boundary neighbours of each corner, when it has exactly two
    /// (the tangency test; a pinched corner has more and is never pruned).
    sides: Vec<Option<[Point; 2]>>,
    /// For each corner, the corners it sees, with the distance.
    edges: Vec<Vec<(u32, f64)>>,
    /// The triangles of the space around each of its vertices.
    fans: HashMap<u32, Vec<u32>>,
}

/// Shortest lengths from one point of the space to each corner.
#[derive(Debug, Clone)]
pub(crate) struct Reach {
    start: Spot,
    dist: Vec<f64>,
    /// The corner before each one on its shortest way (NONE: straight from
    /// the start).
    pred: Vec<u32>,
}

/// The corners seen from a point (and tangent there), with the distance.
pub(crate) type Sight = Vec<(u32, f64)>;

/// Largest corner count a space may have for exact paths: the graph costs
/// up to the square of it in segment walks (willow-full's largest, 154
/// corners, builds in 1.8 ms; 600 stays near a tenth of a second).
const MAX_CORNERS: usize = 600;

fn coord(p: Point) -> Coord<f64> {
    Coord { x: p[0], y: p[1] }
}

/// > 0 when `c` lies left of the line from `a` to `b` (exact sign).
fn orient(a: Point, b: Point, c: Point) -> f64 {
    orient2d(coord(a), coord(b), coord(c))
}

impl Reach {
    /// The point it was grown from.
    pub fn start(&self) -> Spot {
        self.start
    }
}

impl Visibility {
    /// The visibility graph of space `s`, or `None` when the space has no
    /// holes (its channels are unique) or too many corners.
    pub fn new(mesh: &Mesh, s: u32) -> Option<Visibility> {
        let tris = mesh.space_tris.get(s as usize)?;
        let mut fans: HashMap<u32, Vec<u32>> = HashMap::new();
        let mut angle: HashMap<u32, f64> = HashMap::new();
        let mut neighbours: HashMap<u32, Vec<u32>> = HashMap::new();
        let mut boundary_sides = 0usize;
        for t in tris {
            let tri = &mesh.tris[*t as usize];
            for k in 0..3 {
                let (v, a, b) = (tri.v[k], tri.v[(k + 1) % 3], tri.v[(k + 2) % 3]);
                fans.entry(v).or_default().push(*t);
                let (pv, pa, pb) = (mesh.point(v), mesh.point(a), mesh.point(b));
                let (u, w) = (
                    [pa[0] - pv[0], pa[1] - pv[1]],
                    [pb[0] - pv[0], pb[1] - pv[1]],
                );
                let turn = (u[0] * w[1] - u[1] * w[0]).atan2(u[0] * w[0] + u[1] * w[1]);
                *angle.entry(v).or_default() += turn.abs();
                if !matches!(tri.across[k], Across::Inside(_)) {
                    boundary_sides += 1;
                    neighbours.entry(v).or_default().push(a);
                    neighbours.entry(a).or_default().push(v);
                }
            }
        }
        // Euler: a region with h holes and c components has
        // V - E + T = c - h.
        let (v, t) = (fans.len() as i64, tris.len() as i64);
        let e = (3 * t + boundary_sides as i64) / 2;
        if v - e + t >= components(mesh, tris) as i64 {
            return None;
        }
        let mut corners: Vec<u32> = neighbours
            .keys()
            .copied()
            .filter(|v| {
                angle
                    .get(v)
                    .is_some_and(|a| *a > std::f64::consts::PI + 1e-9)
            })
            .collect();
        if corners.len() > MAX_CORNERS {
            return None;
        }
        corners.sort_unstable();
        let sides = corners
            .iter()
            .map(|c| match neighbours[c].as_slice() {
                [a, b] => Some([mesh.point(*a), mesh.point(*b)]),
                _ => None,
            })
            .collect();
        let points = corners.iter().map(|c| mesh.point(*c)).collect();
        let mut vis = Visibility {
            space: s,
            points,
            corners,
            sides,
            edges: Vec::new(),
            fans,
        };
        vis.edges = vec![Vec::new(); vis.corners.len()];
        let mut scratch = Vec::new();
        for i in 0..vis.corners.len() {
            let pi = vis.points[i];
            for j in i + 1..vis.corners.len() {
                let pj = vis.points[j];
                if !vis.tangent(pi, j) || !vis.tangent(pj, i) {
                    continue;
                }
                scratch.clear();
                if vis.line(mesh, vis.spot(i), vis.spot(j), &mut scratch) {
                    let d = dist(pi, pj);
                    vis.edges[i].push((j as u32, d));
                    vis.edges[j].push((i as u32, d));
                }
            }
        }
        Some(vis)
    }

    /// The number of corners.
    pub fn corner_count(&self) -> usize {
        self.corners.len()
    }

    /// Corner `i` as a spot: its vertex, in the first triangle of its fan.
    fn spot(&self, i: usize) -> Spot {
        let v = self.corners[i];
        let t = self.fans.get(&v).and_then(|f| f.first()).copied();
        (t.unwrap_or(NONE), self.points[i])
    }

    /// Whether a shortest walk can come from `from` to corner `i` and bend
    /// there: the corner's boundary lies on one side of the line.
    fn tangent(&self, from: Point, i: usize) -> bool {
        let Some([a, b]) = self.sides[i] else {
            return true;
        };
        let c = self.points[i];
        let (oa, ob) = (orient(from, c, a), orient(from, c, b));
        !((oa > 0.0 && ob < 0.0) || (oa < 0.0 && ob > 0.0))
    }

    /// The corners seen from `at`, tangent there, with the distance.
    pub fn sight(&self, mesh: &Mesh, at: Spot) -> Sight {
        let mut out = Vec::new();
        let mut scratch = Vec::new();
        for i in 0..self.corners.len() {
            if !self.tangent(at.1, i) {
                continue;
            }
            scratch.clear();
            if self.line(mesh, at, self.spot(i), &mut scratch) {
                out.push((i as u32, dist(at.1, self.points[i])));
            }
        }
        out
    }

    /// Dijkstra over the corners from `start`, whose sight is `seen`.
    pub fn reach(&self, start: Spot, seen: &Sight) -> Reach {
        let n = self.corners.len();
        let mut dist = vec![f64::INFINITY; n];
        let mut pred = vec![NONE; n];
        let mut heap = BinaryHeap::new();
        for (c, d) in seen {
            dist[*c as usize] = *d;
            heap.push(Reverse((d.to_bits(), *c)));
        }
        while let Some(Reverse((key, c))) = heap.pop() {
            if key > dist[c as usize].to_bits() {
                continue;
            }
            let here = dist[c as usize];
            for (u, d) in &self.edges[c as usize] {
                let nd = here + d;
                if nd < dist[*u as usize] {
                    dist[*u as usize] = nd;
                    pred[*u as usize] = c;
                    heap.push(Reverse((nd.to_bits(), *u)));
                }
            }
        }
        Reach { start, dist, pred }
    }

    /// The shortest length from the start of `reach` to `to`, whose sight
    /// is `seen`, and the last corner on the way (NONE: straight).
    pub fn length_to(&self, mesh: &Mesh, reach: &Reach, to: Spot, seen: &Sight) -> (f64, u32) {
        let mut best = (f64::INFINITY, NONE);
        for (c, d) in seen {
            let through = reach.dist[*c as usize] + d;
            if through < best.0 {
                best = (through, *c);
            }
        }
        let straight = dist(reach.start.1, to.1);
        if straight <= best.0 && self.line(mesh, reach.start, to, &mut Vec::new()) {
            best = (straight, NONE);
        }
        best
    }

    /// Appends the triangles of the walk from the start of `reach` to `to`
    /// whose last corner is `last` (from [`Visibility::length_to`]) to
    /// `out`: from the start when `outbound`, else from `to` back.
    pub fn channel_into(
        &self,
        mesh: &Mesh,
        reach: &Reach,
        last: u32,
        to: Spot,
        outbound: bool,
        out: &mut Vec<u32>,
    ) -> Option<()> {
        if !outbound {
            let mut back = Vec::new();
            self.channel_into(mesh, reach, last, to, true, &mut back)?;
            out.extend(back.iter().rev());
            return Some(());
        }
        let mut chain = Vec::new();
        let mut c = last;
        while c != NONE {
            chain.push(c);
            c = reach.pred[c as usize];
            if chain.len() > self.corners.len() {
                return None;
            }
        }
        let mut at = reach.start;
        for c in chain.iter().rev() {
            let next = self.spot(*c as usize);
            self.line(mesh, at, next, out).then_some(())?;
            at = next;
        }
        self.line(mesh, at, to, out).then_some(())
    }

    /// Walks the straight segment from `from` to `to` through the space's
    /// triangles, appending them (from `from.0` to `to.0`, no step back) to
    /// `out`; `false` when the segment leaves the space.
    fn line(&self, mesh: &Mesh, from: Spot, to: Spot, out: &mut Vec<u32>) -> bool {
        let (p, q) = (from.1, to.1);
        let mut t = from.0;
        if mesh
            .tris
            .get(t as usize)
            .is_none_or(|tri| tri.space != self.space)
        {
            return false;
        }
        push(out, t);
        // The vertex of `t` the walk stands on, if any.
        let mut at_vertex = vertex_at(mesh, t, p);
        let mut here = p;
        let limit = 4 * mesh.space_tris[self.space as usize].len() + 16;
        for _ in 0..limit {
            if let Some(v) = at_vertex.take() {
                here = mesh.point(v);
                if here == q {
                    return self.join(mesh, t, to.0, v, out);
                }
                let Some(next) = self
                    .fans
                    .get(&v)
                    .and_then(|fan| fan.iter().copied().find(|u| wedge_holds(mesh, *u, v, q)))
                else {
                    return false;
                };
                if !self.join(mesh, t, next, v, out) {
                    return false;
                }
                t = next;
            }
            let tri = &mesh.tris[t as usize];
            let pts = tri.v.map(|v| mesh.point(v));
            if (0..3).all(|k| orient(pts[k], pts[(k + 1) % 3], q) >= 0.0) {
                return self.finish(mesh, t, to, out);
            }
            let o = pts.map(|v| orient(p, q, v));
            if let Some(k) = (0..3).find(|k| o[*k] < 0.0 && o[(k + 1) % 3] > 0.0) {
                match tri.across[k] {
                    Across::Inside(u) => {
                        push(out, u);
                        t = u;
                        continue;
                    }
                    _ => return false,
                }
            }
            // The segment runs through a vertex ahead: the nearest one.
            let ahead = (0..3)
                .filter(|k| o[*k] == 0.0)
                .map(|k| (k, along(here, q, pts[k])))
                .filter(|(_, s)| *s > 0.0)
                .min_by(|a, b| a.1.total_cmp(&b.1));
            match ahead {
                Some((k, _)) => at_vertex = Some(tri.v[k]),
                None => return false,
            }
        }
        false
    }

    /// Ends a segment walk in `t` (which holds `to`'s point) at `to`'s own
    /// triangle.
    fn finish(&self, mesh: &Mesh, t: u32, to: Spot, out: &mut Vec<u32>) -> bool {
        if t == to.0 {
            return true;
        }
        if mesh.tris[t as usize].across.contains(&Across::Inside(to.0)) {
            push(out, to.0);
            return true;
        }
        let Some(end) = mesh.tris.get(to.0 as usize) else {
            return false;
        };
        // Both hold the point: they share the vertex it lies on.
        match vertex_at(mesh, t, to.1).or_else(|| {
            let shared = mesh.tris[t as usize].v;
            shared
                .into_iter()
                .filter(|v| end.v.contains(v))
                .min_by(|a, b| dist(mesh.point(*a), to.1).total_cmp(&dist(mesh.point(*b), to.1)))
        }) {
            Some(v) => self.join(mesh, t, to.0, v, out),
            None => false,
        }
    }

    /// Appends the triangles around vertex `v` from `from` to `to`
    /// (breadth first through the space's edges at `v`).
    fn join(&self, mesh: &Mesh, from: u32, to: u32, v: u32, out: &mut Vec<u32>) -> bool {
        if from == to {
            return true;
        }
        let Some(fan) = self.fans.get(&v) else {
            return false;
        };
        let mut prev: Vec<(u32, u32)> = vec![(from, NONE)];
        let mut i = 0;
        while i < prev.len() {
            let t = prev[i].0;
            if t == to {
                let mut path = vec![t];
                let mut back = prev[i].1;
                while back != NONE {
                    let (u, b) = prev[back as usize];
                    path.push(u);
                    back = b;
                }
                for u in path.iter().rev().skip(1) {
                    push(out, *u);
                }
                return true;
            }
            let tri = &mesh.tris[t as usize];
            for k in 0..3 {
                let Across::Inside(u) = tri.across[k] else {
                    continue;
                };
                let touches = tri.v[k] == v || tri.v[(k + 1) % 3] == v;
                if touches && fan.contains(&u) && !prev.iter().any(|(w, _)| *w == u) {
                    prev.push((u, i as u32));
                }
            }
            i += 1;
        }
        false
    }
}

/// Appends `t` to a channel, dropping a step straight back.
fn push(out: &mut Vec<u32>, t: u32) {
    let n = out.len();
    if n >= 1 && out[n - 1] == t {
        return;
    }
    if n >= 2 && out[n - 2] == t {
        out.pop();
        return;
    }
    out.push(t);
}

/// The vertex of triangle `t` at exactly `p`, if any.
fn vertex_at(mesh: &Mesh, t: u32, p: Point) -> Option<u32> {
    mesh.tris[t as usize]
        .v
        .into_iter()
        .find(|v| mesh.point(*v) == p)
}

/// Whether the direction from vertex `v` of triangle `t` towards `q` lies
/// in the triangle's angle at `v` (edges included).
fn wedge_holds(mesh: &Mesh, t: u32, v: u32, q: Point) -> bool {
    let tri = &mesh.tris[t as usize];
    let Some(k) = tri.v.iter().position(|w| *w == v) else {
        return false;
    };
    let (pv, a, b) = (
        mesh.point(v),
        mesh.point(tri.v[(k + 1) % 3]),
        mesh.point(tri.v[(k + 2) % 3]),
    );
    orient(pv, a, q) >= 0.0 && orient(pv, b, q) <= 0.0
}

/// How far along the direction from `from` to `to` the point `p` lies
/// (the dot product; > 0 ahead).
fn along(from: Point, to: Point, p: Point) -> f64 {
    (to[0] - from[0]) * (p[0] - from[0]) + (to[1] - from[1]) * (p[1] - from[1])
}

/// The number of connected pieces of a set of triangles (through shared
/// edges of one space).
fn components(mesh: &Mesh, tris: &[u32]) -> usize {
    let index: HashMap<u32, usize> = tris.iter().enumerate().map(|(i, t)| (*t, i)).collect();
    let mut seen = vec![false; tris.len()];
    let mut count = 0;
    for start in 0..tris.len() {
        if seen[start] {
            continue;
        }
        count += 1;
        seen[start] = true;
        let mut stack = vec![tris[start]];
        while let Some(t) = stack.pop() {
            for across in mesh.tris[t as usize].across {
                if let Across::Inside(u) = across
                    && let Some(&i) = index.get(&u)
                    && !std::mem::replace(&mut seen[i], true)
                {
                    stack.push(u);
                }
            }
        }
    }
    count
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Nrg, Space, SpaceId, SpaceKind};

    fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<Point> {
        vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
    }

    /// A 10 m × 10 m room (outline points every metre, so segments run
    /// through vertices and along edges) with the given holes.
    fn room(holes: Vec<Vec<Point>>) -> Mesh {
        let mut outline = Vec::new();
        for i in 0..10 {
            outline.push([f64::from(i), 0.0]);
        }
        for i in 0..10 {
            outline.push([10.0, f64::from(i)]);
        }
        for i in 0..10 {
            outline.push([10.0 - f64::from(i), 10.0]);
        }
        for i in 0..10 {
            outline.push([0.0, 10.0 - f64::from(i)]);
        }
        let mut space = Space::new(SpaceId(1), SpaceKind::Room, [0.5, 0.5], outline);
        space.holes = holes;
        Mesh::new(&Nrg::new(vec![space], Vec::new()).unwrap())
    }

    fn spot(mesh: &Mesh, p: Point) -> Spot {
        (mesh.locate(p, Some(0)).unwrap(), p)
    }

    /// The length of the walk from `a` to `b`, and the funnel's length
    /// through the channel it gives.
    fn walk(mesh: &Mesh, vis: &Visibility, a: Point, b: Point) -> (f64, f64) {
        let (from, to) = (spot(mesh, a), spot(mesh, b));
        let reach = vis.reach(from, &vis.sight(mesh, from));
        let (length, last) = vis.length_to(mesh, &reach, to, &vis.sight(mesh, to));
        let mut channel = Vec::new();
        vis.channel_into(mesh, &reach, last, to, true, &mut channel)
            .unwrap();
        assert_eq!(channel.first(), Some(&from.0));
        assert_eq!(channel.last(), Some(&to.0));
        let mut back = Vec::new();
        vis.channel_into(mesh, &reach, last, to, false, &mut back)
            .unwrap();
        assert!(
            back.iter().eq(channel.iter().rev()),
            "inbound is the way back"
        );
        let portals = super::super::layer::portals(mesh, &channel);
        assert_eq!(portals.len(), channel.len() - 1, "a channel of neighbours");
        let walked = super::super::funnel::funnel(a, b, &portals);
        (length, super::super::funnel::polyline_length(&walked))
    }

    #[test]
    fn a_room_without_holes_needs_no_graph() {
        assert!(Visibility::new(&room(Vec::new()), 0).is_none());
    }

    #[test]
    fn the_corners_are_the_pillars() {
        let mesh = room(vec![rect(4.0, 4.0, 6.0, 6.0)]);
        let vis = Visibility::new(&mesh, 0).unwrap();
        let mut corners = vis.points.clone();
        corners.sort_by(|a, b| a.partial_cmp(b).unwrap());
        assert_eq!(
            corners,
            vec![[4.0, 4.0], [4.0, 6.0], [6.0, 4.0], [6.0, 6.0]]
        );
        // Each corner sees its two neighbours round the pillar, never the
        // one across it.
        assert!(vis.edges.iter().all(|e| e.len() == 2), "{:?}", vis.edges);
    }

    #[test]
    fn the_walk_takes_the_shorter_side_of_a_pillar() {
        let mesh = room(vec![rect(4.0, 4.0, 6.0, 6.0)]);
        let vis = Visibility::new(&mesh, 0).unwrap();
        // Above: two slanted metres of 1.28 m and the pillar's 2 m top.
        let above = 2.0 * (1.0f64 + 0.64).sqrt() + 2.0;
        for (a, b) in [([3.0, 5.2], [7.0, 5.2]), ([7.0, 5.2], [3.0, 5.2])] {
            let (length, walked) = walk(&mesh, &vis, a, b);
            assert!((length - above).abs() < 1e-9, "{length} vs {above}");
            assert!((walked - above).abs() < 1e-9, "{walked} vs {above}");
        }
        // Below, mirrored.
        let (length, _) = walk(&mesh, &vis, [3.0, 4.8], [7.0, 4.8]);
        assert!((length - above).abs() < 1e-9);
    }

    #[test]
    fn segments_through_vertices_and_along_edges_are_seen() {
        // Two pillars in a row: the line y = 5 runs along both tops and
        // through their corners, and along the room's grid of vertices.
        let mesh = room(vec![rect(2.0, 4.0, 3.0, 5.0), rect(5.0, 4.0, 6.0, 5.0)]);
        let vis = Visibility::new(&mesh, 0).unwrap();
        let (length, walked) = walk(&mesh, &vis, [1.0, 5.0], [7.0, 5.0]);
        assert!((length - 6.0).abs() < 1e-9, "{length}");
        assert!((walked - 6.0).abs() < 1e-9, "{walked}");
        // Along the wall, through its vertices.
        let (length, _) = walk(&mesh, &vis, [0.0, 0.0], [10.0, 0.0]);
        assert!((length - 10.0).abs() < 1e-9, "{length}");
        // Through a pillar is never seen: the way round is longer.
        let (length, walked) = walk(&mesh, &vis, [2.5, 3.0], [2.5, 6.0]);
        let round = 2.0 * (0.25f64 + 1.0).sqrt() + 1.0;
        assert!((length - round).abs() < 1e-9, "{length} vs {round}");
        assert!((walked - round).abs() < 1e-9, "{walked} vs {round}");
    }

    #[test]
    fn a_point_sees_only_the_corners_it_can_bend_round() {
        let mesh = room(vec![rect(4.0, 4.0, 6.0, 6.0)]);
        let vis = Visibility::new(&mesh, 0).unwrap();
        let seen = vis.sight(&mesh, spot(&mesh, [1.0, 5.0]));
        let mut points: Vec<Point> = seen.iter().map(|(c, _)| vis.points[*c as usize]).collect();
        points.sort_by(|a, b| a.partial_cmp(b).unwrap());
        // (4, 4) and (4, 6) are tangent from the left; (6, *) are hidden.
        assert_eq!(points, vec![[4.0, 4.0], [4.0, 6.0]]);
    }
}

#[cfg(test)]
mod measure {
    use super::*;

    #[test]
    #[ignore = "prints corner counts and build times of the spaces with holes"]
    fn corner_counts_on_shared_maps() {
        for name in [
            "willow-full",
            "office_a_furnitures",
            "lab_intel_furnitures",
            "aws_small_house",
        ] {
            let Some(nrg) = crate::fixtures::shared_map_nrg(name) else {
                continue;
            };
            let mesh = Mesh::new(&nrg);
            for s in 0..mesh.space_ids.len() as u32 {
                let t = std::time::Instant::now();
                if let Some(v) = Visibility::new(&mesh, s) {
                    let edges: usize = v.edges.iter().map(Vec::len).sum();
                    eprintln!(
                        "{name} space {}: {} triangles, {} corners, {edges} visible pairs, {:?}",
                        mesh.space_ids[s as usize].0,
                        mesh.space_tris[s as usize].len(),
                        v.corners.len(),
                        t.elapsed()
                    );
                }
            }
        }
    }
}
