//! Space outlines: contours of each label (Suzuki–Abe, via imageproc),
//! simplified, in metres in the map frame, exterior CCW and holes CW.

use image::GrayImage;
use imageproc::contours::{BorderType, find_contours};

use super::simplify::simplify_ring;
use crate::grid::OccupancyGrid;
use crate::imaging::Labels;
use crate::model::{Point, Ring, polygon_area};

/// Bounding box `[min_col, min_row, max_col, max_row]` of every label (index 0 unused).
pub(crate) fn bounding_boxes(labels: &Labels) -> Vec<[u32; 4]> {
    labels.bounding_boxes()
}

/// The outline of label `l` (largest outer border) and its holes, in metres.
pub(crate) fn outline(
    labels: &Labels,
    l: u32,
    bbox: [u32; 4],
    grid: &OccupancyGrid,
    simplify_m: f64,
) -> (Ring, Vec<Ring>) {
    let [x0, y0, x1, y1] = bbox;
    if x0 > x1 || y0 > y1 {
        return (Vec::new(), Vec::new());
    }
    // One pixel of padding so borders never touch the crop's edge.
    let (cw, ch) = (x1 - x0 + 3, y1 - y0 + 3);
    let w = labels.width as usize;
    let mut crop = GrayImage::new(cw, ch);
    let (cols, cw) = ((x1 - x0 + 1) as usize, cw as usize);
    for (y, dst) in crop
        .chunks_exact_mut(cw)
        .skip(1)
        .take((y1 - y0 + 1) as usize)
        .enumerate()
    {
        let start = (y0 as usize + y) * w + x0 as usize;
        let src = &labels.data[start..start + cols];
        for (d, &s) in dst[1..=cols].iter_mut().zip(src) {
            *d = if s == l { 255 } else { 0 };
        }
    }
    let contours = find_contours::<i32>(&crop);
    let to_m = |c: &imageproc::contours::Contour<i32>| -> Ring {
        c.points
            .iter()
            .map(|p| {
                let col = f64::from(x0) + f64::from(p.x - 1) + 0.5;
                let row = f64::from(y0) + f64::from(p.y - 1) + 0.5;
                grid.pixel_to_metres(col, row)
            })
            .collect()
    };
    let outer = contours
        .iter()
        .enumerate()
        .filter(|(_, c)| c.border_type == BorderType::Outer)
        .max_by(|a, b| {
            polygon_area(&to_m(a.1))
                .abs()
                .total_cmp(&polygon_area(&to_m(b.1)).abs())
        });
    let Some((oi, oc)) = outer else {
        return (Vec::new(), Vec::new());
    };
    let exterior = finish(to_m(oc), simplify_m, true);
    let exterior = if distinct(&exterior) < 3 {
        pixel_box(bbox, grid)
    } else {
        exterior
    };
    let holes = contours
        .iter()
        .filter(|c| c.border_type == BorderType::Hole && c.parent == Some(oi))
        .map(|c| finish(to_m(c), simplify_m, false))
        .filter(|r| distinct(r) >= 3 && polygon_area(r).abs() > 0.0)
        .collect();
    (exterior, holes)
}

fn finish(ring: Ring, simplify_m: f64, ccw: bool) -> Ring {
    let mut r = simplify_ring(&ring, simplify_m);
    if distinct(&r) < 3 {
        r = ring;
    }
    if (polygon_area(&r) > 0.0) != ccw {
        r.reverse();
    }
    r
}

fn distinct(r: &[Point]) -> usize {
    let mut v: Vec<Point> = r.to_vec();
    v.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    v.dedup();
    if polygon_area(r).abs() < 1e-12 {
        v.len().min(2)
    } else {
        v.len()
    }
}

/// The outer corners of a pixel box, CCW in metres (for one-pixel-thin spaces).
fn pixel_box(bbox: [u32; 4], grid: &OccupancyGrid) -> Ring {
    let [x0, y0, x1, y1] = bbox.map(f64::from);
    let mut r = vec![
        grid.pixel_to_metres(x0, y1 + 1.0),
        grid.pixel_to_metres(x1 + 1.0, y1 + 1.0),
        grid.pixel_to_metres(x1 + 1.0, y0),
        grid.pixel_to_metres(x0, y0),
    ];
    if polygon_area(&r) < 0.0 {
        r.reverse();
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::Cell;

    #[test]
    fn square_outline_in_metres_ccw_with_hole() {
        let grid = OccupancyGrid::from_cells(7, 7, 1.0, [0.0; 3], vec![Cell::Free; 49]);
        let mut labels = Labels::new(7, 7);
        for y in 1..6 {
            for x in 1..6 {
                labels.data[y * 7 + x] = if (x, y) == (3, 3) { 0 } else { 1 };
            }
        }
        labels.count = 1;
        let b = bounding_boxes(&labels);
        assert_eq!(b[1], [1, 1, 5, 5]);
        let (ext, holes) = outline(&labels, 1, b[1], &grid, 0.01);
        assert_eq!(ext.len(), 4);
        assert!(polygon_area(&ext) > 0.0);
        // Pixel centres 1.5..5.5 in x, and y = 7 - row - 0.5.
        assert!(ext.contains(&[1.5, 5.5]) && ext.contains(&[5.5, 1.5]));
        assert_eq!(holes.len(), 1);
        assert!(polygon_area(&holes[0]) < 0.0);
    }

    #[test]
    fn a_thin_line_gets_a_box() {
        let grid = OccupancyGrid::from_cells(5, 1, 1.0, [0.0; 3], vec![Cell::Free; 5]);
        let labels = Labels {
            width: 5,
            height: 1,
            data: vec![0, 1, 1, 1, 0],
            count: 1,
        };
        let (ext, _) = outline(&labels, 1, [1, 0, 3, 0], &grid, 0.01);
        assert_eq!(ext.len(), 4);
        assert!((polygon_area(&ext) - 3.0).abs() < 1e-9);
    }
}
