//! Binary erosion, dilation, opening and closing with a disk of any real
//! radius `r`: a pixel is within the disk when its centre is at Euclidean
//! distance ≤ `r` (so a radius in metres converts to pixels without
//! rounding the shape).
//!
//! Computed from per-row distances: a disk is a stack of horizontal chords,
//! so for each row offset `dy` the question "is there a pixel of the other
//! colour within the chord?" is answered by the horizontal distance to the
//! nearest such pixel in that row. That is `2r + 1` lookups a pixel, which
//! for the small radii the pipeline uses (a few pixels) is several times
//! faster than a full Euclidean distance transform and gives the same
//! result (the tests compare with one).

use super::Mask;

/// Per pixel, the horizontal distance to the nearest pixel of its row whose
/// foreground-ness is `target`, with `outside` telling whether the columns
/// just outside the image count as such a pixel; distances of `cap` or more
/// are `cap` (so `cap` stands for "none within reach"), `cap` ≤ 255.
///
/// The disk filters only ask whether a distance is within a chord of at
/// most `r`, so for the small radii of the pipeline a byte with a cap just
/// above `r` answers the same as the exact distance, and the row is
/// swept once per offset with no dependence between pixels.
fn row_distances(mask: &Mask, target: bool, outside: bool, cap: u8) -> Vec<u8> {
    let (w, h) = (mask.width() as usize, mask.height() as usize);
    let src = mask.as_raw();
    let mut out = vec![cap; w * h];
    let mut is_target = vec![0u8; w];
    for (row, dst) in src
        .chunks_exact(w.max(1))
        .zip(out.chunks_exact_mut(w.max(1)))
        .take(h)
    {
        // 0 on target pixels, `cap` elsewhere.
        for (t, &p) in is_target.iter_mut().zip(row) {
            *t = if (p != 0) == target { 0 } else { cap };
        }
        dst.copy_from_slice(&is_target);
        for k in 1..cap {
            let k_us = k as usize;
            if k_us >= w {
                break;
            }
            // Target `k` to the left, then `k` to the right.
            for (o, &t) in dst[k_us..].iter_mut().zip(&is_target) {
                *o = (*o).min(t | k);
            }
            for (o, &t) in dst.iter_mut().zip(&is_target[k_us..]) {
                *o = (*o).min(t | k);
            }
        }
        if outside {
            for (x, o) in dst.iter_mut().enumerate() {
                let edge = (x + 1).min(w - x).min(cap as usize) as u8;
                *o = (*o).min(edge);
            }
        }
    }
    out
}

/// For each row offset `dy` of a disk of radius² `r2`, the largest
/// horizontal distance still inside it: `floor(sqrt(r2 - dy²))`.
fn chords(r2: f64) -> Vec<(i64, u32)> {
    let reach = r2.max(0.0).sqrt().floor() as i64;
    (-reach..=reach)
        .map(|dy| (dy, (r2 - (dy * dy) as f64).max(0.0).sqrt().floor() as u32))
        .collect()
}

/// `base` pixels (non-zero in `src` when `keep_foreground`, every pixel
/// otherwise) kept or added by a disk test: a pixel is "hit" when some row
/// of its disk has a row distance within the chord. Erosion keeps the
/// foreground pixels not hit (rows outside the image hit); dilation marks
/// the pixels hit or already foreground (rows outside never hit).
fn disk_filter(mask: &Mask, r: f64, erode: bool) -> Mask {
    let (w, h) = (mask.width() as usize, mask.height() as usize);
    if r.abs() >= f64::from(u8::MAX - 1) {
        return wide_disk_filter(mask, r, erode);
    }
    // Every chord is at most floor(r) < cap.
    let cap = r.abs().floor() as u8 + 1;
    let rd = row_distances(mask, !erode, erode, cap);
    let src = mask.as_raw();
    let chords = chords(r * r);
    let mut data = vec![0u8; w * h];
    // Per pixel of a row: 0 if hit, else non-zero.
    let mut miss = vec![0u8; w];
    for y in 0..h {
        miss.iter_mut().for_each(|v| *v = 1);
        let mut outside_hit = false;
        for &(dy, lim) in &chords {
            let yy = y as i64 + dy;
            if yy < 0 || yy >= h as i64 {
                outside_hit |= erode;
                continue;
            }
            let lim = lim as u8;
            let row = &rd[yy as usize * w..(yy as usize + 1) * w];
            miss.iter_mut()
                .zip(row)
                .for_each(|(v, &d)| *v &= u8::from(d > lim));
        }
        let row_src = &src[y * w..(y + 1) * w];
        let row_out = &mut data[y * w..(y + 1) * w];
        if erode {
            if !outside_hit {
                for ((o, &s), &m) in row_out.iter_mut().zip(row_src).zip(&miss) {
                    *o = if s != 0 && m != 0 { 255 } else { 0 };
                }
            }
        } else {
            for ((o, &s), &m) in row_out.iter_mut().zip(row_src).zip(&miss) {
                *o = if s != 0 || m == 0 { 255 } else { 0 };
            }
        }
    }
    Mask::from_raw(mask.width(), mask.height(), data).unwrap_or_else(|| mask.clone())
}

