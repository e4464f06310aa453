//! The boundaries between labels along pixel edges (crack following): the
//! planar graph whose vertices are pixel corners and whose edges separate
//! two pixels of different labels, cut into arcs between junctions.
//!
//! A junction is a corner with three or four boundary edges: three or more
//! labels meet there, or a label touches itself diagonally (label 0, no
//! space, counts as a label; the image is framed with 0). An arc runs from
//! junction to junction with the same two labels on its sides; a closed
//! boundary without junctions is one arc starting (and ending) at its
//! top-left corner. Each label's rings are chains of arcs, so two labels
//! that touch share the very same arc.
//!
//! Uses the label image; knows nothing of metres or simplification.

use std::collections::HashMap;

use super::simplify::Corner;
use crate::imaging::Labels;

/// A step along a pixel edge, in image axes (row down).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Dir {
    East,
    North,
    West,
    South,
}

impl Dir {
    const ALL: [Dir; 4] = [Dir::East, Dir::North, Dir::West, Dir::South];

    /// `[dcol, drow]` of one step.
    pub(crate) fn delta(self) -> Corner {
        match self {
            Dir::East => [1, 0],
            Dir::North => [0, -1],
            Dir::West => [-1, 0],
            Dir::South => [0, 1],
        }
    }

    fn opposite(self) -> Dir {
        match self {
            Dir::East => Dir::West,
            Dir::North => Dir::South,
            Dir::West => Dir::East,
            Dir::South => Dir::North,
        }
    }
}

/// A boundary arc: corners from one junction to the next (or round a
/// closed boundary), only where the direction turns.
#[derive(Debug, Clone)]
pub(crate) struct Arc {
    /// The corners, first and last included (equal for a closed arc).
    pub pts: Vec<Corner>,
    /// The label on the left going forwards (image axes, row down).
    pub left: u32,
    /// The label on the right.
    pub right: u32,
    /// The arc ends at junctions (false: a closed boundary of two labels).
    pub at_junctions: bool,
}

/// One ring of a label: arcs in order, each forwards (label on the left)
/// or backwards.
#[derive(Debug, Clone, Default)]
pub(crate) struct RingArcs {
    pub arcs: Vec<(usize, bool)>,
}

/// The label image framed with 0, read at any integer pixel.
struct Framed<'a> {
    labels: &'a Labels,
    w: i64,
    h: i64,
}

impl Framed<'_> {
    fn at(&self, x: i64, y: i64) -> u32 {
        if x < 0 || y < 0 || x >= self.w || y >= self.h {
            return 0;
        }
        self.labels.data[(y * self.w + x) as usize]
    }

    /// (left, right) labels of the edge from corner `c` one step in `d`.
    fn sides(&self, c: Corner, d: Dir) -> (u32, u32) {
        let (x, y) = (i64::from(c[0]), i64::from(c[1]));
        match d {
            Dir::East => (self.at(x, y - 1), self.at(x, y)),
            Dir::West => (self.at(x - 1, y), self.at(x - 1, y - 1)),
            Dir::South => (self.at(x, y), self.at(x - 1, y)),
            Dir::North => (self.at(x - 1, y - 1), self.at(x, y - 1)),
        }
    }

    fn has_edge(&self, c: Corner, d: Dir) -> bool {
        let (l, r) = self.sides(c, d);
        l != r
    }

    fn degree(&self, c: Corner) -> usize {
        Dir::ALL.iter().filter(|&&d| self.has_edge(c, d)).count()
    }
}

/// Visited flags of horizontal and vertical pixel edges.
struct Visited {
    w: usize,
    horizontal: Vec<bool>,
    vertical: Vec<bool>,
}

impl Visited {
    /// Marks the edge from `c` in `d`; false if it already was.
    fn mark(&mut self, c: Corner, d: Dir) -> bool {
        let (x, y) = (c[0] as usize, c[1] as usize);
        let slot = match d {
            Dir::East => &mut self.horizontal[y * self.w + x],
            Dir::West => &mut self.horizontal[y * self.w + x - 1],
            Dir::South => &mut self.vertical[y * (self.w + 1) + x],
            Dir::North => &mut self.vertical[(y - 1) * (self.w + 1) + x],
        };
        !std::mem::replace(slot, true)
    }
}

