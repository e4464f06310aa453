//! The occupancy grid behind a revision, as every engine stores it: its
//! classified cells (free 255, occupied 0, unknown 205) in an 8-bit grey
//! PNG with resolution and origin. Kept when a revision is imported from a
//! ROS map so that later revisions from other mapping runs can be aligned
//! to it. Encoding (slow for large grids) happens before a commit takes the
//! write lock.

use image::{ExtendedColorType, ImageEncoder, ImageFormat, codecs::png::PngEncoder};

use super::StoreError;
use crate::grid::{Cell, OccupancyGrid};

/// A grid encoded as PNG with its geometry, ready to be stored.
#[derive(Debug, Clone, PartialEq)]
pub struct EncodedGrid {
    /// Cells across.
    pub width: u32,
    /// Cells down.
    pub height: u32,
    /// Metres per cell.
    pub resolution: f64,
    /// Map-frame pose `[x, y, yaw]` of the lower-left corner.
    pub origin: [f64; 3],
    /// The cells as an 8-bit grey PNG.
    pub png: Vec<u8>,
}

impl EncodedGrid {
    /// Encodes `grid`.
    pub fn encode(grid: &OccupancyGrid) -> Result<EncodedGrid, StoreError> {
        let grey: Vec<u8> = grid.cells.iter().map(|c| c.grey()).collect();
        let mut png = Vec::new();
        PngEncoder::new(&mut png)
            .write_image(&grey, grid.width, grid.height, ExtendedColorType::L8)
            .map_err(|e| StoreError::Corrupt {
                map: String::new(),
                row: 0,
                what: format!("cannot encode the occupancy grid: {e}"),
            })?;
        Ok(EncodedGrid {
            width: grid.width,
            height: grid.height,
            resolution: grid.resolution,
            origin: grid.origin,
            png,
        })
    }

    /// Decodes the grid of revision `seq` of `map` (named in errors).
    pub fn decode(&self, map: &str, seq: u32) -> Result<OccupancyGrid, StoreError> {
        let corrupt = |what: String| StoreError::Corrupt {
            map: map.to_string(),
            row: 0,
            what: format!("grid of revision {seq}: {what}"),
        };
        let img = image::load_from_memory_with_format(&self.png, ImageFormat::Png)
            .map_err(|e| corrupt(e.to_string()))?
            .to_luma8();
        if img.width() != self.width || img.height() != self.height {
            return Err(corrupt(format!(
                "png is {}×{}, row says {}×{}",
                img.width(),
                img.height(),
                self.width,
                self.height
            )));
        }
        let cells = img
            .as_raw()
            .iter()
            .map(|&g| match g {
                255 => Cell::Free,
                0 => Cell::Occupied,
                _ => Cell::Unknown,
            })
            .collect();
        Ok(OccupancyGrid::from_cells(
            self.width,
            self.height,
            self.resolution,
            self.origin,
            cells,
        ))
    }
}

#[cfg(test)]
mod tests {
    use crate::grid::OccupancyGrid;
    use crate::store::{ImportMeta, Store};

    #[test]
    fn grids_round_trip_through_the_store() {
        let grid = OccupancyGrid::from_ascii("#####\n#...#\n#.?.#\n#####", 0.05);
        let nrg = crate::fixtures::corridor_building(1);
        let mut store = Store::open_in_memory().unwrap();
        store
            .import_with_grid("m", &nrg, ImportMeta::new("a", "b"), Some(&grid))
            .unwrap();
        let other = crate::fixtures::corridor_building(2);
        store
            .import("m", &other, ImportMeta::new("c", "d"))
            .unwrap();
        assert_eq!(store.grid("m", Some(1)).unwrap(), Some(grid));
        assert_eq!(store.grid("m", None).unwrap(), None);
        assert!(store.grid("m", Some(3)).is_err());
    }
}