/// [`disk_filter`] for radii beyond a byte's reach: the same test from
/// exact row distances.
fn wide_disk_filter(mask: &Mask, r: f64, erode: bool) -> Mask {
    let (w, h) = (mask.width() as usize, mask.height() as usize);
    let src = mask.as_raw();
    let (target, outside) = (!erode, erode);
    // Per pixel, the exact row distance to a target pixel (u32::MAX: none).
    let mut rd = vec![u32::MAX; w * h];
    let none = if outside { 0 } else { u32::MAX / 2 };
    for (row, dst) in src
        .chunks_exact(w.max(1))
        .zip(rd.chunks_exact_mut(w.max(1)))
        .take(h)
    {
        let mut d = none;
        for (o, &p) in dst.iter_mut().zip(row) {
            d = if (p != 0) == target {
                0
            } else {
                d.saturating_add(1)
            };
            *o = d;
        }
        let mut d = none;
        for (o, &p) in dst.iter_mut().zip(row).rev() {
            d = if (p != 0) == target {
                0
            } else {
                d.saturating_add(1)
            };
            *o = (*o).min(d);
        }
        if !outside {
            dst.iter_mut()
                .filter(|o| **o >= u32::MAX / 2)
                .for_each(|o| *o = u32::MAX);
        }
    }
    let chords = chords(r * r);
    let mut data = vec![0u8; w * h];
    let mut hit = vec![false; w];
    for y in 0..h {
        hit.iter_mut().for_each(|v| *v = false);
        let mut outside_hit = false;
        for &(dy, lim) in &chords {
            let yy = y as i64 + dy;
            if yy < 0 || yy >= h as i64 {
                outside_hit |= erode;
                continue;
            }
            let row = &rd[yy as usize * w..(yy as usize + 1) * w];
            hit.iter_mut().zip(row).for_each(|(v, &d)| *v |= d <= lim);
        }
        let row_src = &src[y * w..(y + 1) * w];
        let row_out = &mut data[y * w..(y + 1) * w];
        for ((o, &s), &t) in row_out.iter_mut().zip(row_src).zip(&hit) {
            let on = if erode {
                s != 0 && !t && !outside_hit
            } else {
                s != 0 || t
            };
            *o = if on { 255 } else { 0 };
        }
    }
    Mask::from_raw(mask.width(), mask.height(), data).unwrap_or_else(|| mask.clone())
}

/// Foreground pixels whose disk of radius `r` (pixels) lies in the foreground
/// (outside the image counts as background).
///
/// ```
/// use nrgdb::imaging::{binarize, erode};
/// let m = binarize(5, 5, &[255; 25], 250);
/// // The one-pixel rim goes (outside the image is background).
/// assert_eq!(erode(&m, 1.0).as_raw().iter().filter(|&&p| p != 0).count(), 9);
/// ```
pub fn erode(mask: &Mask, r: f64) -> Mask {
    disk_filter(mask, r, true)
}

/// Pixels within distance `r` (pixels) of the foreground.
pub fn dilate(mask: &Mask, r: f64) -> Mask {
    disk_filter(mask, r, false)
}

