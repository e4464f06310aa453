//! Door widths against the ground truth: each detected door matched to a
//! GT doorway line (its pixel centroid within the door radius, as
//! [`door_scores`](super::door_scores) matches), its reported width
//! ([`doorway`](crate::model::doorway())) against the line's length.
//!
//! A GT doorway line is the part of the line drawn across a doorway that
//! lies over free map pixels, so its length is the opening from jamb to
//! jamb: the extent of its pixels along their principal axis, each pixel
//! counted whole (a run of n pixels along a row is n pixels long).

use serde::Serialize;

use super::{DoorLine, GroundTruth};
use crate::extract::Extraction;
use crate::model::{SpaceKind, doorway};

/// One detected door matched to a GT doorway line.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DoorWidth {
    /// The door's space id.
    pub door: u32,
    /// Index of the GT doorway line in [`GroundTruth::doors`].
    pub line: usize,
    /// The width the model reports, metres.
    pub reported_m: f64,
    /// The GT doorway line's length, metres.
    pub truth_m: f64,
}

impl DoorWidth {
    /// The absolute error, metres.
    pub fn error_m(&self) -> f64 {
        (self.reported_m - self.truth_m).abs()
    }
}

/// Summary of the width errors of one map.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WidthScores {
    /// Doors matched to a GT doorway line.
    pub matched: usize,
    /// Median absolute width error, metres (None without a match).
    pub median_m: Option<f64>,
    /// 90th percentile of the absolute width error, metres (nearest rank).
    pub p90_m: Option<f64>,
}

