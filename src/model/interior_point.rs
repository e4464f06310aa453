//! A stable interior point of a polygon with holes: the pole of
//! inaccessibility, the centre of (nearly) the largest inscribed circle —
//! the polylabel algorithm (Agafonkin, Mapbox 2016): quadtree cells over
//! the bounding box, searched best-first by the distance an inner point of
//! the cell could reach, until no cell can beat the best by `precision`.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use super::geometry::{Point, point_in_ring, polygon_centroid, segment_distance};

/// Signed distance from `p` to the polygon's boundary: positive inside
/// (exterior minus holes), negative outside.
fn signed_distance(p: Point, exterior: &[Point], holes: &[Vec<Point>]) -> f64 {
    let inside = point_in_ring(p, exterior) && !holes.iter().any(|h| point_in_ring(p, h));
    let mut best = f64::INFINITY;
    for ring in std::iter::once(exterior).chain(holes.iter().map(Vec::as_slice)) {
        let n = ring.len();
        for i in 0..n {
            best = best.min(segment_distance(p, ring[i], ring[(i + 1) % n]));
        }
    }
    if inside { best } else { -best }
}

#[derive(Debug, Clone, Copy)]
struct Cell {
    centre: Point,
    half: f64,
    distance: f64,
    /// The most any point of the cell can be from the boundary.
    bound: f64,
}

impl Cell {
    fn new(centre: Point, half: f64, exterior: &[Point], holes: &[Vec<Point>]) -> Cell {
        let distance = signed_distance(centre, exterior, holes);
        Cell {
            centre,
            half,
            distance,
            bound: distance + half * std::f64::consts::SQRT_2,
        }
    }
}

