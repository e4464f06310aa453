//! The dominant edge orientation of a mask, modulo a quarter turn: the
//! angle at which its boundary pixels line up best on two perpendicular
//! axes (the wall directions of a Manhattan building).

use super::Mask;

/// Most boundary pixels used for the 1° search and for the 0.1° refinement
/// (evenly subsampled).
const COARSE_POINTS: usize = 1500;
const FINE_POINTS: usize = 4000;

/// The angle θ in `[0°, 90°)` (degrees, counter-clockwise in image
/// coordinates with y down) that makes the boundary of `mask` most
/// axis-aligned once the mask is turned by −θ: boundary pixels are projected
/// on the two axes turned by θ and the sum of squared counts of 1-px bins
/// is maximised, over 1° steps then 0.1° around the best. Maps are usually
/// drawn axis-aligned, so 0 is kept unless the best angle scores at least
/// 5 % more (this also keeps tiny masks, whose pixel lattice lines up
/// along many angles, unturned). 0 for a mask without boundary.
///
/// ```
/// use nrgdb::imaging::{binarize, dominant_orientation};
/// // An axis-aligned square.
/// let mut grey = vec![0u8; 20 * 20];
/// for y in 5..15 { for x in 5..15 { grey[y * 20 + x] = 255; } }
/// let m = binarize(20, 20, &grey, 250);
/// assert!(dominant_orientation(&m) < 0.5 || dominant_orientation(&m) > 89.5);
/// ```
pub fn dominant_orientation(mask: &Mask) -> f64 {
    let fine_points = subsample(boundary_points(mask), FINE_POINTS);
    if fine_points.is_empty() {
        return 0.0;
    }
    let coarse_points = subsample(fine_points.clone(), COARSE_POINTS);
    let mut bins = Vec::new();
    let mut best = |points: &[[f64; 2]], angles: &mut dyn Iterator<Item = f64>| {
        let mut top = (f64::NEG_INFINITY, 0.0);
        for deg in angles {
            let s = sharpness(points, deg.to_radians(), &mut bins);
            if s > top.0 {
                top = (s, deg);
            }
        }
        top
    };
    let (_, coarse) = best(&coarse_points, &mut (0..90).map(f64::from));
    let (top, fine) = best(
        &fine_points,
        &mut (-10..=10).map(|k| coarse + f64::from(k) * 0.1),
    );
    let (at_zero, _) = best(&fine_points, &mut std::iter::once(0.0));
    if top < 1.05 * at_zero {
        return 0.0;
    }
    fine.rem_euclid(90.0)
}

/// Every `k`-th point, so at most `max` remain.
pub(super) fn subsample(points: Vec<[f64; 2]>, max: usize) -> Vec<[f64; 2]> {
    let step = points.len().div_ceil(max).max(1);
    points.into_iter().step_by(step).collect()
}

/// Foreground pixels with a background 4-neighbour.
pub(super) fn boundary_points(mask: &Mask) -> Vec<[f64; 2]> {
    let (w, h) = (mask.width() as usize, mask.height() as usize);
    let d = mask.as_raw();
    let on = |x: usize, y: usize| d[y * w + x] != 0;
    let mut pts = Vec::new();
    for y in 1..h.saturating_sub(1) {
        for x in 1..w.saturating_sub(1) {
            if on(x, y) && (!on(x - 1, y) || !on(x + 1, y) || !on(x, y - 1) || !on(x, y + 1)) {
                pts.push([x as f64, y as f64]);
            }
        }
    }
    pts
}

/// Sum of squared 1-px bin counts of the points projected on both axes
/// turned by `a` radians (`bins` is scratch space).
fn sharpness(points: &[[f64; 2]], a: f64, bins: &mut Vec<u32>) -> f64 {
    let (s, c) = a.sin_cos();
    // Image coordinates are ≥ 0, so projections lie within ±(x + y).
    let reach = points.iter().map(|p| p[0] + p[1]).fold(0.0, f64::max);
    let size = 2 * (reach.ceil() as usize) + 2;
    let mut total = 0.0;
    for axis in [(c, s), (-s, c)] {
        bins.clear();
        bins.resize(size, 0);
        for p in points {
            // Shifted by `reach` to be non-negative, so truncation is floor.
            let v = p[0] * axis.0 + p[1] * axis.1 + reach;
            bins[v as usize] += 1;
        }
        total += bins
            .iter()
            .map(|&b| f64::from(b) * f64::from(b))
            .sum::<f64>();
    }
    total
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// A filled rectangle of `w` × `h` pixels turned by `deg` about the
    /// image centre.
    pub(in crate::imaging) fn turned_rectangle(deg: f64) -> Mask {
        let (s, c) = deg.to_radians().sin_cos();
        Mask::from_fn(200, 200, |x, y| {
            let (dx, dy) = (f64::from(x) - 100.0, f64::from(y) - 100.0);
            let (u, v) = (dx * c + dy * s, -dx * s + dy * c);
            image::Luma([if u.abs() < 60.0 && v.abs() < 35.0 {
                255
            } else {
                0
            }])
        })
    }

    #[test]
    fn finds_the_turn_of_a_rectangle() {
        for deg in [0.0, 12.0, 35.0, 55.0, 80.0] {
            let got = dominant_orientation(&turned_rectangle(deg));
            let err = (got - deg.rem_euclid(90.0) + 45.0).rem_euclid(90.0) - 45.0;
            assert!(err.abs() <= 0.6, "turned {deg}°, found {got}°");
        }
    }
}
