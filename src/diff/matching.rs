//! Space matching by polygon overlap (intersection over union).
//!
//! Every pair of spaces (one from the old revision, one from the new) whose
//! bounding boxes meet is scored by the IoU of their polygons (holes
//! included), computed exactly: bit-identical outlines by their area,
//! convex pairs by Sutherland–Hodgman clipping, all others by a slab sweep
//! ([`super::overlap_area`]) that measures the intersection without
//! building it (a general boolean operation, as `geo`'s, cost 10–50×
//! more on the non-convex outlines extraction produces). Pairs below
//! [`MatchParams::min_iou`] are dropped. The remaining pairs form a sparse
//! bipartite graph; each connected component of it is solved as an
//! assignment problem (Kuhn–Munkres, maximising the summed IoU), so the
//! matching is optimal and one-to-one. Components are small (a room
//! overlaps only its own continuation and a few neighbours), so the cubic
//! cost of the Hungarian method stays tiny; a component of more than
//! [`MAX_OPTIMAL_COMPONENT`] spaces (only spaces piled on each other make
//! one) is matched greedily, best IoU first, instead of building an n×n
//! matrix (issue 21, defect 8: 20 000 piled cells took 11 min and 4.5 GB).
//! [`match_spaces_within`] also bounds the pairs measured.
//!
//! When a room is split, the larger part keeps the old identity (it has the
//! larger IoU); when two rooms merge, the merged room continues the one it
//! overlaps most.
//!
//! Doors are matched apart, in three stages: (1) the non-door spaces by
//! IoU as above; (2) doors to doors by their doorway line and the spaces
//! they join ([`super::door_match`]: a door strip a pixel or two deep has
//! almost no area, so overlap cannot tell whether two doors are one);
//! (3) what is left, a door to a non-door space, by IoU again (a thick
//! door strip that became part of a room is re-kinded, not replaced).

use std::collections::{BTreeMap, BTreeSet, HashMap};

use pathfinding::prelude::{Matrix, kuhn_munkres};

use super::door_match::{door_candidates, door_sides, line_share};
use super::overlap_area::{Edges, intersection_area_of};
use super::overlaps::Overlaps;
use super::params::MatchParams;
use crate::model::{Nrg, Point, Ring, Space, SpaceId, convex_hull, level_name, polygon_area};

/// One space of the new revision continuing one space of the old.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpaceMatch {
    /// The space's id in the old revision.
    pub old: SpaceId,
    /// The space's id in the new revision.
    pub new: SpaceId,
    /// Intersection over union of the two polygons (0..1]; for doors,
    /// which are matched by their doorway instead (see the module doc),
    /// it may be 0: a door strip a pixel or two deep has no area.
    pub iou: f64,
}

/// Matches the spaces of `new` to the spaces of `old` they continue, by
/// polygon overlap, one-to-one, maximising the summed IoU; doors by their
/// doorway and the spaces they join (see the module doc). The result is
/// sorted by the new id; unmatched spaces are simply absent.
///
/// ```
/// use nrgdb::diff::{match_spaces, MatchParams};
/// use nrgdb::model::{Nrg, Space, SpaceId, SpaceKind};
/// let square = |id, x: f64| Space::new(SpaceId(id), SpaceKind::Room, [x + 1.0, 1.0],
///     vec![[x, 0.0], [x + 2.0, 0.0], [x + 2.0, 2.0], [x, 2.0]]);
/// let old = Nrg::new(vec![square(1, 0.0), square(2, 2.0)], vec![])?;
/// let new = Nrg::new(vec![square(7, 2.1), square(8, 0.1)], vec![])?;
/// let m = match_spaces(&old, &new, &MatchParams::default());
/// assert_eq!((m[0].new, m[0].old), (SpaceId(7), SpaceId(2)));
/// assert_eq!((m[1].new, m[1].old), (SpaceId(8), SpaceId(1)));
/// # Ok::<(), nrgdb::model::ModelError>(())
/// ```
pub fn match_spaces(old: &Nrg, new: &Nrg, params: &MatchParams) -> Vec<SpaceMatch> {
    match_overlaps(&overlaps(old, new), params)
}