impl PartialEq for Cell {
    fn eq(&self, other: &Cell) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Cell {}
impl PartialOrd for Cell {
    fn partial_cmp(&self, other: &Cell) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Cell {
    fn cmp(&self, other: &Cell) -> Ordering {
        // Best bound first; ties by position so the order is total and
        // does not depend on insertion order.
        self.bound
            .total_cmp(&other.bound)
            .then(other.centre[0].total_cmp(&self.centre[0]))
            .then(other.centre[1].total_cmp(&self.centre[1]))
    }
}

/// Most cells examined (bounds the work on huge or degenerate input).
const MAX_CELLS: usize = 100_000;

/// Most point-to-segment distances one search computes (each cell costs
/// one per edge): a 500 000-vertex outline examines 400 cells, not 100 000
/// (minutes).
const MAX_DISTANCES: usize = 200_000_000;

/// About the most cells the search starts from (see
/// [`pole_of_inaccessibility`]).
const MAX_START_CELLS: usize = 4096;

/// The pole of inaccessibility of the polygon (`exterior` with `holes`),
/// to within `precision` metres of the best distance, and its distance to
/// the boundary. Of the points nearly as deep as the deepest (within
/// `2 × precision` and 1 %), the one nearest the polygon's centroid wins,
/// so a straight corridor's pole is its middle and a quarter turn of the
/// map turns the pole with it. `None` for fewer than three points or a
/// polygon whose extent overflows.
///
/// ```
/// use nrgdb::model::pole_of_inaccessibility;
/// // An L of 2 m wide legs: the widest spot is where the legs meet (a
/// // circle of radius ≈ 1.16 m), not the centroid (3.9, 1.9).
/// let l = vec![[0.0, 0.0], [10.0, 0.0], [10.0, 2.0], [2.0, 2.0], [2.0, 6.0], [0.0, 6.0]];
/// let (p, r) = pole_of_inaccessibility(&l, &[], 0.01).unwrap();
/// assert!(r > 1.1 && r < 1.2 && p[0] < 2.0 && p[1] < 2.0, "{p:?} {r}");
/// ```
pub fn pole_of_inaccessibility(
    exterior: &[Point],
    holes: &[Vec<Point>],
    precision: f64,
) -> Option<(Point, f64)> {
    if exterior.len() < 3 || exterior.iter().flatten().any(|c| !c.is_finite()) {
        return None;
    }
    let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
    for p in exterior {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
    if !(w.is_finite() && h.is_finite()) {
        return None;
    }
    let size = w.min(h);
    let precision = precision.max(1e-9);
    let centroid = polygon_centroid(exterior).unwrap_or(lo);
    let mut best = Cell::new(centroid, 0.0, exterior, holes);
    if size <= 0.0 {
        return Some((best.centre, best.distance.max(0.0)));
    }
    // Square cells as wide as the polygon's short side cover its box, but
    // no more than about MAX_START_CELLS of them (a sliver a kilometre
    // long and a micrometre wide would need billions): larger cells then.
    let limit = MAX_START_CELLS as f64;
    // (√w·√h: w·h overflows for coordinates near f64::MAX.)
    let cell = size
        .max(w.sqrt() * h.sqrt() / limit.sqrt())
        .max(w.max(h) / limit);
    let (nx, ny) = ((w / cell).ceil().max(1.0), (h / cell).ceil().max(1.0));
    let half = cell / 2.0;
    let mut queue = BinaryHeap::new();
    for i in 0..nx as usize {
        for j in 0..ny as usize {
            let corner = [lo[0] + i as f64 * cell, lo[1] + j as f64 * cell];
            queue.push(Cell::new(
                [corner[0] + half, corner[1] + half],
                half,
                exterior,
                holes,
            ));
        }
    }
    let edges = exterior.len() + holes.iter().map(Vec::len).sum::<usize>();
    let max_cells = (MAX_DISTANCES / edges.max(1)).clamp(64, MAX_CELLS);
    let mut seen = 0;
    let mut examined = vec![best];
    while let Some(cell) = queue.pop() {
        examined.push(cell);
        if cell.distance > best.distance + 1e-12 {
            best = cell;
        }
        if cell.bound - best.distance <= precision || seen >= max_cells {
            continue;
        }
        let h = cell.half / 2.0;
        for (dx, dy) in [(-h, -h), (h, -h), (-h, h), (h, h)] {
            queue.push(Cell::new(
                [cell.centre[0] + dx, cell.centre[1] + dy],
                h,
                exterior,
                holes,
            ));
            seen += 1;
        }
    }
    // Of the points nearly as deep as the best (a corridor's centre line is
    // a plateau), the one nearest the centroid: a rule that turns with the
    // map, unlike the search order.
    let tolerance = 2.0 * precision + 0.01 * best.distance.max(0.0);
    let pick = examined
        .iter()
        .filter(|c| c.distance >= best.distance - tolerance)
        .min_by(|a, b| {
            let d = |c: &Cell| (c.centre[0] - centroid[0]).hypot(c.centre[1] - centroid[1]);
            d(a).total_cmp(&d(b))
                .then(a.centre[0].total_cmp(&b.centre[0]))
                .then(a.centre[1].total_cmp(&b.centre[1]))
        })
        .copied()
        .unwrap_or(best);
    Some((pick.centre, pick.distance.max(0.0)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn turn(p: Point) -> Point {
        [-p[1], p[0]]
    }

    /// Found by the fuzz harness: an imported cell 1e300 m long and a
    /// fraction of a metre wide made the start grid allocate gigabytes.
    #[test]
    fn issue_21_slivers_and_huge_cells_start_from_a_bounded_grid() {
        // A thousand kilometres long and a millimetre wide: a billion start
        // cells before.
        let sliver = vec![[0.0, 0.0], [1e6, 0.0], [1e6, 1e-3], [0.0, 1e-3]];
        let (p, r) = pole_of_inaccessibility(&sliver, &[], 1e-4).unwrap();
        assert!(p[1] > 0.0 && p[1] < 1e-3, "{p:?}");
        assert!(r > 0.0 && r <= 5e-4 + 1e-9, "{r}");
        // At 1e300 m the arithmetic is noise; it must still end, soon.
        let huge = vec![[0.0, 0.0], [1e300, 0.0], [1e300, 0.5], [0.0, 0.5]];
        let _ = pole_of_inaccessibility(&huge, &[], 1e-3);
        let overflowing = vec![[-1e308, 0.0], [1e308, 0.0], [0.0, 1e308]];
        assert_eq!(pole_of_inaccessibility(&overflowing, &[], 1e-3), None);
        // Near f64::MAX but with a finite extent: w·h overflows, the
        // answer must not.
        let near_max = vec![[0.0, 0.0], [1e308, 0.0], [1e308, 1e308]];
        if let Some((p, r)) = pole_of_inaccessibility(&near_max, &[], 1e-3) {
            assert!(
                p.iter().all(|c| c.is_finite()) && r.is_finite(),
                "{p:?} {r}"
            );
        }
        // A 4 000 : 1 corridor keeps cells as wide as it is.
        let corridor = vec![[0.0, 0.0], [4000.0, 0.0], [4000.0, 1.0], [0.0, 1.0]];
        let (p, r) = pole_of_inaccessibility(&corridor, &[], 1e-3).unwrap();
        assert!(
            (r - 0.5).abs() < 2e-3 && (p[1] - 0.5).abs() < 2e-3,
            "{p:?} {r}"
        );
    }

    #[test]
    fn square_pole_is_its_centre() {
        let sq = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let (p, r) = pole_of_inaccessibility(&sq, &[], 1e-3).unwrap();
        assert!((p[0] - 2.0).abs() < 1e-2 && (p[1] - 2.0).abs() < 1e-2);
        assert!((r - 2.0).abs() < 1e-2);
    }

    #[test]
    fn a_hole_pushes_the_pole_aside() {
        let sq = vec![[0.0, 0.0], [6.0, 0.0], [6.0, 4.0], [0.0, 4.0]];
        let hole = vec![[2.0, 1.0], [2.0, 3.0], [4.0, 3.0], [4.0, 1.0]];
        let (p, r) = pole_of_inaccessibility(&sq, std::slice::from_ref(&hole), 1e-3).unwrap();
        assert!(signed_distance(p, &sq, &[hole]) > 0.0);
        // Within the 1 % the centroid tie-break may trade for centrality.
        assert!(r >= 0.98, "{r}");
    }

    #[test]
    fn a_quarter_turn_turns_the_pole() {
        let l = vec![
            [0.0, 0.0],
            [7.0, 0.0],
            [7.0, 3.0],
            [3.0, 3.0],
            [3.0, 5.0],
            [0.0, 5.0],
        ];
        let (p, r) = pole_of_inaccessibility(&l, &[], 1e-3).unwrap();
        let turned: Vec<Point> = l.iter().map(|q| turn(*q)).collect();
        let (q, s) = pole_of_inaccessibility(&turned, &[], 1e-3).unwrap();
        assert!((r - s).abs() < 2e-3);
        let tp = turn(p);
        assert!((tp[0] - q[0]).hypot(tp[1] - q[1]) < 0.05, "{tp:?} vs {q:?}");
    }
}
