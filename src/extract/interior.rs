//! Unknown pockets inside rooms: the insides of furniture and of anything
//! else the sensor could not see into (drawn grey in the IPA maps, left
//! unknown by a LiDAR). They belong to the room around them, so each such
//! pocket is given to the spaces it touches, pixel by pixel, nearest first.

use std::collections::VecDeque;

use crate::grid::{Cell, OccupancyGrid};
use crate::imaging::{Labels, Mask, label_runs};

/// Grows `labels` into every 8-connected component of unknown cells that
/// does not touch the image border (what touches it is the outside) and
/// has at most `max_px` pixels (larger ones are unexplored rooms, or walls
/// drawn grey). Growth is a breadth-first flood from the labelled pixels,
/// 4-connected, so a pocket between two spaces is shared at the middle.
pub(crate) fn claim_enclosed_unknown(labels: &mut Labels, grid: &OccupancyGrid, max_px: usize) {
    let (w, h) = (grid.width as usize, grid.height as usize);
    if max_px == 0 || w == 0 || h == 0 {
        return;
    }
    let unknown_data = grid
        .cells
        .iter()
        .map(|c| if *c == Cell::Unknown { 255 } else { 0 })
        .collect();
    let unknown = Mask::from_raw(grid.width, grid.height, unknown_data)
        .unwrap_or_else(|| Mask::new(grid.width, grid.height));
    let pockets = label_runs(&unknown, true);
    let area = pockets.areas();
    let on_border = pockets.touches_border();
    let claimable: Vec<bool> = (0..area.len())
        .map(|p| p != 0 && !on_border[p] && area[p] <= max_px)
        .collect();
    if !claimable.contains(&true) {
        return;
    }
    let mut in_pocket = vec![false; w * h];
    for r in pockets.runs.iter().filter(|r| claimable[r.label as usize]) {
        let i = r.y as usize * w;
        in_pocket[i + r.x0 as usize..i + r.x1 as usize].fill(true);
    }
    let open = |i: usize, labels: &Labels| labels.data[i] == 0 && in_pocket[i];
    // The flood starts from the labelled pixels next to an open one, in
    // raster order: found from the open pixels, which are few.
    let mut starts = Vec::new();
    for r in pockets.runs.iter().filter(|r| claimable[r.label as usize]) {
        let row = r.y as usize * w;
        for i in row + r.x0 as usize..row + r.x1 as usize {
            if labels.data[i] == 0 {
                starts.extend(neighbours(i, w, h).filter(|&j| labels.data[j] != 0));
            }
        }
    }
    starts.sort_unstable();
    starts.dedup();
    let mut queue = VecDeque::from(starts);
    while let Some(i) = queue.pop_front() {
        let l = labels.data[i];
        for j in neighbours(i, w, h) {
            if open(j, labels) {
                labels.data[j] = l;
                queue.push_back(j);
            }
        }
    }
}

/// Gives every unlabelled 4-connected speck of at most `max_px` pixels that
/// lies wholly inside one space (all its neighbours carry that one label,
/// none is the image border) to that space: specks of clutter or noise are
/// not holes in a room, and side by side they would make polygon rings
/// that touch.
pub(crate) fn fill_specks(labels: &mut Labels, max_px: usize) {
    let w = labels.width as usize;
    let unlabelled_data = labels
        .data
        .iter()
        .map(|&l| if l == 0 { 255 } else { 0 })
        .collect();
    let unlabelled = Mask::from_raw(labels.width, labels.height, unlabelled_data)
        .unwrap_or_else(|| Mask::new(labels.width, labels.height));
    let specks = label_runs(&unlabelled, false);
    let area = specks.areas();
    // The one label around each speck: 0 = none yet, u32::MAX = several or the border.
    let mut around = vec![0u32; area.len()];
    for (s, touches) in around.iter_mut().zip(specks.touches_border()) {
        if touches {
            *s = u32::MAX;
        }
    }
    for r in &specks.runs {
        let s = r.label as usize;
        if around[s] == u32::MAX {
            continue;
        }
        // Not on the border, so all four neighbours are in the image.
        let row = r.y as usize * w;
        for i in row + r.x0 as usize..row + r.x1 as usize {
            for j in [i - 1, i + 1, i - w, i + w] {
                let l = labels.data[j];
                if l != 0 && around[s] != l {
                    around[s] = if around[s] == 0 { l } else { u32::MAX };
                }
            }
        }
    }
    for r in &specks.runs {
        let s = r.label as usize;
        if area[s] <= max_px && around[s] != 0 && around[s] != u32::MAX {
            let row = r.y as usize * w;
            labels.data[row + r.x0 as usize..row + r.x1 as usize].fill(around[s]);
        }
    }
}

/// The 4-neighbours of pixel `i` inside a `w`×`h` image.
pub(crate) fn neighbours(i: usize, w: usize, h: usize) -> impl Iterator<Item = usize> {
    let (x, y) = (i % w, i / w);
    [
        (x > 0).then(|| i - 1),
        (x + 1 < w).then(|| i + 1),
        (y > 0).then(|| i - w),
        (y + 1 < h).then(|| i + w),
    ]
    .into_iter()
    .flatten()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pockets_inside_rooms_are_claimed_outside_is_not() {
        // Room 1 (left) holds a 2-px unknown pocket; the unknown outside
        // touches the border; room 2 (right) is walled off from the pocket.
        let g = OccupancyGrid::from_ascii(
            "??????????
             ?########?
             ?#...#..#?
             ?#.??#..#?
             ?#...#..#?
             ?########?
             ??????????",
            0.1,
        );
        let mut labels = Labels::new(g.width, g.height);
        for (i, c) in g.cells.iter().enumerate() {
            if *c == Cell::Free {
                labels.data[i] = if i % 10 < 5 { 1 } else { 2 };
            }
        }
        labels.count = 2;
        let mut small = labels.clone();
        claim_enclosed_unknown(&mut labels, &g, 4);
        assert_eq!((labels.data[33], labels.data[34]), (1, 1));
        assert_eq!(labels.data[0], 0, "outside stays unlabelled");
        assert_eq!(labels.data.iter().filter(|&&l| l == 1).count(), 9);
        // A pocket above the size limit is left alone.
        claim_enclosed_unknown(&mut small, &g, 1);
        assert_eq!((small.data[33], small.data[34]), (0, 0));
    }

    #[test]
    fn specks_inside_one_space_are_filled_others_stay() {
        // A 1-px speck inside label 1, a speck between labels 1 and 2, and
        // the unlabelled border.
        let mut labels = Labels {
            width: 5,
            height: 4,
            data: vec![
                0, 0, 0, 0, 0, //
                0, 1, 1, 1, 0, //
                0, 1, 0, 1, 0, //
                0, 1, 1, 0, 2, //
            ],
            count: 2,
        };
        fill_specks(&mut labels, 4);
        assert_eq!(labels.data[12], 1, "speck inside 1 filled");
        assert_eq!(labels.data[18], 0, "speck between 1 and 2 stays");
        assert_eq!(labels.data[0], 0, "border stays");
    }
}