/// [`match_spaces`], giving up (`None`) rather than measure more than
/// `max_pairs` pairs of spaces whose bounding boxes meet (a model of
/// spaces piled on each other over another such: every pair meets).
pub fn match_spaces_within(
    old: &Nrg,
    new: &Nrg,
    params: &MatchParams,
    max_pairs: usize,
) -> Option<Vec<SpaceMatch>> {
    Some(match_overlaps(
        &overlaps_within(old, new, max_pairs, None)?,
        params,
    ))
}

/// Every overlapping pair of spaces of `old` and `new` on the same level,
/// found through a grid of bounding boxes and measured exactly.
pub fn overlaps(old: &Nrg, new: &Nrg) -> Overlaps {
    overlaps_within(old, new, usize::MAX, None).unwrap_or_default()
}

/// Pairs of spaces (one of each model) whose boxes meet that matching
/// measures at most: a revision of 20 000 spaces meets about ten times as
/// many; 20 000 piled over 20 000 would be 400 million (issue 21, defect
/// 8). Imports and every diff stop there with a clear error.
pub const MAX_MATCH_PAIRS: usize = 2_000_000;

/// Pairs measured between two looks at the clock.
const DEADLINE_EVERY: usize = 1024;

/// [`overlaps`], or `None` past `max_pairs` pairs whose boxes meet or past
/// `deadline` (checked every [`DEADLINE_EVERY`] pairs).
pub(crate) fn overlaps_within(
    old: &Nrg,
    new: &Nrg,
    max_pairs: usize,
    deadline: Option<std::time::Instant>,
) -> Option<Overlaps> {
    let old_shapes: Vec<Shape> = old.spaces().iter().map(Shape::new).collect();
    let new_shapes: Vec<Shape> = new.spaces().iter().map(Shape::new).collect();
    let (old_sides, new_sides) = (door_sides(old), door_sides(new));
    let grid = BoxGrid::new(&old_shapes);
    let mut pairs: Vec<(usize, usize, f64)> = Vec::new();
    let mut door_shares: Vec<(usize, usize, f64)> = Vec::new();
    let mut candidates = Vec::new();
    let mut measured = 0usize;
    for (j, n) in new_shapes.iter().enumerate() {
        grid.candidates(n, &mut candidates);
        for &i in &candidates {
            let o = &old_shapes[i];
            // Spaces on different levels never continue each other.
            if !o.bbox_meets(n)
                || level_name(old.spaces()[i].level.as_ref())
                    != level_name(new.spaces()[j].level.as_ref())
            {
                continue;
            }
            measured += 1;
            if measured > max_pairs {
                return None;
            }
            if measured.is_multiple_of(DEADLINE_EVERY)
                && deadline.is_some_and(|d| std::time::Instant::now() >= d)
            {
                return None;
            }
            // A door of one side in a non-door space of the other.
            let line = match (&old_sides[i], &new_sides[j]) {
                (Some(d), None) => d.line.map(|l| (l, n)),
                (None, Some(d)) => d.line.map(|l| (l, o)),
                _ => None,
            };
            if let Some((line, space)) = line {
                let share = line_share(line, &space.rings);
                if share > 0.0 {
                    door_shares.push((i, j, share));
                }
            }
            let inter = o.intersection_area(n);
            if inter > 0.0 && inter.is_finite() {
                pairs.push((i, j, inter));
            }
        }
    }
    Some(Overlaps {
        old_ids: old_shapes.iter().map(|s| s.id).collect(),
        new_ids: new_shapes.iter().map(|s| s.id).collect(),
        old_area: old_shapes.iter().map(|s| s.area).collect(),
        new_area: new_shapes.iter().map(|s| s.area).collect(),
        pairs,
        door_shares,
        old_sides,
        new_sides,
    })
}

