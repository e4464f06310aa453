//! The occupancy grid behind a revision (table `revision_grids`, schema
//! 2): kept when a revision is imported from a ROS map so that later
//! revisions from other mapping runs can be aligned to it.
//!
//! The grid is stored as its classified cells (free 255, occupied 0,
//! unknown 205) in an 8-bit grey PNG with resolution and origin.

use image::{ExtendedColorType, ImageEncoder, ImageFormat, codecs::png::PngEncoder};
use rusqlite::{Connection, OptionalExtension, params};

use super::read::{latest, map_id};
use super::{Store, StoreError};
use crate::grid::{Cell, OccupancyGrid};

impl Store {
    /// The occupancy grid revision `rev` of `map` was imported from (the
    /// latest revision when `None`), or `None` when it came from a model
    /// file.
    pub fn grid(&self, map: &str, rev: Option<u32>) -> Result<Option<OccupancyGrid>, StoreError> {
        let id = map_id(&self.conn, map)?;
        let last = latest(&self.conn, id)?;
        let seq = match rev {
            None if last > 0 => last,
            Some(r) if r >= 1 && r <= last => r,
            _ => {
                return Err(StoreError::NoSuchRevision {
                    map: map.to_string(),
                    rev: rev.unwrap_or(0),
                    latest: last,
                });
            }
        };
        type Row = (u32, u32, f64, f64, f64, f64, Vec<u8>);
        let row: Option<Row> = self
            .conn
            .query_row(
                "SELECT width, height, resolution, origin_x, origin_y, origin_yaw, png
                 FROM revision_grids WHERE map_id = ?1 AND seq = ?2",
                params![id, seq],
                |r| {
                    Ok((
                        r.get(0)?,
                        r.get(1)?,
                        r.get(2)?,
                        r.get(3)?,
                        r.get(4)?,
                        r.get(5)?,
                        r.get(6)?,
                    ))
                },
            )
            .optional()?;
        let Some((width, height, resolution, ox, oy, yaw, png)) = row else {
            return Ok(None);
        };
        let corrupt = |what: String| StoreError::Corrupt {
            map: map.to_string(),
            row: 0,
            what: format!("grid of revision {seq}: {what}"),
        };
        let img = image::load_from_memory_with_format(&png, ImageFormat::Png)
            .map_err(|e| corrupt(e.to_string()))?
            .to_luma8();
        if img.width() != width || img.height() != height {
            return Err(corrupt(format!(
                "png is {}×{}, row says {width}×{height}",
                img.width(),
                img.height()
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
        Ok(Some(OccupancyGrid::from_cells(
            width,
            height,
            resolution,
            [ox, oy, yaw],
            cells,
        )))
    }
}

/// A grid encoded as PNG, ready to be stored.
pub(crate) struct EncodedGrid<'a> {
    grid: &'a OccupancyGrid,
    png: Vec<u8>,
}

/// Encodes `grid` (before the import takes the write lock: a large grid
/// takes a while to compress).
pub(crate) fn encode_grid(grid: &OccupancyGrid) -> Result<EncodedGrid<'_>, StoreError> {
    let grey: Vec<u8> = grid.cells.iter().map(|c| c.grey()).collect();
    let mut png = Vec::new();
    PngEncoder::new(&mut png)
        .write_image(&grey, grid.width, grid.height, ExtendedColorType::L8)
        .map_err(|e| StoreError::Corrupt {
            map: String::new(),
            row: 0,
            what: format!("cannot encode the occupancy grid: {e}"),
        })?;
    Ok(EncodedGrid { grid, png })
}

/// Stores `encoded` as the source of revision `seq` (inside the import's
/// transaction).
pub(crate) fn insert_grid(
    conn: &Connection,
    map_id: i64,
    seq: u32,
    encoded: &EncodedGrid<'_>,
) -> Result<(), StoreError> {
    let EncodedGrid { grid, png } = encoded;
    conn.execute(
        "INSERT INTO revision_grids (map_id, seq, width, height, resolution, origin_x, origin_y, origin_yaw, png)
         VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)",
        params![
            map_id,
            seq,
            grid.width,
            grid.height,
            grid.resolution,
            grid.origin[0],
            grid.origin[1],
            grid.origin[2],
            png
        ],
    )?;
    Ok(())
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
