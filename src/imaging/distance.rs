//! Exact Euclidean distance transforms: to the foreground via imageproc
//! (Felzenszwalb–Huttenlocher, f64), to the background by Meijster's
//! separable algorithm in integers (A. Meijster, J. Roerdink, W. Hesselink,
//! "A general algorithm for computing distance transforms in linear time",
//! 2000), which is what the pipeline needs and about three times faster:
//! no inverted copy, no f64 image, and the image border folded in.

use imageproc::distance_transform::euclidean_squared_distance_transform;

use super::Mask;

/// Squared Euclidean distance in pixels from every pixel to the nearest
/// foreground pixel (0 on the foreground; huge if the mask is empty).
pub fn squared_distance_to_foreground(mask: &Mask) -> Vec<f64> {
    euclidean_squared_distance_transform(mask).into_raw()
}

/// Euclidean distance in pixels from each foreground pixel to the nearest
/// background pixel (0 on the background); pixels outside the image count
/// as background.
///
/// ```
/// use nrgdb::imaging::{binarize, distance_to_background};
/// let m = binarize(5, 5, &[255; 25], 250);
/// let d = distance_to_background(&m);
/// assert_eq!((d[0], d[2 * 5 + 2]), (1.0, 3.0)); // corner, centre
/// ```
pub fn distance_to_background(mask: &Mask) -> Vec<f32> {
    meijster(mask, true)
}

/// [`distance_to_background`] with nothing outside the image: a pixel's
/// distance is to the nearest background pixel inside it (more than
/// `width + height` where the mask has no background at all).
///
/// ```
/// use nrgdb::imaging::{binarize, distance_to_background_inside};
/// let m = binarize(5, 1, &[0, 255, 255, 255, 255], 250);
/// assert_eq!(distance_to_background_inside(&m), vec![0.0, 1.0, 2.0, 3.0, 4.0]);
/// ```
pub fn distance_to_background_inside(mask: &Mask) -> Vec<f32> {
    meijster(mask, false)
}

/// Meijster's transform; `outside` says whether the pixels beyond the
/// image's edge are background.
fn meijster(mask: &Mask, outside: bool) -> Vec<f32> {
    let (w, h) = (mask.width() as usize, mask.height() as usize);
    let src = mask.as_raw();
    let mut out = vec![0f32; w * h];
    if w == 0 || h == 0 {
        return out;
    }
    // Phase 1, per column: distance to the nearest background pixel of the
    // column (the rows just outside the image count as background if
    // `outside`, else as farther than any pixel). Rows are swept top-down
    // then bottom-up, all columns at once.
    let far = if outside { 0 } else { (w + h) as u32 + 1 };
    let mut g = vec![0u32; w * h];
    let mut above = vec![far; w];
    for (row, g_row) in src.chunks_exact(w).zip(g.chunks_exact_mut(w)) {
        for ((a, &p), o) in above.iter_mut().zip(row).zip(g_row.iter_mut()) {
            *a = if p == 0 { 0 } else { *a + 1 };
            *o = *a;
        }
    }
    let mut below = vec![far; w];
    for (row, g_row) in src.chunks_exact(w).zip(g.chunks_exact_mut(w)).rev() {
        for ((b, &p), o) in below.iter_mut().zip(row).zip(g_row.iter_mut()) {
            *b = if p == 0 { 0 } else { *b + 1 };
            *o = (*o).min(*b);
        }
    }
    // Phase 2, per row: the lower envelope of the parabolas (x - u)² + g(u)²,
    // plus the columns just outside the image (g = 0). A background pixel
    // of the row (g = 0) is nearer than anything beyond it, so each run of
    // foreground is done on its own, between the background pixels that
    // bound it, and background runs are skipped.
    let mut s = vec![0usize; w];
    let mut t = vec![0i64; w];
    let mut sq = vec![0i64; w];
    for ((row, g_row), o_row) in src
        .chunks_exact(w)
        .zip(g.chunks_exact(w))
        .zip(out.chunks_exact_mut(w))
    {
        let mut x = 0;
        while let Some(offset) = row[x..].iter().position(|&p| p != 0) {
            let a = x + offset;
            let b = row[a..].iter().position(|&p| p == 0).map_or(w, |e| a + e);
            x = b;
            let (lo, hi) = (a.saturating_sub(1), (b + 1).min(w));
            for (q, &gv) in sq[lo..hi].iter_mut().zip(&g_row[lo..hi]) {
                *q = i64::from(gv) * i64::from(gv);
            }
            lower_envelope(&sq[lo..hi], &mut s, &mut t, |i, d2| {
                let x = lo + i;
                if row[x] != 0 {
                    let edge = (x + 1).min(w - x) as i64;
                    let d2 = if outside { d2.min(edge * edge) } else { d2 };
                    o_row[x] = (d2 as f64).sqrt() as f32;
                }
            });
            if x == w {
                break;
            }
        }
    }
    out
}

