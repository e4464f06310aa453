//! Alignment of two occupancy maps of one building from different mapping
//! runs: the rigid transform taking the second map's frame into the
//! first's, with a quality score, refused when unreliable.
//!
//! 1. Wall points: the boundary of the free space, as extraction sees it
//!    (free is the only class extraction trusts; everything else is
//!    obstacle): every cell that is not free and has a free 4-neighbour, in
//!    metres. Not "occupied cells next to free ones": on a clean drawn map
//!    the walls are anti-aliased, so a band of intermediate greys (classed
//!    unknown by the loader's ROS thresholds) always lies between the black
//!    core and the white floor and no occupied cell touches a free one
//!    (office_g: 159 159 occupied cells, none next to a free cell); some
//!    drawn maps have grey walls with no occupied cell at all.
//! 2. Rotation candidates: histograms of local wall directions (PCA of the
//!    wall points within 4 cells, 1° bins, mod 180°) are cross-correlated
//!    circularly; the best shift δ and its multiples of 90° (buildings are
//!    mostly rectilinear, so the histogram cannot tell them apart) and the
//!    second peak ± 180° are the candidates, each refined ±1° in 0.5° steps.
//! 3. Translation: for each candidate angle, a chamfer search (mean
//!    truncated distance to the reference walls, read from its Euclidean
//!    distance transform) over a ±`search_m` grid around the translation
//!    that lines up the wall centroids (Borgefors 1988, "Hierarchical
//!    chamfer matching").
//! 4. Refinement: point-to-point ICP (Besl & McKay 1992) with trimmed pairs
//!    and the closed-form 2D Procrustes step, from the three best distinct
//!    chamfer fits.
//! 5. Quality: the share of the moving map's wall points within
//!    `inlier_tol_m` of a reference wall. Below `min_inliers`, or when a
//!    different fit scores within `ambiguity_margin` of the best (a
//!    symmetric building), the alignment is refused.

use image::{GrayImage, Luma};
use rstar::RTree;

use super::error::DiffError;
use super::params::AlignParams;
use super::transform::RigidTransform;
use crate::grid::{Cell, OccupancyGrid};
use crate::imaging::squared_distance_to_foreground;
use crate::model::Point;

/// A rigid alignment and how well it fits.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Alignment {
    /// Moving-map metres → reference-map metres.
    pub transform: RigidTransform,
    /// Share of the moving map's wall points within `tolerance_m` of a
    /// reference wall (0..1).
    pub inliers: f64,
    /// RMS distance of the inliers, metres.
    pub rms_m: f64,
    /// The inlier distance used, metres.
    pub tolerance_m: f64,
}

/// Fewest wall points either map must have.
const MIN_WALLS: usize = 50;

