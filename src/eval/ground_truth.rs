//! The ground truth: IPA-style room image (rooms = 8-connected white
//! components) and the doorway lines drawn into it.

use std::path::Path;

use petgraph::unionfind::UnionFind;

use super::EvalError;
use crate::grid::{GridError, LoadOptions, OccupancyGrid};
use crate::imaging::{Labels, Mask, label_components};

/// A doorway line of the ground truth.
#[derive(Debug, Clone, PartialEq)]
pub struct DoorLine {
    /// Its pixels (row-major indices).
    pub pixels: Vec<u32>,
    /// The GT rooms it touches (at least two).
    pub rooms: Vec<u32>,
}

/// GT rooms and doorway lines in the map's pixel frame.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundTruth {
    /// Room id per pixel (0 = no room); rooms of ≤ 100 px are dropped.
    pub rooms: Labels,
    /// Doorway lines.
    pub doors: Vec<DoorLine>,
}

impl GroundTruth {
    /// Builds the GT from its grey image and the map's grey image (same size):
    /// rooms are the 8-connected components of GT grey > 250 with more than
    /// 100 px; doorway lines are the 8-connected components (≥ 3 px) of
    /// pixels free in the map (≥ 250) but not in the GT (≤ 250) that touch
    /// two rooms, components one pixel apart that touch the same rooms
    /// counting as one line (a speck of noise on a doorway).
    pub fn from_grey(width: u32, height: u32, gt: &[u8], map: &[u8]) -> GroundTruth {
        let white = Mask::from_raw(
            width,
            height,
            gt.iter().map(|&g| if g > 250 { 255 } else { 0 }).collect(),
        )
        .unwrap_or_else(|| Mask::new(width, height));
        let mut rooms = label_components(&white, true);
        let areas = rooms.areas();
        for l in &mut rooms.data {
            if *l != 0 && areas[*l as usize] <= 100 {
                *l = 0;
            }
        }
        rooms.compact();
        let line_mask = Mask::from_raw(
            width,
            height,
            gt.iter()
                .zip(map)
                .map(|(&g, &m)| if m >= 250 && g <= 250 { 255 } else { 0 })
                .collect(),
        )
        .unwrap_or_else(|| Mask::new(width, height));
        GroundTruth::with_lines(rooms, &line_mask)
    }

    /// Builds the GT from a colour image (ROSE2 style): each distinct
    /// non-black colour with more than 100 px is one room; doorway lines are
    /// map-free pixels in no room, otherwise as for [`GroundTruth::from_grey`].
    pub fn from_colours(width: u32, height: u32, rgb: &[[u8; 3]], map: &[u8]) -> GroundTruth {
        let mut ids: std::collections::HashMap<[u8; 3], u32> = std::collections::HashMap::new();
        let mut data = Vec::with_capacity(rgb.len());
        for c in rgb {
            if *c == [0, 0, 0] {
                data.push(0);
                continue;
            }
            let next = ids.len() as u32 + 1;
            data.push(*ids.entry(*c).or_insert(next));
        }
        let mut rooms = Labels {
            width,
            height,
            data,
            count: ids.len() as u32,
        };
        let areas = rooms.areas();
        for l in &mut rooms.data {
            if *l != 0 && areas[*l as usize] <= 100 {
                *l = 0;
            }
        }
        rooms.compact();
        let line_mask = Mask::from_raw(
            width,
            height,
            rooms
                .data
                .iter()
                .zip(map)
                .map(|(&r, &m)| if m >= 250 && r == 0 { 255 } else { 0 })
                .collect(),
        )
        .unwrap_or_else(|| Mask::new(width, height));
        GroundTruth::with_lines(rooms, &line_mask)
    }

    /// Doorway lines from `line_mask`: its 8-connected components that
    /// touch two rooms, where components touching the same rooms with only
    /// a one-pixel gap between them are one line (a speck of map noise on
    /// a drawn doorway line does not make two doorways).
    fn with_lines(rooms: Labels, line_mask: &Mask) -> GroundTruth {
        let (width, height) = (rooms.width, rooms.height);
        let lines = label_components(line_mask, true);
        let count = lines.count as usize + 1;
        let mut pixels: Vec<Vec<u32>> = vec![Vec::new(); count];
        for (i, &l) in lines.data.iter().enumerate() {
            if l != 0 {
                pixels[l as usize].push(i as u32);
            }
        }
        let (w, h) = (i64::from(width), i64::from(height));
        // Pixels within `r` (Chebyshev) of pixel `p`, inside the image.
        let around = |p: u32, r: i64| {
            let (x, y) = (i64::from(p) % w, i64::from(p) / w);
            (-r..=r).flat_map(move |dy| {
                (-r..=r).filter_map(move |dx| {
                    let (nx, ny) = (x + dx, y + dy);
                    (nx >= 0 && ny >= 0 && nx < w && ny < h).then_some((ny * w + nx) as usize)
                })
            })
        };
        let touched: Vec<Vec<u32>> = pixels
            .iter()
            .map(|px| {
                let mut t: Vec<u32> = px
                    .iter()
                    .flat_map(|&p| around(p, 1))
                    .map(|n| rooms.data[n])
                    .filter(|&r| r != 0)
                    .collect();
                t.sort_unstable();
                t.dedup();
                t
            })
            .collect();
        // Union of components one pixel apart that touch the same rooms.
        let mut sets = UnionFind::<usize>::new(count);
        for a in 1..count {
            if touched[a].len() < 2 {
                continue;
            }
            for &p in &pixels[a] {
                for n in around(p, 2) {
                    let b = lines.data[n] as usize;
                    if b != 0 && b != a && touched[b] == touched[a] {
                        sets.union(a, b);
                    }
                }
            }
        }
        // Each set's pixels under its lowest component.
        let mut first_of = vec![usize::MAX; count];
        let mut merged: Vec<Vec<u32>> = vec![Vec::new(); count];
        for (a, px) in pixels.iter_mut().enumerate().skip(1) {
            let r = sets.find_mut(a);
            if first_of[r] == usize::MAX {
                first_of[r] = a;
            }
            merged[first_of[r]].append(px);
        }
        let mut doors = Vec::new();
        for (a, mut px) in merged.into_iter().enumerate().skip(1) {
            if px.len() < 3 || touched[a].len() < 2 {
                continue;
            }
            px.sort_unstable();
            doors.push(DoorLine {
                pixels: px,
                rooms: touched[a].clone(),
            });
        }
        GroundTruth { rooms, doors }
    }
}

