//! Noding of the mesh's constraint edges: every crossing of two edges and
//! every vertex lying on another edge becomes a shared vertex, so that the
//! triangulation receives edges that meet only at their ends. spade can
//! split crossing constraints itself (`add_constraint_and_split`), but it
//! panics on nearly collinear crossings (spade issues 107, 111, 116): the
//! kind a repaired overlap leaves, where one ring runs a few nanometres
//! off its neighbour's edge. Intersections are snapped to the mesh's
//! micrometre grid and shared through the same vertex table.
//!
//! Only run when the bulk load reports conflicts; a model whose rings meet
//! only at shared vertices (every extraction) never pays for it.

use rustc_hash::FxHashMap;

use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{AABB, RTree};

use crate::model::Point;

/// A vertex closer than this to an edge lies on it (metres): a little more
/// than the micrometre snapping grid.
const ON_EDGE_M: f64 = 2.0e-6;

type Segment = GeomWithData<Rectangle<[f64; 2]>, usize>;

/// The vertex table: points and the index of each snapped position.
pub(super) struct Vertices<'a> {
    pub points: &'a mut Vec<Point>,
    pub index: &'a mut FxHashMap<[u64; 2], u32>,
    pub snap: fn(Point) -> Point,
}

impl Vertices<'_> {
    fn vertex(&mut self, p: Point) -> u32 {
        let snapped = (self.snap)(p);
        let key = snapped.map(f64::to_bits);
        let points = &mut *self.points;
        *self.index.entry(key).or_insert_with(|| {
            points.push(snapped);
            (points.len() - 1) as u32
        })
    }
}

