//! Furniture islands: small obstacle blobs standing free inside rooms
//! (table and chair legs, boxes, pillars). The paper's stated weakness is
//! that clutter cuts rooms into pieces; here such islands are treated as
//! free space while the rooms are segmented, so a room is found as if it
//! were empty and the pixels under its furniture belong to it.

use crate::grid::{Cell, OccupancyGrid};
use crate::imaging::{Mask, label_runs};

/// The free mask (255 free) of `grid` in which every 8-connected component
/// of non-free pixels that does not touch the image border and whose
/// bounding box is at most `max_extent_px` on both sides is free too.
/// Walls are connected to the building's outline or long, so they stay.
pub(crate) fn free_without_furniture(grid: &OccupancyGrid, max_extent_px: f64) -> Mask {
    let (w, h) = (grid.width, grid.height);
    let free: Vec<u8> = grid
        .cells
        .iter()
        .map(|c| if *c == Cell::Free { 255 } else { 0 })
        .collect();
    if max_extent_px < 1.0 {
        return Mask::from_raw(w, h, free).unwrap_or_else(|| Mask::new(w, h));
    }
    let blocked_data = free.iter().map(|&f| 255 - f).collect();
    let blocked = Mask::from_raw(w, h, blocked_data).unwrap_or_else(|| Mask::new(w, h));
    let blobs = label_runs(&blocked, true);
    let bbox = blobs.bounding_boxes();
    let island: Vec<bool> = bbox
        .iter()
        .map(|b| {
            let touches_border = b[0] == 0 || b[1] == 0 || b[2] + 1 >= w || b[3] + 1 >= h;
            let extent = f64::from(
                (b[2] + 1)
                    .saturating_sub(b[0])
                    .max((b[3] + 1).saturating_sub(b[1])),
            );
            b[0] != u32::MAX && !touches_border && extent <= max_extent_px
        })
        .collect();
    let mut data = free;
    for r in blobs.runs.iter().filter(|r| island[r.label as usize]) {
        let i = r.y as usize * w as usize;
        data[i + r.x0 as usize..i + r.x1 as usize].fill(255);
    }
    Mask::from_raw(w, h, data).unwrap_or_else(|| Mask::new(w, h))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::mask_ascii;

    #[test]
    fn small_islands_become_free_walls_stay() {
        // A room with a 2-px table, a 6-px long free-standing wall and a
        // wall stub joined to the outline.
        let g = OccupancyGrid::from_ascii(
            "############
             #..........#
             #.##.......#
             #.##..######
             #..........#
             #..######..#
             #..........#
             ############",
            0.1,
        );
        let m = free_without_furniture(&g, 3.0);
        let expected = "............
                        .##########.
                        .##########.
                        .#####......
                        .##########.
                        .##......##.
                        .##########.
                        ............";
        let expected: String = expected
            .lines()
            .map(|l| format!("{}\n", l.trim()))
            .collect();
        assert_eq!(mask_ascii(&m), expected);
    }
}
