//! Which space holds a point, in logarithmic time for spaces with many
//! vertices (issue 21: a 50 000-vertex zigzag outline made tagging the
//! mesh test each of its 25 000 notches against every vertex: 1.2 s, and
//! quadratic beyond).
//!
//! Owns [`Containment`]: per space with more than [`INDEXED_FROM`]
//! vertices an R-tree of its ring edges; a point's even-odd ray test then
//! visits only the edges its ray can cross. The answer is exactly
//! `point_in_ring` on the exterior and not in any hole, edge for edge.

use rstar::primitives::{GeomWithData, Rectangle};
use rstar::{AABB, RTree};

use crate::model::{Point, Space, point_in_ring};

/// Spaces with more vertices than this get an index.
const INDEXED_FROM: usize = 64;

/// An edge `(a, b)` of ring `ring` (0: the exterior), as `point_in_ring`
/// visits it (from the previous vertex `a` to `b`).
type Edge = GeomWithData<Rectangle<[f64; 2]>, (u32, Point, Point)>;

/// Point-in-space tests over a model's spaces.
#[derive(Debug)]
pub(crate) struct Containment<'a> {
    spaces: &'a [Space],
    /// Per space: its edge index and the largest x of its vertices.
    index: Vec<Option<(RTree<Edge>, f64)>>,
}

impl<'a> Containment<'a> {
    /// Indexes the spaces with many vertices.
    pub fn new(spaces: &'a [Space]) -> Containment<'a> {
        let index = spaces
            .iter()
            .map(|s| {
                let n = s.polygon.len() + s.holes.iter().map(Vec::len).sum::<usize>();
                (n > INDEXED_FROM).then(|| edge_index(s))
            })
            .collect();
        Containment { spaces, index }
    }

    /// Whether `p` lies in space `i` (its exterior, not a hole).
    pub fn contains(&self, i: usize, p: Point) -> bool {
        let Some(space) = self.spaces.get(i) else {
            return false;
        };
        let Some(Some((tree, max_x))) = self.index.get(i) else {
            return point_in_ring(p, &space.polygon)
                && !space.holes.iter().any(|h| point_in_ring(p, h));
        };
        if p[0].is_nan() || p[0] > *max_x {
            return false;
        }
        let ray = AABB::from_corners([p[0], p[1]], [*max_x, p[1]]);
        // Crossings per ring (exterior first), as `point_in_ring` counts.
        let mut odd = vec![false; 1 + space.holes.len()];
        for e in tree.locate_in_envelope_intersecting(&ray) {
            let (ring, [xj, yj], [xi, yi]) = e.data;
            if (yi > p[1]) != (yj > p[1]) && p[0] < (xj - xi) * (p[1] - yi) / (yj - yi) + xi {
                odd[ring as usize] = !odd[ring as usize];
            }
        }
        odd[0] && !odd[1..].iter().any(|o| *o)
    }
}

/// The R-tree of a space's ring edges and its largest x.
fn edge_index(space: &Space) -> (RTree<Edge>, f64) {
    let mut edges = Vec::new();
    let mut max_x = f64::MIN;
    for (r, ring) in std::iter::once(&space.polygon)
        .chain(&space.holes)
        .enumerate()
    {
        let n = ring.len();
        for i in 0..n {
            let (a, b) = (ring[(i + n - 1) % n], ring[i]);
            max_x = max_x.max(b[0]);
            let lo = [a[0].min(b[0]), a[1].min(b[1])];
            let hi = [a[0].max(b[0]), a[1].max(b[1])];
            edges.push(GeomWithData::new(
                Rectangle::from_corners(lo, hi),
                (r as u32, a, b),
            ));
        }
    }
    (RTree::bulk_load(edges), max_x)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{SpaceId, SpaceKind};

    /// A zigzag ring of `n` vertices around (0, 0) with a square hole.
    fn zigzag(n: usize) -> Space {
        let poly: Vec<Point> = (0..n)
            .map(|i| {
                let t = std::f64::consts::TAU * i as f64 / n as f64;
                let r = if i % 2 == 0 { 10.0 } else { 9.5 };
                [r * t.cos(), r * t.sin()]
            })
            .collect();
        let mut s = Space::new(SpaceId(1), SpaceKind::Room, [5.0, 0.0], poly);
        s.holes = vec![vec![[-1.0, -1.0], [-1.0, 1.0], [1.0, 1.0], [1.0, -1.0]]];
        s
    }

    #[test]
    fn the_index_answers_as_the_plain_test_does() {
        let spaces = vec![zigzag(400)];
        let c = Containment::new(&spaces);
        assert!(c.index[0].is_some());
        let plain = |p: Point| {
            point_in_ring(p, &spaces[0].polygon)
                && !spaces[0].holes.iter().any(|h| point_in_ring(p, h))
        };
        let mut inside = 0;
        for i in -60..=60 {
            for j in -60..=60 {
                // On a grid that hits vertices and edges exactly too.
                let p = [
                    f64::from(i) / 5.0,
                    f64::from(j) / 5.0 + 0.013 * f64::from(i % 3),
                ];
                assert_eq!(c.contains(0, p), plain(p), "{p:?}");
                inside += usize::from(plain(p));
            }
        }
        assert!(inside > 1000, "{inside}");
        assert!(!c.contains(0, [0.0, 0.0]), "the hole");
        assert!(!c.contains(0, [50.0, 0.0]));
        assert!(!c.contains(3, [5.0, 0.0]), "no such space");
    }
}
