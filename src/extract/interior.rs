//! Unknown pockets inside rooms: the insides of furniture and of anything
//! else the sensor could not see into (drawn grey in the IPA maps, left
//! unknown by a LiDAR). They belong to the room around them, so each such
//! pocket is given to the spaces it touches, pixel by pixel, nearest first.

use std::collections::VecDeque;

use crate::grid::{Cell, OccupancyGrid};
use crate::imaging::{Labels, Mask, label_components};

/// Grows `labels` into every 8-connected component of unknown cells that
/// does not touch the image border (what touches it is the outside), has
/// at most `max_px` pixels (larger ones are unexplored rooms) and is
/// surrounded by space: at least half of the pixels bordering it are
/// labelled. The inside of a wall drawn as two lines with grey between is
/// bordered by the lines, so it stays out. Growth is a breadth-first flood
/// from the labelled pixels, 4-connected, so a pocket between two spaces is
/// shared at the middle; labels from `fixed_from` up (doors, whose shape is
/// already cut) do not grow.
pub(crate) fn claim_enclosed_unknown(
    labels: &mut Labels,
    grid: &OccupancyGrid,
    max_px: usize,
    thick_px: usize,
    fixed_from: u32,
) {
    if max_px == 0 {
        return;
    }
    let (w, h) = (grid.width as usize, grid.height as usize);
    let unknown_data = grid
        .cells
        .iter()
        .map(|c| if *c == Cell::Unknown { 255 } else { 0 })
        .collect();
    let unknown = Mask::from_raw(grid.width, grid.height, unknown_data)
        .unwrap_or_else(|| Mask::new(grid.width, grid.height));
    let pockets = label_components(&unknown, true);
    let n = pockets.count as usize + 1;
    let mut area = vec![0usize; n];
    let mut on_border = vec![false; n];
    let mut bbox = vec![[usize::MAX, usize::MAX, 0, 0]; n];
    // Per pocket: (labelled, all) pixel sides bordering it.
    let mut rim = vec![(0usize, 0usize); n];
    for (i, &p) in pockets.data.iter().enumerate() {
        if p == 0 {
            continue;
        }
        let p = p as usize;
        area[p] += 1;
        let (x, y) = (i % w, i / w);
        if x == 0 || y == 0 || x + 1 == w || y + 1 == h {
            on_border[p] = true;
        }
        let b = &mut bbox[p];
        *b = [b[0].min(x), b[1].min(y), b[2].max(x), b[3].max(y)];
        for j in neighbours(i, w, h).filter(|&j| pockets.data[j] as usize != p) {
            rim[p].1 += 1;
            rim[p].0 += usize::from(labels.data[j] != 0);
        }
    }
    let claimable: Vec<bool> = (0..n)
        .map(|p| {
            p != 0
                && !on_border[p]
                && area[p] <= max_px
                && (2 * rim[p].0 >= rim[p].1 || holds_square(&pockets, p as u32, bbox[p], thick_px))
        })
        .collect();
    let open =
        |i: usize, labels: &Labels| labels.data[i] == 0 && claimable[pockets.data[i] as usize];
    let mut queue: VecDeque<usize> = (0..w * h)
        .filter(|&i| labels.data[i] != 0 && labels.data[i] < fixed_from)
        .filter(|&i| neighbours(i, w, h).any(|j| open(j, labels)))
        .collect();
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

/// Whether the pixels labelled `id` inside `bbox` (`[x0, y0, x1, y1]`,
/// inclusive) contain a `side` × `side` square, by a summed-area table.
fn holds_square(labels: &Labels, id: u32, bbox: [usize; 4], side: usize) -> bool {
    let [x0, y0, x1, y1] = bbox;
    let (bw, bh) = (x1 + 1 - x0, y1 + 1 - y0);
    if side == 0 || bw < side || bh < side {
        return side == 0;
    }
    let w = labels.width as usize;
    // sat[(y + 1) * (bw + 1) + x + 1] = count of `id` pixels in [0..=x] × [0..=y].
    let mut sat = vec![0u32; (bw + 1) * (bh + 1)];
    for y in 0..bh {
        let mut row = 0;
        for x in 0..bw {
            row += u32::from(labels.data[(y0 + y) * w + x0 + x] == id);
            sat[(y + 1) * (bw + 1) + x + 1] = sat[y * (bw + 1) + x + 1] + row;
        }
    }
    let full = (side * side) as u32;
    let at = |x: usize, y: usize| sat[y * (bw + 1) + x];
    (side..=bh).any(|y| {
        (side..=bw)
            .any(|x| at(x, y) + at(x - side, y - side) - at(x - side, y) - at(x, y - side) == full)
    })
}

/// Gives every unlabelled 4-connected speck of at most `max_px` pixels that
/// lies wholly inside one space (all its neighbours carry that one label,
/// none is the image border) to that space: specks of clutter or noise are
/// not holes in a room, and side by side they would make polygon rings
/// that touch.
pub(crate) fn fill_specks(labels: &mut Labels, max_px: usize) {
    let (w, h) = (labels.width as usize, labels.height as usize);
    let unlabelled_data = labels
        .data
        .iter()
        .map(|&l| if l == 0 { 255 } else { 0 })
        .collect();
    let unlabelled = Mask::from_raw(labels.width, labels.height, unlabelled_data)
        .unwrap_or_else(|| Mask::new(labels.width, labels.height));
    let specks = label_components(&unlabelled, false);
    let n = specks.count as usize + 1;
    let mut area = vec![0usize; n];
    // The one label around each speck: 0 = none yet, u32::MAX = several or the border.
    let mut around = vec![0u32; n];
    for (i, &s) in specks.data.iter().enumerate() {
        if s == 0 {
            continue;
        }
        let s = s as usize;
        area[s] += 1;
        let (x, y) = (i % w, i / w);
        if x == 0 || y == 0 || x + 1 == w || y + 1 == h {
            around[s] = u32::MAX;
        }
        for j in neighbours(i, w, h) {
            let l = labels.data[j];
            if l != 0 && around[s] != l {
                around[s] = if around[s] == 0 { l } else { u32::MAX };
            }
        }
    }
    for (l, &s) in labels.data.iter_mut().zip(&specks.data) {
        let s = s as usize;
        if s != 0 && area[s] <= max_px && around[s] != 0 && around[s] != u32::MAX {
            *l = around[s];
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
        claim_enclosed_unknown(&mut labels, &g, 4, 2, 3);
        assert_eq!((labels.data[33], labels.data[34]), (1, 1));
        assert_eq!(labels.data[0], 0, "outside stays unlabelled");
        assert_eq!(labels.data.iter().filter(|&&l| l == 1).count(), 9);
        // A pocket above the size limit is left alone.
        claim_enclosed_unknown(&mut small, &g, 1, 2, 3);
        assert_eq!((small.data[33], small.data[34]), (0, 0));
    }

    #[test]
    fn wall_insides_are_not_claimed() {
        // A wall drawn as two lines with grey between, open at a doorway on
        // the left that belongs to room 1.
        let g = OccupancyGrid::from_ascii(
            "##########
             #........#
             #..#######
             #..??????#
             #..#######
             #........#
             ##########",
            0.1,
        );
        let mut labels = Labels::new(g.width, g.height);
        for (i, c) in g.cells.iter().enumerate() {
            if *c == Cell::Free {
                labels.data[i] = if i / 10 < 4 { 1 } else { 2 };
            }
        }
        labels.count = 2;
        let before = labels.clone();
        claim_enclosed_unknown(&mut labels, &g, 100, 2, 3);
        assert_eq!(labels, before, "the wall's inside stays unlabelled");
    }

    #[test]
    fn squares_inside_a_label() {
        // Label 1: an L of width 2 and a 3 x 3 block.
        let labels = Labels {
            width: 6,
            height: 3,
            data: vec![1, 1, 0, 1, 1, 1, 1, 1, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1],
            count: 1,
        };
        assert!(holds_square(&labels, 1, [0, 0, 5, 2], 3));
        assert!(!holds_square(&labels, 1, [0, 0, 2, 2], 3));
        assert!(holds_square(&labels, 1, [0, 0, 2, 2], 2));
    }

    #[test]
    fn doors_do_not_grow_into_pockets() {
        // A pocket with door 2 on three sides and room 1 below: only
        // the room grows into it.
        let g = OccupancyGrid::from_ascii(".....\n..?..\n.....", 0.1);
        let mut labels = Labels::new(g.width, g.height);
        for (i, c) in g.cells.iter().enumerate() {
            if *c == Cell::Free {
                labels.data[i] = if i == 12 { 1 } else { 2 };
            }
        }
        labels.count = 2;
        claim_enclosed_unknown(&mut labels, &g, 100, 2, 2);
        assert_eq!(labels.data[7], 1);
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
