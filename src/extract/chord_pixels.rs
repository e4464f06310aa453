//! What a doorway chord meets at each pixel ([`Pixel`]): the regions'
//! free space, the map's walls, and the specks and noise between them
//! that a chord crosses ([`outside_pixels`], [`classifier`]); and which
//! obstacles inside the regions narrow a doorway line to its clear part
//! ([`obstacle_in_regions`]).

use super::furniture::Islands;
use crate::grid::{Cell, OccupancyGrid};
use crate::imaging::{Labels, Mask, label_runs};

/// What a chord meets at a pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Pixel {
    /// Free space of the map's regions, or a pixel outside them that a
    /// chord passes through: a speck standing free, a free cell the noise
    /// filter took (see [`outside_pixels`]).
    Free,
    /// Not free, but not surely a wall either: a speck of an unknown or
    /// uncertain grey (JPEG artefacts, a stray ray).
    Noise,
    /// A wall pixel (an occupied cell or one next to it), or beyond the
    /// map.
    Wall,
    /// Only in [`outside_pixels`]' answer: an occupied cell that is no
    /// speck, in a piece of at least `obstacle_min` occupied cells.
    /// Outside the regions the classifier calls it a
    /// [`Pixel::Wall`]; inside them (an obstacle the furniture filter let
    /// the spaces take in) chords run through it, and it narrows the
    /// doorway line to its clear part
    /// ([`clear_part`](super::clear_width::clear_part)).
    Obstacle,
}

/// What each pixel is to a chord: free where `labels` is non-zero,
/// elsewhere what `outside` says (a wall with `None`), and a wall beyond
/// the image (see [`door_span`](super::doorway::door_span)).
pub(super) fn classifier<'a>(
    labels: &'a Labels,
    outside: Option<&'a [Pixel]>,
) -> impl Fn(i64, i64) -> Pixel + 'a {
    move |x: i64, y: i64| {
        let Some(i) = index_in(labels, x, y) else {
            return Pixel::Wall;
        };
        if labels.data[i] != 0 {
            return Pixel::Free;
        }
        match outside.and_then(|o| o.get(i).copied()) {
            Some(Pixel::Obstacle) | None => Pixel::Wall,
            Some(told) => told,
        }
    }
}

/// Whether pixel `(x, y)` is an obstacle the regions took in: labelled in
/// `labels`, yet an occupied cell that is no speck in `outside` (see
/// [`Pixel::Obstacle`]). False without `outside` and beyond the image.
pub(super) fn obstacle_in_regions<'a>(
    labels: &'a Labels,
    outside: Option<&'a [Pixel]>,
) -> impl Fn(i64, i64) -> bool + 'a {
    move |x: i64, y: i64| {
        index_in(labels, x, y).is_some_and(|i| {
            labels.data[i] != 0
                && outside.is_some_and(|o| o.get(i).copied() == Some(Pixel::Obstacle))
        })
    }
}

/// The row-major index of pixel `(x, y)` in `labels`; None beyond the
/// image.
fn index_in(labels: &Labels, x: i64, y: i64) -> Option<usize> {
    let (w, h) = (i64::from(labels.width), i64::from(labels.height));
    (x >= 0 && y >= 0 && x < w && y < h).then(|| (y * w + x) as usize)
}