/// The optimal one-to-one matching over precomputed overlaps (see
/// [`match_spaces`]).
pub fn match_overlaps(ov: &Overlaps, params: &MatchParams) -> Vec<SpaceMatch> {
    let iou_edges = |keep: &dyn Fn(usize, usize) -> bool| -> Vec<(usize, usize, f64)> {
        ov.pairs
            .iter()
            .filter(|&&(i, j, _)| keep(i, j))
            .map(|&(i, j, inter)| (i, j, ov.iou(i, j, inter)))
            .filter(|&(_, _, iou)| iou >= params.min_iou && iou > 0.0)
            .collect()
    };
    let (n_old, n_new) = (ov.old_ids.len(), ov.new_ids.len());
    // 1. Non-door spaces by IoU.
    let mut pairs = solve(
        &iou_edges(&|i, j| !ov.old_is_door(i) && !ov.new_is_door(j)),
        n_old,
        n_new,
    );
    // 2. Doors by their doorway and the spaces they join.
    let rooms: HashMap<usize, usize> = pairs.iter().map(|&(i, j, _)| (i, j)).collect();
    let doors = solve(&door_candidates(ov, &rooms, params), n_old, n_new);
    pairs.extend(doors);
    // 3. What is left, a door and a non-door space, by IoU.
    let (old_done, new_done): (BTreeSet<usize>, BTreeSet<usize>) =
        pairs.iter().map(|&(i, j, _)| (i, j)).unzip();
    let mixed = iou_edges(&|i, j| {
        ov.old_is_door(i) != ov.new_is_door(j) && !old_done.contains(&i) && !new_done.contains(&j)
    });
    pairs.extend(solve(&mixed, n_old, n_new));
    let inter: HashMap<(usize, usize), f64> =
        ov.pairs.iter().map(|&(i, j, a)| ((i, j), a)).collect();
    let mut matches: Vec<SpaceMatch> = pairs
        .into_iter()
        .map(|(i, j, _)| SpaceMatch {
            old: ov.old_ids[i],
            new: ov.new_ids[j],
            iou: inter.get(&(i, j)).map_or(0.0, |&a| ov.iou(i, j, a)),
        })
        .collect();
    matches.sort_by_key(|m| m.new);
    matches
}

/// The optimal one-to-one assignment over scored edges, component by
/// component.
fn solve(edges: &[(usize, usize, f64)], n_old: usize, n_new: usize) -> Vec<(usize, usize, f64)> {
    components(edges, n_old, n_new)
        .iter()
        .flat_map(|c| assign(c))
        .collect()
}

/// Intersection over union of two spaces' polygons (holes included), 0
/// when they do not overlap.
pub fn overlap_iou(a: &Space, b: &Space) -> f64 {
    Shape::new(a).iou(&Shape::new(b))
}

/// A space's polygon with its area and bounding box, ready to intersect.
struct Shape {
    id: SpaceId,
    /// The exterior ring, counter-clockwise, when the space is convex and
    /// has no holes: then overlaps are clipped directly (fast path).
    convex: Option<Ring>,
    /// Exterior ring first, then the holes.
    rings: Vec<Ring>,
    /// Their edges, for the slab sweep.
    edges: Edges,
    /// The exterior's convex hull (counter-clockwise), to reject pairs
    /// that share no area cheaply.
    hull: Vec<Point>,
    area: f64,
    min: [f64; 2],
    max: [f64; 2],
}

impl Shape {
    fn new(space: &Space) -> Shape {
        let mut rings = Vec::with_capacity(1 + space.holes.len());
        rings.push(space.polygon.clone());
        rings.extend(space.holes.iter().cloned());
        let area = (polygon_area(&space.polygon).abs()
            - space
                .holes
                .iter()
                .map(|h| polygon_area(h).abs())
                .sum::<f64>())
        .max(0.0);
        let mut min = [f64::INFINITY; 2];
        let mut max = [f64::NEG_INFINITY; 2];
        for p in &space.polygon {
            for k in 0..2 {
                min[k] = min[k].min(p[k]);
                max[k] = max[k].max(p[k]);
            }
        }
        let convex = (space.holes.is_empty() && is_convex(&space.polygon)).then(|| {
            let mut ring = space.polygon.clone();
            if polygon_area(&ring) < 0.0 {
                ring.reverse();
            }
            ring
        });
        Shape {
            id: space.id,
            convex,
            edges: Edges::new(&rings.iter().map(Vec::as_slice).collect::<Vec<_>>()),
            hull: convex_hull(&space.polygon),
            rings,
            area,
            min,
            max,
        }
    }

    fn bbox_meets(&self, other: &Shape) -> bool {
        (0..2).all(|k| self.min[k] < other.max[k] && other.min[k] < self.max[k])
    }

    fn intersection_area(&self, other: &Shape) -> f64 {
        if !self.bbox_meets(other) {
            return 0.0;
        }
        if self.rings == other.rings {
            return self.area;
        }
        if hulls_apart(&self.hull, &other.hull) {
            return 0.0;
        }
        match (&self.convex, &other.convex) {
            (Some(a), Some(b)) => clipped_area(a, b),
            _ => intersection_area_of(&self.edges, &other.edges),
        }
    }

