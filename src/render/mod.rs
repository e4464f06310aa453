//! Pictures for people: a model over its occupancy map, spaces filled by
//! kind (Okabe–Ito, colour-blind safe), the graph, labels, a route, a diff,
//! a legend and a scale bar in metres, as SVG (always) or PNG (feature
//! `render`, tiny-skia).
//!
//! A [`Scene`] (metres, map frame) is laid out once by [`layout`] through
//! one [`MapTransform`] into a [`Drawing`] (pixels, y down); each back end
//! only draws that display list, so SVG and PNG show the same picture.
//! [`kind_picture`] is the older label-image picture used by the demo.
//!
//! Uses grid, model, diff's change sets ([`diff_overlay`]: the change set
//! comes from `diff::compare`, the renderer never diffs) and (for the
//! demo picture) imaging labels; takes routes as a plain overlay, made
//! from a route's data (`route::Route`, per level in a building). Knows
//! nothing of SQL, HTTP or the terminal.

mod data_uri;
mod drawing;
mod error;
#[cfg(feature = "render")]
mod font;
mod layout;
mod legend;
mod levels;
mod overlay;
mod picture;
#[cfg(feature = "render")]
mod png;
mod scene;
pub mod style;
mod svg;
mod transform;

pub use data_uri::{base64, grey_png_uri};
pub use drawing::{Anchor, Drawing, Hatch, Item, Rgba, Stroke, Tag};
pub use error::RenderError;
pub use layout::layout;
pub use legend::nice_length_m;
pub use levels::{diff_by_level, route_by_level};
pub use overlay::diff_overlay;
pub use picture::{PALETTE, kind_picture, kind_picture_png};
#[cfg(feature = "render")]
pub use png::{drawing_pixmap, drawing_png, render_png};
pub use scene::{
    DiffOverlay, LabelMode, LevelMark, OverlaySpace, RenderOptions, RouteOverlay, Scene,
};
pub use svg::{drawing_svg, render_svg};
pub use transform::MapTransform;
