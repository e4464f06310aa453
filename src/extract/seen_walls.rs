//! Whether a line drawn across free space ends on walls the sensor saw,
//! not on space it never saw (the shadow behind furniture): what an
//! opening into a room hardly wider than its front must end on
//! (`WallGap::narrow_faces`, see `pipeline.rs`, `openings`).

use crate::grid::{Cell, OccupancyGrid};

/// Whether both ends of the line through `pixels` (row-major in `grid`, in
/// order along the line) end on walls the sensor saw. An end does where an
/// occupied cell lies within `reach` pixels further along the line, or
/// where occupied cells lie on **both** sides of the line within `reach`
/// across it, within `reach` beyond the end: the two seen faces of a wall
/// whose end face between them the sensor never saw (a wall stub's end,
/// which rays only graze; log-odds maps leave a wall's core unknown). A
/// piece of furniture seen from one side only has one such face.
pub(crate) fn ends_on_seen_walls(grid: &OccupancyGrid, pixels: &[u32], reach: i64) -> bool {
    let (Some(&a), Some(&b)) = (pixels.first(), pixels.last()) else {
        return false;
    };
    let w = grid.width;
    let at = |p: u32| [f64::from(p % w), f64::from(p / w)];
    let (a, b) = (at(a), at(b));
    let len = (b[0] - a[0]).hypot(b[1] - a[1]);
    if len <= 0.0 {
        return false;
    }
    let u = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
    // Whether the cell `t` pixels along the line from `p` and `s` across
    // it is occupied.
    let occupied = |p: [f64; 2], t: f64, s: f64| {
        let (x, y) = (
            (p[0] + u[0] * t - u[1] * s).round(),
            (p[1] + u[1] * t + u[0] * s).round(),
        );
        x >= 0.0 && y >= 0.0 && grid.cell(x as u32, y as u32) == Some(Cell::Occupied)
    };
    let beyond = |sign: f64| (1..=reach).map(move |t| sign * t as f64);
    let face = |p: [f64; 2], sign: f64, side: f64| {
        beyond(sign).any(|t| (1..=reach).any(|s| occupied(p, t, side * s as f64)))
    };
    let seen = |p: [f64; 2], sign: f64| {
        beyond(sign).any(|t| occupied(p, t, 0.0)) || (face(p, sign, 1.0) && face(p, sign, -1.0))
    };
    seen(a, -1.0) && seen(b, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pixels of row `y` from `x0` to `x1` (exclusive) of a grid `w`
    /// wide.
    fn row(w: u32, y: u32, x0: u32, x1: u32) -> Vec<u32> {
        (x0..x1).map(|x| y * w + x).collect()
    }

    #[test]
    fn a_line_ends_on_seen_walls_only_where_both_ends_meet_occupied_cells() {
        let grid = OccupancyGrid::from_ascii(
            "#.....#
             ?.....#
             ?.....?
             #.....#",
            0.05,
        );
        assert!(ends_on_seen_walls(&grid, &row(7, 0, 1, 6), 1));
        // One end on unknown space, a wall's face on one side of it only.
        assert!(!ends_on_seen_walls(&grid, &row(7, 1, 1, 6), 1));
        assert!(!ends_on_seen_walls(&grid, &row(7, 2, 1, 6), 1));
        assert!(!ends_on_seen_walls(&grid, &[], 1));
        // A wall a pixel further than the reach is not met.
        let short = OccupancyGrid::from_ascii("#?.....?#", 0.05);
        let line: Vec<u32> = (2..7).collect();
        assert!(ends_on_seen_walls(&short, &line, 2));
        assert!(!ends_on_seen_walls(&short, &line, 1));
    }

    #[test]
    fn a_wall_end_seen_on_both_faces_is_seen_though_its_end_face_is_not() {
        // The left end of row 2 meets the end of a wall 3 px thick whose
        // faces (rows 1 and 3) the sensor saw and whose core it did not.
        let stub = OccupancyGrid::from_ascii(
            "........#
             ###.....#
             ???.....#
             ###.....#
             ........#",
            0.05,
        );
        assert!(ends_on_seen_walls(&stub, &row(9, 2, 3, 8), 1));
        // The faces lie two pixels beyond the end: not within a reach of 1.
        let set_back = OccupancyGrid::from_ascii(
            ".........#
             ##?......#
             ???......#
             ##?......#
             .........#",
            0.05,
        );
        assert!(ends_on_seen_walls(&set_back, &row(10, 2, 3, 9), 2));
        assert!(!ends_on_seen_walls(&set_back, &row(10, 2, 3, 9), 1));
        // A box seen from above only (its far side in its own shadow).
        let shadow = OccupancyGrid::from_ascii(
            "........#
             ###.....#
             ???.....#
             ???.....#
             ........#",
            0.05,
        );
        assert!(!ends_on_seen_walls(&shadow, &row(9, 2, 3, 8), 1));
    }
}
