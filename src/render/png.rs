//! The PNG back end: a [`Drawing`] rasterised with tiny-skia
//! (anti-aliased paths, the map scaled with nearest-neighbour filtering,
//! hatching clipped to its polygon by a mask, text from [`super::font`]).

use tiny_skia::{
    FillRule, FilterQuality, LineCap, LineJoin, Mask, Paint, Path, PathBuilder, Pixmap,
    PixmapPaint, StrokeDash, Transform,
};

use super::drawing::{Drawing, Hatch, Item, Rgba, Stroke};
use super::error::RenderError;
use super::font::draw_text;
use super::layout::layout;
use super::scene::Scene;

/// Renders `scene` as PNG bytes.
///
/// ```
/// use nrgdb::render::{RenderOptions, Scene, render_png};
/// let nrg = nrgdb::fixtures::corridor_building(2);
/// let options = RenderOptions::default();
/// let png = render_png(&Scene { nrg: &nrg, map: None, route: None, diff: None, options: &options })?;
/// assert_eq!(&png[1..4], b"PNG");
/// # Ok::<(), nrgdb::render::RenderError>(())
/// ```
pub fn render_png(scene: &Scene<'_>) -> Result<Vec<u8>, RenderError> {
    drawing_png(&layout(scene)?)
}

/// A laid-out drawing as PNG bytes.
pub fn drawing_png(d: &Drawing) -> Result<Vec<u8>, RenderError> {
    drawing_pixmap(d)?
        .encode_png()
        .map_err(|e| RenderError::Encode(e.to_string()))
}

/// Rasterises a laid-out drawing.
pub fn drawing_pixmap(d: &Drawing) -> Result<Pixmap, RenderError> {
    let mut pixmap = Pixmap::new(d.width, d.height).ok_or(RenderError::Allocate {
        width: d.width,
        height: d.height,
    })?;
    let [r, g, b, a] = d.background.0;
    pixmap.fill(tiny_skia::Color::from_rgba8(r, g, b, a));
    for item in &d.items {
        draw_item(&mut pixmap, item);
    }
    Ok(pixmap)
}

fn paint(c: Rgba) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8(c.0[0], c.0[1], c.0[2], c.0[3]);
    p.anti_alias = true;
    p
}

fn skia_stroke(s: &Stroke) -> tiny_skia::Stroke {
    tiny_skia::Stroke {
        width: s.width as f32,
        line_cap: LineCap::Round,
        line_join: LineJoin::Round,
        dash: if s.dash.is_empty() {
            None
        } else {
            StrokeDash::new(s.dash.iter().map(|v| *v as f32).collect(), 0.0)
        },
        ..tiny_skia::Stroke::default()
    }
}

fn path_of(rings: &[Vec<[f64; 2]>], close: bool) -> Option<Path> {
    let mut pb = PathBuilder::new();
    for ring in rings {
        for (i, p) in ring.iter().enumerate() {
            if i == 0 {
                pb.move_to(p[0] as f32, p[1] as f32);
            } else {
                pb.line_to(p[0] as f32, p[1] as f32);
            }
        }
        if close {
            pb.close();
        }
    }
    pb.finish()
}

