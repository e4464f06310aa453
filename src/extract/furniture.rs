//! Furniture islands: small obstacle blobs standing free inside rooms
//! (table and chair legs, boxes, pillars). The paper's stated weakness is
//! that clutter cuts rooms into pieces; here such islands are treated as
//! free space while the rooms are segmented, so a room is found as if it
//! were empty and the pixels under its furniture belong to it. The
//! islands are labelled once per extraction ([`islands`]); the larger
//! ones that are no pieces of wall are the clutter a doorway's jamb cannot
//! be ([`clutter_pixels`]), and the smallest are specks doorway chords
//! cross (`chord_pixels::outside_pixels`).

use super::clutter::{LineLimits, WallLines, is_wall_piece};
use crate::grid::{Cell, OccupancyGrid};
use crate::imaging::{Mask, Moments, Principal, Run, RunLabels, dominant_orientation, label_runs};

/// Which islands are treated as free, in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct IslandLimits {
    /// `furniture_max_m`: islands at most this long on both sides are
    /// furniture.
    pub furniture: f64,
    /// `clutter_max_m`: larger islands up to this are clutter unless they
    /// look like walls (see [`super::clutter`]).
    pub clutter: f64,
    /// How far a wall piece between two doorways may stand from the walls
    /// in line with it (`wall_gap_width_max_m`).
    pub wall_piece_gap: f64,
    /// How many times longer than thick (by second moments) an island must
    /// be for its own axis to be followed when it lies off the building's
    /// directions (a wall piece in a wing built at another angle).
    pub wall_elongation: f64,
    /// What makes a wall line for the clutter rule.
    pub lines: LineLimits,
}

/// The free mask (255 free) of `grid` in which every 8-connected component
/// of non-free pixels that does not touch the image border and whose
/// bounding box is at most `limits.furniture` on both sides is free too,
/// and so is every such island up to `limits.clutter` that is no wall piece
/// by [`is_wall_piece`] (a cluster of chairs and tables).
/// Walls are connected to the building's outline or long, so they stay.
/// So do pieces of wall between two doorways: islands at least 1.5 times
/// as long as thick that lie in line with a wall of about their thickness on
/// both ends, each within `limits.wall_piece_gap` (a pillar between the two
/// leaves of a double door, the wall between two doors side by side),
/// along one of the building's two directions, or along their own axis
/// when at least `limits.wall_elongation` times as long as thick and the
/// walls met run on along it (a wing built at another angle); see
/// [`in_wall_line`].
pub(crate) fn free_without_furniture(
    grid: &OccupancyGrid,
    islands: &Islands,
    limits: &IslandLimits,
) -> Mask {
    let (w, h) = (grid.width, grid.height);
    let free: Vec<u8> = grid
        .cells
        .iter()
        .map(|c| if *c == Cell::Free { 255 } else { 0 })
        .collect();
    let largest = limits.furniture.max(limits.clutter);
    if largest < 1.0 {
        return Mask::from_raw(w, h, free).unwrap_or_else(|| Mask::new(w, h));
    }
    let Islands {
        pieces: blobs,
        extent,
        ..
    } = islands;
    let free_mask = Mask::from_raw(w, h, free.clone()).unwrap_or_else(|| Mask::new(w, h));
    // The building's two directions: pieces of wall lie along them.
    let deg = dominant_orientation(&free_mask);
    let mut island: Vec<bool> = extent
        .iter()
        .map(|e| e.is_some_and(|e| e <= limits.furniture))
        .collect();
    let candidate: Vec<bool> = extent
        .iter()
        .map(|e| e.is_some_and(|e| e > limits.furniture && e <= limits.clutter))
        .collect();
    if candidate.iter().any(|&c| c) {
        let clutter = clutter_islands(grid, &free, deg, blobs, extent, &candidate, limits);
        for (island, clutter) in island.iter_mut().zip(clutter) {
            *island |= clutter;
        }
    }
    let mut data = free;
    for r in blobs.runs.iter().filter(|r| island[r.label as usize]) {
        let i = r.y as usize * w as usize;
        data[i + r.x0 as usize..i + r.x1 as usize].fill(255);
    }
    // With every island gone, the obstacles left are walls.
    let walls = Mask::from_raw(w, h, data.clone()).unwrap_or_else(|| Mask::new(w, h));
    let mut runs_of: Vec<Vec<&Run>> = vec![Vec::new(); island.len()];
    for r in blobs.runs.iter().filter(|r| island[r.label as usize]) {
        runs_of[r.label as usize].push(r);
    }
    let building = directions(deg);
    let wall_piece: Vec<bool> = runs_of
        .iter()
        .map(|runs| {
            !runs.is_empty()
                && (in_wall_line(&walls, runs, building, limits.wall_piece_gap, false)
                    || principal_axis(runs).is_some_and(|(axis, elongation)| {
                        elongation >= limits.wall_elongation
                            && in_wall_line(&walls, runs, axis, limits.wall_piece_gap, true)
                    }))
        })
        .collect();
    for r in blobs.runs.iter().filter(|r| wall_piece[r.label as usize]) {
        let i = r.y as usize * w as usize;
        data[i + r.x0 as usize..i + r.x1 as usize].fill(0);
    }
    Mask::from_raw(w, h, data).unwrap_or_else(|| Mask::new(w, h))
}

