//! The paper's Experiment I (Tab. 1): binarise, erode, open, connected
//! components; the pixels the opening removed (`erd XOR opn`) are where the
//! components meet, and the door spaces are cut there.

use super::segment::fill_unreached;
use crate::imaging::{Labels, Mask, erode, label_components, open, watershed};

/// Rooms as the 8-connected components of the eroded-then-opened free space,
/// grown back breadth-first over the reachable free pixels (so they meet
/// inside the XOR zone, i.e. in the doorways).
pub(crate) fn segment_ccl(clean: &Mask, reachable: &[bool], erode_px: f64, open_px: f64) -> Labels {
    let erd = if erode_px >= 0.5 { erode(clean, erode_px) } else { clean.clone() };
    let opn = if open_px >= 0.5 { open(&erd, open_px) } else { erd };
    let rooms = label_components(&opn, true);
    let mut grown = watershed(&vec![0u16; rooms.data.len()], &rooms, reachable);
    fill_unreached(&mut grown, reachable);
    grown
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::ascii_mask;

    #[test]
    fn doorway_separates_two_components() {
        let m = ascii_mask(
            "..............
             .#####..#####.
             .#####..#####.
             .############.
             .#####..#####.
             .#####..#####.
             ..............",
        );
        let reach: Vec<bool> = m.iter().map(|&p| p != 0).collect();
        let l = segment_ccl(&m, &reach, 0.0, 1.5);
        assert_eq!(l.count, 2);
        assert_ne!(l.data[14 + 1], l.data[14 + 12]);
        assert!(l.data.iter().zip(&reach).all(|(&v, &r)| (v != 0) == r));
    }
}
