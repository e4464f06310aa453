//! Pictures for people. For now: the occupancy map with each space
//! painted by kind and a route on top ([`kind_picture`]), as PNG.
//!
//! Uses grid, imaging labels and the model; knows nothing of SQL, HTTP or
//! the terminal.

mod picture;

pub use picture::{PALETTE, kind_picture, kind_picture_png};
