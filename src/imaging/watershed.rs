//! Marker-controlled watershed by Meyer's flooding algorithm
//! (F. Meyer, "Topographic distance and watershed lines", 1994), with a
//! hierarchical (bucket) queue over 16-bit elevations.

use super::Labels;

/// Floods `markers` over the pixels where `allowed` is true, lowest
/// `elevation` first, 4-connected; pixels are claimed by the first basin to
/// reach them, so every allowed pixel connected to a marker gets a label (no
/// watershed lines). Among equal elevations the flood is breadth-first.
/// Markers outside `allowed` still seed their basin.
///
/// ```
/// use nrgdb::imaging::{Labels, watershed};
/// // A 1-D valley profile with markers at both ends: the ridge at x=2 splits them.
/// let markers = Labels { width: 5, height: 1, data: vec![1, 0, 0, 0, 2], count: 2 };
/// let out = watershed(&[0, 1, 5, 2, 0], &markers, &[true; 5]);
/// assert_eq!(out.data[..2], [1, 1]);
/// assert_eq!(out.data[3..], [2, 2]);
/// ```
pub fn watershed(elevation: &[u16], markers: &Labels, allowed: &[bool]) -> Labels {
    let (w, h) = (markers.width as usize, markers.height as usize);
    let n = w * h;
    if elevation.len() != n || allowed.len() != n || n == 0 {
        return markers.clone();
    }
    // The flood runs in a copy framed by one pixel: every pixel then has
    // four neighbours at fixed offsets (no bounds checks, no division to
    // find a pixel's row). The frame is never queued and has no label.
    let pw = w + 2;
    let framed = |y: usize| (y + 1) * pw + 1;
    let mut label = vec![0u32; pw * (h + 2)];
    let mut height = vec![0u16; pw * (h + 2)];
    // Queued pixels, and pixels that never will be (labelled, disallowed,
    // the frame).
    let mut done = vec![true; pw * (h + 2)];
    for y in 0..h {
        let (src, dst) = (y * w..(y + 1) * w, framed(y)..framed(y) + w);
        label[dst.clone()].copy_from_slice(&markers.data[src.clone()]);
        height[dst.clone()].copy_from_slice(&elevation[src.clone()]);
        for ((d, &l), &a) in done[dst]
            .iter_mut()
            .zip(&markers.data[src.clone()])
            .zip(&allowed[src])
        {
            *d = l != 0 || !a;
        }
    }
    let offsets = [pw.wrapping_neg(), usize::MAX, 1, pw]; // up, left, right, down
    // One FIFO per level. Pushes never go below the level being flooded,
    // so each level is a plain Vec read through a cursor (`head`) and
    // dropped once flooded.
    let mut queues: Vec<Vec<u32>> = Vec::new();
    let push = |queues: &mut Vec<Vec<u32>>, level: usize, idx: usize| {
        if queues.len() <= level {
            queues.resize_with(level + 1, Vec::new);
        }
        queues[level].push(idx as u32);
    };
    // Seed: every unlabelled allowed neighbour of a marker pixel (the
    // frame has no label, so this is the interior in raster order).
    for (i, &l) in label.iter().enumerate() {
        if l == 0 {
            continue;
        }
        for j in offsets.map(|o| i.wrapping_add(o)) {
            if !done[j] {
                done[j] = true;
                push(&mut queues, usize::from(height[j]), j);
            }
        }
    }
    let (mut level, mut head) = (0, 0);
    while level < queues.len() {
        let Some(&i) = queues[level].get(head) else {
            queues[level] = Vec::new();
            (level, head) = (level + 1, 0);
            continue;
        };
        head += 1;
        let i = i as usize;
        let nb = offsets.map(|o| i.wrapping_add(o));
        // Take the label of the first labelled neighbour (all are from the same flood front).
        label[i] = nb.iter().map(|&j| label[j]).find(|&l| l != 0).unwrap_or(0);
        for j in nb {
            if !done[j] {
                done[j] = true;
                push(&mut queues, usize::from(height[j]).max(level), j);
            }
        }
    }
    let mut out = markers.clone();
    for (y, row) in out.data.chunks_exact_mut(w).enumerate() {
        row.copy_from_slice(&label[framed(y)..framed(y) + w]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_basins_meet_at_the_ridge() {
        // Two pits (0) separated by a ridge column of 9.
        let elev: Vec<u16> = vec![
            1, 0, 1, 9, 1, 0, 1, //
            1, 1, 1, 9, 1, 1, 1, //
            1, 1, 1, 3, 1, 1, 1,
        ];
        let mut markers = Labels::new(7, 3);
        markers.data[1] = 1;
        markers.data[5] = 2;
        markers.count = 2;
        let out = watershed(&elev, &markers, &[true; 21]);
        for y in 0..3 {
            assert_eq!(out.data[y * 7], 1);
            assert_eq!(out.data[y * 7 + 2], 1);
            assert_eq!(out.data[y * 7 + 4], 2);
            assert_eq!(out.data[y * 7 + 6], 2);
            assert_ne!(out.data[y * 7 + 3], 0, "ridge pixels are claimed too");
        }
    }

    #[test]
    fn disallowed_pixels_block_the_flood() {
        let elev = vec![0u16; 5];
        let markers = Labels {
            width: 5,
            height: 1,
            data: vec![1, 0, 0, 0, 0],
            count: 1,
        };
        let out = watershed(&elev, &markers, &[true, true, false, true, true]);
        assert_eq!(out.data, vec![1, 1, 0, 0, 0]);
    }
}