/// The arcs of `labels` and the rings of each label (index = label; 0 has none).
pub(crate) struct Boundaries {
    pub arcs: Vec<Arc>,
    /// Per label, its rings (exterior and holes, in no particular order).
    pub rings: Vec<Vec<RingArcs>>,
}

/// Traces every boundary of `labels` into arcs and chains each label's
/// arcs into rings.
pub(crate) fn trace_boundaries(labels: &Labels) -> Boundaries {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let f = Framed {
        labels,
        w: w as i64,
        h: h as i64,
    };
    let mut seen = Visited {
        w,
        horizontal: vec![false; w * (h + 1)],
        vertical: vec![false; (w + 1) * h],
    };
    let mut arcs = Vec::new();
    let data = &labels.data;
    // The framed pixel rows above and below corner row `cy`.
    let rows = |cy: usize| {
        let up = (cy > 0).then(|| &data[(cy - 1) * w..cy * w]);
        let down = (cy < h).then(|| &data[cy * w..(cy + 1) * w]);
        let px =
            move |row: Option<&[u32]>, cx: usize| row.and_then(|r| r.get(cx)).copied().unwrap_or(0);
        (move |cx| px(up, cx), move |cx| px(down, cx))
    };
    // Arcs from junctions: corners with three or four boundary edges. The
    // pixels left of a corner are those right of the previous one.
    for cy in 0..=h {
        let (up, down) = rows(cy);
        let (mut a, mut p) = (0, 0);
        for cx in 0..=w {
            let (b, q) = (up(cx), down(cx));
            let degree = usize::from(a != b)
                + usize::from(p != q)
                + usize::from(a != p)
                + usize::from(b != q);
            if degree >= 3 {
                let c = [cx as i32, cy as i32];
                for d in Dir::ALL {
                    if f.has_edge(c, d) && seen.mark(c, d) {
                        arcs.push(walk(&f, &mut seen, c, d));
                    }
                }
            }
            (a, p) = (b, q);
        }
    }
    // Closed boundaries without junctions start at their first horizontal
    // edge in row-major order: their top-left corner, heading east.
    for cy in 0..=h {
        let (up, down) = rows(cy);
        for cx in 0..w {
            if up(cx) != down(cx) && !seen.horizontal[cy * w + cx] {
                let c = [cx as i32, cy as i32];
                seen.mark(c, Dir::East);
                arcs.push(walk(&f, &mut seen, c, Dir::East));
            }
        }
    }
    let rings = chain_rings(&arcs, labels.count as usize);
    Boundaries { arcs, rings }
}

/// Follows the boundary from corner `c` (edge `d` already marked) to the
/// next junction, or back to `c`.
fn walk(f: &Framed, seen: &mut Visited, start: Corner, d: Dir) -> Arc {
    let (left, right) = f.sides(start, d);
    let mut pts = vec![start];
    let (mut c, mut dir) = (start, d);
    loop {
        let [dx, dy] = dir.delta();
        c = [c[0] + dx, c[1] + dy];
        let back = dir.opposite();
        let degree = f.degree(c);
        if c == start || degree != 2 {
            pts.push(c);
            return Arc {
                pts,
                left,
                right,
                at_junctions: degree != 2,
            };
        }
        let Some(next) = Dir::ALL
            .into_iter()
            .find(|&n| n != back && f.has_edge(c, n))
        else {
            pts.push(c);
            return Arc {
                pts,
                left,
                right,
                at_junctions: true,
            };
        };
        if next != dir {
            pts.push(c);
        }
        if !seen.mark(c, next) {
            // Cannot happen on a consistent image: a degree-2 corner's edges
            // belong to one arc only.
            pts.push(c);
            return Arc {
                pts,
                left,
                right,
                at_junctions: true,
            };
        }
        dir = next;
    }
}

