//! Route fidelity: how close a router's walks between rooms are to the
//! free-space geodesic, and whether they stay inside the spaces.
//!
//! Owns [`route_fidelity`] and its report. The router is any function from
//! two points to `(length_m, polyline)`, so the harness measures whatever
//! routing layer is plugged in; the yardstick is
//! [`FreeSpaceGrid`](super::FreeSpaceGrid), which shares no code with
//! `route`. Uses `model` and `sim` (for the seeded generator); must not use
//! `route`.

use serde::Serialize;

use super::geodesic::FreeSpaceGrid;
use crate::model::{Nrg, Point, Ring, Space, SpaceId, SpaceKind, point_in_ring};
use crate::sim::SplitMix64;

/// Distance between two samples along a route's polyline, metres.
pub const SAMPLE_STEP_M: f64 = 0.02;

/// A sample this close to a space's boundary counts as inside it, metres.
pub const BOUNDARY_TOLERANCE_M: f64 = 1e-6;

/// A route's reported length and its polyline's length may differ by this
/// much, relative.
pub const LENGTH_TOLERANCE: f64 = 1e-6;

/// The router under test: from one point to another, `(length_m,
/// polyline)`, or `None` when it finds no route.
pub type Router<'a> = &'a dyn Fn(Point, Point) -> Option<(f64, Vec<Point>)>;

/// One pair of spaces routed anchor to anchor.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PairFidelity {
    /// The start space.
    pub from: SpaceId,
    /// The goal space.
    pub to: SpaceId,
    /// The length the router reported, if it found a route.
    pub route_m: Option<f64>,
    /// The length of the router's polyline.
    pub polyline_m: Option<f64>,
    /// Whether the two agree within [`LENGTH_TOLERANCE`].
    pub length_consistent: Option<bool>,
    /// The free-space geodesic between the anchors, if there is one.
    pub geodesic_m: Option<f64>,
    /// `route_m / geodesic_m`, when both exist.
    pub ratio: Option<f64>,
    /// Samples taken along the polyline (every [`SAMPLE_STEP_M`], both ends).
    pub samples: usize,
    /// The share of those samples in no space.
    pub outside_fraction: Option<f64>,
}

/// Figures over many pairs (see [`FidelitySummary::of`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FidelitySummary {
    /// Pairs tried.
    pub pairs: usize,
    /// Pairs where the router found a route.
    pub routes: usize,
    /// Pairs with both a route and a geodesic (those with a ratio).
    pub n: usize,
    /// Median ratio (linear interpolation between order statistics).
    pub median_ratio: Option<f64>,
    /// 90th percentile ratio.
    pub p90_ratio: Option<f64>,
    /// Largest ratio.
    pub max_ratio: Option<f64>,
    /// Routes with at least one sample outside every space.
    pub routes_outside: usize,
    /// Largest outside fraction of a route.
    pub max_outside_fraction: f64,
    /// Pairs where exactly one of router and geodesic found a way.
    pub one_sided: usize,
    /// Routes whose reported length is not their polyline's.
    pub length_mismatches: usize,
}

impl FidelitySummary {
    /// Summarises `pairs` (which may come from several models).
    pub fn of(pairs: &[PairFidelity]) -> FidelitySummary {
        let mut ratios: Vec<f64> = pairs.iter().filter_map(|p| p.ratio).collect();
        ratios.sort_by(f64::total_cmp);
        FidelitySummary {
            pairs: pairs.len(),
            routes: pairs.iter().filter(|p| p.route_m.is_some()).count(),
            n: ratios.len(),
            median_ratio: quantile(&ratios, 0.5),
            p90_ratio: quantile(&ratios, 0.9),
            max_ratio: ratios.last().copied(),
            routes_outside: pairs
                .iter()
                .filter(|p| p.outside_fraction.is_some_and(|f| f > 0.0))
                .count(),
            max_outside_fraction: pairs
                .iter()
                .filter_map(|p| p.outside_fraction)
                .fold(0.0, f64::max),
            one_sided: pairs
                .iter()
                .filter(|p| p.route_m.is_some() != p.geodesic_m.is_some())
                .count(),
            length_mismatches: pairs
                .iter()
                .filter(|p| p.length_consistent == Some(false))
                .count(),
        }
    }
}

