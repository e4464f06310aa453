//! Clutter or wall: whether an obstacle island standing free in the map
//! (larger than furniture, up to `clutter_max_m` across) is a piece of the
//! building or a cluster of chairs, tables and shelves that cuts a room.
//!
//! The idea is ROSE²'s decluttering (Luperto et al., RA-L 2022): a
//! building's walls are straight and run along its few dominant directions;
//! clutter is neither. An island is a **wall piece** when it is
//! - a straight bar: its minimum rotated rectangle is at least
//!   [`BAR_MIN_ELONGATION`] times as long as it is thick;
//! - a solid block (a pillar, a built-in cabinet): it fills at least
//!   [`BLOCK_MIN_FILL`] of that rectangle;
//! - or on the building's wall lines: at least [`ON_LINE_MIN_FRACTION`] of
//!   its outline lies within [`LineLimits::tolerance`] of a line, along one
//!   of the map's two dominant directions, on which the walls joined to the
//!   building run straight for [`LineLimits::min_run`] (a wall face), in
//!   one run or in pieces of at least [`LineLimits::piece_min`] with
//!   doorway-wide breaks (a wall standing free between doorways); the
//!   lengths are set in metres in `pixel_config.rs`.
//!
//! Anything else is clutter: rooms are segmented as if it were free.

use std::collections::HashSet;

use super::wall_runs::{self, Run, WallRuns};

use geo::{ConvexHull, MinimumRotatedRect, MultiPoint, Point};

/// A bar at least this many times as long as thick is a wall piece.
pub(crate) const BAR_MIN_ELONGATION: f64 = 5.0;
/// An island filling at least this share of its minimum rotated rectangle
/// is a solid block.
pub(crate) const BLOCK_MIN_FILL: f64 = 0.75;
/// Share of an island's outline on wall lines that makes it a wall piece.
pub(crate) const ON_LINE_MIN_FRACTION: f64 = 0.4;

/// What makes a wall line, in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LineLimits {
    /// Shortest straight run of wall face that makes a wall line.
    pub min_run: f64,
    /// Longest break bridged in such a run (a ragged scan), whole pixels.
    pub gap: i64,
    /// How far from a wall line an outline pixel may lie and be on it,
    /// whole pixels.
    pub tolerance: i64,
    /// A wall standing in pieces between doorways: runs of at least this
    /// many pixels (each bridging breaks of `gap`) ...
    pub piece_min: f64,
    /// ... with breaks of at most this many pixels between them (a doorway
    /// gap) make a wall line where they add up to `min_run`.
    pub piece_gap: f64,
}

/// The wall lines of a map, in pixels: for each of the two dominant
/// directions, the offsets (in whole pixels across the direction) of the
/// lines on which a wall face runs straight long enough, in one run or in
/// pieces between doorways (`LineLimits::piece_min`).
#[derive(Debug, Clone)]
pub(crate) struct WallLines {
    /// Unit vectors across each direction (the axis offsets are taken on).
    across: [(f64, f64); 2],
    /// The wall lines' offsets along each `across`.
    lines: [HashSet<i64>; 2],
    /// Tolerance in whole pixels.
    tolerance: i64,
}

impl WallLines {
    /// The wall lines through `face` (outline pixels `[x, y]` of the walls
    /// joined to the building) along `deg` (degrees, image coordinates) and
    /// a quarter turn from it.
    pub(crate) fn new(face: &[[u32; 2]], deg: f64, limits: &LineLimits) -> WallLines {
        // One pass: a run of `min_run` is a piece that adds up by itself.
        let pieces = WallRuns::new(face, deg, limits.piece_min.min(limits.min_run), limits.gap);
        let lines = [0, 1].map(|k| {
            pieces
                .lines(k)
                .filter(|&off| pieces_add_up(pieces.near(k, off as f64, 0).collect(), limits))
                .collect()
        });
        WallLines {
            across: [pieces.across(0), pieces.across(1)],
            lines,
            tolerance: limits.tolerance,
        }
    }

    /// Whether pixel `p` lies on a wall line.
    fn on_line(&self, p: [u32; 2]) -> bool {
        self.across.iter().zip(&self.lines).any(|(&a, lines)| {
            let off = project(p, a);
            (-self.tolerance..=self.tolerance).any(|k| lines.contains(&(off + k)))
        })
    }
}

