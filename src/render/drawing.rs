//! The display list both back ends draw: shapes in picture pixels (y
//! down) with their colours, strokes and hatching, each tagged with a class
//! (and a space id where it has one) so the SVG can be scripted.

use crate::model::SpaceId;

/// An sRGB colour with alpha (0..255).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rgba(pub [u8; 4]);

impl Rgba {
    /// An opaque colour.
    pub const fn rgb(r: u8, g: u8, b: u8) -> Rgba {
        Rgba([r, g, b, 255])
    }

    /// The same colour with alpha `a`.
    pub const fn with_alpha(self, a: u8) -> Rgba {
        Rgba([self.0[0], self.0[1], self.0[2], a])
    }

    /// `#rrggbb`.
    pub fn hex(&self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.0[0], self.0[1], self.0[2])
    }

    /// Alpha as 0..1.
    pub fn opacity(&self) -> f64 {
        f64::from(self.0[3]) / 255.0
    }
}

/// A line style.
#[derive(Debug, Clone, PartialEq)]
pub struct Stroke {
    /// Colour.
    pub colour: Rgba,
    /// Width in pixels.
    pub width: f64,
    /// Dash pattern (on, off, …) in pixels; empty = solid.
    pub dash: Vec<f64>,
}

impl Stroke {
    /// A solid line.
    pub fn solid(colour: Rgba, width: f64) -> Stroke {
        Stroke {
            colour,
            width,
            dash: Vec::new(),
        }
    }

    /// A dashed line.
    pub fn dashed(colour: Rgba, width: f64, dash: &[f64]) -> Stroke {
        Stroke {
            colour,
            width,
            dash: dash.to_vec(),
        }
    }
}

/// Parallel lines filling a polygon.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hatch {
    /// Line colour.
    pub colour: Rgba,
    /// Distance between lines (px).
    pub spacing: f64,
    /// Line direction in degrees (45 = "/" on screen, 135 = "\").
    pub angle_deg: f64,
    /// Line width (px).
    pub width: f64,
}

/// Where a text sits relative to its position.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Anchor {
    /// Left end at the position.
    Start,
    /// Centred on the position.
    Middle,
}

/// What an item is, for the SVG's `class`/`id` and `data-space`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Tag {
    /// Space-separated classes (e.g. `space room`).
    pub class: String,
    /// A unique element id (e.g. `route`).
    pub id: Option<String>,
    /// The space this item shows.
    pub space: Option<SpaceId>,
}

impl Tag {
    /// A tag with classes only.
    pub fn class(class: impl Into<String>) -> Tag {
        Tag {
            class: class.into(),
            ..Tag::default()
        }
    }
}

/// One thing to draw, in picture pixels.
#[derive(Debug, Clone, PartialEq)]
pub enum Item {
    /// A raster image (the occupancy map) placed by an affine map from its
    /// pixels to picture pixels (`[a, b, c, d, e, f]`, SVG order).
    Raster {
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
        /// Grey per pixel, row 0 at the top.
        grey: Vec<u8>,
        /// Image pixel → picture pixel.
        affine: [f64; 6],
    },
    /// A filled and/or outlined polygon with holes (first ring exterior).
    Polygon {
        /// Rings of points.
        rings: Vec<Vec<[f64; 2]>>,
        /// Fill colour.
        fill: Option<Rgba>,
        /// Hatching over the fill.
        hatch: Option<Hatch>,
        /// Outline.
        stroke: Option<Stroke>,
        /// What it is.
        tag: Tag,
    },
    /// An open polyline.
    Line {
        /// Points.
        points: Vec<[f64; 2]>,
        /// Style.
        stroke: Stroke,
        /// What it is.
        tag: Tag,
    },
    /// A circle.
    Circle {
        /// Centre.
        centre: [f64; 2],
        /// Radius (px).
        radius: f64,
        /// Fill colour.
        fill: Option<Rgba>,
        /// Outline.
        stroke: Option<Stroke>,
        /// What it is.
        tag: Tag,
    },
    /// A line of text (PNG draws ASCII and Latin-1; other characters as `?`).
    Text {
        /// Baseline position.
        at: [f64; 2],
        /// The text.
        text: String,
        /// Height in pixels (PNG uses an 8 px font scaled by whole steps).
        size: f64,
        /// Colour.
        colour: Rgba,
        /// Alignment.
        anchor: Anchor,
        /// What it is.
        tag: Tag,
    },
}

/// A picture: its size, background colour and items, drawn in order.
#[derive(Debug, Clone, PartialEq)]
pub struct Drawing {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Background colour.
    pub background: Rgba,
    /// Items, back to front.
    pub items: Vec<Item>,
    /// The map-frame → pixel transform of the map area (written into the
    /// SVG so a page can place things given in metres).
    pub transform: Option<super::transform::MapTransform>,
}

impl Item {
    /// The item moved by `d` pixels.
    fn moved(mut self, d: [f64; 2]) -> Item {
        let shift = |p: &mut [f64; 2]| {
            p[0] += d[0];
            p[1] += d[1];
        };
        match &mut self {
            Item::Raster { affine, .. } => {
                affine[4] += d[0];
                affine[5] += d[1];
            }
            Item::Polygon { rings, .. } => rings.iter_mut().flatten().for_each(shift),
            Item::Line { points, .. } => points.iter_mut().for_each(shift),
            Item::Circle { centre, .. } => shift(centre),
            Item::Text { at, .. } => shift(at),
        }
        self
    }

    fn tag_mut(&mut self) -> Option<&mut Tag> {
        match self {
            Item::Raster { .. } => None,
            Item::Polygon { tag, .. }
            | Item::Line { tag, .. }
            | Item::Circle { tag, .. }
            | Item::Text { tag, .. } => Some(tag),
        }
    }
}

impl Drawing {
    /// Pictures side by side, left to right with tops aligned, as one
    /// picture (e.g. a route's levels). Element ids after the first panel
    /// get `-2`, `-3`, … so they stay unique; the result has no single
    /// map transform. None when there are no panels or the result would
    /// be wider or taller than `max_px`.
    ///
    /// ```
    /// use nrgdb::render::{Drawing, Rgba};
    /// let panel = |w| Drawing { width: w, height: 50, background: Rgba::rgb(255, 255, 255), items: vec![], transform: None };
    /// let both = Drawing::beside(vec![panel(100), panel(60)], 8_192).unwrap();
    /// assert_eq!((both.width, both.height), (160, 50));
    /// assert!(Drawing::beside(vec![panel(100), panel(60)], 150).is_none());
    /// ```
    pub fn beside(panels: Vec<Drawing>, max_px: u64) -> Option<Drawing> {
        let first = panels.first()?;
        let background = first.background;
        let width: u64 = panels.iter().map(|p| u64::from(p.width)).sum();
        let height = panels.iter().map(|p| p.height).max().unwrap_or(0);
        if width > max_px || u64::from(height) > max_px {
            return None;
        }
        let mut items = Vec::new();
        let mut x = 0.0;
        for (k, panel) in panels.into_iter().enumerate() {
            for item in panel.items {
                let mut item = item.moved([x, 0.0]);
                if k > 0
                    && let Some(tag) = item.tag_mut()
                    && let Some(id) = &mut tag.id
                {
                    id.push_str(&format!("-{}", k + 1));
                }
                items.push(item);
            }
            x += f64::from(panel.width);
        }
        Some(Drawing {
            width: u32::try_from(width).ok()?,
            height,
            background,
            items,
            transform: None,
        })
    }
}