/// The 8-connected pieces of non-free cells of a grid, with each piece's
/// extent (by label, index 0 unused).
pub(crate) struct Islands {
    /// The pieces.
    pub pieces: RunLabels,
    /// Each piece's extent in pixels (the longer side of its bounding
    /// box), None for a piece on the image's edge (the outside, or walls
    /// joined to it): only islands standing free have one.
    pub extent: Vec<Option<f64>>,
}

/// The non-free pieces of `grid` and their extents (see [`Islands`]).
pub(crate) fn islands(grid: &OccupancyGrid) -> Islands {
    let (w, h) = (grid.width, grid.height);
    let blocked_data = grid
        .cells
        .iter()
        .map(|c| if *c == Cell::Free { 0 } else { 255 })
        .collect();
    let blocked = Mask::from_raw(w, h, blocked_data).unwrap_or_else(|| Mask::new(w, h));
    let pieces = label_runs(&blocked, true);
    let bbox = pieces.bounding_boxes();
    let extent = bbox
        .iter()
        .map(|b| {
            let touches_border = b[0] == 0 || b[1] == 0 || b[2] + 1 >= w || b[3] + 1 >= h;
            (b[0] != u32::MAX && !touches_border).then(|| {
                f64::from(
                    (b[2] + 1)
                        .saturating_sub(b[0])
                        .max((b[3] + 1).saturating_sub(b[1])),
                )
            })
        })
        .collect();
    Islands { pieces, extent }
}

/// Per pixel of the grid `isl` was labelled in: whether it is **clutter**,
/// a cell of an island at most `max_px` across that is no piece of wall:
/// less than `wall_elongation` times as long as it is thick, by its second
/// moments (so at any angle). A doorway's jambs are the building's walls;
/// a border ending on clutter runs between furniture and whatever it
/// stands by.
pub(crate) fn clutter_pixels(isl: &Islands, max_px: f64, wall_elongation: f64) -> Vec<bool> {
    let elongation = elongations(&isl.pieces);
    let clutter: Vec<bool> = isl
        .extent
        .iter()
        .zip(&elongation)
        .map(|(e, &k)| e.is_some_and(|e| e <= max_px) && k < wall_elongation)
        .collect();
    let w = isl.pieces.width as usize;
    let mut out = vec![false; w * isl.pieces.height as usize];
    for r in isl.pieces.runs.iter().filter(|r| clutter[r.label as usize]) {
        let i = r.y as usize * w;
        out[i + r.x0 as usize..i + r.x1 as usize].fill(true);
    }
    out
}