/// Whether the runs of one line, `runs`, with breaks of at most
/// `limits.piece_gap` between neighbours, add up to `limits.min_run`
/// somewhere along it: a wall in pieces between doorways, such as a room
/// front whose wall stands free between its doorways (a T of walls cut off
/// by a doorway on each side is an island, but it lies on that line).
fn pieces_add_up(mut runs: Vec<Run>, limits: &LineLimits) -> bool {
    runs.sort_unstable();
    let mut sum = 0.0;
    let mut last: Option<i64> = None;
    for (start, end) in runs {
        if last.is_some_and(|l| (start - l - 1) as f64 > limits.piece_gap) {
            sum = 0.0;
        }
        sum += (end - start + 1) as f64;
        if sum >= limits.min_run {
            return true;
        }
        last = Some(end);
    }
    false
}

/// Pixel `p`'s coordinate along `axis`, rounded.
fn project(p: [u32; 2], axis: (f64, f64)) -> i64 {
    wall_runs::project([f64::from(p[0]), f64::from(p[1])], axis).round() as i64
}

/// Whether the island with `area` pixels and outline pixels `outline`
/// (`[x, y]`, those with a free 4-neighbour) is a wall piece (see the
/// module doc).
pub(crate) fn is_wall_piece(area: usize, outline: &[[u32; 2]], lines: &WallLines) -> bool {
    if outline.is_empty() {
        return false;
    }
    let bar_or_block = rectangle_sides(outline).is_some_and(|(long, thick)| {
        long >= BAR_MIN_ELONGATION * thick || area as f64 >= BLOCK_MIN_FILL * long * thick
    });
    if bar_or_block {
        return true;
    }
    on_wall_lines(outline, lines, ON_LINE_MIN_FRACTION)
}

/// Whether at least `min_fraction` of the island outline `outline`
/// (`[x, y]` pixels with a free 4-neighbour) lies on `lines`.
pub(crate) fn on_wall_lines(outline: &[[u32; 2]], lines: &WallLines, min_fraction: f64) -> bool {
    let on = outline.iter().filter(|&&p| lines.on_line(p)).count();
    !outline.is_empty() && on as f64 >= min_fraction * outline.len() as f64
}