/// What [`route_fidelity`] measured on one model.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FidelityReport {
    /// The geodesic raster's cell size, metres.
    pub cell_m: f64,
    /// The gap bridged between spaces, metres (0: the exact union).
    pub gap_m: f64,
    /// The seed the pairs were drawn with.
    pub seed: u64,
    /// Why the geodesic raster was refused, if it was; then every
    /// `geodesic_m` is `None` and `one_sided` says nothing.
    pub raster_error: Option<String>,
    /// The figures.
    pub summary: FidelitySummary,
    /// Each pair.
    pub pairs: Vec<PairFidelity>,
}

/// Routes `pairs` random distinct pairs of rooms of `nrg` (rooms and
/// corridors when there are fewer than two rooms; all pairs when there are
/// fewer) anchor to anchor with `router`, and measures each route against
/// the free-space geodesic on a raster of `cell_m` metres: the length
/// ratio, the share of the polyline outside every space (sampled every
/// [`SAMPLE_STEP_M`]; a sample within [`BOUNDARY_TOLERANCE_M`] of a space's
/// boundary is inside it), and whether the reported length is the
/// polyline's. The pairs are deterministic in `seed` ([`SplitMix64`]).
pub fn route_fidelity(
    nrg: &Nrg,
    pairs: usize,
    seed: u64,
    cell_m: f64,
    router: Router<'_>,
) -> FidelityReport {
    route_fidelity_with_gap(nrg, pairs, seed, cell_m, 0.0, router)
}

/// [`route_fidelity`] on a model whose spaces do not quite touch: the
/// geodesic raster bridges gaps of about `2 gap_m`
/// ([`FreeSpaceGrid::with_gap`]) and a sample within `gap_m` of a space
/// (rather than [`BOUNDARY_TOLERANCE_M`]) counts as inside it. Use about
/// one map pixel for extracted models, 0 for exact ones.
pub fn route_fidelity_with_gap(
    nrg: &Nrg,
    pairs: usize,
    seed: u64,
    cell_m: f64,
    gap_m: f64,
    router: Router<'_>,
) -> FidelityReport {
    let (grid, raster_error) = match FreeSpaceGrid::with_gap(nrg, cell_m, gap_m) {
        Ok(g) => (Some(g), None),
        Err(e) => (None, Some(e.to_string())),
    };
    let spaces = SpaceIndex::new(nrg, gap_m.max(BOUNDARY_TOLERANCE_M));
    let measured: Vec<PairFidelity> = pick_pairs(nrg, pairs, seed)
        .into_iter()
        .map(|(a, b)| {
            let geodesic_m = grid
                .as_ref()
                .and_then(|g| g.shortest_path(a.anchor, b.anchor))
                .map(|p| p.length_m);
            measure_pair(&spaces, a, b, geodesic_m, router)
        })
        .collect();
    let mut summary = FidelitySummary::of(&measured);
    if raster_error.is_some() {
        summary.one_sided = 0;
    }
    FidelityReport {
        cell_m,
        gap_m,
        seed,
        raster_error,
        summary,
        pairs: measured,
    }
}

