//! A ground truth carried from the map it was drawn on onto another map of
//! the same building (our own map of a robot log, say), given where each
//! map's points lie in the other's frame.
//!
//! Rooms are sampled: each pixel of the target that is free there (grey ≥
//! 250, as the GT's own rule) takes the GT room under its centre in the
//! reference; rooms left with ≤ 100 px are dropped, the rest renumbered.
//! Doorway lines are carried the other way: each line pixel's centre lands
//! on a target pixel, and the line keeps the rooms it joined that survive
//! (a line left joining fewer than two is dropped). Pixels of the reference
//! that are free there but not in the target are not the target's rooms:
//! the GT keeps the target's own free-space convention, so room figures
//! measure the extraction on the target, not how the two maps differ.

use crate::grid::OccupancyGrid;
use crate::imaging::Labels;
use crate::model::Point;

use super::{DoorLine, GroundTruth};

/// Smallest grey of a free pixel (the GT's rule, BENCHMARK.md §1.1).
const FREE_GREY: u8 = 250;

/// Fewest pixels a GT room keeps (BENCHMARK.md §1.1: rooms of ≤ 100 px are
/// dropped).
const ROOM_MIN_PX: usize = 101;

/// `gt`, drawn on `reference`, carried onto `target`'s pixels.
/// `to_reference` takes a point in `target`'s map frame (metres) to
/// `reference`'s, `to_target` the other way.
pub fn transfer_ground_truth(
    gt: &GroundTruth,
    reference: &OccupancyGrid,
    target: &OccupancyGrid,
    to_reference: impl Fn(Point) -> Point,
    to_target: impl Fn(Point) -> Point,
) -> GroundTruth {
    let (w, h) = (target.width, target.height);
    let mut rooms = Labels::new(w, h);
    rooms.count = gt.rooms.count;
    for row in 0..h {
        for col in 0..w {
            let i = row as usize * w as usize + col as usize;
            if target.grey[i] < FREE_GREY {
                continue;
            }
            let p =
                to_reference(target.pixel_to_metres(f64::from(col) + 0.5, f64::from(row) + 0.5));
            if let Some(j) = pixel_index(reference, p) {
                rooms.data[i] = gt.rooms.data[j];
            }
        }
    }
    // Keep rooms over the size limit, renumbered 1..=n.
    let areas = rooms.areas();
    let mut new_id = vec![0u32; areas.len()];
    let mut next = 0;
    for (id, &a) in areas.iter().enumerate().skip(1) {
        if a >= ROOM_MIN_PX {
            next += 1;
            new_id[id] = next;
        }
    }
    for l in &mut rooms.data {
        *l = new_id[*l as usize];
    }
    rooms.count = next;
    let doors = gt
        .doors
        .iter()
        .filter_map(|line| {
            let mut joined: Vec<u32> = line
                .rooms
                .iter()
                .filter_map(|&r| new_id.get(r as usize).copied())
                .filter(|&r| r != 0)
                .collect();
            joined.sort_unstable();
            joined.dedup();
            let mut pixels: Vec<u32> = line
                .pixels
                .iter()
                .filter_map(|&p| {
                    let (col, row) = (p % reference.width, p / reference.width);
                    let m = reference.pixel_to_metres(f64::from(col) + 0.5, f64::from(row) + 0.5);
                    pixel_index(target, to_target(m)).map(|j| j as u32)
                })
                .collect();
            pixels.sort_unstable();
            pixels.dedup();
            (joined.len() >= 2 && pixels.len() >= 3).then_some(DoorLine {
                pixels,
                rooms: joined,
            })
        })
        .collect();
    GroundTruth { rooms, doors }
}

/// The row-major index of the pixel of `grid` holding the point `p`, if
/// inside.
fn pixel_index(grid: &OccupancyGrid, p: Point) -> Option<usize> {
    let [col, row] = grid.metres_to_pixel(p);
    let (col, row) = (col.floor(), row.floor());
    (col >= 0.0 && row >= 0.0 && col < f64::from(grid.width) && row < f64::from(grid.height))
        .then(|| row as usize * grid.width as usize + col as usize)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::Cell;

    /// A `w`×`h` grid of free cells at 0.1 m, its origin at `origin`.
    fn free_grid(w: u32, h: u32, origin: [f64; 3]) -> OccupancyGrid {
        OccupancyGrid::from_cells(w, h, 0.1, origin, vec![Cell::Free; (w * h) as usize])
    }

    /// Two 12×12 GT rooms side by side (columns 0–11 and 13–24 of a 25×12
    /// image) and a doorway line in column 12, rows 4–6.
    fn two_rooms() -> GroundTruth {
        let (w, h) = (25u32, 12u32);
        let data = (0..w * h)
            .map(|i| match i % w {
                0..=11 => 1,
                12 => 0,
                _ => 2,
            })
            .collect();
        GroundTruth {
            rooms: Labels {
                width: w,
                height: h,
                data,
                count: 2,
            },
            doors: vec![DoorLine {
                pixels: (4..7).map(|r| r * w + 12).collect(),
                rooms: vec![1, 2],
            }],
        }
    }

    #[test]
    fn a_map_turned_half_a_turn_gets_the_rooms_and_the_line_turned() {
        let gt = two_rooms();
        let reference = free_grid(25, 12, [0.0, 0.0, 0.0]);
        // The target is the same area turned 180° about (1.25, 0.6): its
        // point p lies at (2.5 − x, 1.2 − y) in the reference.
        let target = free_grid(25, 12, [0.0, 0.0, 0.0]);
        let turn = |p: Point| [2.5 - p[0], 1.2 - p[1]];
        let t = transfer_ground_truth(&gt, &reference, &target, turn, turn);
        assert_eq!(t.rooms.count, 2);
        // The reference's room 1 (left) is now on the right: renumbered in
        // id order, it stays 1.
        assert_eq!(t.rooms.data[24], 1);
        assert_eq!(t.rooms.data[0], 2);
        assert_eq!(t.rooms.data[12], 0);
        assert_eq!(t.doors.len(), 1);
        // Rows 4–6 turned are rows 5–7, still column 12.
        assert_eq!(
            t.doors[0].pixels,
            vec![5 * 25 + 12, 6 * 25 + 12, 7 * 25 + 12]
        );
        assert_eq!(t.doors[0].rooms, vec![1, 2]);
    }

    #[test]
    fn pixels_not_free_in_the_target_and_rooms_left_small_are_dropped() {
        let gt = two_rooms();
        let reference = free_grid(25, 12, [0.0, 0.0, 0.0]);
        let mut target = free_grid(25, 12, [0.0, 0.0, 0.0]);
        // Columns 13..25 of the target are walls but for a 10×10 block
        // (100 px, too small a room).
        for row in 0..12u32 {
            for col in 13..25u32 {
                let i = (row * 25 + col) as usize;
                let inside = (1..11).contains(&row) && (14..24).contains(&col);
                if !inside {
                    target.grey[i] = 0;
                    target.cells[i] = Cell::Occupied;
                }
            }
        }
        let same = |p: Point| p;
        let t = transfer_ground_truth(&gt, &reference, &target, same, same);
        assert_eq!(t.rooms.count, 1);
        assert_eq!(t.rooms.areas()[1], 144);
        assert_eq!(t.rooms.data[2 * 25 + 15], 0);
        // The line joins one surviving room only: no doorway.
        assert!(t.doors.is_empty());
    }
}