/// The long and the short side (pixels) of the minimum rotated rectangle
/// round the pixel squares of `outline`.
fn rectangle_sides(outline: &[[u32; 2]]) -> Option<(f64, f64)> {
    let corners: MultiPoint<f64> = outline
        .iter()
        .flat_map(|&[x, y]| {
            let (x, y) = (f64::from(x), f64::from(y));
            [(x, y), (x + 1.0, y), (x, y + 1.0), (x + 1.0, y + 1.0)]
        })
        .map(|(x, y)| Point::new(x, y))
        .collect();
    let rect = corners.convex_hull().minimum_rotated_rect()?;
    let c: Vec<_> = rect.exterior().coords().copied().collect();
    if c.len() < 4 {
        return None;
    }
    let side = |a: usize, b: usize| ((c[a].x - c[b].x).powi(2) + (c[a].y - c[b].y).powi(2)).sqrt();
    let (a, b) = (side(0, 1), side(1, 2));
    Some((a.max(b), a.min(b).max(1.0)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Outline pixels of the `#`s of `rows` (a `#` with a non-`#`
    /// 4-neighbour or on the edge) and their count.
    fn island(rows: &[&str]) -> (usize, Vec<[u32; 2]>) {
        let on = |x: i64, y: i64| {
            y >= 0
                && x >= 0
                && rows
                    .get(y as usize)
                    .and_then(|r| r.as_bytes().get(x as usize))
                    == Some(&b'#')
        };
        let mut area = 0;
        let mut outline = Vec::new();
        for (y, r) in rows.iter().enumerate() {
            for x in 0..r.len() {
                let (xi, yi) = (x as i64, y as i64);
                if on(xi, yi) {
                    area += 1;
                    if !(on(xi - 1, yi) && on(xi + 1, yi) && on(xi, yi - 1) && on(xi, yi + 1)) {
                        outline.push([x as u32, y as u32]);
                    }
                }
            }
        }
        (area, outline)
    }

    /// The limits `pixel_config` sets at 0.1 m/px: 2.5 m runs, 0.1 m
    /// breaks and tolerance, pieces of 0.75 m up to 2.1 m apart.
    const AT_10_CM: LineLimits = LineLimits {
        min_run: 25.0,
        gap: 1,
        tolerance: 1,
        piece_min: 7.5,
        piece_gap: 21.0,
    };

    fn no_lines() -> WallLines {
        WallLines::new(&[], 0.0, &AT_10_CM)
    }

    #[test]
    fn bars_and_blocks_are_wall_pieces() {
        let (a, o) = island(&["############", "############"]);
        assert!(
            is_wall_piece(a, &o, &no_lines()),
            "a bar 6 times as long as thick"
        );
        let (a, o) = island(&["#####", "#####", "#####", "#####"]);
        assert!(is_wall_piece(a, &o, &no_lines()), "a solid block");
    }

    #[test]
    fn a_ragged_cluster_is_clutter() {
        // Chairs round a table: a sparse blob, neither bar nor block.
        let rows = [
            "#...#...#.",
            "##.###.##.",
            ".#..#..#..",
            ".########.",
            "..#.#.#...",
            ".##...##..",
            "#.......##",
        ];
        let (a, o) = island(&rows);
        assert!(!is_wall_piece(a, &o, &no_lines()));
    }

    #[test]
    fn a_cluster_along_a_wall_line_is_a_wall_piece() {
        // A wall face along row 20 from x = 0 to 39 (4 m at 0.1 m/px) and a
        // ragged island whose outline lies on that row and the one below.
        let face: Vec<[u32; 2]> = (0..40).map(|x| [x, 20]).collect();
        let lines = WallLines::new(&face, 0.0, &AT_10_CM);
        let outline: Vec<[u32; 2]> = (50..58).flat_map(|x| [[x, 20], [x, 21]]).collect();
        assert!(
            is_wall_piece(10, &outline, &lines),
            "ragged, but on the wall line"
        );
        let off: Vec<[u32; 2]> = outline.iter().map(|&[x, y]| [x, y + 5]).collect();
        assert!(
            !is_wall_piece(10, &off, &lines),
            "half a metre off the line"
        );
    }

    #[test]
    fn a_short_face_makes_no_wall_line() {
        let face: Vec<[u32; 2]> = (0..20).map(|x| [x, 20]).collect();
        let lines = WallLines::new(&face, 0.0, &AT_10_CM);
        assert!(!lines.on_line([30, 20]), "2 m of wall is not a wall line");
        let broken: Vec<[u32; 2]> = (0..40).filter(|x| x % 5 > 1).map(|x| [x, 20]).collect();
        let lines = WallLines::new(&broken, 0.0, &AT_10_CM);
        assert!(
            !lines.on_line([30, 20]),
            "breaks wider than 0.1 m end a run, and 0.3 m pieces are no wall"
        );
        let ragged: Vec<[u32; 2]> = (0..40).filter(|x| x % 10 > 0).map(|x| [x, 20]).collect();
        let lines = WallLines::new(&ragged, 0.0, &AT_10_CM);
        assert!(lines.on_line([30, 20]), "0.1 m breaks do not");
    }

    /// A face along row 20: pieces `piece` px long starting every `every`
    /// px, `n` of them.
    fn pieces(piece: u32, every: u32, n: u32) -> WallLines {
        let face: Vec<[u32; 2]> = (0..n)
            .flat_map(|k| (0..piece).map(move |x| [k * every + x, 20]))
            .collect();
        WallLines::new(&face, 0.0, &AT_10_CM)
    }

    #[test]
    fn a_wall_in_pieces_between_doorways_is_a_wall_line() {
        // Three 1 m pieces with 0.9 m doorways between them: 3 m of wall.
        assert!(pieces(10, 19, 3).on_line([70, 20]));
        assert!(!pieces(10, 19, 3).on_line([70, 25]), "0.5 m off the line");
        // Two such pieces are 2 m of wall, short of a line.
        assert!(!pieces(10, 19, 2).on_line([50, 20]));
        // Pieces under 0.75 m are no wall, however many.
        assert!(!pieces(7, 16, 6).on_line([50, 20]));
        // Pieces further apart than a doorway gap are separate walls.
        assert!(!pieces(10, 32, 3).on_line([50, 20]));
        assert!(pieces(10, 31, 3).on_line([50, 20]), "2.1 m apart");
    }
}