/// Each label's rings: arcs with the label on their left run forwards,
/// those with it on their right backwards, chained end to start.
fn chain_rings(arcs: &[Arc], count: usize) -> Vec<Vec<RingArcs>> {
    let mut rings: Vec<Vec<RingArcs>> = vec![Vec::new(); count + 1];
    // Half-arcs by (start corner, label), in arc order.
    let mut starting: HashMap<(Corner, u32), Vec<(usize, bool)>> = HashMap::new();
    let mut halves = Vec::new();
    for (k, a) in arcs.iter().enumerate() {
        let (first, last) = (a.pts[0], a.pts[a.pts.len() - 1]);
        for (label, forwards, from) in [(a.left, true, first), (a.right, false, last)] {
            if label == 0 || label as usize > count {
                continue;
            }
            halves.push((k, forwards, label));
            starting
                .entry((from, label))
                .or_default()
                .push((k, forwards));
        }
    }
    let mut used: HashMap<(usize, bool), ()> = HashMap::with_capacity(halves.len());
    for (k, forwards, label) in halves {
        if used.insert((k, forwards), ()).is_some() {
            continue;
        }
        let mut ring = RingArcs {
            arcs: vec![(k, forwards)],
        };
        let start = end_of(&arcs[k], !forwards);
        let mut at = end_of(&arcs[k], forwards);
        while at != start {
            let next = starting
                .get(&(at, label))
                .and_then(|v| v.iter().find(|h| !used.contains_key(h)).copied());
            let Some(next) = next else { break };
            used.insert(next, ());
            ring.arcs.push(next);
            at = end_of(&arcs[next.0], next.1);
        }
        rings[label as usize].push(ring);
    }
    rings
}

/// The last corner of arc `a` run forwards (or backwards: its first).
fn end_of(a: &Arc, forwards: bool) -> Corner {
    if forwards {
        a.pts[a.pts.len() - 1]
    } else {
        a.pts[0]
    }
}

/// Twice the signed area of a closed ring of corners (first point not
/// repeated), image axes: negative for a label's exterior (label on the
/// left), positive for its holes.
pub(crate) fn twice_area(ring: &[Corner]) -> i64 {
    let n = ring.len();
    (0..n)
        .map(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            i64::from(a[0]) * i64::from(b[1]) - i64::from(b[0]) * i64::from(a[1])
        })
        .sum()
}

/// The corners of a ring whose arcs have the points `geom[k]`.
pub(crate) fn ring_corners(ring: &RingArcs, geom: &[Vec<Corner>]) -> Vec<Corner> {
    let mut out = Vec::new();
    for &(k, forwards) in &ring.arcs {
        let p = &geom[k];
        if forwards {
            out.extend_from_slice(&p[..p.len() - 1]);
        } else {
            out.extend(p[1..].iter().rev());
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_lone_label_is_one_closed_arc() {
        let b = trace_boundaries(&Labels::from_digits(&["000", "011", "000"]));
        assert_eq!(b.arcs.len(), 1);
        assert_eq!(b.arcs[0].pts, [[1, 1], [3, 1], [3, 2], [1, 2], [1, 1]]);
        assert_eq!((b.arcs[0].left, b.arcs[0].right), (0, 1));
        let corners = ring_corners(&b.rings[1][0], &[b.arcs[0].pts.clone()]);
        assert_eq!(twice_area(&corners), -4);
    }

    #[test]
    fn two_labels_share_their_arc() {
        let b = trace_boundaries(&Labels::from_digits(&["1122", "1122"]));
        // Junctions at the top and bottom of the shared edge.
        let shared: Vec<&Arc> = b
            .arcs
            .iter()
            .filter(|a| a.left != 0 && a.right != 0)
            .collect();
        assert_eq!(shared.len(), 1);
        assert_eq!(b.rings[1].len(), 1);
        assert_eq!(b.rings[2].len(), 1);
        let geom: Vec<Vec<Corner>> = b.arcs.iter().map(|a| a.pts.clone()).collect();
        assert_eq!(twice_area(&ring_corners(&b.rings[1][0], &geom)), -8);
        assert_eq!(twice_area(&ring_corners(&b.rings[2][0], &geom)), -8);
    }
}