/// Euclidean distance in pixels from each labelled pixel (label ≠ 0) to
/// the nearest pixel of another label or none (0 on label 0); pixels
/// outside the image count as another label. Each label's pixels get
/// [`distance_to_background`] of that label's own mask, all labels in one
/// pass of Meijster's transform: a column's distance runs to where its
/// label changes, and a row's lower envelope is taken over each run of
/// one label. `data` is `width` × `height` labels, row by row.
///
/// ```
/// use nrgdb::imaging::distance_within_labels;
/// // Two labels side by side: each is as wide as its own run.
/// let d = distance_within_labels(&[1, 1, 1, 2, 2, 0], 6, 1);
/// assert_eq!(d, vec![1.0, 1.0, 1.0, 1.0, 1.0, 0.0]);
/// let d = distance_within_labels(&[1; 25], 5, 5);
/// assert_eq!(d[12], 3.0);
/// ```
pub fn distance_within_labels(data: &[u32], width: usize, height: usize) -> Vec<f32> {
    let mut out = vec![0f32; data.len()];
    within_label_runs(data, width, height, |y, a, _, run| {
        out[y * width + a..y * width + a + run.len()].copy_from_slice(run);
    });
    out
}

/// The largest of [`distance_within_labels`] per label `0..=count` (labels
/// above `count` are left out): twice it is the widest circle inside each
/// label's pixels. The distances are not kept.
///
/// ```
/// use nrgdb::imaging::widest_within_labels;
/// let w = widest_within_labels(&[1, 1, 1, 2, 2, 0, 3], 7, 1, 2);
/// assert_eq!(w, vec![0.0, 1.0, 1.0]);
/// ```
pub fn widest_within_labels(data: &[u32], width: usize, height: usize, count: u32) -> Vec<f32> {
    let mut widest = vec![0f32; count as usize + 1];
    within_label_runs(data, width, height, |_, _, l, run| {
        if let Some(m) = widest.get_mut(l as usize) {
            *m = run.iter().copied().fold(*m, f32::max);
        }
    });
    widest
}

/// Meijster's transform for every label's own mask (see
/// [`distance_within_labels`]): calls `run(y, a, label, distances)` for each
/// run of one label ≠ 0 in row `y` starting at column `a`.
fn within_label_runs(
    data: &[u32],
    w: usize,
    h: usize,
    mut run: impl FnMut(usize, usize, u32, &[f32]),
) {
    if w == 0 || h == 0 || data.len() != w * h {
        return;
    }
    // Phase 1, per column: rows to the nearest pixel of another label (the
    // rows just outside the image count as one), down then up.
    let mut g = vec![0u32; w * h];
    let mut above = vec![0u32; w];
    for y in 0..h {
        let row = &data[y * w..(y + 1) * w];
        let up = if y > 0 {
            &data[(y - 1) * w..y * w]
        } else {
            row
        };
        for (x, (a, o)) in above.iter_mut().zip(&mut g[y * w..(y + 1) * w]).enumerate() {
            let l = row[x];
            *a = if l == 0 {
                0
            } else if y > 0 && up[x] == l {
                *a + 1
            } else {
                1
            };
            *o = *a;
        }
    }
    let mut below = vec![0u32; w];
    for y in (0..h).rev() {
        let row = &data[y * w..(y + 1) * w];
        let down = if y + 1 < h {
            &data[(y + 1) * w..(y + 2) * w]
        } else {
            row
        };
        for (x, (b, o)) in below.iter_mut().zip(&mut g[y * w..(y + 1) * w]).enumerate() {
            let l = row[x];
            *b = if l == 0 {
                0
            } else if y + 1 < h && down[x] == l {
                *b + 1
            } else {
                1
            };
            *o = (*o).min(*b);
        }
    }
    // Phase 2, per row: each run of one label on its own, the pixels just
    // beside it (another label) at distance 0.
    let mut s = vec![0usize; w];
    let mut t = vec![0i64; w];
    let mut sq = vec![0i64; w];
    let mut found = vec![0f32; w];
    for (y, (row, g_row)) in data.chunks_exact(w).zip(g.chunks_exact(w)).enumerate() {
        let mut a = 0;
        while a < w {
            let l = row[a];
            let b = row[a..].iter().position(|&m| m != l).map_or(w, |e| a + e);
            if l != 0 {
                let (lo, hi) = (a.saturating_sub(1), (b + 1).min(w));
                for (x, q) in (lo..hi).zip(sq[lo..hi].iter_mut()) {
                    *q = if (a..b).contains(&x) {
                        i64::from(g_row[x]) * i64::from(g_row[x])
                    } else {
                        0
                    };
                }
                lower_envelope(&sq[lo..hi], &mut s, &mut t, |i, d2| {
                    let x = lo + i;
                    if (a..b).contains(&x) {
                        let edge = (x + 1).min(w - x) as i64;
                        found[x] = (d2.min(edge * edge) as f64).sqrt() as f32;
                    }
                });
                run(y, a, l, &found[a..b]);
            }
            a = b;
        }
    }
}