/// Loads a GT image (any format `grid` reads) for `map`; its size must match.
/// A grey GT is read IPA style, a coloured one ROSE2 style (a room a colour).
pub fn load_ground_truth(path: &Path, map: &OccupancyGrid) -> Result<GroundTruth, EvalError> {
    let opts = LoadOptions {
        max_pixels: u64::MAX,
        ..LoadOptions::default()
    };
    let img = crate::grid::decode_image(path, &opts)?;
    if (img.width(), img.height()) != (map.width, map.height) {
        return Err(GridError::SizeMismatch {
            path: path.to_path_buf(),
            width: img.width(),
            height: img.height(),
            expected_width: map.width,
            expected_height: map.height,
            what: "the map's size",
        }
        .into());
    }
    let rgb = img.to_rgb8();
    // ROSE2 style when most non-black pixels are not grey.
    let non_black = rgb.pixels().filter(|p| p.0 != [0, 0, 0]).count();
    let colour = rgb
        .pixels()
        .filter(|p| p[0] != p[1] || p[1] != p[2])
        .count();
    let coloured = colour * 2 > non_black;
    let gt = if coloured {
        let px: Vec<[u8; 3]> = rgb.pixels().map(|p| p.0).collect();
        GroundTruth::from_colours(map.width, map.height, &px, &map.grey)
    } else {
        let (grey, _) = crate::grid::grey_and_alpha(&img);
        GroundTruth::from_grey(map.width, map.height, &grey, &map.grey)
    };
    if gt.rooms.count == 0 {
        return Err(EvalError::NoRooms {
            path: path.to_path_buf(),
        });
    }
    Ok(gt)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rooms_and_doorway_lines() {
        // Two 12x12 rooms (144 px each) separated by a wall with a 3 px doorway
        // that the GT closes with a black line.
        let (w, h) = (27u32, 14u32);
        let mut map = vec![0u8; (w * h) as usize];
        for y in 1..13 {
            for x in 1..26 {
                if x != 13 || (5..8).contains(&y) {
                    map[(y * w + x) as usize] = 255;
                }
            }
        }
        let mut gt = map.clone();
        for y in 5..8 {
            gt[(y * w + 13) as usize] = 0;
        }
        let g = GroundTruth::from_grey(w, h, &gt, &map);
        assert_eq!(g.rooms.count, 2);
        assert_eq!(g.doors.len(), 1);
        assert_eq!(g.doors[0].rooms, vec![1, 2]);
        assert_eq!(g.doors[0].pixels.len(), 3);
    }

    /// Two 12x12 rooms and a wall with a doorway from row 2 to row 10;
    /// the GT closes it with a black line; `specks` rows of the doorway are
    /// occupied in the map.
    fn doorway_with_specks(specks: &[u32]) -> GroundTruth {
        let (w, h) = (27u32, 14u32);
        let mut map = vec![0u8; (w * h) as usize];
        for y in 1..13 {
            for x in 1..26 {
                if x != 13 || ((2..11).contains(&y) && !specks.contains(&y)) {
                    map[(y * w + x) as usize] = 255;
                }
            }
        }
        let mut gt = map.clone();
        for y in 2..11 {
            gt[(y * w + 13) as usize] = 0;
        }
        GroundTruth::from_grey(w, h, &gt, &map)
    }

    #[test]
    fn a_speck_of_noise_does_not_split_a_doorway_line() {
        // One occupied pixel in the doorway: still one line, 8 pixels.
        let g = doorway_with_specks(&[6]);
        assert_eq!(g.doors.len(), 1);
        assert_eq!(g.doors[0].pixels.len(), 8);
        assert_eq!(g.doors[0].rooms, vec![1, 2]);
        // Two occupied pixels in a row are a wall piece: two doorways.
        let g = doorway_with_specks(&[5, 6]);
        assert_eq!(g.doors.len(), 2);
    }

    #[test]
    fn rooms_by_colour() {
        let (w, h) = (30u32, 10u32);
        let map = vec![255u8; (w * h) as usize];
        let rgb: Vec<[u8; 3]> = (0..w * h)
            .map(|i| match i % w {
                0..=13 => [200, 10, 10],
                14 => [0, 0, 0],
                _ => [10, 200, 10],
            })
            .collect();
        let g = GroundTruth::from_colours(w, h, &rgb, &map);
        assert_eq!(g.rooms.count, 2);
        assert_eq!(g.doors.len(), 1);
        assert_eq!(g.doors[0].rooms, vec![1, 2]);
    }
}
