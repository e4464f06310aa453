//! The wall directions of a building besides its dominant pair: the walls
//! of wings built at other angles, found from the histogram of its edge
//! normals.

use super::Mask;
use super::orientation::{boundary_points, subsample};

/// Radius (px) of the disc over which an edge's normal is taken.
const NORMAL_RADIUS: i64 = 4;
/// Most boundary pixels whose normals are histogrammed.
const NORMAL_POINTS: usize = 40_000;
/// A further wall direction holds at least this share of the edge weight
/// of the dominant one (both summed over 5°)…
const FURTHER_MIN_SHARE: f64 = 0.25;
/// …and the histogram falls, between the two, below this share of its
/// peak: a direction of its own, not the flank of the dominant one nor
/// the ripple that pixel staircases and scan noise leave everywhere.
const FURTHER_MAX_VALLEY: f64 = 0.2;
/// Further directions closer than this (degrees) are one.
const FURTHER_MIN_APART: f64 = 5.0;

/// The wall directions of `mask` besides `dominant` (degrees in `[0°, 90°)`,
/// as [`dominant_orientation`] gives it): the walls of wings built at
/// other angles, each modulo a quarter turn, strongest first. Each
/// boundary pixel's edge normal is taken over a disc of free pixels
/// around it and weighed by how clear it is; a direction is a peak of
/// their histogram (1° bins, summed over 5°), at least twice
/// `FURTHER_MIN_APART` from the dominant direction, with a deep valley
/// between the two (see `FURTHER_MAX_VALLEY`). Empty on
/// maps built along one pair of axes, and on robot maps whose edges
/// scatter round every angle.
pub fn further_wall_directions(mask: &Mask, dominant: f64) -> Vec<f64> {
    let hist = normal_histogram(mask);
    let bin = |k: i64| hist[k.rem_euclid(90) as usize];
    let summed: Vec<f64> = (0..90i64)
        .map(|k| (-2..=2).map(|j| bin(k + j)).sum())
        .collect();
    let at = |k: i64| summed[k.rem_euclid(90) as usize];
    let home = dominant.round() as i64;
    let top = at(home).max(f64::MIN_POSITIVE);
    // Peaks off the dominant direction, strongest first.
    let mut peaks: Vec<(f64, f64)> = (0..90i64)
        .filter(|&k| at(k) > at(k - 1) && at(k) >= at(k + 1))
        .filter(|&k| quarter_turn_apart(k as f64, dominant) >= 2.0 * FURTHER_MIN_APART)
        .filter(|&k| at(k) >= FURTHER_MIN_SHARE * top)
        .filter(|&k| {
            // The histogram must dip both ways round from the dominant
            // direction to the peak: the higher of the two floors.
            let floor = |step: i64| {
                let mut j = home;
                let mut low = f64::INFINITY;
                while (j - k).rem_euclid(90) != 0 {
                    j += step;
                    low = low.min(at(j));
                }
                low
            };
            floor(1).max(floor(-1)) <= FURTHER_MAX_VALLEY * at(k)
        })
        .map(|k| {
            // The vertex of the parabola through the peak and its two neighbours.
            let (l, c, r) = (at(k - 1), at(k), at(k + 1));
            let curve = l - 2.0 * c + r;
            let shift = if curve < 0.0 {
                0.5 * (l - r) / curve
            } else {
                0.0
            };
            ((k as f64 + shift).rem_euclid(90.0), c)
        })
        .collect();
    peaks.sort_by(|a, b| b.1.total_cmp(&a.1));
    let mut out: Vec<f64> = Vec::new();
    for (deg, _) in peaks {
        if out
            .iter()
            .all(|&d| quarter_turn_apart(d, deg) >= FURTHER_MIN_APART)
        {
            out.push(deg);
        }
    }
    out
}

/// How far apart two directions are (degrees), modulo a quarter turn.
fn quarter_turn_apart(a: f64, b: f64) -> f64 {
    ((a - b + 45.0).rem_euclid(90.0) - 45.0).abs()
}

/// Histogram (1° bins, modulo a quarter turn) of the edge normals of
/// `mask`'s boundary pixels, each taken as the first moment of the free
/// pixels in a disc round the pixel and weighed by its length.
fn normal_histogram(mask: &Mask) -> [f64; 90] {
    let (w, h) = (i64::from(mask.width()), i64::from(mask.height()));
    let data = mask.as_raw();
    let free =
        |x: i64, y: i64| x >= 0 && y >= 0 && x < w && y < h && data[(y * w + x) as usize] != 0;
    let r = NORMAL_RADIUS;
    // The disk's offsets, with their step in the image's pixel order.
    let disk: Vec<(i64, i64, i64)> = (-r..=r)
        .flat_map(|dy| (-r..=r).map(move |dx| (dx, dy)))
        .filter(|&(dx, dy)| dx * dx + dy * dy <= r * r)
        .map(|(dx, dy)| (dx, dy, dy * w + dx))
        .collect();
    let mut hist = [0.0f64; 90];
    for p in subsample(boundary_points(mask), NORMAL_POINTS) {
        let (x, y) = (p[0] as i64, p[1] as i64);
        let (mut gx, mut gy) = (0i64, 0i64);
        if x >= r && y >= r && x + r < w && y + r < h {
            // The whole disk inside the image: no bounds to check.
            let at = y * w + x;
            for &(dx, dy, step) in &disk {
                if data[(at + step) as usize] != 0 {
                    gx += dx;
                    gy += dy;
                }
            }
        } else {
            for &(dx, dy, _) in &disk {
                if free(x + dx, y + dy) {
                    gx += dx;
                    gy += dy;
                }
            }
        }
        let (gx, gy) = (gx as f64, gy as f64);
        let weight = gx.hypot(gy);
        if weight > 0.0 {
            let deg = gy.atan2(gx).to_degrees().rem_euclid(90.0);
            hist[deg.round() as usize % 90] += weight;
        }
    }
    hist
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::dominant_orientation;
    use crate::imaging::orientation::tests::turned_rectangle;

    #[test]
    fn finds_a_wing_built_at_another_angle() {
        // An 80 x 180 px hall along the axes and a 120 x 50 px wing turned
        // by 35 degrees beside it.
        let (s, c) = 35f64.to_radians().sin_cos();
        let m = Mask::from_fn(300, 200, |x, y| {
            let hall = (10..90).contains(&x) && (10..190).contains(&y);
            let (dx, dy) = (f64::from(x) - 200.0, f64::from(y) - 100.0);
            let (u, v) = (dx * c + dy * s, -dx * s + dy * c);
            let wing = u.abs() < 60.0 && v.abs() < 25.0;
            image::Luma([if hall || wing { 255 } else { 0 }])
        });
        let deg = dominant_orientation(&m);
        assert!(!(0.5..=89.5).contains(&deg), "{deg}");
        let further = further_wall_directions(&m, deg);
        assert_eq!(further.len(), 1, "{further:?}");
        assert!((further[0] - 35.0).abs() <= 1.0, "{further:?}");
    }

    #[test]
    fn a_building_along_one_pair_of_axes_has_no_further_direction() {
        for deg in [0.0, 12.0, 35.0] {
            let m = turned_rectangle(deg);
            let further = further_wall_directions(&m, dominant_orientation(&m));
            assert!(further.is_empty(), "turned {deg}°: {further:?}");
        }
    }
}
