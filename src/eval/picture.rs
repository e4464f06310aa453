//! A picture of an evaluation, to see where an extraction and its ground
//! truth disagree: the map, the extracted spaces, the GT doorway lines
//! (found or missed) and the detected doors (right or wrong), in the map's
//! pixels.

use image::{Rgb, RgbImage};

use super::GroundTruth;
use super::metrics::{door_centroids, door_labels, door_matches, door_radius_px};
use crate::extract::Extraction;
use crate::grid::{Cell, OccupancyGrid};

/// Colour of a GT doorway line a detected door matched.
pub const LINE_FOUND: [u8; 3] = [0, 158, 115];
/// Colour of a GT doorway line no detected door matched.
pub const LINE_MISSED: [u8; 3] = [255, 0, 255];
/// Colour of the ring around a detected door that matched a GT line.
pub const DOOR_RIGHT: [u8; 3] = [0, 114, 178];
/// Colour of the ring around a detected door that matched none.
pub const DOOR_WRONG: [u8; 3] = [213, 0, 0];
/// Colour of door spaces.
const DOOR_SPACE: [u8; 3] = [230, 159, 0];

/// Draws the evaluation of `x` against `gt` on `grid` (same size), one
/// pixel per map cell, row 0 at the top: obstacles black, unknown grey,
/// free cells in no space white, each room or corridor a pale colour of its
/// own, door spaces orange; GT doorway lines green where a door was found
/// and magenta where none was; a square ring around each detected door's
/// centroid, blue when it matched a line and red when it matched none.
pub fn evaluation_picture(grid: &OccupancyGrid, gt: &GroundTruth, x: &Extraction) -> RgbImage {
    let (w, h) = (grid.width, grid.height);
    let is_door = door_labels(x);
    let mut img = RgbImage::from_fn(w, h, |col, row| {
        let i = (row * w + col) as usize;
        let label = x.labels.data.get(i).copied().unwrap_or(0);
        let cell = grid.cells.get(i).copied().unwrap_or(Cell::Unknown);
        Rgb(match (label, cell) {
            (0, Cell::Free) => [255, 255, 255],
            (0, Cell::Occupied) => [0, 0, 0],
            (0, Cell::Unknown) => [150, 150, 150],
            (l, _) if is_door.get(l as usize).copied().unwrap_or(false) => DOOR_SPACE,
            (l, _) => pale(l),
        })
    });
    let doors = door_centroids(x);
    let m = door_matches(gt, &doors, door_radius_px(grid.resolution));
    for (line, &found) in gt.doors.iter().zip(&m.lines) {
        for &p in &line.pixels {
            img.put_pixel(
                p % w,
                p / w,
                Rgb(if found { LINE_FOUND } else { LINE_MISSED }),
            );
        }
    }
    for (c, &right) in doors.iter().zip(&m.doors) {
        let colour = Rgb(if right { DOOR_RIGHT } else { DOOR_WRONG });
        ring(&mut img, c, 4, colour);
    }
    img
}

/// A pale colour of its own for label `l` (a fixed hash, so pictures of the
/// same extraction are the same).
fn pale(l: u32) -> [u8; 3] {
    let v = l.wrapping_mul(2_654_435_761);
    [
        150 + (v >> 8) as u8 % 100,
        150 + (v >> 16) as u8 % 100,
        150 + (v >> 24) as u8 % 100,
    ]
}

/// A square ring of half-size `r` pixels, 2 px thick, around `c` (`[col, row]`).
fn ring(img: &mut RgbImage, c: &[f64; 2], r: i64, colour: Rgb<u8>) {
    let (cx, cy) = (c[0].round() as i64, c[1].round() as i64);
    for dy in -r..=r {
        for dx in -r..=r {
            let edge = dx.abs() >= r - 1 || dy.abs() >= r - 1;
            let (x, y) = (cx + dx, cy + dy);
            if edge && x >= 0 && y >= 0 && x < i64::from(img.width()) && y < i64::from(img.height())
            {
                img.put_pixel(x as u32, y as u32, colour);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::eval::GroundTruth;
    use crate::extract::{ExtractParams, extract};

    #[test]
    fn found_and_missed_lines_and_doors_are_coloured() {
        // Two rooms joined by a doorway; the GT closes the doorway and also
        // draws a line across the left room that no door matches.
        let mut rows = vec!["#".repeat(45)];
        for y in 0..20 {
            let door = (6..14).contains(&y);
            rows.push(format!(
                "#{}{}{}#",
                ".".repeat(20),
                if door { ".." } else { "##" },
                ".".repeat(21)
            ));
        }
        rows.push("#".repeat(45));
        let grid = OccupancyGrid::from_ascii(&rows.join("\n"), 0.1);
        let x = extract(&grid, &ExtractParams::default()).unwrap();
        let (w, h) = (grid.width, grid.height);
        let mut gt_grey: Vec<u8> = grid.grey.clone();
        for y in 7..15 {
            gt_grey[(y * w + 21) as usize] = 0;
            gt_grey[(y * w + 22) as usize] = 0;
        }
        for y in 1..21 {
            gt_grey[(y * w + 10) as usize] = 0;
        }
        let gt = GroundTruth::from_grey(w, h, &gt_grey, &grid.grey);
        assert_eq!(gt.doors.len(), 2);
        let img = evaluation_picture(&grid, &gt, &x);
        assert_eq!(img.dimensions(), (w, h));
        let at = |col: u32, row: u32| img.get_pixel(col, row).0;
        assert_eq!(at(21, 3), [0, 0, 0], "wall");
        assert_eq!(at(10, 5), LINE_MISSED, "the line across the room");
        assert!(
            [at(21, 10), at(22, 10)].contains(&LINE_FOUND),
            "the doorway"
        );
        let rings = img.pixels().filter(|p| p.0 == DOOR_RIGHT).count();
        assert!(rings > 0, "the detected door is ringed as right");
        assert_eq!(img.pixels().filter(|p| p.0 == DOOR_WRONG).count(), 0);
    }
}
