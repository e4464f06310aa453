//! A raster picture of an extraction: the map's walls and unknown space,
//! each space filled by its kind (Okabe–Ito colour-blind-safe palette) and
//! a route drawn through its waypoints.

use image::{ImageEncoder, Rgb, RgbImage};

use crate::grid::{Cell, OccupancyGrid};
use crate::imaging::Labels;
use crate::model::{Nrg, Point, SpaceId, SpaceKind};

/// Colours by kind (Okabe–Ito): room sky blue, corridor orange, door
/// bluish green, other yellow; the route is vermillion.
pub const PALETTE: [(SpaceKind, [u8; 3]); 4] = [
    (SpaceKind::Room, [86, 180, 233]),
    (SpaceKind::Corridor, [230, 159, 0]),
    (SpaceKind::Door, [0, 158, 115]),
    (SpaceKind::Other, [240, 228, 66]),
];
const ROUTE: [u8; 3] = [213, 94, 0];

fn colour(kind: SpaceKind) -> [u8; 3] {
    PALETTE
        .iter()
        .find(|(k, _)| *k == kind)
        .map_or([255, 255, 255], |(_, c)| *c)
}

/// Paints `grid` with the spaces of `labels` (pixel label = space id of
/// `nrg`) by kind, and `route` (waypoints in metres) as a 3-pixel line.
pub fn kind_picture(grid: &OccupancyGrid, labels: &Labels, nrg: &Nrg, route: &[Point]) -> RgbImage {
    let (w, h) = (grid.width, grid.height);
    let mut img = RgbImage::new(w, h);
    for (i, px) in img.pixels_mut().enumerate() {
        let label = labels.data.get(i).copied().unwrap_or(0);
        let space = (label != 0).then(|| nrg.space(SpaceId(label))).flatten();
        *px = Rgb(match (space, grid.cells.get(i)) {
            (Some(s), _) => colour(s.kind),
            (None, Some(Cell::Free)) => [255, 255, 255],
            (None, Some(Cell::Occupied)) => [0, 0, 0],
            _ => [205, 205, 205],
        });
    }
    for pair in route.windows(2) {
        let [c0, r0] = grid.metres_to_pixel(pair[0]);
        let [c1, r1] = grid.metres_to_pixel(pair[1]);
        let steps = (c1 - c0).abs().max((r1 - r0).abs()).ceil().max(1.0) as usize;
        for s in 0..=steps {
            let t = s as f64 / steps as f64;
            let (c, r) = (c0 + (c1 - c0) * t, r0 + (r1 - r0) * t);
            for dc in -1..=1 {
                for dr in -1..=1 {
                    let (x, y) = (c.floor() as i64 + dc, r.floor() as i64 + dr);
                    if x >= 0 && y >= 0 && (x as u32) < w && (y as u32) < h {
                        img.put_pixel(x as u32, y as u32, Rgb(ROUTE));
                    }
                }
            }
        }
    }
    img
}

/// [`kind_picture`] encoded as PNG.
pub fn kind_picture_png(
    grid: &OccupancyGrid,
    labels: &Labels,
    nrg: &Nrg,
    route: &[Point],
) -> Result<Vec<u8>, image::ImageError> {
    let img = kind_picture(grid, labels, nrg, route);
    let mut out = Vec::new();
    image::codecs::png::PngEncoder::new(&mut out).write_image(
        img.as_raw(),
        img.width(),
        img.height(),
        image::ExtendedColorType::Rgb8,
    )?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Space;

    #[test]
    fn spaces_take_their_kind_colour_and_walls_stay_black() {
        let grid = OccupancyGrid::from_ascii("#..\n#..", 1.0);
        let mut labels = Labels::new(3, 2);
        labels.data = vec![0, 1, 1, 0, 2, 0];
        let sq = |x: f64| vec![[x, 0.0], [x + 1.0, 0.0], [x + 1.0, 1.0], [x, 1.0]];
        let nrg = Nrg::new(
            vec![
                Space::new(SpaceId(1), SpaceKind::Room, [1.5, 1.5], sq(1.0)),
                Space::new(SpaceId(2), SpaceKind::Door, [1.5, 0.5], sq(1.0)),
            ],
            vec![],
        )
        .unwrap();
        let img = kind_picture(&grid, &labels, &nrg, &[]);
        assert_eq!(img.get_pixel(0, 0).0, [0, 0, 0]);
        assert_eq!(img.get_pixel(1, 0).0, colour(SpaceKind::Room));
        assert_eq!(img.get_pixel(1, 1).0, colour(SpaceKind::Door));
        assert_eq!(img.get_pixel(2, 1).0, [255, 255, 255]);
    }
}