/// Finds the rigid transform taking `moving`'s map frame onto
/// `reference`'s (see the module doc), or refuses with
/// [`DiffError::Unreliable`] / [`DiffError::TooFewWalls`].
pub fn align_grids(
    reference: &OccupancyGrid,
    moving: &OccupancyGrid,
    params: &AlignParams,
) -> Result<Alignment, DiffError> {
    let ref_walls = wall_points(reference);
    let mov_walls = wall_points(moving);
    for (which, walls) in [("first", &ref_walls), ("second", &mov_walls)] {
        if walls.len() < MIN_WALLS {
            return Err(DiffError::TooFewWalls {
                which,
                walls: walls.len(),
                needed: MIN_WALLS,
            });
        }
    }
    let res = reference.resolution.max(moving.resolution);
    let tol = params.inlier_tol_m.unwrap_or(2.0 * res);
    let tree = RTree::bulk_load(ref_walls.clone());
    let moving_pts = subsample(&mov_walls, params.max_points);
    let coarse_pts = subsample(&mov_walls, 400);
    let field = Field::new(&ref_walls, res.max(0.2), params.search_m + 2.0);

    // Rotation candidates.
    let h_ref = direction_histogram(
        &subsample(&ref_walls, 3000),
        &tree,
        4.0 * reference.resolution,
    );
    let h_mov = direction_histogram(
        &subsample(&mov_walls, 3000),
        &tree_of(&mov_walls),
        4.0 * moving.resolution,
    );
    let peaks = correlation_peaks(&h_ref, &h_mov);
    let mut angles: Vec<f64> = Vec::new();
    if let Some(&best) = peaks.first() {
        angles.extend((0..4).map(|k| best + 90.0 * f64::from(k)));
    }
    if let Some(&second) = peaks.get(1) {
        angles.extend([second, second + 180.0]);
    }
    let c_ref = centroid(&ref_walls);
    let c_mov = centroid(&mov_walls);
    let mut fits: Vec<(f64, RigidTransform)> = Vec::new();
    for base in angles {
        for step in -2..=2 {
            let deg = base + 0.5 * f64::from(step);
            fits.push(chamfer_search(
                &field,
                &coarse_pts,
                deg,
                c_ref,
                c_mov,
                params.search_m,
            ));
        }
    }
    fits.sort_by(|a, b| a.0.total_cmp(&b.0));
    // Three best distinct starts.
    let mut starts: Vec<RigidTransform> = Vec::new();
    for (_, t) in &fits {
        if starts.iter().all(|s| !close(s, t, 3.0, 1.0)) {
            starts.push(*t);
        }
        if starts.len() == 3 {
            break;
        }
    }
    let mut refined: Vec<Alignment> = starts
        .iter()
        .map(|t| {
            let t = icp(&tree, &moving_pts, *t, tol);
            quality(&tree, &moving_pts, t, tol)
        })
        .collect();
    refined.sort_by(|a, b| b.inliers.total_cmp(&a.inliers));
    let Some(best) = refined.first().copied() else {
        return Err(DiffError::Unreliable {
            inliers_pct: 0.0,
            needed_pct: 100.0 * params.min_inliers,
            tolerance_m: tol,
            ambiguity: String::new(),
        });
    };
    let rival = refined
        .iter()
        .skip(1)
        .find(|r| !close(&r.transform, &best.transform, 2.0, 0.5));
    let ambiguous = rival.filter(|r| r.inliers >= best.inliers - params.ambiguity_margin);
    if best.inliers < params.min_inliers || ambiguous.is_some() {
        return Err(DiffError::Unreliable {
            inliers_pct: 100.0 * best.inliers,
            needed_pct: 100.0 * params.min_inliers,
            tolerance_m: tol,
            ambiguity: ambiguous.map_or_else(String::new, |r| {
                format!(
                    ", and a different fit (rotation {:.1}°) reaches {:.0}%",
                    r.transform.rotation_deg(),
                    100.0 * r.inliers
                )
            }),
        });
    }
    Ok(best)
}

/// The share of `moving`'s walls that land within the inlier tolerance of
/// `reference`'s walls under `transform`: how well two maps already agree
/// (1 for a map and itself). Used to decide whether two maps share a frame.
pub fn alignment_quality(
    reference: &OccupancyGrid,
    moving: &OccupancyGrid,
    transform: RigidTransform,
    params: &AlignParams,
) -> Alignment {
    let ref_walls = wall_points(reference);
    let tol = params
        .inlier_tol_m
        .unwrap_or(2.0 * reference.resolution.max(moving.resolution));
    let tree = RTree::bulk_load(ref_walls);
    let pts = subsample(&wall_points(moving), params.max_points);
    quality(&tree, &pts, transform, tol)
}

/// The boundary of the free space: cells that are not free (occupied or
/// unknown) with a free 4-neighbour, as cell centres in metres (see the
/// module doc for why not only occupied cells).
///
/// ```
/// use nrgdb::grid::OccupancyGrid;
/// // A drawn wall: black core `#`, anti-aliased edge `?` (unknown), floor `.`.
/// let g = OccupancyGrid::from_ascii("...?#?...", 1.0);
/// assert_eq!(nrgdb::diff::wall_points(&g), vec![[3.5, 0.5], [5.5, 0.5]]);
/// ```
pub fn wall_points(grid: &OccupancyGrid) -> Vec<Point> {
    let (w, h) = (grid.width, grid.height);
    let mut out = Vec::new();
    for row in 0..h {
        for col in 0..w {
            if grid.cell(col, row) == Some(Cell::Free) {
                continue;
            }
            let free = |c: i64, r: i64| {
                u32::try_from(c)
                    .ok()
                    .zip(u32::try_from(r).ok())
                    .and_then(|(c, r)| grid.cell(c, r))
                    == Some(Cell::Free)
            };
            let (c, r) = (i64::from(col), i64::from(row));
            if free(c - 1, r) || free(c + 1, r) || free(c, r - 1) || free(c, r + 1) {
                out.push(grid.pixel_to_metres(f64::from(col) + 0.5, f64::from(row) + 0.5));
            }
        }
    }
    out
}