fn measure_pair(
    spaces: &SpaceIndex<'_>,
    a: &Space,
    b: &Space,
    geodesic_m: Option<f64>,
    router: Router<'_>,
) -> PairFidelity {
    let route = router(a.anchor, b.anchor);
    let polyline_m = route.as_ref().map(|(_, line)| polyline_length(line));
    let (samples, outside_fraction) = match &route {
        Some((_, line)) => {
            let points = sample_polyline(line, SAMPLE_STEP_M);
            let outside = points.iter().filter(|&&p| !spaces.contains(p)).count();
            let fraction = (!points.is_empty()).then(|| outside as f64 / points.len() as f64);
            (points.len(), fraction)
        }
        None => (0, None),
    };
    let route_m = route.map(|(len, _)| len);
    let length_consistent = route_m
        .zip(polyline_m)
        .map(|(r, p)| (r - p).abs() <= LENGTH_TOLERANCE * r.abs().max(p.abs()) + f64::MIN_POSITIVE);
    let ratio = route_m
        .zip(geodesic_m)
        .filter(|&(_, g)| g > 0.0)
        .map(|(r, g)| r / g);
    PairFidelity {
        from: a.id,
        to: b.id,
        route_m,
        polyline_m,
        length_consistent,
        geodesic_m,
        ratio,
        samples,
        outside_fraction,
    }
}

/// `count` distinct unordered pairs of rooms (or rooms and corridors),
/// drawn by a partial Fisher–Yates shuffle of all pairs.
fn pick_pairs(nrg: &Nrg, count: usize, seed: u64) -> Vec<(&Space, &Space)> {
    let of_kinds = |kinds: &[SpaceKind]| -> Vec<&Space> {
        nrg.spaces()
            .iter()
            .filter(|s| kinds.contains(&s.kind))
            .collect()
    };
    let mut ends = of_kinds(&[SpaceKind::Room]);
    if ends.len() < 2 {
        ends = of_kinds(&[SpaceKind::Room, SpaceKind::Corridor]);
    }
    let mut all: Vec<(usize, usize)> = (0..ends.len())
        .flat_map(|i| (i + 1..ends.len()).map(move |j| (i, j)))
        .collect();
    let take = count.min(all.len());
    let mut rng = SplitMix64::new(seed);
    for k in 0..take {
        let pick = rng.int(k, all.len() - 1);
        all.swap(k, pick);
    }
    all.truncate(take);
    all.into_iter().map(|(i, j)| (ends[i], ends[j])).collect()
}

/// The length of a polyline, metres.
pub fn polyline_length(line: &[Point]) -> f64 {
    line.windows(2).map(|w| distance(w[0], w[1])).sum()
}

/// Points along `line` every `step` metres of arc length from its start,
/// plus its last point (a single point for a one-point line, none for an
/// empty one).
pub fn sample_polyline(line: &[Point], step: f64) -> Vec<Point> {
    let Some(&last) = line.last() else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let (mut k, mut walked) = (0u64, 0.0);
    for w in line.windows(2) {
        let len = distance(w[0], w[1]);
        loop {
            let s = k as f64 * step - walked;
            if s > len || len == 0.0 {
                break;
            }
            let t = s / len;
            out.push([
                w[0][0] + t * (w[1][0] - w[0][0]),
                w[0][1] + t * (w[1][1] - w[0][1]),
            ]);
            k += 1;
        }
        walked += len;
    }
    if out.last().is_none_or(|&p| distance(p, last) > 1e-9) {
        out.push(last);
    }
    out
}

/// The spaces with their bounding boxes, for "is this point in any space".
struct SpaceIndex<'a> {
    spaces: Vec<([f64; 4], &'a Space)>,
    tolerance_m: f64,
}