/// The largest of `dist`, at least 0 (so 0 for an empty slice). Kept in
/// independent lanes, so there is no chain of dependent compares; max is
/// exact, so the result is the same as a fold in order.
///
/// ```
/// use nrgdb::imaging::max_distance;
/// assert_eq!(max_distance(&[1.0, 3.5, 2.0]), 3.5);
/// assert_eq!(max_distance(&[]), 0.0);
/// ```
pub fn max_distance(dist: &[f32]) -> f32 {
    if dist.len() < 64 {
        return dist.iter().copied().fold(0.0, f32::max);
    }
    let mut lanes = [0.0f32; 16];
    let chunks = dist.chunks_exact(lanes.len());
    let rest = chunks.remainder();
    for chunk in chunks {
        for (l, &d) in lanes.iter_mut().zip(chunk) {
            *l = l.max(d);
        }
    }
    lanes.iter().chain(rest).copied().fold(0.0, f32::max)
}

/// Meijster's second phase over one row of squared column distances `f`:
/// calls `emit(x, min_u (x - u)² + f(u))` for every `x`, right to left.
/// `s` and `t` are scratch of at least `f.len()`.
fn lower_envelope(f: &[i64], s: &mut [usize], t: &mut [i64], mut emit: impl FnMut(usize, i64)) {
    let m = f.len();
    let dist = |x: i64, u: usize| (x - u as i64) * (x - u as i64) + f[u];
    // Where the parabola of `u` starts to be below the one of `i < u`.
    let sep = |i: usize, u: usize| {
        let (ii, uu) = (i as i64, u as i64);
        (uu * uu - ii * ii + f[u] - f[i]).div_euclid(2 * (uu - ii))
    };
    let mut q = 0usize;
    s[0] = 0;
    t[0] = 0;
    for u in 1..m {
        // Pop the parabolas that `u` is below of at their start.
        let mut empty = false;
        while dist(t[q], s[q]) > dist(t[q], u) {
            if q == 0 {
                empty = true;
                break;
            }
            q -= 1;
        }
        if empty {
            s[0] = u;
        } else {
            let start = 1 + sep(s[q], u);
            if start < m as i64 {
                q += 1;
                s[q] = u;
                t[q] = start;
            }
        }
    }
    for x in (0..m).rev() {
        emit(x, dist(x as i64, s[q]));
        if x as i64 == t[q] && q > 0 {
            q -= 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::ascii_mask;

    #[test]
    fn distances_are_euclidean() {
        let m = ascii_mask(
            "..........
             .######...
             .#######..
             .#######..
             .#######..
             .#######..
             ..........",
        );
        let d = distance_to_background(&m);
        let w = 10;
        assert_eq!(d[w + 1], 1.0);
        assert_eq!(d[3 * w + 4], 3.0);
        // (6,2): nearest background (7,1) is diagonal.
        assert!((d[2 * w + 6] - 2f32.sqrt()).abs() < 1e-6);
        let sq = squared_distance_to_foreground(&m);
        assert_eq!(sq[0], 2.0);
    }

    #[test]
    fn outside_the_image_is_background() {
        let m = ascii_mask("###\n###\n###");
        assert_eq!(distance_to_background(&m)[4], 2.0);
        let wide = ascii_mask("#######");
        assert_eq!(distance_to_background(&wide), vec![1.0; 7]);
    }

    /// The former implementation: imageproc's transform of the inverse,
    /// clamped by the distance to the image edge.
    fn reference(mask: &Mask) -> Vec<f32> {
        let mut inverse = mask.clone();
        inverse
            .iter_mut()
            .for_each(|p| *p = if *p == 0 { 255 } else { 0 });
        let (w, h) = (mask.width() as usize, mask.height() as usize);
        euclidean_squared_distance_transform(&inverse)
            .into_raw()
            .into_iter()
            .enumerate()
            .map(|(i, d)| {
                let (x, y) = (i % w, i / w);
                let edge = (x + 1).min(y + 1).min(w - x).min(h - y) as f64;
                d.sqrt().min(edge) as f32
            })
            .collect()
    }

    #[test]
    fn agrees_with_imageproc_on_random_masks() {
        let mut seed = 5u64;
        for round in 0..200u32 {
            let (w, h) = (1 + round % 23, 1 + (round * 7) % 19);
            // Densities from sparse background to sparse foreground.
            let keep = 2 + u64::from(round % 9);
            let m = Mask::from_fn(w, h, |_, _| {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                image::Luma([if (seed >> 33).is_multiple_of(keep) {
                    0
                } else {
                    255
                }])
            });
            assert_eq!(distance_to_background(&m), reference(&m), "{w}x{h}");
            if m.contains(&0) {
                assert_eq!(
                    distance_to_background_inside(&m),
                    inside_reference(&m),
                    "{w}x{h}"
                );
            }
        }
    }

    /// imageproc's transform of the inverse, with nothing outside the image.
    fn inside_reference(mask: &Mask) -> Vec<f32> {
        let mut inverse = mask.clone();
        inverse
            .iter_mut()
            .for_each(|p| *p = if *p == 0 { 255 } else { 0 });
        euclidean_squared_distance_transform(&inverse)
            .into_raw()
            .into_iter()
            .map(|d| d.sqrt() as f32)
            .collect()
    }

    #[test]
    fn agrees_with_imageproc_on_rooms() {
        // Large open areas, where distances far exceed the random masks'.
        let m = Mask::from_fn(97, 61, |x, y| {
            let wall = x % 40 < 2 || y % 30 == 0 || (x + 2 * y) % 53 == 0;
            image::Luma([if wall { 0 } else { 255 }])
        });
        assert_eq!(distance_to_background(&m), reference(&m));
        let full = Mask::from_pixel(64, 33, image::Luma([255]));
        assert_eq!(distance_to_background(&full), reference(&full));
    }

    #[test]
    fn within_labels_is_each_labels_own_transform() {
        // Random label images of 0–3 labels in blobs: every labelled pixel
        // gets the distance of its own label's mask (imageproc's transform,
        // outside the image as background).
        let mut seed = 11u64;
        let mut next = |n: u64| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 33) % n
        };
        for round in 0..200u32 {
            let (w, h) = (1 + round % 29, 1 + (round * 5) % 23);
            let mut data: Vec<u32> = (0..w * h).map(|_| next(4) as u32).collect();
            // Grow blobs: copy a neighbour's label most of the time.
            for i in 1..data.len() {
                if next(4) != 0 {
                    data[i] = data[i - 1];
                }
            }
            let got = distance_within_labels(&data, w as usize, h as usize);
            for l in 1..4u32 {
                let m = Mask::from_fn(w, h, |x, y| {
                    image::Luma([if data[(y * w + x) as usize] == l {
                        255
                    } else {
                        0
                    }])
                });
                let want = reference(&m);
                for (i, (&d, &l2)) in got.iter().zip(&data).enumerate() {
                    if l2 == l {
                        assert_eq!(d, want[i], "{w}x{h} label {l} pixel {i}");
                    }
                }
            }
            assert!(got.iter().zip(&data).all(|(&d, &l)| l != 0 || d == 0.0));
        }
    }
}
