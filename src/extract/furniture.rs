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
/// So do pieces of wall between two doorways: islands at least 1.5 times
/// as long as thick that lie in line with a wall of about their thickness on
/// both ends, each within `gap_px` (a pillar between the two leaves of a
/// double door, the wall between two doors side by side).
pub(crate) fn free_without_furniture(
    grid: &OccupancyGrid,
    max_extent_px: f64,
    gap_px: f64,
) -> Mask {
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
    // With every island gone, the obstacles left are walls.
    let walls = Mask::from_raw(w, h, data.clone()).unwrap_or_else(|| Mask::new(w, h));
    let wall_piece: Vec<bool> = bbox
        .iter()
        .enumerate()
        .map(|(l, b)| island[l] && in_wall_line(&walls, *b, gap_px))
        .collect();
    for r in blobs.runs.iter().filter(|r| wall_piece[r.label as usize]) {
        let i = r.y as usize * w as usize;
        data[i + r.x0 as usize..i + r.x1 as usize].fill(0);
    }
    Mask::from_raw(w, h, data).unwrap_or_else(|| Mask::new(w, h))
}

/// Whether the island with bounding box `b` (`[x0, y0, x1, y1]`, inclusive)
/// lies in a wall line of `walls` (0 = wall): at least 1.5 times as long
/// as thick, with a wall within `gap_px` of either end along its middle line,
/// and each of those walls no thicker across the line than twice the
/// island plus two pixels (a wall running on in line, not a side wall).
fn in_wall_line(walls: &Mask, b: [u32; 4], gap_px: f64) -> bool {
    let (w, h) = (walls.width() as i64, walls.height() as i64);
    let [x0, y0, x1, y1] = b.map(i64::from);
    let (long, thick) = (x1 - x0 + 1, y1 - y0 + 1);
    let horizontal = long >= thick;
    let (long, thick) = if horizontal {
        (long, thick)
    } else {
        (thick, long)
    };
    if 2 * long < 3 * thick {
        return false;
    }
    let wall = |x: i64, y: i64| {
        x < 0 || y < 0 || x >= w || y >= h || walls.as_raw()[(y * w + x) as usize] == 0
    };
    // (x, y) of a point `t` along the line and `s` across it.
    let at = |t: i64, s: i64| if horizontal { (t, s) } else { (s, t) };
    let (t0, t1, mid) = if horizontal {
        (x0, x1, (y0 + y1) / 2)
    } else {
        (y0, y1, (x0 + x1) / 2)
    };
    let gap = gap_px.ceil() as i64;
    let thin_wall_within = |dir: i64| {
        let start = if dir < 0 { t0 - 1 } else { t1 + 1 };
        let Some(t) = (0..=gap).map(|k| start + dir * k).find(|&t| {
            let (x, y) = at(t, mid);
            wall(x, y)
        }) else {
            return false;
        };
        let across = |sdir: i64| {
            (1..=2 * thick + 2)
                .take_while(|&k| {
                    let (x, y) = at(t, mid + sdir * k);
                    wall(x, y)
                })
                .count() as i64
        };
        1 + across(-1) + across(1) <= 2 * thick + 2
    };
    thin_wall_within(-1) && thin_wall_within(1)
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
        let m = free_without_furniture(&g, 3.0, 0.0);
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

    #[test]
    fn a_pillar_between_two_doorways_stays() {
        // A wall line (row 4) with two doorways and a 4-px pillar between
        // them; a 2-px desk stands free in the room below.
        let g = OccupancyGrid::from_ascii(
            "################
             #..............#
             #..............#
             #..............#
             ####...####...##
             #..............#
             #......##......#
             #..............#
             ################",
            0.1,
        );
        let m = free_without_furniture(&g, 4.0, 3.0);
        let row = |y: u32| -> String {
            (0..16)
                .map(|x| if m.get_pixel(x, y)[0] == 0 { '#' } else { '.' })
                .collect()
        };
        assert_eq!(row(4), "####...####...##", "the pillar stays");
        assert_eq!(row(6), "#..............#", "the desk goes");
    }
}
