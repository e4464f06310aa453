//! Thresholding a grey raster into a [`Mask`].

use super::Mask;

/// Foreground where `grey >= min_grey`; `grey` is row-major `width × height`.
///
/// ```
/// let m = nrgdb::imaging::binarize(3, 1, &[0, 250, 255], 250);
/// assert_eq!(m.as_raw(), &vec![0, 255, 255]);
/// ```
pub fn binarize(width: u32, height: u32, grey: &[u8], min_grey: u8) -> Mask {
    let data = grey
        .iter()
        .map(|&g| if g >= min_grey { 255 } else { 0 })
        .collect();
    Mask::from_raw(width, height, data).unwrap_or_else(|| Mask::new(width, height))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn threshold_is_inclusive() {
        let m = binarize(2, 2, &[249, 250, 0, 255], 250);
        assert_eq!(m.as_raw(), &vec![0, 255, 0, 255]);
    }
}