/// `edges` (pairs of vertex indices) split at every crossing with another
/// edge and at every vertex lying on them, sorted and without duplicates
/// or zero-length pieces. New vertices are added to `vertices`.
pub(super) fn node(edges: &[[usize; 2]], vertices: &mut Vertices<'_>) -> Vec<[usize; 2]> {
    let segment = |pts: &[Point], e: &[usize; 2]| (pts[e[0]], pts[e[1]]);
    let tree: RTree<Segment> = RTree::bulk_load(
        edges
            .iter()
            .enumerate()
            .map(|(i, e)| {
                let (a, b) = segment(vertices.points, e);
                GeomWithData::new(Rectangle::from_corners(a, b), i)
            })
            .collect(),
    );
    // Split positions along each edge: (parameter, vertex).
    let mut splits: Vec<Vec<(f64, u32)>> = vec![Vec::new(); edges.len()];
    for (i, e) in edges.iter().enumerate() {
        let (a, b) = segment(vertices.points, e);
        let reach = AABB::from_corners(
            [a[0].min(b[0]) - ON_EDGE_M, a[1].min(b[1]) - ON_EDGE_M],
            [a[0].max(b[0]) + ON_EDGE_M, a[1].max(b[1]) + ON_EDGE_M],
        );
        let others: Vec<usize> = tree
            .locate_in_envelope_intersecting(&reach)
            .map(|s| s.data)
            .filter(|&j| j > i)
            .collect();
        for j in others {
            let f = edges[j];
            let (c, d) = segment(vertices.points, &f);
            // An end of one lying inside the other.
            for (end, on, (p, q)) in [
                (f[0], i, (a, b)),
                (f[1], i, (a, b)),
                (e[0], j, (c, d)),
                (e[1], j, (c, d)),
            ] {
                let v = vertices.points[end];
                if let Some(t) = inner_parameter(v, p, q) {
                    splits[on].push((t, end as u32));
                }
            }
            // A proper crossing.
            if let Some((t, u, x)) = crossing(a, b, c, d) {
                let v = vertices.vertex(x);
                splits[i].push((t, v));
                splits[j].push((u, v));
            }
        }
    }
    let mut out = Vec::with_capacity(edges.len());
    for (e, mut cuts) in edges.iter().zip(splits) {
        cuts.sort_by(|x, y| x.0.total_cmp(&y.0));
        let chain = std::iter::once(e[0] as u32)
            .chain(cuts.into_iter().map(|(_, v)| v))
            .chain(std::iter::once(e[1] as u32));
        let mut prev: Option<u32> = None;
        for v in chain {
            if let Some(p) = prev
                && p != v
            {
                let (lo, hi) = (p.min(v) as usize, p.max(v) as usize);
                out.push([lo, hi]);
            }
            prev = Some(v);
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

/// Where along `p`→`q` (strictly between its ends) `v` lies, when it is
/// within [`ON_EDGE_M`] of the segment.
fn inner_parameter(v: Point, p: Point, q: Point) -> Option<f64> {
    let d = [q[0] - p[0], q[1] - p[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    if len2 == 0.0 || v == p || v == q {
        return None;
    }
    let t = ((v[0] - p[0]) * d[0] + (v[1] - p[1]) * d[1]) / len2;
    let margin = ON_EDGE_M / len2.sqrt();
    if t <= margin || t >= 1.0 - margin {
        return None;
    }
    let off = [p[0] + t * d[0] - v[0], p[1] + t * d[1] - v[1]];
    (off[0].hypot(off[1]) <= ON_EDGE_M).then_some(t)
}

/// The proper crossing of `a`→`b` and `c`→`d` (both strictly inside):
/// its parameters along each and the point.
fn crossing(a: Point, b: Point, c: Point, d: Point) -> Option<(f64, f64, Point)> {
    let r = [b[0] - a[0], b[1] - a[1]];
    let s = [d[0] - c[0], d[1] - c[1]];
    let denom = r[0] * s[1] - r[1] * s[0];
    if denom == 0.0 {
        return None;
    }
    let w = [c[0] - a[0], c[1] - a[1]];
    let t = (w[0] * s[1] - w[1] * s[0]) / denom;
    let u = (w[0] * r[1] - w[1] * r[0]) / denom;
    let inside = |x: f64| x > 0.0 && x < 1.0;
    if !(inside(t) && inside(u)) {
        return None;
    }
    let x = [a[0] + t * r[0], a[1] + t * r[1]];
    // A crossing at an end (within the grid) is a shared vertex already.
    let near = |p: Point| (p[0] - x[0]).hypot(p[1] - x[1]) <= ON_EDGE_M;
    if near(a) || near(b) || near(c) || near(d) {
        return None;
    }
    Some((t, u, x))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn snap(p: Point) -> Point {
        p.map(|c| (c * 1e6).round() / 1e6)
    }

    fn run(points: Vec<Point>, edges: &[[usize; 2]]) -> (Vec<Point>, Vec<[usize; 2]>) {
        let mut points = points;
        let mut index: FxHashMap<[u64; 2], u32> = points
            .iter()
            .enumerate()
            .map(|(i, p)| (p.map(f64::to_bits), i as u32))
            .collect();
        let out = node(
            edges,
            &mut Vertices {
                points: &mut points,
                index: &mut index,
                snap,
            },
        );
        (points, out)
    }

    #[test]
    fn a_cross_gets_a_shared_middle_vertex() {
        let (points, edges) = run(
            vec![[0.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 0.0]],
            &[[0, 1], [2, 3]],
        );
        assert_eq!(points.len(), 5);
        assert_eq!(points[4], [1.0, 1.0]);
        assert_eq!(edges, vec![[0, 4], [1, 4], [2, 4], [3, 4]]);
    }

    #[test]
    fn a_vertex_a_nanometre_off_an_edge_splits_it() {
        // A T-junction as a boolean operation leaves it: (1, 1e-9) is not
        // exactly on the bottom edge.
        let (points, edges) = run(
            vec![[0.0, 0.0], [2.0, 0.0], [1.0, 1e-9], [1.0, 1.0]],
            &[[0, 1], [2, 3]],
        );
        assert_eq!(points.len(), 4, "no new vertex");
        assert_eq!(edges, vec![[0, 2], [1, 2], [2, 3]]);
    }

    #[test]
    fn edges_meeting_at_their_ends_are_kept() {
        let (points, edges) = run(
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]],
            &[[0, 1], [1, 2], [0, 2]],
        );
        assert_eq!(points.len(), 3);
        assert_eq!(edges, vec![[0, 1], [0, 2], [1, 2]]);
    }
}
