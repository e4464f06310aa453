//! Working resolution: maps finer than [`ExtractParams::working_resolution_m`]
//! are segmented on a coarser copy (k × k cells to one) and the labels are
//! brought back to the map's own pixels. Every parameter is in metres, so
//! the segmentation itself does not change character; it runs on k² times
//! fewer pixels.
//!
//! [`ExtractParams::working_resolution_m`]: super::ExtractParams::working_resolution_m

use std::collections::{BTreeMap, VecDeque};

use super::interior::neighbours;
use crate::grid::{Cell, OccupancyGrid};
use crate::imaging::Labels;
use crate::model::SpaceId;

/// The grid with each `k`×`k` block of cells as one cell: free when all its
/// cells are free, occupied when any is occupied, unknown otherwise. Blocks
/// past the right and bottom edges are padded with unknown; the origin is
/// moved so that every cell keeps its place in the map frame.
pub(crate) fn coarsen(grid: &OccupancyGrid, k: u32) -> OccupancyGrid {
    let (w, h) = (grid.width as usize, grid.height as usize);
    let k = k.max(1) as usize;
    let (cw, ch) = (w.div_ceil(k), h.div_ceil(k));
    let mut cells = vec![Cell::Free; cw * ch];
    for (cy, row) in cells.chunks_exact_mut(cw.max(1)).enumerate().take(ch) {
        for (cx, cell) in row.iter_mut().enumerate() {
            let mut any_occupied = false;
            let mut all_free = true;
            for y in cy * k..cy * k + k {
                for x in cx * k..cx * k + k {
                    match (x < w && y < h).then(|| grid.cells[y * w + x]) {
                        Some(Cell::Free) => {}
                        Some(Cell::Occupied) => any_occupied = true,
                        _ => all_free = false,
                    }
                }
            }
            *cell = if any_occupied {
                Cell::Occupied
            } else if all_free {
                Cell::Free
            } else {
                Cell::Unknown
            };
        }
    }
    let corner = grid.pixel_to_metres(0.0, (ch * k) as f64);
    OccupancyGrid::from_cells(
        cw as u32,
        ch as u32,
        grid.resolution * k as f64,
        [corner[0], corner[1], grid.origin[2]],
        cells,
    )
}

/// Labels at the map's own size from labels of its [`coarsen`]ed copy: a
/// pixel takes its block's label; free pixels of unlabelled blocks (next to
/// walls) take the label of the nearest labelled free pixel at most `k`
/// steps away, breadth-first.
pub(crate) fn refine(coarse: &Labels, grid: &OccupancyGrid, k: u32) -> Labels {
    let (w, h) = (grid.width as usize, grid.height as usize);
    let (k, cw) = (k.max(1) as usize, coarse.width as usize);
    let mut fine = Labels::new(grid.width, grid.height);
    fine.count = coarse.count;
    for y in 0..h {
        let src = &coarse.data[(y / k) * cw..(y / k + 1) * cw];
        for (x, l) in fine.data[y * w..(y + 1) * w].iter_mut().enumerate() {
            *l = src[x / k];
        }
    }
    let open = |i: usize, fine: &Labels| fine.data[i] == 0 && grid.cells[i] == Cell::Free;
    // First ring: open pixels beside a labelled one (few: along walls).
    let mut queue: VecDeque<(usize, usize)> = VecDeque::new();
    for i in 0..w * h {
        let beside = open(i, &fine)
            .then(|| neighbours(i, w, h).map(|j| fine.data[j]).find(|&l| l != 0))
            .flatten();
        if let Some(l) = beside {
            queue.push_back((i, l as usize));
        }
    }
    for &(i, l) in &queue {
        fine.data[i] = l as u32;
    }
    let mut queue: VecDeque<(usize, usize)> = queue.into_iter().map(|(i, _)| (i, 1)).collect();
    while let Some((i, depth)) = queue.pop_front() {
        if depth >= k {
            continue;
        }
        for j in neighbours(i, w, h) {
            if open(j, &fine) {
                fine.data[j] = fine.data[i];
                queue.push_back((j, depth + 1));
            }
        }
    }
    fine
}

/// Mean `[col, row]` of the pixels of each label.
pub(crate) fn pixel_centroids(labels: &Labels) -> BTreeMap<SpaceId, [f64; 2]> {
    let w = labels.width as usize;
    let mut sums = vec![(0usize, 0.0f64, 0.0f64); labels.count as usize + 1];
    for (i, &l) in labels.data.iter().enumerate() {
        if let Some(s) = sums.get_mut(l as usize).filter(|_| l != 0) {
            s.0 += 1;
            s.1 += (i % w) as f64;
            s.2 += (i / w) as f64;
        }
    }
    sums.iter()
        .enumerate()
        .filter(|(_, s)| s.0 > 0)
        .map(|(l, s)| (SpaceId(l as u32), [s.1 / s.0 as f64, s.2 / s.0 as f64]))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coarse_cells_keep_their_place_and_labels_come_back() {
        let g = OccupancyGrid::from_ascii(
            "#####
             #...#
             #...#
             #####",
            0.05,
        );
        let c = coarsen(&g, 2);
        assert_eq!((c.width, c.height, c.resolution), (3, 2, 0.1));
        // The padded bottom row is the same height below: corners agree.
        assert_eq!(c.pixel_to_metres(0.0, 0.0), g.pixel_to_metres(0.0, 0.0));
        assert!(c.cells.iter().all(|&cell| cell == Cell::Occupied));
        // A coarse label on the middle block comes back on its free pixels
        // and reaches the free pixels of the blocks around it.
        let coarse = Labels {
            width: 3,
            height: 2,
            data: vec![0, 7, 0, 0, 0, 0],
            count: 7,
        };
        let fine = refine(&coarse, &g, 2);
        let free: Vec<u32> = (0..20)
            .filter(|&i| g.cells[i] == Cell::Free)
            .map(|i| fine.data[i])
            .collect();
        assert_eq!(free, vec![7; 6]);
        assert_eq!(pixel_centroids(&fine)[&SpaceId(7)], [17.0 / 8.0, 9.0 / 8.0]);
    }
}