impl<'a> SpaceIndex<'a> {
    fn new(nrg: &'a Nrg, tolerance_m: f64) -> SpaceIndex<'a> {
        let t = tolerance_m;
        let spaces = nrg
            .spaces()
            .iter()
            .filter_map(|s| {
                let first = s.polygon.first()?;
                let b = s
                    .polygon
                    .iter()
                    .fold([first[0], first[1], first[0], first[1]], |b, p| {
                        [
                            b[0].min(p[0]),
                            b[1].min(p[1]),
                            b[2].max(p[0]),
                            b[3].max(p[1]),
                        ]
                    });
                Some(([b[0] - t, b[1] - t, b[2] + t, b[3] + t], s))
            })
            .collect();
        SpaceIndex {
            spaces,
            tolerance_m,
        }
    }

    /// Whether `p` is in some space: inside or on (within the tolerance)
    /// the exterior and not strictly inside a hole.
    fn contains(&self, p: Point) -> bool {
        self.spaces.iter().any(|(b, s)| {
            p[0] >= b[0]
                && p[0] <= b[2]
                && p[1] >= b[1]
                && p[1] <= b[3]
                && in_or_on(p, &s.polygon, self.tolerance_m)
                && !s.holes.iter().any(|h| strictly_in(p, h, self.tolerance_m))
        })
    }
}

fn in_or_on(p: Point, ring: &Ring, tolerance_m: f64) -> bool {
    point_in_ring(p, ring) || distance_to_ring(p, ring) <= tolerance_m
}

fn strictly_in(p: Point, ring: &Ring, tolerance_m: f64) -> bool {
    point_in_ring(p, ring) && distance_to_ring(p, ring) > tolerance_m
}

/// Distance from `p` to the nearest edge of the (closed) ring.
fn distance_to_ring(p: Point, ring: &[Point]) -> f64 {
    let n = ring.len();
    (0..n)
        .map(|i| distance_to_segment(p, ring[i], ring[(i + 1) % n]))
        .fold(f64::INFINITY, f64::min)
}

fn distance_to_segment(p: Point, a: Point, b: Point) -> f64 {
    let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
    let len2 = ex * ex + ey * ey;
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    distance(p, [a[0] + t * ex, a[1] + t * ey])
}

/// The `q` quantile of sorted values (linear between order statistics).
fn quantile(sorted: &[f64], q: f64) -> Option<f64> {
    let last = sorted.len().checked_sub(1)?;
    let x = q * last as f64;
    let (lo, hi) = (x.floor() as usize, x.ceil() as usize);
    Some(sorted[lo] + (x - lo as f64) * (sorted[hi] - sorted[lo]))
}

fn distance(a: Point, b: Point) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn samples_every_step_and_the_end() {
        let line = [[0.0, 0.0], [0.05, 0.0], [0.05, 0.03]];
        let s = sample_polyline(&line, 0.02);
        // arc 0, .02, .04, .06, .08 and the end at .08
        assert_eq!(s.len(), 5);
        assert!(distance(s[3], [0.05, 0.01]) < 1e-12);
        assert_eq!(sample_polyline(&[[1.0, 2.0]], 0.02), vec![[1.0, 2.0]]);
        assert!(sample_polyline(&[], 0.02).is_empty());
    }

    #[test]
    fn quantiles_interpolate() {
        let v = [1.0, 2.0, 3.0, 4.0, 5.0];
        assert_eq!(quantile(&v, 0.5), Some(3.0));
        assert!((quantile(&v, 0.9).unwrap() - 4.6).abs() < 1e-12);
        assert_eq!(quantile(&[], 0.5), None);
    }

    #[test]
    fn boundary_counts_as_inside_and_holes_as_outside() {
        let ring = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        let mut s = Space::new(SpaceId(1), SpaceKind::Room, [0.5, 0.5], ring);
        s.holes
            .push(vec![[1.0, 1.0], [1.0, 3.0], [3.0, 3.0], [3.0, 1.0]]);
        let nrg = Nrg::new(vec![s], vec![]).unwrap();
        let index = SpaceIndex::new(&nrg, BOUNDARY_TOLERANCE_M);
        for p in [[4.0, 2.0], [2.0, 4.0], [0.0, 0.0], [1.0, 2.0], [0.5, 0.5]] {
            assert!(index.contains(p), "{p:?}");
        }
        for p in [[4.001, 2.0], [2.0, 2.0], [-1e-5, 1.0]] {
            assert!(!index.contains(p), "{p:?}");
        }
    }
}
