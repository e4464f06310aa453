//! Doors: narrow borders between two basins become door spaces.

use std::collections::BTreeMap;

use crate::imaging::{Labels, Mask, squared_distance_to_foreground, watershed};

/// One border between two regions.
#[derive(Debug, Clone)]
pub(crate) struct Border {
    /// The two regions, `a < b`.
    pub pair: (u32, u32),
    /// Widest passage across the border, in pixels.
    pub width_px: f64,
    /// Pixels on either side of the border.
    pub pixels: Vec<u32>,
}

/// Every border between two labels with its passage width (twice the
/// largest distance to an obstacle along it, plus one pixel).
pub(crate) fn borders(labels: &Labels, dist: &[f32]) -> Vec<Border> {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let d = &labels.data;
    let mut map: BTreeMap<(u32, u32), Border> = BTreeMap::new();
    let mut add = |i: usize, j: usize| {
        let (a, b) = (d[i], d[j]);
        if a == 0 || b == 0 || a == b {
            return;
        }
        let pair = (a.min(b), a.max(b));
        let e = map.entry(pair).or_insert_with(|| Border {
            pair,
            width_px: 0.0,
            pixels: Vec::new(),
        });
        let half = f64::from(dist[i].min(dist[j]));
        e.width_px = e.width_px.max(2.0 * half + 1.0);
        e.pixels.push(i as u32);
        e.pixels.push(j as u32);
    };
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if x + 1 < w {
                add(i, i + 1);
            }
            if y + 1 < h {
                add(i, i + w);
            }
        }
    }
    map.into_values().collect()
}

/// Cuts a door space of thickness `depth_px` across each border in `doors`,
/// labelled `labels.count + 1 + k` for the k-th door; returns the new labels.
pub(crate) fn cut_doors(labels: &Labels, doors: &[&Border], depth_px: f64) -> Labels {
    let (w, h) = (labels.width, labels.height);
    let n = labels.data.len();
    let mut seeds = Labels::new(w, h);
    let mut border_mask = Mask::new(w, h);
    for (k, door) in doors.iter().enumerate() {
        for &p in &door.pixels {
            seeds.data[p as usize] = labels.count + 1 + k as u32;
            border_mask.as_mut()[p as usize] = 255;
        }
    }
    seeds.count = labels.count + doors.len() as u32;
    let r = (depth_px / 2.0 - 0.5).max(0.0);
    let sq = squared_distance_to_foreground(&border_mask);
    let band: Vec<bool> = (0..n)
        .map(|i| labels.data[i] != 0 && sq[i] <= r * r)
        .collect();
    let grown = watershed(&vec![0u16; n], &seeds, &band);
    let mut out = labels.clone();
    for (o, &g) in out.data.iter_mut().zip(&grown.data) {
        if g != 0 {
            *o = g;
        }
    }
    out.count = seeds.count;
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn border_width_and_door_cut() {
        // Two regions side by side, 3 rows tall, distance 1 at the middle row.
        let labels = Labels {
            width: 6,
            height: 3,
            data: vec![1, 1, 1, 2, 2, 2, 1, 1, 1, 2, 2, 2, 1, 1, 1, 2, 2, 2],
            count: 2,
        };
        let dist = vec![
            1.0f32, 1., 1., 1., 1., 1., 1., 2., 2., 2., 2., 1., 1., 1., 1., 1., 1., 1.,
        ];
        let b = borders(&labels, &dist);
        assert_eq!(b.len(), 1);
        assert_eq!(b[0].pair, (1, 2));
        assert_eq!(b[0].width_px, 5.0);
        let cut = cut_doors(&labels, &[&b[0]], 2.0);
        assert_eq!(cut.count, 3);
        assert_eq!(cut.data[..6], [1, 1, 3, 3, 2, 2]);
    }
}
