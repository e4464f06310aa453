//! Map loading: a ROS map_server YAML (or a bare image) in, an
//! [`OccupancyGrid`] out.
//!
//! Owns the YAML fields, image decoding (PGM/PNG, 8/16-bit, grey, grey+alpha,
//! RGB, RGBA), the free/occupied/unknown classification and the pixel ↔ metre
//! conversion (ROS convention: row 0 is the top of the image, the map frame
//! has y up, `origin` is the lower-left pixel's outer corner). Loads from
//! files ([`load_map`]) or from bytes in memory ([`load_map_bytes`], for
//! uploads), with the same checks and the same grid. Uses `image` and
//! `serde_yaml_ng`; must not use imaging, extract or anything above.

mod error;
mod image_check;
mod load;
mod occupancy;
mod yaml;

pub use error::GridError;
pub use image_check::image_warnings;
pub use load::{
    LoadOptions, MAX_YAML_BYTES, decode_image, decode_image_bytes, grey_and_alpha, load_image,
    load_map, load_map_bytes,
};
pub use occupancy::{Cell, OccupancyGrid};
pub use yaml::{MapMode, MapYaml};
