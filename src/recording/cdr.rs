//! `nav_msgs/msg/OccupancyGrid` in CDR, as ROS 2 serialises it (XCDR1,
//! little- or big-endian, after the 4-byte encapsulation header): the
//! header (stamp, frame id), the map meta data (load time, resolution,
//! width, height, origin pose) and the `int8` cells, row 0 at the origin
//! (the map's bottom), −1 unknown and 0–100 occupancy.
//!
//! Decoding is two steps so a recording can be scanned cheaply:
//! [`GridMessage::parse`] reads the fields and checks every length against
//! the message and the pixel limit, borrowing the cells; [`GridMessage::to_grid`]
//! classifies them with the map saver's thresholds into an
//! [`OccupancyGrid`] (rows flipped to our image order, yaw from the
//! origin's quaternion).

use crate::grid::{Cell, OccupancyGrid};

/// Why a message is not a readable OccupancyGrid.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CdrError {
    /// The message ends before a field.
    #[error("the message ends inside {field} (at byte {at} of {len})")]
    Truncated {
        /// The field being read.
        field: &'static str,
        /// Where it starts.
        at: usize,
        /// The message's length.
        len: usize,
    },
    /// The encapsulation header names a layout this reader does not read.
    #[error(
        "unknown CDR layout {0:#06x} (read: 0x0000 CDR big-endian, 0x0001 CDR little-endian, as ROS 2 writes them)"
    )]
    Layout(u16),
    /// A field holds an impossible value.
    #[error("{field} is {value}: {why}")]
    Bad {
        /// The field.
        field: &'static str,
        /// Its value, as text.
        value: String,
        /// What is wrong.
        why: &'static str,
    },
}

/// The cells a grid message may hold at most unless told otherwise (as
/// map images: 64 Mpx).
pub const DEFAULT_MAX_CELLS: u64 = 64 * 1024 * 1024;

/// Occupancy at or below which a cell is free, and at or above which it
/// is occupied (percent): Nav2's map saver defaults (`free_thresh` 0.25,
/// `occupied_thresh` 0.65), so a message imported here and the same map
/// saved by the map saver and imported as YAML give the same grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Thresholds {
    /// Free at or below this occupancy (0–100).
    pub free_max: i8,
    /// Occupied at or above this occupancy (0–100).
    pub occupied_min: i8,
}

impl Default for Thresholds {
    fn default() -> Thresholds {
        Thresholds {
            free_max: 25,
            occupied_min: 65,
        }
    }
}

impl Thresholds {
    /// The class of one cell value.
    pub fn classify(&self, value: i8) -> Cell {
        if !(0..=100).contains(&value) {
            Cell::Unknown
        } else if value <= self.free_max {
            Cell::Free
        } else if value >= self.occupied_min {
            Cell::Occupied
        } else {
            Cell::Unknown
        }
    }
}

/// One OccupancyGrid message, its cells borrowed.
#[derive(Debug, Clone, PartialEq)]
pub struct GridMessage<'a> {
    /// `header.stamp`, nanoseconds since the epoch (0 when unset).
    pub stamp_ns: i64,
    /// `header.frame_id` (usually `map`).
    pub frame_id: String,
    /// Metres per cell.
    pub resolution: f64,
    /// Cells per row.
    pub width: u32,
    /// Rows.
    pub height: u32,
    /// Origin position `[x, y]` and yaw (radians) of cell (0, 0)'s outer
    /// corner in the frame.
    pub origin: [f64; 3],
    /// The cells, row-major, row 0 at the origin.
    pub data: &'a [u8],
}

/// A cursor over CDR bytes, aligned relative to the payload's start.
struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
    little: bool,
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize, align: usize, field: &'static str) -> Result<&'a [u8], CdrError> {
        // Alignment counts from the end of the 4-byte encapsulation header.
        let pad = (align - (self.at - 4) % align) % align;
        let start = self.at + pad;
        let end = start.checked_add(n).filter(|e| *e <= self.bytes.len());
        let Some(end) = end else {
            return Err(CdrError::Truncated {
                field,
                at: start,
                len: self.bytes.len(),
            });
        };
        self.at = end;
        Ok(&self.bytes[start..end])
    }

    fn u32(&mut self, field: &'static str) -> Result<u32, CdrError> {
        let b: [u8; 4] = self.take(4, 4, field)?.try_into().unwrap_or_default();
        Ok(if self.little {
            u32::from_le_bytes(b)
        } else {
            u32::from_be_bytes(b)
        })
    }

    fn i32(&mut self, field: &'static str) -> Result<i32, CdrError> {
        self.u32(field).map(|v| v as i32)
    }

    fn f32(&mut self, field: &'static str) -> Result<f32, CdrError> {
        self.u32(field).map(f32::from_bits)
    }

    fn f64(&mut self, field: &'static str) -> Result<f64, CdrError> {
        let b: [u8; 8] = self.take(8, 8, field)?.try_into().unwrap_or_default();
        Ok(f64::from_bits(if self.little {
            u64::from_le_bytes(b)
        } else {
            u64::from_be_bytes(b)
        }))
    }

    fn string(&mut self, field: &'static str) -> Result<String, CdrError> {
        let n = self.u32(field)? as usize;
        let bytes = self.take(n, 1, field)?;
        // The length counts the terminating NUL.
        let text = bytes.strip_suffix(&[0]).unwrap_or(bytes);
        Ok(String::from_utf8_lossy(text).into_owned())
    }
}