/// Per label of `pieces` (index 0 unused): how many times longer than
/// thick the piece is (see [`elongation`]).
fn elongations(pieces: &RunLabels) -> Vec<f64> {
    let mut sums = vec![Moments::default(); pieces.count as usize + 1];
    for r in &pieces.runs {
        sums[r.label as usize].add_row(r.y, r.x0, r.x1);
    }
    sums.iter()
        .map(|s| s.principal().map_or(1.0, |p| elongation(&p)))
        .collect()
}

/// How many times longer than thick pixels with principal axes `p` are:
/// the square root of the ratio of the principal second moments, each
/// pixel a unit square (its own spread, 1/12 on each axis, keeps a single
/// row of pixels finite).
fn elongation(p: &Principal) -> f64 {
    let pixel = 1.0 / 12.0;
    ((p.major + pixel) / (p.minor + pixel)).sqrt()
}

/// Which of the `candidate` islands (by label; larger than furniture and
/// at most `limits.clutter` across) are clutter: no wall piece by the wall
/// lines of the components that are no island of either size (the
/// building).
fn clutter_islands(
    grid: &OccupancyGrid,
    free: &[u8],
    deg: f64,
    blobs: &RunLabels,
    extent: &[Option<f64>],
    candidate: &[bool],
    limits: &IslandLimits,
) -> Vec<bool> {
    let w = grid.width as usize;
    let building: Vec<bool> = extent
        .iter()
        .map(|e| e.is_none_or(|e| e > limits.clutter))
        .collect();
    let is_free = |x: usize, y: usize| free.get(y * w + x).is_some_and(|&f| f != 0);
    let mut face = Vec::new();
    let mut outlines: Vec<Vec<[u32; 2]>> = vec![Vec::new(); building.len()];
    for r in &blobs.runs {
        let l = r.label as usize;
        if !building[l] && !candidate[l] {
            continue;
        }
        let y = r.y as usize;
        for x in r.x0 as usize..r.x1 as usize {
            let outline = (x > 0 && is_free(x - 1, y))
                || is_free(x + 1, y)
                || (y > 0 && is_free(x, y - 1))
                || is_free(x, y + 1);
            if outline {
                let p = [x as u32, y as u32];
                if building[l] {
                    face.push(p);
                } else {
                    outlines[l].push(p);
                }
            }
        }
    }
    let lines = WallLines::new(&face, deg, &limits.lines);
    let areas = blobs.areas();
    (0..building.len())
        .map(|l| candidate[l] && !is_wall_piece(areas[l], &outlines[l], &lines))
        .collect()
}

/// The building's two directions as unit vectors: `deg` and a quarter
/// turn from it (degrees, image coordinates, see
/// `imaging::dominant_orientation`).
fn directions(deg: f64) -> [[f64; 2]; 2] {
    let (sin, cos) = deg.to_radians().sin_cos();
    [[cos, sin], [-sin, cos]]
}

/// The principal axis of the island made of `runs` and the one across it
/// (unit vectors), and how many times longer than thick it is (see
/// [`elongation`]). None for no pixels.
fn principal_axis(runs: &[&Run]) -> Option<([[f64; 2]; 2], f64)> {
    let mut sums = Moments::default();
    for r in runs {
        sums.add_row(r.y, r.x0, r.x1);
    }
    let p = sums.principal()?;
    Some((directions(p.angle.to_degrees()), elongation(&p)))
}

