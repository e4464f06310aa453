//! Exact Euclidean distance transforms (Felzenszwalb–Huttenlocher, via imageproc).

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
    }
}
