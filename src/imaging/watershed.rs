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
    let mut out = markers.clone();
    let n = w * h;
    if elevation.len() != n || allowed.len() != n {
        return out;
    }
    // One FIFO per level. Pushes never go below the level being flooded,
    // so each level is a plain Vec read through a cursor (`head`) and
    // dropped once flooded.
    let mut queues: Vec<Vec<u32>> = Vec::new();
    let push = |queues: &mut Vec<Vec<u32>>, level: usize, idx: u32| {
        if queues.len() <= level {
            queues.resize_with(level + 1, Vec::new);
        }
        queues[level].push(idx);
    };
    // Seed: every unlabelled allowed neighbour of a marker pixel.
    let mut queued: Vec<bool> = out.data.iter().map(|&l| l != 0).collect();
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if out.data[i] == 0 {
                continue;
            }
            let (nb, k) = neighbour_array(i, x, y, w, h);
            for &j in &nb[..k] {
                if !queued[j] && allowed[j] {
                    queued[j] = true;
                    push(&mut queues, elevation[j] as usize, j as u32);
                }
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
        // Indices fit in u32 (the queues hold them so); u32 division is cheaper.
        let (x, y) = (
            (i as u32 % w as u32) as usize,
            (i as u32 / w as u32) as usize,
        );
        let (nb, k) = neighbour_array(i, x, y, w, h);
        let nb = &nb[..k];
        // Take the label of the first labelled neighbour (all are from the same flood front).
        let label = nb
            .iter()
            .map(|&j| out.data[j])
            .find(|&l| l != 0)
            .unwrap_or(0);
        out.data[i] = label;
        for &j in nb {
            if !queued[j] && allowed[j] {
                queued[j] = true;
                let lj = (elevation[j] as usize).max(level);
                push(&mut queues, lj, j as u32);
            }
        }
    }
    out
}

/// The 4-neighbours of pixel `i` inside a `w × h` image (up, left, right,
/// down), as an array and its length; `(x, y)` are `i`'s column and row.
fn neighbour_array(i: usize, x: usize, y: usize, w: usize, h: usize) -> ([usize; 4], usize) {
    let mut out = [0; 4];
    let mut k = 0;
    for (ok, j) in [
        (y > 0, i.wrapping_sub(w)),
        (x > 0, i.wrapping_sub(1)),
        (x + 1 < w, i + 1),
        (y + 1 < h, i + w),
    ] {
        if ok {
            out[k] = j;
            k += 1;
        }
    }
    (out, k)
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