fn draw_item(pixmap: &mut Pixmap, item: &Item) {
    let id = Transform::identity();
    match item {
        Item::Raster {
            width,
            height,
            grey,
            affine,
        } => {
            let Some(mut img) = Pixmap::new(*width, *height) else {
                return;
            };
            for (px, g) in img.data_mut().chunks_exact_mut(4).zip(grey) {
                px.copy_from_slice(&[*g, *g, *g, 255]);
            }
            let [a, b, c, d, e, f] = affine.map(|v| v as f32);
            let paint = PixmapPaint {
                quality: FilterQuality::Nearest,
                ..PixmapPaint::default()
            };
            pixmap.draw_pixmap(
                0,
                0,
                img.as_ref(),
                &paint,
                Transform::from_row(a, b, c, d, e, f),
                None,
            );
        }
        Item::Polygon {
            rings,
            fill,
            hatch,
            stroke,
            ..
        } => {
            let Some(path) = path_of(rings, true) else {
                return;
            };
            if let Some(c) = fill {
                pixmap.fill_path(&path, &paint(*c), FillRule::EvenOdd, id, None);
            }
            if let Some(h) = hatch {
                draw_hatch(pixmap, &path, h);
            }
            if let Some(s) = stroke {
                pixmap.stroke_path(&path, &paint(s.colour), &skia_stroke(s), id, None);
            }
        }
        Item::Line { points, stroke, .. } => {
            if let Some(path) = path_of(std::slice::from_ref(points), false) {
                pixmap.stroke_path(&path, &paint(stroke.colour), &skia_stroke(stroke), id, None);
            }
        }
        Item::Circle {
            centre,
            radius,
            fill,
            stroke,
            ..
        } => {
            let Some(path) =
                PathBuilder::from_circle(centre[0] as f32, centre[1] as f32, *radius as f32)
            else {
                return;
            };
            if let Some(c) = fill {
                pixmap.fill_path(&path, &paint(*c), FillRule::Winding, id, None);
            }
            if let Some(s) = stroke {
                pixmap.stroke_path(&path, &paint(s.colour), &skia_stroke(s), id, None);
            }
        }
        Item::Text {
            at,
            text,
            size,
            colour,
            anchor,
            ..
        } => draw_text(pixmap, *at, text, *size, *colour, *anchor),
    }
}

/// Parallel lines across the polygon's bounding box, clipped by a mask.
fn draw_hatch(pixmap: &mut Pixmap, path: &Path, h: &Hatch) {
    let Some(mut mask) = Mask::new(pixmap.width(), pixmap.height()) else {
        return;
    };
    mask.fill_path(path, FillRule::EvenOdd, true, Transform::identity());
    let b = path.bounds();
    let (cx, cy) = (
        f64::from(b.left() + b.right()) / 2.0,
        f64::from(b.top() + b.bottom()) / 2.0,
    );
    let half = f64::from(b.width()).hypot(f64::from(b.height())) / 2.0 + h.spacing;
    // Screen angle: y grows downwards, so 45° ("/") goes up to the right.
    let (s, c) = (-h.angle_deg.to_radians()).sin_cos();
    let (dir, normal) = ([c, s], [-s, c]);
    let mut pb = PathBuilder::new();
    let n = (half / h.spacing.max(1.0)).ceil() as i64;
    for k in -n..=n {
        let o = k as f64 * h.spacing;
        let (mx, my) = (cx + normal[0] * o, cy + normal[1] * o);
        pb.move_to((mx - dir[0] * half) as f32, (my - dir[1] * half) as f32);
        pb.line_to((mx + dir[0] * half) as f32, (my + dir[1] * half) as f32);
    }
    if let Some(lines) = pb.finish() {
        let stroke = skia_stroke(&Stroke::solid(h.colour, h.width));
        pixmap.stroke_path(
            &lines,
            &paint(h.colour),
            &stroke,
            Transform::identity(),
            Some(&mask),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::{RenderOptions, RouteOverlay};

    #[test]
    fn rooms_are_painted_in_their_kind_colour_over_white() {
        let nrg = crate::fixtures::corridor_building(2);
        let options = RenderOptions {
            px_per_m: Some(20.0),
            legend: false,
            graph: false,
            labels: crate::render::LabelMode::None,
            ..RenderOptions::default()
        };
        let route = RouteOverlay::default();
        let d = layout(&Scene {
            nrg: &nrg,
            map: None,
            route: Some(&route),
            diff: None,
            options: &options,
        })
        .unwrap();
        let p = drawing_pixmap(&d).unwrap();
        // Room 10 spans x 0.1..3.9, y 2.2..7: its middle (2, 4.6) at 20 px/m with
        // the 20 px margin and y_max = 7 is (60, 68).
        let c = p.pixel(60, 68).unwrap();
        let sky = crate::render::style::kind_fill(crate::model::SpaceKind::Room);
        let expect = |ch: u8| (u32::from(ch) * 170 + 255 * 85) / 255;
        assert!(
            (i64::from(c.red()) - expect(sky.0[0]) as i64).abs() <= 2,
            "{c:?}"
        );
        assert!(
            (i64::from(c.blue()) - expect(sky.0[2]) as i64).abs() <= 2,
            "{c:?}"
        );
        // The margin stays white.
        assert_eq!(
            p.pixel(5, 5).map(|c| (c.red(), c.green(), c.blue())),
            Some((255, 255, 255))
        );
    }
}
