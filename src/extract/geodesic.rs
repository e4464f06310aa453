//! The length of a space along itself: its geodesic diameter, the longest
//! of the shortest walks between two of its pixels. A corridor is long
//! and narrow along that walk; a room lined with shelves or a living area
//! with an alcove may have a narrow inscribed circle, but no long walk.

use crate::imaging::Labels;

/// Cost of a step to a 4-neighbour; a diagonal step costs
/// [`DIAGONAL`] (7/5 ≈ √2, the chamfer 5-7 metric).
const STRAIGHT: u32 = 5;
/// Cost of a diagonal step.
const DIAGONAL: u32 = 7;

/// The geodesic diameter (px) of each region `1..=regions` of `labels`
/// for which `wanted(label)` holds (8-connected walks inside the region,
/// chamfer 5-7 lengths; index 0, labels above `regions` and regions not
/// wanted: 0), from two sweeps: the farthest pixel from any pixel, then
/// the farthest from that one (exact on trees and convex shapes, a close
/// lower bound otherwise).
pub(crate) fn geodesic_lengths(
    labels: &Labels,
    regions: u32,
    wanted: impl Fn(u32) -> bool,
) -> Vec<f64> {
    let w = labels.width as usize;
    let boxes = labels.bounding_boxes();
    let mut out = vec![0.0; labels.count as usize + 1];
    for l in (1..=regions.min(labels.count)).filter(|&l| wanted(l)) {
        let b = boxes[l as usize];
        if b[0] > b[2] {
            continue;
        }
        let (x0, y0) = (b[0] as usize, b[1] as usize);
        let (bw, bh) = ((b[2] - b[0] + 1) as usize, (b[3] - b[1] + 1) as usize);
        let inside: Vec<bool> = (0..bw * bh)
            .map(|i| labels.data[(y0 + i / bw) * w + x0 + i % bw] == l)
            .collect();
        let Some(start) = inside.iter().position(|&v| v) else {
            continue;
        };
        let (far, _) = farthest(&inside, bw, bh, start);
        let (_, length) = farthest(&inside, bw, bh, far);
        out[l as usize] = f64::from(length) / f64::from(STRAIGHT);
    }
    out
}

/// The pixel of `inside` (a `bw` × `bh` box) farthest from `start` along
/// walks inside it, and its chamfer distance (Dial's bucket queue).
fn farthest(inside: &[bool], bw: usize, bh: usize, start: usize) -> (usize, u32) {
    const BUCKETS: usize = DIAGONAL as usize + 1;
    let mut dist = vec![u32::MAX; inside.len()];
    let mut buckets: Vec<Vec<usize>> = vec![Vec::new(); BUCKETS];
    dist[start] = 0;
    buckets[0].push(start);
    let (mut best, mut best_d) = (start, 0);
    let (mut d, mut pending) = (0u32, 1usize);
    while pending > 0 {
        let slot = d as usize % BUCKETS;
        while let Some(p) = buckets[slot].pop() {
            pending -= 1;
            if dist[p] != d {
                continue;
            }
            if d > best_d {
                (best, best_d) = (p, d);
            }
            let (x, y) = ((p % bw) as i64, (p / bw) as i64);
            for (dx, dy) in [
                (1i64, 0i64),
                (-1, 0),
                (0, 1),
                (0, -1),
                (1, 1),
                (1, -1),
                (-1, 1),
                (-1, -1),
            ] {
                let (nx, ny) = (x + dx, y + dy);
                if nx < 0 || ny < 0 || nx as usize >= bw || ny as usize >= bh {
                    continue;
                }
                let q = ny as usize * bw + nx as usize;
                let step = if dx != 0 && dy != 0 {
                    DIAGONAL
                } else {
                    STRAIGHT
                };
                if inside[q] && d + step < dist[q] {
                    dist[q] = d + step;
                    buckets[(d + step) as usize % BUCKETS].push(q);
                    pending += 1;
                }
            }
        }
        d += 1;
    }
    (best, best_d)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn labels(width: u32, height: u32, f: impl Fn(u32, u32) -> u32) -> Labels {
        let data = (0..width * height)
            .map(|i| f(i % width, i / width))
            .collect();
        Labels {
            width,
            height,
            data,
            count: 2,
        }
    }

    #[test]
    fn a_strip_is_as_long_as_it_runs_and_an_l_along_both_legs() {
        // Region 1: a 40 x 4 strip; region 2: an L of two 20 x 4 legs.
        let l = labels(60, 30, |x, y| {
            if y < 4 && x < 40 {
                1
            } else if ((10..14).contains(&y) && x < 20)
                || ((16..20).contains(&x) && (10..30).contains(&y))
            {
                2
            } else {
                0
            }
        });
        let g = geodesic_lengths(&l, 2, |_| true);
        assert_eq!(geodesic_lengths(&l, 2, |l| l == 2)[1], 0.0, "not wanted");
        // 39 steps along plus 3 across, chamfer: 36 straight + 3 diagonal.
        assert!((g[1] - (36.0 + 3.0 * 1.4)).abs() < 1e-9, "{g:?}");
        // Corner to corner round the bend: about 13 straight steps and 3
        // diagonal ones along each leg (they share their 4 x 4 corner),
        // far longer than either leg's 20.
        assert!((g[2] - 2.0 * (13.0 + 3.0 * 1.4)).abs() < 1.0, "{g:?}");
    }
}