    fn iou(&self, other: &Shape) -> f64 {
        let inter = self.intersection_area(other);
        let union = self.area + other.area - inter;
        if union > 0.0 && inter.is_finite() {
            (inter / union).clamp(0.0, 1.0)
        } else {
            0.0
        }
    }
}

/// Whether two convex counter-clockwise hulls have a separating axis (an
/// edge normal of either along which their projections do not overlap):
/// then the polygons inside them share no area (separating axis theorem).
fn hulls_apart(a: &[Point], b: &[Point]) -> bool {
    if a.len() < 3 || b.len() < 3 {
        return false;
    }
    let project = |poly: &[Point], n: Point| {
        poly.iter()
            .map(|p| p[0] * n[0] + p[1] * n[1])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            })
    };
    [a, b].iter().any(|poly| {
        (0..poly.len()).any(|i| {
            let (p, q) = (poly[i], poly[(i + 1) % poly.len()]);
            let n = [q[1] - p[1], p[0] - q[0]];
            let ((alo, ahi), (blo, bhi)) = (project(a, n), project(b, n));
            ahi <= blo || bhi <= alo
        })
    })
}

/// A uniform grid over bounding boxes (cell = the mean box size), so
/// candidate pairs cost about O(n) instead of O(n²) on large models.
struct BoxGrid {
    cell: f64,
    cells: HashMap<(i64, i64), Vec<usize>>,
    /// Shapes covering too many cells, checked against everything.
    huge: Vec<usize>,
}

/// Past this many cells a shape goes to [`BoxGrid::huge`].
const MAX_CELLS_PER_SHAPE: i64 = 4096;

impl BoxGrid {
    fn new(shapes: &[Shape]) -> BoxGrid {
        let sizes: Vec<f64> = shapes
            .iter()
            .map(|s| (s.max[0] - s.min[0]).max(s.max[1] - s.min[1]))
            .filter(|d| d.is_finite() && *d > 0.0)
            .collect();
        let mean = sizes.iter().sum::<f64>() / sizes.len().max(1) as f64;
        let cell = if mean > 0.0 { mean } else { 1.0 };
        let mut grid = BoxGrid {
            cell,
            cells: HashMap::new(),
            huge: Vec::new(),
        };
        for (i, s) in shapes.iter().enumerate() {
            match grid.range(s) {
                Some((x0, y0, x1, y1)) => {
                    for cx in x0..=x1 {
                        for cy in y0..=y1 {
                            grid.cells.entry((cx, cy)).or_default().push(i);
                        }
                    }
                }
                None => grid.huge.push(i),
            }
        }
        grid
    }

    /// The cells a shape's box covers, or None when there are too many.
    fn range(&self, s: &Shape) -> Option<(i64, i64, i64, i64)> {
        let to_cell = |v: f64| (v / self.cell).floor() as i64;
        let (x0, y0) = (to_cell(s.min[0]), to_cell(s.min[1]));
        let (x1, y1) = (to_cell(s.max[0]), to_cell(s.max[1]));
        // Checked: a box near ±1e308 saturates the casts to i64::MIN/MAX,
        // and `x1 - x0 + 1` wrapped to a negative count that passed the
        // bound (an import looped for ever holding the write lock).
        let span = |lo: i64, hi: i64| hi.checked_sub(lo)?.checked_add(1);
        let count = span(x0, x1)?.checked_mul(span(y0, y1)?)?;
        (s.min.iter().chain(&s.max).all(|v| v.is_finite())
            && (1..=MAX_CELLS_PER_SHAPE).contains(&count))
        .then_some((x0, y0, x1, y1))
    }

    /// Indices of the shapes whose cells meet `s`'s cells (sorted, unique).
    fn candidates(&self, s: &Shape, out: &mut Vec<usize>) {
        out.clear();
        out.extend_from_slice(&self.huge);
        match self.range(s) {
            Some((x0, y0, x1, y1)) => {
                for cx in x0..=x1 {
                    for cy in y0..=y1 {
                        if let Some(v) = self.cells.get(&(cx, cy)) {
                            out.extend_from_slice(v);
                        }
                    }
                }
            }
            None => out.extend(self.cells.values().flatten()),
        }
        out.sort_unstable();
        out.dedup();
    }
}

