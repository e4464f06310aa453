//! The paper's door detector (Tab. 2): a doorway is where the skeleton of
//! the free space (its medial axis, the generalised Voronoi graph) meets
//! the skeleton of the complement of the opened free space (the walls,
//! joined across each doorway the opening closed). Chosen with
//! `door_rule = "skeleton"`; the default rule is the border constriction.

use crate::imaging::{Mask, dilate, erode, open, skeletonize};

/// Per pixel, whether it lies within `near_px` of a doorway point of the
/// paper's Tab. 2 on `free` (non-zero = free): the AND of `skeleton(free)`
/// and `skeleton(inverse(I_opn))`, with `I_opn = open(erode(free,
/// erode_px), open_px)` as in Tab. 1 (walls thickened, then doorways
/// narrower than the opening's disk closed). Tab. 2 writes the first as
/// `skeleton(I_opn)`; its text says the free space's skeleton, which is
/// what can meet the walls' skeleton inside a doorway. Two
/// 8-connected skeletons can cross diagonally without sharing a pixel, so
/// the free-space skeleton is widened by one pixel first. The complement
/// is taken only within `open_px + 2` of free space: far from it the
/// obstacle skeleton does not reach a doorway and would only cost time.
pub(crate) fn skeleton_doorways(
    free: &Mask,
    erode_px: f64,
    open_px: f64,
    near_px: f64,
) -> Vec<bool> {
    let voronoi = dilate(&skeletonize(free), 1.0);
    let opened = open(&erode(free, erode_px), open_px);
    // The walls: the band around free space that the opening left out.
    let mut walls = dilate(free, open_px + 2.0);
    walls
        .iter_mut()
        .zip(opened.iter())
        .for_each(|(c, &o)| *c = if *c != 0 && o == 0 { 255 } else { 0 });
    let mut meet = skeletonize(&walls);
    meet.iter_mut()
        .zip(voronoi.iter())
        .for_each(|(m, &v)| *m = if *m != 0 && v != 0 { 255 } else { 0 });
    dilate(&meet, near_px).iter().map(|&p| p != 0).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::ascii_mask;

    #[test]
    fn the_skeletons_meet_in_a_doorway() {
        // Two 9 × 9 rooms joined by a 3-px doorway through a 2-px wall
        // (columns 10-11, rows 4-6).
        let mut rows = Vec::new();
        for y in 0..11 {
            let mut r = String::from("#");
            for x in 1..21 {
                let wall = y == 0 || y == 10 || ((10..12).contains(&x) && !(4..7).contains(&y));
                r.push(if wall { '#' } else { '.' });
            }
            r.push('#');
            rows.push(r);
        }
        let mut free = ascii_mask(&rows.join("\n"));
        free.iter_mut().for_each(|p| *p = 255 - *p);
        // Walls thickened by 1 px, then a disk of radius 3 cannot pass the
        // doorway: the walls' skeleton runs through it, across the free
        // space's skeleton.
        let door = skeleton_doorways(&free, 1.0, 3.0, 0.0);
        let w = 22;
        let hits: Vec<(usize, usize)> = (0..door.len())
            .filter(|&i| door[i])
            .map(|i| (i % w, i / w))
            .collect();
        assert!(!hits.is_empty());
        assert!(
            hits.iter()
                .all(|&(x, y)| (9..13).contains(&x) && (3..8).contains(&y)),
            "{hits:?}"
        );
    }
}