fn finite(field: &'static str, v: f64) -> Result<f64, CdrError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(CdrError::Bad {
            field,
            value: v.to_string(),
            why: "not a finite number",
        })
    }
}

impl<'a> GridMessage<'a> {
    /// Reads a serialised message (encapsulation header included), with
    /// at most `max_cells` cells.
    pub fn parse(bytes: &'a [u8], max_cells: u64) -> Result<GridMessage<'a>, CdrError> {
        let Some(head) = bytes.get(..4) else {
            return Err(CdrError::Truncated {
                field: "the encapsulation header",
                at: 0,
                len: bytes.len(),
            });
        };
        let little = match u16::from_be_bytes([head[0], head[1]]) {
            0x0000 => false,
            0x0001 => true,
            other => return Err(CdrError::Layout(other)),
        };
        let mut r = Reader {
            bytes,
            at: 4,
            little,
        };
        let sec = r.i32("header.stamp.sec")?;
        let nsec = r.u32("header.stamp.nanosec")?;
        let frame_id = r.string("header.frame_id")?;
        r.i32("info.map_load_time.sec")?;
        r.u32("info.map_load_time.nanosec")?;
        let resolution = f64::from(r.f32("info.resolution")?);
        let width = r.u32("info.width")?;
        let height = r.u32("info.height")?;
        let x = finite("info.origin.position.x", r.f64("info.origin.position.x")?)?;
        let y = finite("info.origin.position.y", r.f64("info.origin.position.y")?)?;
        r.f64("info.origin.position.z")?;
        let q = [
            r.f64("info.origin.orientation.x")?,
            r.f64("info.origin.orientation.y")?,
            r.f64("info.origin.orientation.z")?,
            r.f64("info.origin.orientation.w")?,
        ];
        let n = r.u32("data")? as usize;
        let data = r.take(n, 1, "data")?;
        if !(resolution.is_finite() && resolution > 0.0) {
            return Err(CdrError::Bad {
                field: "info.resolution",
                value: resolution.to_string(),
                why: "must be a positive number of metres per cell",
            });
        }
        let cells = u64::from(width) * u64::from(height);
        if cells == 0 || cells > max_cells {
            return Err(CdrError::Bad {
                field: "info.width × info.height",
                value: format!("{width} × {height}"),
                why: "must be between 1 cell and the pixel limit",
            });
        }
        if n as u64 != cells {
            return Err(CdrError::Bad {
                field: "data",
                value: format!("{n} cells"),
                why: "must hold width × height cells",
            });
        }
        let [qx, qy, qz, qw] = q;
        if !q.iter().all(|v| v.is_finite()) {
            return Err(CdrError::Bad {
                field: "info.origin.orientation",
                value: format!("{q:?}"),
                why: "not a finite quaternion",
            });
        }
        let yaw = (2.0 * (qw * qz + qx * qy)).atan2(1.0 - 2.0 * (qy * qy + qz * qz));
        Ok(GridMessage {
            stamp_ns: i64::from(sec) * 1_000_000_000 + i64::from(nsec),
            frame_id,
            resolution,
            width,
            height,
            origin: [x, y, yaw],
            data,
        })
    }

    /// The grid: cells classified by `thresholds`, row 0 at the top.
    pub fn to_grid(&self, thresholds: &Thresholds) -> OccupancyGrid {
        let w = self.width as usize;
        let mut cells = Vec::with_capacity(self.data.len());
        // Our rows run top-down; the message's from the origin up.
        for row in self.data.chunks_exact(w.max(1)).rev() {
            cells.extend(row.iter().map(|v| thresholds.classify(*v as i8)));
        }
        OccupancyGrid::from_cells(self.width, self.height, self.resolution, self.origin, cells)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 3 × 2 grid written out byte by byte (little-endian), with the
    /// padding CDR puts before the doubles.
    fn tiny() -> Vec<u8> {
        let mut b = vec![0x00, 0x01, 0x00, 0x00];
        b.extend(7i32.to_le_bytes()); // stamp.sec
        b.extend(500u32.to_le_bytes()); // stamp.nanosec
        b.extend(4u32.to_le_bytes()); // frame_id length with NUL
        b.extend(b"map\0");
        b.extend(0i32.to_le_bytes()); // map_load_time
        b.extend(0u32.to_le_bytes());
        b.extend(0.5f32.to_le_bytes()); // resolution
        b.extend(3u32.to_le_bytes()); // width
        b.extend(2u32.to_le_bytes()); // height
        // Payload offset is now 36: 4 bytes of padding to 40.
        b.extend([0u8; 4]);
        for v in [1.0f64, 2.0, 0.0] {
            b.extend(v.to_le_bytes());
        }
        // Orientation: a quarter turn about z.
        let h = std::f64::consts::FRAC_1_SQRT_2;
        for v in [0.0f64, 0.0, h, h] {
            b.extend(v.to_le_bytes());
        }
        b.extend(6u32.to_le_bytes());
        // Bottom row: free, occupied, unknown; top row: 25, 26, 65.
        b.extend([0u8, 100, 0xff, 25, 26, 65]);
        b
    }

    #[test]
    fn a_hand_written_message_decodes() {
        let bytes = tiny();
        let m = GridMessage::parse(&bytes, 100).unwrap();
        assert_eq!(m.stamp_ns, 7_000_000_500);
        assert_eq!(m.frame_id, "map");
        assert_eq!((m.width, m.height, m.resolution), (3, 2, 0.5));
        assert_eq!(&m.origin[..2], &[1.0, 2.0]);
        assert!((m.origin[2] - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        let g = m.to_grid(&Thresholds::default());
        use Cell::{Free, Occupied, Unknown};
        // Row 0 of the grid is the message's last row.
        assert_eq!(
            g.cells,
            vec![Free, Unknown, Occupied, Free, Occupied, Unknown]
        );
    }

    #[test]
    fn big_endian_reads_the_same() {
        // Re-encode the tiny message big-endian, field by field.
        let le = tiny();
        let mut be = vec![0x00, 0x00, 0x00, 0x00];
        let swap = |s: &[u8]| s.iter().rev().copied().collect::<Vec<u8>>();
        // 4-byte fields up to the padding, then 8-byte ones, then the length.
        let mut at = 4;
        for size in [4, 4, 4] {
            be.extend(swap(&le[at..at + size]));
            at += size;
        }
        be.extend(&le[at..at + 4]); // "map\0"
        at += 4;
        for _ in 0..5 {
            be.extend(swap(&le[at..at + 4]));
            at += 4;
        }
        be.extend(&le[at..at + 4]);
        at += 4;
        for _ in 0..7 {
            be.extend(swap(&le[at..at + 8]));
            at += 8;
        }
        be.extend(swap(&le[at..at + 4]));
        at += 4;
        be.extend(&le[at..]);
        let (a, b) = (
            GridMessage::parse(&le, 100).unwrap(),
            GridMessage::parse(&be, 100).unwrap(),
        );
        assert_eq!(a, b);
    }

    #[test]
    fn broken_messages_say_what_is_wrong() {
        let bytes = tiny();
        for cut in [0, 3, 10, 30, 60, bytes.len() - 1] {
            let err = GridMessage::parse(&bytes[..cut], 100).unwrap_err();
            assert!(matches!(err, CdrError::Truncated { .. }), "{cut}: {err}");
        }
        let mut xcdr2 = bytes.clone();
        xcdr2[1] = 0x07;
        assert_eq!(
            GridMessage::parse(&xcdr2, 100).unwrap_err(),
            CdrError::Layout(7)
        );
        let err = GridMessage::parse(&bytes, 5).unwrap_err().to_string();
        assert!(err.contains("3 × 2"), "{err}");
        let mut zero = bytes.clone();
        zero[28..32].copy_from_slice(&0f32.to_le_bytes());
        let err = GridMessage::parse(&zero, 100).unwrap_err().to_string();
        assert!(err.starts_with("info.resolution is 0"), "{err}");
        let mut short = bytes.clone();
        let n = short.len();
        short[n - 10..n - 6].copy_from_slice(&5u32.to_le_bytes());
        let err = GridMessage::parse(&short, 100).unwrap_err().to_string();
        assert!(err.contains("5 cells"), "{err}");
    }
}