/// Erosion then dilation: removes foreground parts narrower than `2r`.
pub fn open(mask: &Mask, r: f64) -> Mask {
    let mut out = dilate(&erode(mask, r), r);
    // The reconstruction of a disk erosion can round outward by one pixel; stay inside.
    out.iter_mut().zip(mask.iter()).for_each(|(o, m)| *o &= *m);
    out
}

/// Dilation then erosion: fills background gaps narrower than `2r`.
pub fn close(mask: &Mask, r: f64) -> Mask {
    let mut out = erode(&dilate(mask, r), r);
    out.iter_mut().zip(mask.iter()).for_each(|(o, m)| *o |= *m);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::{ascii_mask, mask_ascii};

    const BLOCKS: &str = "
        .........
        .###.....
        .####....
        .###.###.
        .....###.
        .....###.";

    #[test]
    fn erode_and_dilate() {
        let m = ascii_mask(BLOCKS);
        assert_eq!(
            mask_ascii(&erode(&m, 1.0)),
            ".........\n.........\n..##.....\n.........\n......#..\n.........\n"
        );
        let d = dilate(&ascii_mask("...\n.#.\n..."), 1.0);
        assert_eq!(mask_ascii(&d), ".#.\n###\n.#.\n");
    }

    /// The definition, from an exact Euclidean distance transform.
    fn reference(mask: &Mask, r: f64, erode: bool) -> Mask {
        use crate::imaging::squared_distance_to_foreground;
        let (w, h) = (mask.width() as usize, mask.height() as usize);
        let mut target = mask.clone();
        if erode {
            target
                .iter_mut()
                .for_each(|p| *p = if *p == 0 { 255 } else { 0 });
        }
        let d = squared_distance_to_foreground(&target);
        let data = d
            .iter()
            .enumerate()
            .map(|(i, &v)| {
                let (x, y) = (i % w, i / w);
                let edge = (x + 1).min(y + 1).min(w - x).min(h - y) as f64;
                let on = if erode {
                    v > r * r && edge * edge > r * r
                } else {
                    v <= r * r
                };
                if on { 255 } else { 0 }
            })
            .collect();
        Mask::from_raw(mask.width(), mask.height(), data).unwrap()
    }

    #[test]
    fn agrees_with_the_distance_transform() {
        let mut seed = 11u64;
        for round in 0..30u32 {
            let (w, h) = (3 + round % 17, 3 + (round * 5) % 13);
            let m = Mask::from_fn(w, h, |_, _| {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                image::Luma([if (seed >> 33).is_multiple_of(4) {
                    0
                } else {
                    255
                }])
            });
            for r in [0.0, 0.5, 1.0, 1.5, 2.3, 3.0, 4.7, 9.9, 260.0] {
                assert_eq!(erode(&m, r), reference(&m, r, true), "erode {w}x{h} r={r}");
                assert_eq!(
                    dilate(&m, r),
                    reference(&m, r, false),
                    "dilate {w}x{h} r={r}"
                );
            }
        }
    }

    #[test]
    fn byte_distances_agree_with_exact_ones() {
        let mut seed = 13u64;
        for round in 0..20u32 {
            let (w, h) = (5 + round * 3, 4 + (round * 7) % 31);
            let m = Mask::from_fn(w, h, |_, _| {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                image::Luma([if (seed >> 33).is_multiple_of(2 + u64::from(round % 9)) {
                    0
                } else {
                    255
                }])
            });
            for r in [-2.0, 0.0, 0.3, 1.0, 2.5, 4.0, 6.1, 12.0, 253.9] {
                for erode in [true, false] {
                    assert_eq!(
                        disk_filter(&m, r, erode),
                        wide_disk_filter(&m, r, erode),
                        "{w}x{h} r={r} erode={erode}"
                    );
                }
            }
        }
    }

    #[test]
    fn open_removes_thin_parts_and_close_fills_gaps() {
        let m = ascii_mask(
            "......
             .###..
             .#####
             .###..",
        );
        assert_eq!(
            mask_ascii(&open(&m, 1.0)),
            "......\n..##..\n.####.\n..##..\n"
        );
        let c = close(
            &ascii_mask(".......\n.##.##.\n.##.##.\n.##.##.\n.......\n"),
            1.0,
        );
        assert_eq!(
            mask_ascii(&c),
            ".......\n.##.##.\n.#####.\n.##.##.\n.......\n"
        );
    }
}
