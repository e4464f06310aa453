//! Binary erosion, dilation, opening and closing with a disk of any real
//! radius, computed exactly from the Euclidean distance transform (so a
//! radius in metres converts to pixels without rounding the shape).

use super::{Mask, squared_distance_to_foreground};

fn inverse(mask: &Mask) -> Mask {
    let mut inv = mask.clone();
    inv.iter_mut()
        .for_each(|p| *p = if *p == 0 { 255 } else { 0 });
    inv
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
    let d = squared_distance_to_foreground(&inverse(mask));
    let r2 = r * r;
    let (w, h) = (mask.width() as usize, mask.height() as usize);
    let data = d
        .iter()
        .enumerate()
        .map(|(i, &v)| {
            // Outside the image counts as background too.
            let (x, y) = (i % w, i / w);
            let edge = (x + 1).min(y + 1).min(w - x).min(h - y) as f64;
            if v > r2 && edge * edge > r2 { 255 } else { 0 }
        })
        .collect();
    Mask::from_raw(mask.width(), mask.height(), data).unwrap_or_else(|| mask.clone())
}

/// Pixels within distance `r` (pixels) of the foreground.
pub fn dilate(mask: &Mask, r: f64) -> Mask {
    let d = squared_distance_to_foreground(mask);
    let r2 = r * r;
    let data = d.iter().map(|&v| if v <= r2 { 255 } else { 0 }).collect();
    Mask::from_raw(mask.width(), mask.height(), data).unwrap_or_else(|| mask.clone())
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