/// What each pixel outside the regions is to a doorway chord (and, for
/// [`Pixel::Obstacle`], inside them):
/// - [`Pixel::Obstacle`]: an occupied cell of an 8-connected piece of
///   occupied cells with at least `obstacle_min` cells, but for a speck's;
/// - [`Pixel::Wall`]: another occupied cell, or a cell next to an occupied
///   one (8-neighbours: the uncertain halo of a scanned wall, a blurred
///   drawn wall; a 3 × 3 dilation, by rows then by columns);
/// - [`Pixel::Free`]: a cell of a **speck**, an 8-connected piece of
///   non-free cells standing free (off the image's edge) and at most
///   `speck_px` across on both sides (a stray return beside a jamb, a scan
///   artefact in a doorway), or a free cell the noise filter took (round
///   such a speck, in a jamb's corner): chords run through them, so they
///   do not shorten the doorway;
/// - [`Pixel::Noise`] otherwise (an uncertain grey).
pub(crate) fn outside_pixels(
    grid: &OccupancyGrid,
    islands: &Islands,
    speck_px: f64,
    obstacle_min: usize,
) -> Vec<Pixel> {
    let w = grid.width as usize;
    let mut speck = vec![false; grid.cells.len()];
    for r in &islands.pieces.runs {
        if islands.extent[r.label as usize].is_some_and(|e| e <= speck_px) {
            let i = r.y as usize * w;
            speck[i + r.x0 as usize..i + r.x1 as usize].fill(true);
        }
    }
    let occupied: Vec<bool> = grid
        .cells
        .iter()
        .zip(&speck)
        .map(|(c, &s)| *c == Cell::Occupied && !s)
        .collect();
    // The occupied cells of pieces of at least `obstacle_min` cells.
    let mut big = vec![false; occupied.len()];
    if let Some(mask) = Mask::from_raw(
        grid.width,
        grid.height,
        occupied.iter().map(|&o| if o { 255 } else { 0 }).collect(),
    ) {
        let pieces = label_runs(&mask, true);
        let areas = pieces.areas();
        for r in &pieces.runs {
            if areas[r.label as usize] >= obstacle_min {
                let i = r.y as usize * w;
                big[i + r.x0 as usize..i + r.x1 as usize].fill(true);
            }
        }
    }
    let mut rows = occupied.clone();
    for (row, out) in occupied.chunks(w.max(1)).zip(rows.chunks_mut(w.max(1))) {
        for x in 0..row.len() {
            out[x] = row[x.saturating_sub(1)..(x + 2).min(row.len())].contains(&true);
        }
    }
    (0..rows.len())
        .map(|i| {
            let wall = rows[i] || (i >= w && rows[i - w]) || rows.get(i + w).is_some_and(|&r| r);
            if big[i] {
                Pixel::Obstacle
            } else if wall {
                Pixel::Wall
            } else if speck[i] || grid.cells[i] == Cell::Free {
                Pixel::Free
            } else {
                Pixel::Noise
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::super::doorway::door_span;
    use super::super::doorway::tests::{LIMITS, border, line_length};
    use super::*;
    use crate::extract::furniture::islands;
    use crate::imaging::ascii_labels;

    /// A 3-pixel speck standing a pixel off a jamb, and the free cells the
    /// noise filter took round it, are no jamb: the doorway is measured
    /// from wall to wall. A speck touching the wall is part of it.
    #[test]
    fn a_speck_beside_a_jamb_does_not_narrow_the_doorway() {
        // Room above, room below, a wall 2 rows thick with a 14-pixel
        // doorway (columns 8..=21); a speck at columns 10..=12 of the
        // first wall row, two columns off the left jamb.
        let mut map = vec![".".repeat(30); 8];
        map.push(format!("{}..###.........{}", "#".repeat(8), "#".repeat(8)));
        map.push(format!("{}..............{}", "#".repeat(8), "#".repeat(8)));
        map.extend(vec![".".repeat(30); 8]);
        let grid = OccupancyGrid::from_ascii(&map.join("\n"), 0.05);
        let outside = outside_pixels(&grid, &islands(&grid), 4.0, 1);
        let at = |x: usize, y: usize| outside[y * 30 + x];
        assert_eq!(at(11, 8), Pixel::Free, "speck");
        assert_eq!(at(3, 8), Pixel::Obstacle, "wall");
        assert_eq!(at(8, 8), Pixel::Wall, "halo of the jamb");
        // The regions: every free cell but the one between the jamb's halo
        // and the speck (taken by a noise filter).
        let regions = |map: &[String]| -> Vec<String> {
            map.iter()
                .enumerate()
                .map(|(y, r)| {
                    r.chars()
                        .enumerate()
                        .map(|(x, c)| match c {
                            '.' if y == 8 && x == 9 => '#',
                            '.' if y < 9 => 'a',
                            '.' => 'b',
                            _ => '#',
                        })
                        .collect()
                })
                .collect()
        };
        let length = |map: &[String]| {
            let grid = OccupancyGrid::from_ascii(&map.join("\n"), 0.05);
            let rows = regions(map);
            let refs: Vec<&str> = rows.iter().map(String::as_str).collect();
            let l = ascii_labels(&refs);
            let outside = outside_pixels(&grid, &islands(&grid), 4.0, 1);
            line_length(&door_span(&l, Some(&outside), (1, 2), &border(&l), &LIMITS).unwrap())
        };
        // The whole opening, columns 8..=21.
        let measured = length(&map);
        assert!((measured - 14.0).abs() < 0.6, "{measured}");
        // The same speck joined to the wall is a jamb.
        let mut joined = map.clone();
        joined[8] = format!("{}#####.........{}", "#".repeat(8), "#".repeat(8));
        let short = length(&joined);
        assert!(short < 10.5, "{short}");
    }

    /// An obstacle standing in a doorway that the regions took in (the
    /// furniture filter's) leaves the doorway its longer clear side; a
    /// piece with fewer occupied cells than `obstacle_min` is noise and
    /// leaves it whole. The door still spans the whole opening.
    #[test]
    fn an_obstacle_in_a_doorway_narrows_it_to_its_clear_part() {
        // Room above, room below, a wall 2 rows thick with a 14-pixel
        // doorway (columns 8..=21); an obstacle 3 × 2 at columns 11..=13:
        // 3 pixels clear on its left, 8 on its right.
        let mut map = vec![".".repeat(30); 8];
        for _ in 0..2 {
            map.push(format!("{}...###........{}", "#".repeat(8), "#".repeat(8)));
        }
        map.extend(vec![".".repeat(30); 8]);
        let grid = OccupancyGrid::from_ascii(&map.join("\n"), 0.05);
        // The regions took the obstacle in.
        let rows: Vec<String> = map
            .iter()
            .enumerate()
            .map(|(y, r)| {
                r.chars()
                    .enumerate()
                    .map(|(x, c)| match c {
                        '#' if !(11..=13).contains(&x) => '#',
                        _ if y < 9 => 'a',
                        _ => 'b',
                    })
                    .collect()
            })
            .collect();
        let refs: Vec<&str> = rows.iter().map(String::as_str).collect();
        let l = ascii_labels(&refs);
        let span = |obstacle_min: usize| {
            // Specks are at most 2 pixels across: the obstacle is none.
            let outside = outside_pixels(&grid, &islands(&grid), 2.0, obstacle_min);
            door_span(&l, Some(&outside), (1, 2), &border(&l), &LIMITS).unwrap()
        };
        let narrowed = span(6);
        assert!((line_length(&narrowed) - 8.0).abs() < 0.6, "{narrowed:?}");
        let xs = [narrowed.line[0][0], narrowed.line[1][0]];
        // (Ends are found to an eighth of a pixel.)
        assert!(
            xs.iter().all(|&x| x >= 13.85),
            "on the obstacle's right: {xs:?}"
        );
        // The door's pixels still run from jamb to jamb.
        assert!((8..=21).all(|x| narrowed.covers(x, 8)));
        // Six occupied cells are fewer than seven: noise, crossed.
        let whole = span(7);
        assert!((line_length(&whole) - 14.0).abs() < 0.6, "{whole:?}");
    }

    #[test]
    fn only_obstacles_inside_the_regions_block() {
        // Labels 3 × 1: labelled, labelled, unlabelled; all occupied.
        let labels = Labels {
            width: 3,
            height: 1,
            data: vec![1, 1, 0],
            count: 1,
        };
        let outside = [Pixel::Obstacle, Pixel::Wall, Pixel::Obstacle];
        let blocked = obstacle_in_regions(&labels, Some(&outside));
        assert!(blocked(0, 0), "an obstacle the regions took in");
        assert!(!blocked(1, 0), "a wall's halo inside the regions");
        assert!(!blocked(2, 0), "outside the regions the chord decides");
        assert!(!blocked(-1, 0) && !blocked(3, 0));
        assert!(!obstacle_in_regions(&labels, None)(0, 0));
    }
}