/// Whether the island made of `runs` lies in a wall line of `walls`
/// (0 = wall) along one of two perpendicular unit directions `dirs` (the
/// building's, see [`directions`], or the island's own axis): along the
/// one in which it is longer, at least 1.5 times as long
/// as it is thick, with a wall within `gap_px` of either end along its
/// middle line, and each of those walls no thicker across the line than
/// twice the island plus two pixels (a wall running on in line, not a
/// side wall). Lengths are the spread of the pixel centres plus one, so
/// along the image's axes they are the island's bounding box.
fn in_wall_line(
    walls: &Mask,
    runs: &[&Run],
    dirs: [[f64; 2]; 2],
    gap_px: f64,
    run_on: bool,
) -> bool {
    let (w, h) = (walls.width() as i64, walls.height() as i64);
    // The spread of the pixel centres along each direction.
    let mut spread = [[f64::INFINITY, f64::NEG_INFINITY]; 2];
    for r in runs {
        let y = f64::from(r.y);
        for x in (r.x0..r.x1).map(f64::from) {
            for (d, sp) in dirs.iter().zip(&mut spread) {
                let v = x * d[0] + y * d[1];
                *sp = [sp[0].min(v), sp[1].max(v)];
            }
        }
    }
    let extent = |k: usize| spread[k][1] - spread[k][0] + 1.0;
    let (along, across) = if extent(0) >= extent(1) {
        (0, 1)
    } else {
        (1, 0)
    };
    let (u, n, t) = (dirs[along], dirs[across], spread[along]);
    let (long, thick) = (extent(along), extent(across));
    if !(long.is_finite() && 2.0 * long >= 3.0 * thick) {
        return false;
    }
    let wall = |p: [f64; 2]| {
        // The nearest pixel, halves rounded down (so on a map drawn square
        // to the building the middle line of an island an even number of
        // pixels thick is the upper or left of its two middle rows).
        let (x, y) = ((p[0] - 0.5).ceil() as i64, (p[1] - 0.5).ceil() as i64);
        x < 0 || y < 0 || x >= w || y >= h || walls.as_raw()[(y * w + x) as usize] == 0
    };
    // The point `a` along the island's middle line and `b` across it.
    let mid = (spread[across][0] + spread[across][1]) / 2.0;
    let at = |a: f64, b: f64| [a * u[0] + b * n[0], a * u[1] + b * n[1]];
    let steps = gap_px.ceil() as i64;
    let max_across = 2.0 * thick.round() + 2.0;
    let thin_wall_within = |dir: f64| {
        let start = if dir < 0.0 { t[0] } else { t[1] };
        let Some(a) = (1..=steps + 1)
            .map(|k| start + dir * k as f64)
            .find(|&a| wall(at(a, mid)))
        else {
            return false;
        };
        let across = |side: f64| {
            (1..=max_across as i64)
                .take_while(|&k| wall(at(a, mid + side * k as f64)))
                .count() as f64
        };
        // Off the building's directions, the wall met must also run on
        // along the line, as a wall built at the island's angle does (not
        // one crossed at a slant).
        let runs_on =
            !run_on || (0..=2 * thick.round() as i64).all(|k| wall(at(a + dir * k as f64, mid)));
        1.0 + across(-1.0) + across(1.0) <= max_across && runs_on
    };
    thin_wall_within(-1.0) && thin_wall_within(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::mask_ascii;

    /// Furniture up to `furniture` px, no clutter rule.
    fn limits(furniture: f64, wall_piece_gap: f64) -> IslandLimits {
        IslandLimits {
            furniture,
            clutter: 0.0,
            wall_piece_gap,
            wall_elongation: 3.0,
            lines: LineLimits {
                min_run: 25.0,
                gap: 1,
                tolerance: 1,
                piece_min: 7.5,
                piece_gap: 21.0,
            },
        }
    }

    #[test]
    fn elongation_is_length_over_thickness_at_any_angle() {
        // A 10 x 2 bar, a 4 x 4 block and a diagonal line of 8 pixels.
        let mut rows = vec![".".repeat(30); 20];
        for row in &mut rows[2..4] {
            row.replace_range(2..12, &"#".repeat(10));
        }
        for row in &mut rows[8..12] {
            row.replace_range(2..6, "####");
        }
        for k in 0..8 {
            rows[8 + k].replace_range(14 + k..15 + k, "#");
        }
        let g = OccupancyGrid::from_ascii(&rows.join("\n"), 0.05);
        let isl = islands(&g);
        let k = elongations(&isl.pieces);
        let at = |x: usize, y: usize| {
            let r = isl
                .pieces
                .runs
                .iter()
                .find(|r| r.y as usize == y && (r.x0 as usize..r.x1 as usize).contains(&x));
            k[r.map_or(0, |r| r.label as usize)]
        };
        assert!((at(2, 2) - 5.0).abs() < 1e-9, "{}", at(2, 2));
        assert!((at(2, 8) - 1.0).abs() < 1e-9, "{}", at(2, 8));
        assert!(at(14, 8) > 5.0, "{}", at(14, 8));
    }

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
        let m = free_without_furniture(&g, &islands(&g), &limits(3.0, 0.0));
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
        let m = free_without_furniture(&g, &islands(&g), &limits(4.0, 3.0));
        let row = |y: u32| -> String {
            (0..16)
                .map(|x| if m.get_pixel(x, y)[0] == 0 { '#' } else { '.' })
                .collect()
        };
        assert_eq!(row(4), "####...####...##", "the pillar stays");
        assert_eq!(row(6), "#..............#", "the desk goes");
    }

    #[test]
    fn a_pillar_between_two_doorways_stays_in_a_turned_building() {
        // An 6.5 m × 4.5 m building at 0.05 m/px turned by 20°: a 0.2 m
        // wall across it with two 1 m doorways and a 0.8 m piece of wall
        // between them; a 0.3 m desk stands free in a room.
        let (sin, cos) = 20f64.to_radians().sin_cos();
        let text: Vec<String> = (0..120)
            .map(|y| {
                (0..160)
                    .map(|x| {
                        let (dx, dy) = (f64::from(x) + 0.5 - 80.0, f64::from(y) + 0.5 - 60.0);
                        let (u, v) = (dx * cos + dy * sin, -dx * sin + dy * cos);
                        let outside = u.abs() >= 65.0 || v.abs() >= 45.0;
                        let doorway = (-30.0..-10.0).contains(&u) || (6.0..26.0).contains(&u);
                        let wall = (-2.0..2.0).contains(&v) && !doorway;
                        let desk = (20.0..26.0).contains(&u) && (20.0..26.0).contains(&v);
                        if outside || wall || desk { '#' } else { '.' }
                    })
                    .collect()
            })
            .collect();
        let g = OccupancyGrid::from_ascii(&text.join("\n"), 0.05);
        let m = free_without_furniture(&g, &islands(&g), &limits(20.0, 42.0));
        let at = |u: f64, v: f64| {
            let (x, y) = (80.0 + u * cos - v * sin, 60.0 + u * sin + v * cos);
            m.get_pixel(x as u32, y as u32)[0]
        };
        assert_eq!(at(-2.0, 0.0), 0, "the piece between the doorways stays");
        assert_eq!(at(23.0, 23.0), 255, "the desk goes");
        assert_eq!(at(-20.0, 0.0), 255, "the doorway is open");
    }

    /// Unit vectors along and across a line at `deg` (image coordinates).
    fn frame(deg: f64) -> impl Fn(f64, f64) -> (f64, f64) {
        let (sin, cos) = deg.to_radians().sin_cos();
        move |dx, dy| (dx * cos + dy * sin, -dx * sin + dy * cos)
    }

    /// A grid 160 × 120 at 0.05 m/px, walled round, with `wall(u, v)` wall
    /// in the frame of a line at `deg` through its middle.
    fn drawn(deg: f64, wall: impl Fn(f64, f64, f64) -> bool) -> OccupancyGrid {
        let to = frame(deg);
        let text: Vec<String> = (0..120)
            .map(|y| {
                (0..160)
                    .map(|x| {
                        let edge = x < 2 || y < 2 || x >= 158 || y >= 118;
                        let (u, v) = to(f64::from(x) + 0.5 - 80.0, f64::from(y) + 0.5 - 60.0);
                        if edge || wall(u, v, f64::from(x)) {
                            '#'
                        } else {
                            '.'
                        }
                    })
                    .collect()
            })
            .collect();
        OccupancyGrid::from_ascii(&text.join("\n"), 0.05)
    }

    /// The pixel at `(u, v)` in the frame of a line at `deg` through the
    /// middle of [`drawn`]'s grid.
    fn pixel(deg: f64, u: f64, v: f64) -> (u32, u32) {
        let (sin, cos) = deg.to_radians().sin_cos();
        (
            (80.0 + u * cos - v * sin) as u32,
            (60.0 + u * sin + v * cos) as u32,
        )
    }

    #[test]
    fn a_pillar_between_two_doorways_stays_in_a_wing_at_another_angle() {
        // The building is square to the map; a 0.2 m wall crosses it at
        // 40° with two 1 m doorways and a 0.8 m piece of wall between them.
        // The piece lies off the building's directions and is followed
        // along its own axis.
        let g = drawn(40.0, |u, v, _| {
            let doorway = (-30.0..-10.0).contains(&u) || (6.0..26.0).contains(&u);
            (-2.0..2.0).contains(&v) && !doorway
        });
        let m = free_without_furniture(&g, &islands(&g), &limits(20.0, 42.0));
        let (x, y) = pixel(40.0, -2.0, 0.0);
        assert_eq!(
            m.get_pixel(x, y)[0],
            0,
            "the piece between the doorways stays"
        );
        let (x, y) = pixel(40.0, -20.0, 0.0);
        assert_eq!(m.get_pixel(x, y)[0], 255, "the doorway is open");
    }

    #[test]
    fn a_slanted_bar_whose_line_crosses_walls_at_a_slant_goes() {
        // A 0.8 m × 0.15 m bar at 40° between two 0.2 m walls square to the
        // map, its line meeting each 1.3 m from its end: thin walls in its
        // line, but crossed at a slant, not running on along it.
        let g = drawn(40.0, |u, v, x| {
            (50.0..54.0).contains(&x)
                || (106.0..110.0).contains(&x)
                || ((-8.0..8.0).contains(&u) && (-1.5..1.5).contains(&v))
        });
        let m = free_without_furniture(&g, &islands(&g), &limits(20.0, 42.0));
        let (x, y) = pixel(40.0, 0.0, 0.0);
        assert_eq!(m.get_pixel(x, y)[0], 255, "the bar is furniture");
    }

    #[test]
    fn clutter_goes_bars_and_blocks_stay() {
        // A 6 m × 3.6 m room at 0.1 m/px holding a ragged 1.5 m cluster
        // (chairs round a table), a solid 1.2 m × 0.6 m block and a 2 m
        // free-standing bar 0.2 m thick; furniture up to 1 m, clutter up to
        // 2.5 m.
        let (w, h) = (60usize, 36usize);
        let mut cells = vec![vec!['.'; w]; h];
        for (y, row) in cells.iter_mut().enumerate() {
            for (x, c) in row.iter_mut().enumerate() {
                if x == 0 || y == 0 || x == w - 1 || y == h - 1 {
                    *c = '#';
                }
            }
        }
        let cluster = [
            (5, 5),
            (19, 5),
            (12, 5),
            (5, 19),
            (19, 19),
            (12, 19),
            (5, 12),
            (19, 12),
        ];
        for &(x0, y0) in &cluster {
            for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                cells[y0 + dy][x0 + dx] = '#';
            }
        }
        let mut fill = |xs: std::ops::Range<usize>, ys: std::ops::Range<usize>| {
            for y in ys {
                for x in xs.clone() {
                    cells[y][x] = '#';
                }
            }
        };
        // The table in the middle, joined to the chairs by thin legs.
        fill(12..13, 6..20);
        fill(6..20, 12..13);
        fill(30..42, 5..11);
        fill(30..50, 25..27);
        let text: Vec<String> = cells.iter().map(|r| r.iter().collect()).collect();
        let g = OccupancyGrid::from_ascii(&text.join("\n"), 0.1);
        let freed = |clutter: f64| {
            let limits = IslandLimits {
                clutter,
                ..limits(10.0, 21.0)
            };
            let m = free_without_furniture(&g, &islands(&g), &limits);
            let free_at = |x: u32, y: u32| m.get_pixel(x, y)[0] != 0;
            (free_at(12, 12), free_at(35, 7), free_at(40, 25))
        };
        assert_eq!(
            freed(0.0),
            (false, false, false),
            "without the clutter rule all stay"
        );
        assert_eq!(
            freed(25.0),
            (true, false, false),
            "the cluster goes, the block and the bar stay"
        );
    }
}
