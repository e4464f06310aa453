//! Image check: does a map image look like an occupancy grid? A colour
//! photo or a scanned plan is read as grey all the same, so the loader
//! warns (on stderr, through `tracing`) and says what it assumed. Uses only
//! the decoded pixels; knows nothing of extraction.

use std::path::Path;

use image::DynamicImage;

/// Channels that differ by more than this (of 255) make a pixel coloured.
const COLOUR_SPREAD: u8 = 24;
/// More than this share of coloured pixels makes a colour image.
const COLOUR_SHARE: f64 = 0.01;
/// Greys this close to ROS's unknown grey (205) count as unknown.
const UNKNOWN_GREYS: std::ops::RangeInclusive<u8> = 200..=210;
/// Fewer free or occupied pixels than this share of the pixels that are
/// not the unknown grey makes an image that is no occupancy grid.
const MIN_DECIDED_SHARE: f64 = 0.1;

/// Warnings about `img` (decoded from `path`; `grey` and `alpha` are its
/// grey values after negate and its alpha) as an occupancy grid, each
/// saying what the loader assumed: free at grey ≥ `free_min_grey`,
/// occupied below `occ_max_grey`.
pub fn image_warnings(
    path: &Path,
    img: &DynamicImage,
    grey: &[u8],
    alpha: Option<&[u8]>,
    free_min_grey: u8,
    occ_max_grey: i32,
) -> Vec<String> {
    let mut out = Vec::new();
    let opaque = |i: usize| alpha.is_none_or(|a| a.get(i).is_none_or(|&v| v > 0));
    let path = path.display();
    let rule = format!("free at grey >= {free_min_grey}, occupied below {occ_max_grey}");
    if img.color().has_color() {
        let rgba = img.to_rgba8();
        let (mut coloured, mut seen) = (0usize, 0usize);
        for (_, p) in rgba.pixels().enumerate().filter(|(i, _)| opaque(*i)) {
            let (lo, hi) = (p[0].min(p[1]).min(p[2]), p[0].max(p[1]).max(p[2]));
            seen += 1;
            coloured += usize::from(hi - lo > COLOUR_SPREAD);
        }
        let share = coloured as f64 / seen.max(1) as f64;
        if share > COLOUR_SHARE {
            out.push(format!(
                "{path}: a colour image ({:.0} % of its pixels are coloured), read as the grey \
                 mean of red, green and blue with {rule}; an occupancy map is grey (is this a \
                 photo or a drawing?)",
                share * 100.0
            ));
        }
    }
    let (mut decided, mut considered) = (0usize, 0usize);
    for (i, &g) in grey.iter().enumerate() {
        if !opaque(i) || UNKNOWN_GREYS.contains(&g) {
            continue;
        }
        considered += 1;
        decided += usize::from(g >= free_min_grey || i32::from(g) < occ_max_grey);
    }
    let share = decided as f64 / considered.max(1) as f64;
    if considered > 0 && share < MIN_DECIDED_SHARE {
        out.push(format!(
            "{path}: only {:.0} % of its pixels are free or occupied ({rule}); the rest are \
             read as unknown (is this an occupancy map? its greys may need other thresholds)",
            share * 100.0
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use image::{GrayImage, Luma, Rgb, RgbImage};

    #[test]
    fn warns_about_colour_and_middle_greys_only() {
        let photo = DynamicImage::ImageRgb8(RgbImage::from_fn(10, 10, |x, _| {
            Rgb([(x * 25) as u8, 90, 200])
        }));
        let grey: Vec<u8> = vec![120; 100];
        let w = image_warnings(Path::new("p.png"), &photo, &grey, None, 250, 89);
        assert_eq!(w.len(), 2, "{w:?}");
        assert!(w[0].contains("p.png: a colour image"), "{w:?}");
        let map = DynamicImage::ImageLuma8(GrayImage::from_fn(10, 10, |x, _| {
            Luma([if x < 3 {
                0
            } else if x < 8 {
                254
            } else {
                205
            }])
        }));
        let grey: Vec<u8> = map.to_luma8().into_raw();
        assert!(image_warnings(Path::new("m.pgm"), &map, &grey, None, 250, 89).is_empty());
    }
}