fn tree_of(points: &[Point]) -> RTree<Point> {
    RTree::bulk_load(points.to_vec())
}

fn subsample(points: &[Point], max: usize) -> Vec<Point> {
    if points.len() <= max || max == 0 {
        return points.to_vec();
    }
    let step = points.len() as f64 / max as f64;
    (0..max)
        .filter_map(|k| points.get((k as f64 * step) as usize).copied())
        .collect()
}

fn centroid(points: &[Point]) -> Point {
    let n = points.len().max(1) as f64;
    let s = points
        .iter()
        .fold([0.0, 0.0], |s, p| [s[0] + p[0], s[1] + p[1]]);
    [s[0] / n, s[1] / n]
}

fn close(a: &RigidTransform, b: &RigidTransform, deg: f64, m: f64) -> bool {
    let d = (a.rotation_deg() - b.rotation_deg() + 540.0).rem_euclid(360.0) - 180.0;
    d.abs() <= deg && (a.tx_m - b.tx_m).hypot(a.ty_m - b.ty_m) <= m
}

/// 180 one-degree bins of local wall direction, weighted by linearity,
/// smoothed over ±2 bins.
fn direction_histogram(points: &[Point], tree: &RTree<Point>, radius: f64) -> Vec<f64> {
    let mut h = vec![0.0; 180];
    for p in points {
        let (mut n, mut sx, mut sy, mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        for q in tree.locate_within_distance(*p, radius * radius) {
            n += 1.0;
            sx += q[0];
            sy += q[1];
            sxx += q[0] * q[0];
            syy += q[1] * q[1];
            sxy += q[0] * q[1];
        }
        if n < 3.0 {
            continue;
        }
        let (cxx, cyy, cxy) = (
            sxx / n - (sx / n).powi(2),
            syy / n - (sy / n).powi(2),
            sxy / n - sx * sy / (n * n),
        );
        let tr = cxx + cyy;
        let det = cxx * cyy - cxy * cxy;
        let disc = (tr * tr / 4.0 - det).max(0.0).sqrt();
        let (l1, l2) = (tr / 2.0 + disc, tr / 2.0 - disc);
        if l1 <= 0.0 {
            continue;
        }
        let linearity = (l1 - l2) / l1;
        let angle = 0.5 * (2.0 * cxy).atan2(cxx - cyy);
        let bin = (angle.to_degrees().rem_euclid(180.0) as usize).min(179);
        h[bin] += linearity;
    }
    (0..180i32)
        .map(|k| {
            (-2i32..=2)
                .map(|d| h[(k + d).rem_euclid(180) as usize])
                .sum()
        })
        .collect()
}

/// Shifts δ (degrees, 0..180) maximising the circular correlation of the
/// two histograms, best first (local maxima only).
fn correlation_peaks(reference: &[f64], moving: &[f64]) -> Vec<f64> {
    let n = reference.len();
    let corr: Vec<f64> = (0..n)
        .map(|d| (0..n).map(|k| reference[(k + d) % n] * moving[k]).sum())
        .collect();
    let mut peaks: Vec<(f64, usize)> = (0..n)
        .filter(|&d| corr[d] >= corr[(d + n - 1) % n] && corr[d] > corr[(d + 1) % n])
        .map(|d| (corr[d], d))
        .collect();
    peaks.sort_by(|a, b| b.0.total_cmp(&a.0));
    peaks.into_iter().map(|(_, d)| d as f64).collect()
}

/// A truncated distance field of the reference walls on an axis-aligned
/// grid in metres.
struct Field {
    x0: f64,
    y0: f64,
    cell: f64,
    w: usize,
    h: usize,
    dist: Vec<f32>,
}

/// Distances are truncated here (metres): far points cost the same.
const CHAMFER_CAP_M: f32 = 1.0;

impl Field {
    fn new(walls: &[Point], cell: f64, margin: f64) -> Field {
        let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
        for p in walls {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let (x0, y0) = (lo[0] - margin, lo[1] - margin);
        let w = (((hi[0] + margin - x0) / cell).ceil() as usize).clamp(1, 8192);
        let h = (((hi[1] + margin - y0) / cell).ceil() as usize).clamp(1, 8192);
        let mut mask = GrayImage::new(w as u32, h as u32);
        for p in walls {
            let (c, r) = (((p[0] - x0) / cell) as u32, ((p[1] - y0) / cell) as u32);
            if (c as usize) < w && (r as usize) < h {
                mask.put_pixel(c, r, Luma([255]));
            }
        }
        let dist = squared_distance_to_foreground(&mask)
            .into_iter()
            .map(|d2| ((d2.sqrt() * cell) as f32).min(CHAMFER_CAP_M))
            .collect();
        Field {
            x0,
            y0,
            cell,
            w,
            h,
            dist,
        }
    }

    fn at(&self, p: Point) -> f32 {
        let (c, r) = ((p[0] - self.x0) / self.cell, (p[1] - self.y0) / self.cell);
        if c < 0.0 || r < 0.0 {
            return CHAMFER_CAP_M;
        }
        let (c, r) = (c as usize, r as usize);
        if c >= self.w || r >= self.h {
            return CHAMFER_CAP_M;
        }
        self.dist[r * self.w + c]
    }
}

/// Best translation for rotation `deg` around the centroid fit, coarse to
/// fine: a 0.4 m grid over ±`search_m` on a sparse point subset, then a
/// grid one field cell apart over ±0.4 m around the best coarse cell:
/// (mean truncated distance, transform).
fn chamfer_search(
    field: &Field,
    pts: &[Point],
    deg: f64,
    c_ref: Point,
    c_mov: Point,
    search_m: f64,
) -> (f64, RigidTransform) {
    let rot = RigidTransform::from_degrees(deg, 0.0, 0.0);
    let rotated: Vec<Point> = pts.iter().map(|p| rot.apply(*p)).collect();
    let sparse = subsample(&rotated, 150);
    let rc = rot.apply(c_mov);
    let t0 = [c_ref[0] - rc[0], c_ref[1] - rc[1]];
    let score = |set: &[Point], t: Point| {
        let sum: f32 = set
            .iter()
            .map(|p| field.at([p[0] + t[0], p[1] + t[1]]))
            .sum();
        f64::from(sum) / set.len().max(1) as f64
    };
    let grid_best = |set: &[Point], centre: Point, step: f64, half: f64| {
        let n = (half / step).ceil() as i32;
        let mut best = (f64::MAX, centre);
        for i in -n..=n {
            for j in -n..=n {
                let t = [
                    centre[0] + f64::from(i) * step,
                    centre[1] + f64::from(j) * step,
                ];
                let s = score(set, t);
                if s < best.0 {
                    best = (s, t);
                }
            }
        }
        best
    };
    let coarse = grid_best(&sparse, t0, 0.4, search_m);
    let fine = grid_best(&rotated, coarse.1, field.cell.max(0.05), 0.4);
    (
        fine.0,
        RigidTransform::from_degrees(deg, fine.1[0], fine.1[1]),
    )
}

/// Trimmed point-to-point ICP from `start`.
fn icp(tree: &RTree<Point>, pts: &[Point], start: RigidTransform, tol: f64) -> RigidTransform {
    let mut t = start;
    let icp_pts = subsample(pts, 500);
    for iter in 0..20 {
        let max_d = (1.0 - iter as f64 / 20.0).max(0.0) * 1.0 + 2.0 * tol;
        let mut pairs: Vec<(Point, Point)> = Vec::with_capacity(icp_pts.len());
        for p in &icp_pts {
            let q = t.apply(*p);
            if let Some(n) = tree
                .nearest_neighbor(&q)
                .filter(|n| (n[0] - q[0]).hypot(n[1] - q[1]) <= max_d)
            {
                pairs.push((q, *n));
            }
        }
        if pairs.len() < 3 {
            break;
        }
        let k = pairs.len() as f64;
        let (mut mp, mut mq) = ([0.0; 2], [0.0; 2]);
        for (p, q) in &pairs {
            mp = [mp[0] + p[0] / k, mp[1] + p[1] / k];
            mq = [mq[0] + q[0] / k, mq[1] + q[1] / k];
        }
        let (mut s_cos, mut s_sin) = (0.0, 0.0);
        for (p, q) in &pairs {
            let (px, py, qx, qy) = (p[0] - mp[0], p[1] - mp[1], q[0] - mq[0], q[1] - mq[1]);
            s_cos += px * qx + py * qy;
            s_sin += px * qy - py * qx;
        }
        let theta = s_sin.atan2(s_cos);
        let (s, c) = theta.sin_cos();
        let step = RigidTransform {
            rotation_rad: theta,
            tx_m: mq[0] - (c * mp[0] - s * mp[1]),
            ty_m: mq[1] - (s * mp[0] + c * mp[1]),
        };
        t = step.after(&t);
        if theta.abs() < 1e-6 && step.tx_m.hypot(step.ty_m) < 1e-5 {
            break;
        }
    }
    t
}

fn quality(tree: &RTree<Point>, pts: &[Point], t: RigidTransform, tol: f64) -> Alignment {
    let (mut inliers, mut sq) = (0usize, 0.0);
    for p in pts {
        let q = t.apply(*p);
        if let Some(n) = tree.nearest_neighbor(&q) {
            let d2 = (n[0] - q[0]).powi(2) + (n[1] - q[1]).powi(2);
            if d2 <= tol * tol {
                inliers += 1;
                sq += d2;
            }
        }
    }
    Alignment {
        transform: t,
        inliers: inliers as f64 / pts.len().max(1) as f64,
        rms_m: if inliers > 0 {
            (sq / inliers as f64).sqrt()
        } else {
            0.0
        },
        tolerance_m: tol,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An asymmetric floor: an L of rooms with inner walls, 0.1 m/px.
    fn floor() -> OccupancyGrid {
        let (w, h) = (120u32, 90u32);
        let mut cells = vec![Cell::Unknown; (w * h) as usize];
        for r in 0..h {
            for c in 0..w {
                let inside = (5..115).contains(&c) && (5..85).contains(&r) && !(c > 70 && r > 50);
                let border = inside
                    && (c == 5
                        || c == 114
                        || r == 5
                        || r == 84
                        || (c == 70 && r > 50)
                        || (r == 50 && c > 70));
                let inner = (c == 40 && r < 60 && !(20..28).contains(&r))
                    || (r == 30 && c < 40 && !(10..16).contains(&c));
                cells[(r * w + c) as usize] = if !inside {
                    Cell::Unknown
                } else if border || inner {
                    Cell::Occupied
                } else {
                    Cell::Free
                };
            }
        }
        OccupancyGrid::from_cells(w, h, 0.1, [0.0; 3], cells)
    }

    #[test]
    fn recovers_a_frame_change() {
        let a = floor();
        let mut b = a.clone();
        // Same pixels, another frame: rotated 33° and shifted.
        b.origin = [2.0, -1.5, 33f64.to_radians()];
        let found = align_grids(&a, &b, &AlignParams::default()).unwrap();
        // b's frame → a's frame is the inverse of the origin change.
        let want = RigidTransform::from_degrees(33.0, 2.0, -1.5).inverse();
        assert!(found.inliers > 0.95, "{found:?}");
        assert!(
            close(&found.transform, &want, 0.3, 0.1),
            "{found:?} vs {want:?}"
        );
    }

    /// [`floor`] as a clean drawing: black walls whose edges are
    /// anti-aliased (greys between the loader's occupied and free
    /// thresholds), written as a PNG map and loaded as any map is.
    fn drawn_floor() -> OccupancyGrid {
        let f = floor();
        let grey: Vec<u8> = (0..f.height)
            .flat_map(|r| (0..f.width).map(move |c| (c, r)))
            .map(|(c, r)| match f.cell(c, r) {
                Some(Cell::Occupied) => 0,
                Some(Cell::Free) => {
                    let near_wall =
                        [(0i64, 1i64), (0, -1), (1, 0), (-1, 0)]
                            .iter()
                            .any(|(dc, dr)| {
                                let (cc, rr) = (i64::from(c) + dc, i64::from(r) + dr);
                                u32::try_from(cc)
                                    .ok()
                                    .zip(u32::try_from(rr).ok())
                                    .and_then(|(cc, rr)| f.cell(cc, rr))
                                    == Some(Cell::Occupied)
                            });
                    if near_wall { 150 } else { 255 }
                }
                _ => 178,
            })
            .collect();
        let dir = tempfile::tempdir().unwrap();
        GrayImage::from_raw(f.width, f.height, grey)
            .unwrap()
            .save(dir.path().join("drawn.png"))
            .unwrap();
        let yaml = dir.path().join("drawn.yaml");
        std::fs::write(
            &yaml,
            "image: drawn.png\nresolution: 0.1\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n\
             occupied_thresh: 0.65\nfree_thresh: 0.196\n",
        )
        .unwrap();
        crate::grid::load_map(&yaml, &crate::grid::LoadOptions::default()).unwrap()
    }

    #[test]
    fn issue_19_clean_drawn_maps_have_walls() {
        let a = drawn_floor();
        // As office_g: walls are drawn black, yet no occupied cell touches
        // a free one (the anti-aliased edge lies between), which is what
        // the wall points once required ("0 wall pixels").
        let occupied = a.cells.iter().filter(|c| **c == Cell::Occupied).count();
        assert!(occupied > 300, "{occupied}");
        let touching = (0..a.height)
            .flat_map(|r| (0..a.width).map(move |c| (c, r)))
            .filter(|&(c, r)| a.cell(c, r) == Some(Cell::Occupied))
            .filter(|&(c, r)| {
                [
                    (c.wrapping_sub(1), r),
                    (c + 1, r),
                    (c, r.wrapping_sub(1)),
                    (c, r + 1),
                ]
                .iter()
                .any(|&(c, r)| a.cell(c, r) == Some(Cell::Free))
            })
            .count();
        assert_eq!(touching, 0);
        assert!(wall_points(&a).len() > 300);
        // Itself: the same frame, and aligned (when forced) to the identity.
        let params = AlignParams::default();
        let same = alignment_quality(&a, &a, RigidTransform::IDENTITY, &params);
        assert_eq!(same.inliers, 1.0);
        let fit = align_grids(&a, &a, &params).unwrap();
        assert!(
            close(&fit.transform, &RigidTransform::IDENTITY, 0.3, 0.05),
            "{fit:?}"
        );
        // And in another frame.
        let mut b = a.clone();
        b.origin = [-3.0, 1.0, (-70f64).to_radians()];
        let found = align_grids(&a, &b, &params).unwrap();
        let want = RigidTransform::from_degrees(-70.0, -3.0, 1.0).inverse();
        assert!(found.inliers > 0.95, "{found:?}");
        assert!(close(&found.transform, &want, 0.3, 0.1), "{found:?}");
    }

    #[test]
    fn symmetric_buildings_are_refused() {
        // A square hall with a centred cross of walls: turning it by 90°
        // fits as well as not turning it.
        let n = 80usize;
        let mut cells = vec![Cell::Free; n * n];
        for r in 0..n {
            for c in 0..n {
                // Walls along the two middle lines, with a doorway in each arm.
                let gap = |k: usize| (15..25).contains(&k) || (55..65).contains(&k);
                let cross = (r == n / 2 && !gap(c)) || (c == n / 2 && !gap(r));
                if r == 0 || c == 0 || r == n - 1 || c == n - 1 || cross {
                    cells[r * n + c] = Cell::Occupied;
                }
            }
        }
        let a = OccupancyGrid::from_cells(n as u32, n as u32, 0.1, [0.0; 3], cells);
        let mut b = a.clone();
        b.origin = [1.0, 2.0, 0.3];
        let e = align_grids(&a, &b, &AlignParams::default()).unwrap_err();
        assert!(e.to_string().contains("a different fit"), "{e}");
    }

    #[test]
    fn identical_maps_share_a_frame() {
        let a = floor();
        let q = alignment_quality(&a, &a, RigidTransform::IDENTITY, &AlignParams::default());
        assert_eq!(q.inliers, 1.0);
    }

    #[test]
    fn unrelated_maps_are_refused() {
        let a = floor();
        let empty = OccupancyGrid::from_cells(10, 10, 0.1, [0.0; 3], vec![Cell::Free; 100]);
        assert!(matches!(
            align_grids(&a, &empty, &AlignParams::default()),
            Err(DiffError::TooFewWalls {
                which: "second",
                ..
            })
        ));
        // A square room against the L-shaped floor: no fit covers it.
        let mut cells = vec![Cell::Free; 60 * 60];
        for r in 0..60 {
            for c in 0..60 {
                if r == 0 || c == 0 || r == 59 || c == 59 || (r == 30 && c < 45) {
                    cells[r * 60 + c] = Cell::Occupied;
                }
            }
        }
        let other = OccupancyGrid::from_cells(60, 60, 0.1, [0.0; 3], cells);
        let e = align_grids(&a, &other, &AlignParams::default()).unwrap_err();
        assert!(e.to_string().contains("no reliable alignment"), "{e}");
    }
}