/// The length in pixels of a GT doorway line: the opening it closes,
/// from one jamb to the other.
///
/// The line's pixels are what the GT drew over free map pixels, and a
/// drawn line often carries more than the doorway: spurs where it runs on
/// into an anti-aliased jamb, a stretch of room boundary drawn along a
/// wall face joined to it in an L. So the length is measured on the
/// line's main stroke only: its direction is the one in which a band
/// three pixels wide holds the most pixels (1° steps; the least spread
/// breaks ties), refined to the principal axis of that band's pixels; the
/// stroke is the pixels within three pixels of the band's middle; along
/// it, a whole position counts where at least half the typical (median)
/// number of pixels is drawn, and the length is the longest run of such
/// positions (gaps of one pixel bridged), each pixel counted whole (a run
/// of n pixels along a row is n long).
///
/// ```
/// use nrgdb::eval::{DoorLine, gt_line_length_px};
/// // Pixels 10..=21 of row 3 in an image 40 wide: 12 pixels long.
/// let line = DoorLine { pixels: (10..22).map(|x| 3 * 40 + x).collect(), rooms: vec![1, 2] };
/// assert!((gt_line_length_px(&line, 40) - 12.0).abs() < 1e-9);
/// ```
pub fn gt_line_length_px(line: &DoorLine, width: u32) -> f64 {
    let w = f64::from(width.max(1));
    let pts: Vec<[f64; 2]> = line
        .pixels
        .iter()
        .map(|&p| {
            let p = f64::from(p);
            [p % w + 0.5, (p / w).floor() + 0.5]
        })
        .collect();
    let Some(first) = pts.first().copied() else {
        return 0.0;
    };
    // The most pixels whose exact offsets across `deg` lie within three
    // pixels of each other, and (for a tie) the least spread of such a
    // group, in micro-pixels.
    let band3 = |deg: f64| -> (usize, i64) {
        let (s, c) = deg.to_radians().sin_cos();
        let mut o: Vec<f64> = pts
            .iter()
            .map(|p| -(p[0] - first[0]) * s + (p[1] - first[1]) * c)
            .collect();
        o.sort_by(f64::total_cmp);
        let (mut best, mut j) = ((0usize, i64::MIN), 0usize);
        for i in 0..o.len() {
            while o[i] - o[j] > 3.0 {
                j += 1;
            }
            let key = (i + 1 - j, -((o[i] - o[j]) * 1e6) as i64);
            best = best.max(key);
        }
        best
    };
    let coarse = (0..180)
        .map(f64::from)
        .max_by_key(|&d| (band3(d), std::cmp::Reverse((d * 10.0) as i64)))
        .unwrap_or(0.0);
    // The pixels of the best three-pixel band across `dir`, and its
    // middle offset.
    let offset = |dir: f64, p: &[f64; 2]| {
        let (s, c) = dir.to_radians().sin_cos();
        -(p[0] - first[0]) * s + (p[1] - first[1]) * c
    };
    let band = |dir: f64| -> Vec<&[f64; 2]> {
        let mut o: Vec<(f64, &[f64; 2])> = pts.iter().map(|p| (offset(dir, p), p)).collect();
        o.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (mut best, mut j) = ((0usize, 0usize), 0usize);
        for i in 0..o.len() {
            while o[i].0 - o[j].0 > 3.0 {
                j += 1;
            }
            if i + 1 - j > best.1 - best.0 {
                best = (j, i + 1);
            }
        }
        o[best.0..best.1].iter().map(|x| x.1).collect()
    };
    // The exact direction: the principal axis of the band's pixels.
    let deg = principal_axis_deg(band(coarse).into_iter()).unwrap_or(coarse);
    let mut middle: Vec<f64> = band(deg).iter().map(|p| offset(deg, p)).collect();
    middle.sort_by(f64::total_cmp);
    let Some(&m) = middle.get(middle.len() / 2) else {
        return 0.0;
    };
    let (s, c) = deg.to_radians().sin_cos();
    let along = |p: &[f64; 2]| (p[0] - first[0]) * c + (p[1] - first[1]) * s;
    // Per whole position along the stroke (pixels within three of its
    // middle): pixels, and the extreme exact positions of their centres.
    let mut positions: std::collections::BTreeMap<i64, (usize, f64, f64)> =
        std::collections::BTreeMap::new();
    for p in pts.iter().filter(|p| (offset(deg, p) - m).abs() <= 3.0) {
        let a = along(p);
        let e = positions
            .entry(a.round() as i64)
            .or_insert((0, f64::MAX, f64::MIN));
        *e = (e.0 + 1, e.1.min(a), e.2.max(a));
    }
    let mut counts: Vec<usize> = positions.values().map(|e| e.0).collect();
    counts.sort_unstable();
    let typical = counts.get(counts.len() / 2).copied().unwrap_or(0);
    let drawn: Vec<(i64, f64, f64)> = positions
        .iter()
        .filter(|(_, e)| 2 * e.0 >= typical)
        .map(|(k, e)| (*k, e.1, e.2))
        .collect();
    // The longest run of drawn positions, gaps of one bridged.
    let (mut best, mut start) = (0.0f64, None::<f64>);
    for (i, &(k, lo_a, hi_a)) in drawn.iter().enumerate() {
        let s0 = match (start, i.checked_sub(1).and_then(|j| drawn.get(j))) {
            (Some(s0), Some(prev)) if k - prev.0 <= 2 => s0,
            _ => lo_a,
        };
        start = Some(s0);
        best = best.max(hi_a - s0);
    }
    // Centres span `best`; each end pixel adds half its projected size.
    best + c.abs() + s.abs()
}

/// The direction (degrees) of the principal axis of points.
fn principal_axis_deg<'a>(points: impl Iterator<Item = &'a [f64; 2]> + Clone) -> Option<f64> {
    let n = points.clone().count() as f64;
    if n < 2.0 {
        return None;
    }
    let mean = points
        .clone()
        .fold([0.0, 0.0], |m, p| [m[0] + p[0] / n, m[1] + p[1] / n]);
    let (mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0);
    for p in points {
        let (dx, dy) = (p[0] - mean[0], p[1] - mean[1]);
        sxx += dx * dx;
        syy += dy * dy;
        sxy += dx * dy;
    }
    Some((0.5 * (2.0 * sxy).atan2(sxx - syy)).to_degrees())
}

