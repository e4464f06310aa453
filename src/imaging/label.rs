//! Connected-component labelling (via imageproc's union–find).

use imageproc::region_labelling::{Connectivity, connected_components};

use super::Mask;

/// A label image: row-major, 0 = no label, 1..=count labels.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Labels {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Label per pixel.
    pub data: Vec<u32>,
    /// Largest label used.
    pub count: u32,
}

impl Labels {
    /// An all-zero label image.
    pub fn new(width: u32, height: u32) -> Labels {
        Labels {
            width,
            height,
            data: vec![0; width as usize * height as usize],
            count: 0,
        }
    }

    /// Pixel count of every label, indexed by label (index 0 = unlabelled).
    pub fn areas(&self) -> Vec<usize> {
        let mut a = vec![0usize; self.count as usize + 1];
        for &l in &self.data {
            if let Some(slot) = a.get_mut(l as usize) {
                *slot += 1;
            }
        }
        a
    }

    /// Renumbers labels to 1..=n in order of first appearance, dropping gaps.
    pub fn compact(&mut self) {
        let mut map = vec![0u32; self.count as usize + 1];
        let mut next = 0;
        for l in &mut self.data {
            if *l == 0 {
                continue;
            }
            let m = &mut map[*l as usize];
            if *m == 0 {
                next += 1;
                *m = next;
            }
            *l = *m;
        }
        self.count = next;
    }
}

/// Labels the foreground components of `mask`, 8-connected if `eight` else 4-connected.
///
/// ```
/// use nrgdb::imaging::{binarize, label_components};
/// let m = binarize(5, 1, &[255, 0, 255, 255, 0], 250);
/// assert_eq!(label_components(&m, true).data, vec![1, 0, 2, 2, 0]);
/// ```
pub fn label_components(mask: &Mask, eight: bool) -> Labels {
    let conn = if eight {
        Connectivity::Eight
    } else {
        Connectivity::Four
    };
    let img = connected_components(mask, conn, image::Luma([0u8]));
    let (width, height) = img.dimensions();
    let data = img.into_raw();
    let count = data.iter().copied().max().unwrap_or(0);
    let mut labels = Labels {
        width,
        height,
        data,
        count,
    };
    labels.compact();
    labels
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::ascii_mask;

    #[test]
    fn four_and_eight_connectivity() {
        let m = ascii_mask(
            "#...
             .#..
             ...#",
        );
        assert_eq!(label_components(&m, false).count, 3);
        let l8 = label_components(&m, true);
        assert_eq!(l8.count, 2);
        assert_eq!(l8.areas(), vec![9, 2, 1]);
    }
}
