//! Raster algorithms on binary masks and label images: binarisation,
//! morphology, exact Euclidean distance, connected components, marker
//! watershed, skeletonisation, level-set component trees, region
//! adjacency, the dominant edge orientation and turning a mask.
//!
//! Owns pixel-level algorithms only; knows nothing of maps, metres or the
//! model. Uses `image`/`imageproc`; must not import anything from the crate.
//! A [`Mask`] is a grey image whose non-zero pixels are the foreground.

mod adjacency;
mod binarize;
mod distance;
mod label;
mod moments;
mod morphology;
mod orientation;
mod skeleton;
mod threshold_tree;
mod turn;
mod wall_directions;
mod watershed;

pub use adjacency::{Adjacency, region_adjacency};
pub use binarize::binarize;
pub use distance::{
    distance_to_background, distance_to_background_inside, distance_within_labels, max_distance,
    squared_distance_to_foreground, widest_within_labels,
};
pub use label::{Labels, Run, RunLabels, label_components, label_runs};
pub(crate) use moments::{Moments, Principal};
pub use morphology::{close, dilate, erode, open};
pub use orientation::dominant_orientation;
pub use skeleton::skeletonize;
pub use threshold_tree::{NO_PARENT, ThresholdTree, threshold_tree};
pub use turn::{Turn, line_pixels, turn_mask};
pub use wall_directions::further_wall_directions;
pub use watershed::watershed;

/// A binary image: non-zero pixels are the foreground (255 by convention).
pub type Mask = image::GrayImage;

/// Parses an ASCII picture into a mask: `#` or `1` foreground, anything else background.
#[cfg(test)]
pub(crate) fn ascii_mask(text: &str) -> Mask {
    let rows: Vec<&str> = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect();
    let w = rows.iter().map(|r| r.len()).max().unwrap_or(0) as u32;
    Mask::from_fn(w, rows.len() as u32, |x, y| {
        let c = rows[y as usize]
            .as_bytes()
            .get(x as usize)
            .copied()
            .unwrap_or(b'.');
        image::Luma([if c == b'#' || c == b'1' { 255 } else { 0 }])
    })
}

/// Parses rows of an ASCII picture into labels: `a` is region 1, `b`
/// region 2 and so on; anything else is 0 (no region). `count` is the
/// highest label used.
#[cfg(test)]
pub(crate) fn ascii_labels(rows: &[&str]) -> Labels {
    let data: Vec<u32> = rows
        .iter()
        .flat_map(|r| r.bytes())
        .map(|b| match b {
            b'a'..=b'z' => u32::from(b - b'a') + 1,
            _ => 0,
        })
        .collect();
    Labels {
        width: rows.first().map_or(0, |r| r.len()) as u32,
        height: rows.len() as u32,
        count: data.iter().copied().max().unwrap_or(0),
        data,
    }
}

/// Renders a mask as ASCII (`#` foreground, `.` background), rows joined by newlines.
#[cfg(test)]
pub(crate) fn mask_ascii(mask: &Mask) -> String {
    let mut s = String::new();
    for y in 0..mask.height() {
        for x in 0..mask.width() {
            s.push(if mask.get_pixel(x, y)[0] != 0 {
                '#'
            } else {
                '.'
            });
        }
        s.push('\n');
    }
    s
}