/// Whether a ring is convex (all turns the same way; collinear points
/// allowed).
fn is_convex(ring: &Ring) -> bool {
    let n = ring.len();
    if n < 3 {
        return false;
    }
    let (mut pos, mut neg) = (false, false);
    for i in 0..n {
        let [a, b, c] = [ring[i], ring[(i + 1) % n], ring[(i + 2) % n]];
        let cross = (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
        pos |= cross > 0.0;
        neg |= cross < 0.0;
    }
    !(pos && neg)
}

/// Area of the intersection of two convex counter-clockwise rings by
/// Sutherland–Hodgman clipping of `subject` against each edge of `clip`
/// (Sutherland & Hodgman 1974, "Reentrant polygon clipping").
fn clipped_area(subject: &Ring, clip: &Ring) -> f64 {
    let mut output: Vec<Point> = subject.clone();
    let n = clip.len();
    for i in 0..n {
        if output.is_empty() {
            return 0.0;
        }
        let (a, b) = (clip[i], clip[(i + 1) % n]);
        let side = |p: Point| (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        let input = std::mem::take(&mut output);
        let m = input.len();
        for k in 0..m {
            let (p, q) = (input[k], input[(k + 1) % m]);
            let (sp, sq) = (side(p), side(q));
            if sp >= 0.0 {
                output.push(p);
            }
            if (sp >= 0.0) != (sq >= 0.0) {
                let t = sp / (sp - sq);
                output.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
            }
        }
    }
    polygon_area(&output).abs()
}

/// Splits the bipartite edge list into connected components (union-find
/// over old indices `0..n_old` and new indices `n_old..n_old+n_new`).
fn components(
    edges: &[(usize, usize, f64)],
    n_old: usize,
    n_new: usize,
) -> Vec<Vec<(usize, usize, f64)>> {
    let mut parent: Vec<usize> = (0..n_old + n_new).collect();
    fn find(parent: &mut [usize], mut x: usize) -> usize {
        while parent[x] != x {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        x
    }
    for &(i, j, _) in edges {
        let (a, b) = (find(&mut parent, i), find(&mut parent, n_old + j));
        if a != b {
            parent[a] = b;
        }
    }
    let mut groups: BTreeMap<usize, Vec<(usize, usize, f64)>> = BTreeMap::new();
    for &(i, j, iou) in edges {
        let root = find(&mut parent, i);
        groups.entry(root).or_default().push((i, j, iou));
    }
    groups.into_values().collect()
}

/// Spaces on one side of a component past which it is matched greedily:
/// Kuhn–Munkres needs an n×n matrix and n³ steps.
pub const MAX_OPTIMAL_COMPONENT: usize = 500;

/// Optimal one-to-one assignment inside one component, maximising the
/// summed IoU (scaled to integers for Kuhn–Munkres); greedy past
/// [`MAX_OPTIMAL_COMPONENT`].
fn assign(component: &[(usize, usize, f64)]) -> Vec<(usize, usize, f64)> {
    if let [only] = component {
        return vec![*only];
    }
    let mut olds: Vec<usize> = component.iter().map(|e| e.0).collect();
    let mut news: Vec<usize> = component.iter().map(|e| e.1).collect();
    olds.sort_unstable();
    olds.dedup();
    news.sort_unstable();
    news.dedup();
    let n = olds.len().max(news.len());
    if n > MAX_OPTIMAL_COMPONENT {
        return assign_greedily(component);
    }
    let mut weights = Matrix::new(n, n, 0_i64);
    let mut iou_of = BTreeMap::new();
    for &(i, j, iou) in component {
        let (Ok(r), Ok(c)) = (olds.binary_search(&i), news.binary_search(&j)) else {
            continue;
        };
        // 1e9 keeps six significant digits of IoU and cannot overflow i64
        // for any component this side of 10^9 spaces.
        weights[(r, c)] = (iou * 1e9).round() as i64;
        iou_of.insert((r, c), iou);
    }
    let (_, columns) = kuhn_munkres(&weights);
    let mut out = Vec::new();
    for (r, &c) in columns.iter().enumerate() {
        if let Some(&iou) = iou_of.get(&(r, c)) {
            out.push((olds[r], news[c], iou));
        }
    }
    out
}

/// One-to-one assignment taking the edges by falling IoU (then by index,
/// so the result does not depend on the edges' order).
fn assign_greedily(component: &[(usize, usize, f64)]) -> Vec<(usize, usize, f64)> {
    let mut edges = component.to_vec();
    edges.sort_by(|a, b| b.2.total_cmp(&a.2).then((a.0, a.1).cmp(&(b.0, b.1))));
    let (mut old_done, mut new_done) = (BTreeSet::new(), BTreeSet::new());
    let mut out = Vec::new();
    for (i, j, iou) in edges {
        if !old_done.contains(&i) && !new_done.contains(&j) {
            old_done.insert(i);
            new_done.insert(j);
            out.push((i, j, iou));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::SpaceKind;

    /// Issue 21, defect 8: a component of 600 spaces piled over 600 (every
    /// pair overlapping) is matched one-to-one without Kuhn–Munkres' n×n
    /// matrix; `match_spaces_within` gives up past its bound instead of
    /// measuring every pair.
    #[test]
    fn issue_21_defect_8_piled_spaces_are_matched_within_bounds() {
        let pile =
            |n: u32, dx: f64| nrg((1..=n).map(|k| rect(k, dx, 0.0, dx + 2.0, 2.0)).collect());
        let (old, new) = (pile(600, 0.0), pile(600, 0.1));
        let m = match_spaces(&old, &new, &MatchParams::default());
        assert_eq!(m.len(), 600);
        let olds: BTreeSet<SpaceId> = m.iter().map(|m| m.old).collect();
        assert_eq!(olds.len(), 600);
        let params = MatchParams::default();
        assert!(match_spaces_within(&old, &new, &params, 100_000).is_none());
        assert!(match_spaces_within(&old, &new, &params, 360_000).is_some());
    }

    fn rect(id: u32, x0: f64, y0: f64, x1: f64, y1: f64) -> Space {
        let poly = vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]];
        Space::new(
            SpaceId(id),
            SpaceKind::Room,
            [(x0 + x1) / 2.0, (y0 + y1) / 2.0],
            poly,
        )
    }

    fn nrg(spaces: Vec<Space>) -> Nrg {
        Nrg::new(spaces, vec![]).unwrap()
    }

    /// Issue 21, defect 3: far-flung coordinates made the cell count wrap
    /// and matching loop for ever. Spaces at the model's coordinate limit
    /// match like any others.
    #[test]
    fn far_coordinates_match_without_wrapping() {
        let far = crate::model::MAX_COORD_M;
        let a = nrg(vec![
            rect(1, -far, -far, -far + 4.0, -far + 3.0),
            rect(2, far - 4.0, far - 3.0, far, far),
            rect(3, -far, -far, far, far),
        ]);
        let m = match_spaces(&a, &a, &MatchParams::default());
        assert_eq!(m.len(), 3);
        assert!(m.iter().all(|m| m.old == m.new));
    }

    #[test]
    fn identical_models_match_one_to_one() {
        let a = nrg(vec![
            rect(1, 0.0, 0.0, 4.0, 3.0),
            rect(2, 4.0, 0.0, 8.0, 3.0),
        ]);
        let m = match_spaces(&a, &a, &MatchParams::default());
        assert_eq!(m.len(), 2);
        assert!(
            m.iter()
                .all(|m| m.old == m.new && (m.iou - 1.0).abs() < 1e-12)
        );
    }

    #[test]
    fn split_room_keeps_identity_in_the_larger_part() {
        let old = nrg(vec![
            rect(1, 0.0, 0.0, 10.0, 4.0),
            rect(2, 10.0, 0.0, 14.0, 4.0),
        ]);
        let new = nrg(vec![
            rect(10, 0.0, 0.0, 4.0, 4.0),   // small part of 1
            rect(11, 4.0, 0.0, 10.0, 4.0),  // large part of 1
            rect(12, 10.1, 0.0, 14.1, 4.0), // 2, shifted
        ]);
        let m = match_spaces(&old, &new, &MatchParams::default());
        let pairs: Vec<(u32, u32)> = m.iter().map(|m| (m.new.0, m.old.0)).collect();
        assert_eq!(pairs, vec![(11, 1), (12, 2)]);
        assert!((m[0].iou - 0.6).abs() < 1e-9);
    }

    #[test]
    fn optimal_assignment_beats_greedy() {
        // Greedy takes the best pair first (10-1, iou 0.67) and is left
        // with 11-2 (0.14); the optimum pairs 10-2 (0.54) and 11-1 (0.6).
        let old = nrg(vec![
            rect(1, 0.0, 0.0, 2.0, 1.0),
            rect(2, 1.0, 0.0, 3.0, 1.0),
        ]);
        let new = nrg(vec![
            rect(10, 0.4, 0.0, 2.4, 1.0),
            rect(11, -0.5, 0.0, 1.5, 1.0),
        ]);
        let m = match_spaces(
            &old,
            &new,
            &MatchParams {
                min_iou: 0.1,
                ..MatchParams::default()
            },
        );
        let pairs: Vec<(u32, u32)> = m.iter().map(|m| (m.new.0, m.old.0)).collect();
        assert_eq!(pairs, vec![(10, 2), (11, 1)]);
    }

    #[test]
    fn small_overlap_is_not_a_match() {
        let old = nrg(vec![rect(1, 0.0, 0.0, 4.0, 4.0)]);
        let new = nrg(vec![rect(5, 3.5, 0.0, 7.5, 4.0)]);
        assert!(match_spaces(&old, &new, &MatchParams::default()).is_empty());
    }

    #[test]
    fn convex_fast_path_agrees_with_boolean_ops() {
        let shapes = [
            vec![[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]],
            vec![[1.0, -1.0], [5.0, 1.0], [3.0, 4.0]],
            vec![[2.0, 2.0], [2.0, 0.5], [6.0, 0.5], [6.0, 2.0]], // clockwise
            vec![[-1.0, 1.0], [1.0, -1.0], [3.0, 1.0], [1.0, 3.0]],
            vec![[0.0, 0.0], [2.0, 0.0], [4.0, 0.0], [4.0, 1.0]], // collinear run
            vec![[10.0, 10.0], [11.0, 10.0], [11.0, 11.0]],       // disjoint
        ];
        for a in &shapes {
            for b in &shapes {
                let (sa, sb) = (
                    Shape::new(&Space::new(
                        SpaceId(1),
                        SpaceKind::Room,
                        [0.0, 0.0],
                        a.clone(),
                    )),
                    Shape::new(&Space::new(
                        SpaceId(2),
                        SpaceKind::Room,
                        [0.0, 0.0],
                        b.clone(),
                    )),
                );
                let (ca, cb) = (sa.convex.clone().unwrap(), sb.convex.clone().unwrap());
                let fast = clipped_area(&ca, &cb);
                let exact = intersection_area_of(&sa.edges, &sb.edges);
                // Clipping and the slab sweep agree to rounding.
                assert!(
                    (fast - exact).abs() < 1e-6,
                    "{a:?} & {b:?}: {fast} vs {exact}"
                );
            }
        }
        let l_shape = vec![
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ];
        assert!(!is_convex(&l_shape));
    }

    #[test]
    fn hulls_apart_only_when_separable() {
        let sq =
            |x: f64, y: f64| convex_hull(&[[x, y], [x + 1.0, y], [x + 1.0, y + 1.0], [x, y + 1.0]]);
        assert!(hulls_apart(&sq(0.0, 0.0), &sq(1.0, 0.0))); // touching
        assert!(hulls_apart(&sq(0.0, 0.0), &sq(1.5, 1.5)));
        assert!(!hulls_apart(&sq(0.0, 0.0), &sq(0.5, 0.5)));
        let tri = convex_hull(&[[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]]);
        // Inside the triangle's box, beyond its hypotenuse: apart.
        assert!(hulls_apart(&tri, &sq(2.6, 2.6)));
        assert!(!hulls_apart(&tri, &sq(1.4, 1.4)));
    }

    #[test]
    fn holes_reduce_the_overlap() {
        let mut ring = rect(1, 0.0, 0.0, 4.0, 4.0);
        ring.holes = vec![vec![[1.0, 1.0], [3.0, 1.0], [3.0, 3.0], [1.0, 3.0]]];
        ring.update_area();
        let full = rect(2, 0.0, 0.0, 4.0, 4.0);
        assert!((overlap_iou(&ring, &full) - 12.0 / 16.0).abs() < 1e-9);
    }
}