/// Each detected door whose pixel centroid lies within `radius_px` of a GT
/// doorway line, with the nearest such line: its reported width and the
/// line's length (`resolution` m/px).
pub fn door_widths(
    gt: &GroundTruth,
    x: &Extraction,
    resolution: f64,
    radius_px: f64,
) -> Vec<DoorWidth> {
    let w = gt.rooms.width.max(1);
    let r2 = radius_px * radius_px;
    let mut out = Vec::new();
    for s in x.nrg.spaces().iter().filter(|s| s.kind == SpaceKind::Door) {
        let (Some(c), Some(d)) = (x.pixel_centroids.get(&s.id), doorway(s)) else {
            continue;
        };
        let nearest = gt
            .doors
            .iter()
            .enumerate()
            .map(|(k, line)| {
                let d2 = line
                    .pixels
                    .iter()
                    .map(|&p| {
                        let (px, py) = (f64::from(p % w), f64::from(p / w));
                        (px - c[0]).powi(2) + (py - c[1]).powi(2)
                    })
                    .fold(f64::INFINITY, f64::min);
                (d2, k)
            })
            .filter(|(d2, _)| *d2 <= r2)
            .min_by(|a, b| a.0.total_cmp(&b.0));
        if let Some((_, k)) = nearest {
            out.push(DoorWidth {
                door: s.id.0,
                line: k,
                reported_m: d.width_m,
                truth_m: gt_line_length_px(&gt.doors[k], w) * resolution,
            });
        }
    }
    out
}

/// Median and 90th percentile (nearest rank) of the absolute errors.
pub fn width_scores(widths: &[DoorWidth]) -> WidthScores {
    let mut e: Vec<f64> = widths.iter().map(DoorWidth::error_m).collect();
    e.sort_by(f64::total_cmp);
    let rank = |q: f64| -> Option<f64> {
        let k = ((q * e.len() as f64).ceil() as usize).clamp(1, e.len().max(1)) - 1;
        e.get(k).copied()
    };
    WidthScores {
        matched: e.len(),
        median_m: rank(0.5),
        p90_m: rank(0.9),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_diagonal_line_is_as_long_as_its_pixels_reach() {
        // Ten pixels on the diagonal: centres span 9√2, each pixel's square
        // adds √2 projected on the diagonal.
        let line = DoorLine {
            pixels: (0..10).map(|i| i * 20 + i).collect(),
            rooms: vec![1, 2],
        };
        let len = gt_line_length_px(&line, 20);
        assert!((len - 10.0 * 2f64.sqrt()).abs() < 1e-9, "{len}");
        // Two pixels thick along a column: still 7 long.
        let thick = DoorLine {
            pixels: (0..7).flat_map(|y| [y * 20 + 4, y * 20 + 5]).collect(),
            rooms: vec![1, 2],
        };
        let t = gt_line_length_px(&thick, 20);
        assert!((t - 7.0).abs() < 1e-9, "{t}");
    }

    #[test]
    fn spurs_steps_and_a_boundary_joined_in_an_l_are_not_the_doorway() {
        let w = 100u32;
        let at = |x: u32, y: u32| y * w + x;
        // A line drawn with a one-pixel step: 15 + 16 pixels, 31 long.
        let mut px: Vec<u32> = (5..20).map(|x| at(x, 10)).collect();
        px.extend((19..35).map(|x| at(x, 11)));
        let step = DoorLine {
            pixels: px,
            rooms: vec![1, 2],
        };
        let len = gt_line_length_px(&step, w);
        assert!((len - 30.0).abs() < 0.5, "{len}");
        // A stroke 4 wide and 17 long (columns 20..=23, rows 10..=26),
        // with a one-pixel boundary along a wall running off it to the
        // right at its top and a spur of two pixels below its end.
        let mut px: Vec<u32> = (10..27)
            .flat_map(|y| (20..24).map(move |x| at(x, y)))
            .collect();
        px.extend((24..46).map(|x| at(x, 10)));
        px.extend([at(23, 27), at(23, 28)]);
        let l = DoorLine {
            pixels: px,
            rooms: vec![1, 2],
        };
        let len = gt_line_length_px(&l, w);
        assert!((len - 17.0).abs() < 0.5, "{len}");
    }

    #[test]
    fn median_and_p90_by_nearest_rank() {
        let w = |e: f64| DoorWidth {
            door: 1,
            line: 0,
            reported_m: 1.0 + e,
            truth_m: 1.0,
        };
        let all: Vec<DoorWidth> = (1..=10).map(|k| w(f64::from(k) / 100.0)).collect();
        let s = width_scores(&all);
        assert_eq!(s.matched, 10);
        assert!((s.median_m.unwrap() - 0.05).abs() < 1e-9);
        assert!((s.p90_m.unwrap() - 0.09).abs() < 1e-9);
        assert_eq!(width_scores(&[]).median_m, None);
    }
}
