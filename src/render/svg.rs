//! The SVG back end: a [`Drawing`] written as SVG 1.1 text, no
//! dependency. Spaces carry `class="space room"` and `data-space="12"`,
//! the route `id="route"`, so a page can script the picture. The map is an
//! embedded PNG; hatching is an SVG `<pattern>`.

use std::fmt::Write as _;

use super::data_uri::grey_png_uri;
use super::drawing::{Anchor, Drawing, Hatch, Item, Rgba, Stroke, Tag};
use super::error::RenderError;
use super::layout::layout;
use super::scene::Scene;

/// Renders `scene` as an SVG document.
///
/// ```
/// use nrgdb::render::{RenderOptions, Scene, render_svg};
/// let nrg = nrgdb::fixtures::corridor_building(2);
/// let options = RenderOptions::default();
/// let svg = render_svg(&Scene { nrg: &nrg, map: None, route: None, diff: None, options: &options })?;
/// assert!(svg.starts_with("<svg") && svg.contains("class=\"space room\""));
/// # Ok::<(), nrgdb::render::RenderError>(())
/// ```
pub fn render_svg(scene: &Scene<'_>) -> Result<String, RenderError> {
    drawing_svg(&layout(scene)?)
}

/// Writes a laid-out drawing as SVG.
pub fn drawing_svg(d: &Drawing) -> Result<String, RenderError> {
    let mut s = String::new();
    // The transform as data attributes: x_min, y_max, px/m, offset (see MapTransform).
    let transform = d.transform.map_or_else(String::new, |t| {
        format!(
            " data-x-min=\"{}\" data-y-max=\"{}\" data-px-per-m=\"{}\" data-offset=\"{} {}\"",
            t.x_min, t.y_max, t.px_per_m, t.offset[0], t.offset[1]
        )
    });
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"{w}\" height=\"{h}\" \
         viewBox=\"0 0 {w} {h}\" font-family=\"DejaVu Sans Mono, monospace\"{transform}>",
        w = d.width,
        h = d.height
    );
    let hatches = distinct_hatches(d);
    if !hatches.is_empty() {
        s.push_str("<defs>\n");
        for (i, h) in hatches.iter().enumerate() {
            let _ = writeln!(
                s,
                "<pattern id=\"hatch{i}\" patternUnits=\"userSpaceOnUse\" width=\"{sp}\" height=\"{sp}\" \
                 patternTransform=\"rotate({a})\"><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"{sp}\" \
                 stroke=\"{c}\" stroke-opacity=\"{o}\" stroke-width=\"{w}\"/></pattern>",
                sp = num(h.spacing),
                a = num(90.0 - h.angle_deg),
                c = h.colour.hex(),
                o = num(h.colour.opacity()),
                w = num(h.width),
            );
        }
        s.push_str("</defs>\n");
    }
    let _ = writeln!(
        s,
        "<rect class=\"background\" width=\"100%\" height=\"100%\" fill=\"{}\"/>",
        d.background.hex()
    );
    for item in &d.items {
        item_svg(&mut s, item, &hatches)?;
    }
    s.push_str("</svg>\n");
    Ok(s)
}

fn distinct_hatches(d: &Drawing) -> Vec<Hatch> {
    let mut out: Vec<Hatch> = Vec::new();
    for item in &d.items {
        if let Item::Polygon { hatch: Some(h), .. } = item
            && !out.contains(h)
        {
            out.push(*h);
        }
    }
    out
}

fn item_svg(s: &mut String, item: &Item, hatches: &[Hatch]) -> Result<(), RenderError> {
    match item {
        Item::Raster {
            width,
            height,
            grey,
            affine,
        } => {
            let uri = grey_png_uri(*width, *height, grey)
                .map_err(|e| RenderError::Encode(e.to_string()))?;
            let m: Vec<String> = affine.iter().map(|v| num(*v)).collect();
            let _ = writeln!(
                s,
                "<image class=\"map\" width=\"{width}\" height=\"{height}\" transform=\"matrix({})\" \
                 preserveAspectRatio=\"none\" style=\"image-rendering:pixelated\" href=\"{uri}\"/>",
                m.join(" ")
            );
        }
        Item::Polygon {
            rings,
            fill,
            hatch,
            stroke,
            tag,
        } => {
            let mut d = String::new();
            for ring in rings {
                for (i, p) in ring.iter().enumerate() {
                    let _ = write!(
                        d,
                        "{}{} {}",
                        if i == 0 { "M" } else { "L" },
                        num(p[0]),
                        num(p[1])
                    );
                }
                d.push('Z');
            }
            let _ = write!(s, "<path{} d=\"{d}\" fill-rule=\"evenodd\"", attrs(tag));
            fill_attrs(s, *fill);
            stroke_attrs(s, stroke.as_ref());
            s.push_str("/>\n");
            if let Some(h) = hatch {
                let i = hatches.iter().position(|x| x == h).unwrap_or(0);
                let _ = writeln!(
                    s,
                    "<path class=\"hatch\" d=\"{d}\" fill-rule=\"evenodd\" fill=\"url(#hatch{i})\" stroke=\"none\"/>"
                );
            }
        }
        Item::Line {
            points,
            stroke,
            tag,
        } => {
            let pts: Vec<String> = points
                .iter()
                .map(|p| format!("{},{}", num(p[0]), num(p[1])))
                .collect();
            let _ = write!(
                s,
                "<polyline{} points=\"{}\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\"",
                attrs(tag),
                pts.join(" ")
            );
            stroke_attrs(s, Some(stroke));
            s.push_str("/>\n");
        }
        Item::Circle {
            centre,
            radius,
            fill,
            stroke,
            tag,
        } => {
            let _ = write!(
                s,
                "<circle{} cx=\"{}\" cy=\"{}\" r=\"{}\"",
                attrs(tag),
                num(centre[0]),
                num(centre[1]),
                num(*radius)
            );
            fill_attrs(s, *fill);
            stroke_attrs(s, stroke.as_ref());
            s.push_str("/>\n");
        }
        Item::Text {
            at,
            text,
            size,
            colour,
            anchor,
            tag,
        } => {
            let _ = writeln!(
                s,
                "<text{} x=\"{}\" y=\"{}\" font-size=\"{}\" fill=\"{}\"{} stroke=\"#ffffff\" \
                 stroke-width=\"2\" paint-order=\"stroke\">{}</text>",
                attrs(tag),
                num(at[0]),
                num(at[1]),
                num(*size),
                colour.hex(),
                match anchor {
                    Anchor::Start => "",
                    Anchor::Middle => " text-anchor=\"middle\"",
                },
                escape(text)
            );
        }
    }
    Ok(())
}

fn attrs(tag: &Tag) -> String {
    let mut a = String::new();
    if let Some(id) = &tag.id {
        let _ = write!(a, " id=\"{}\"", escape(id));
    }
    if !tag.class.is_empty() {
        let _ = write!(a, " class=\"{}\"", escape(&tag.class));
    }
    if let Some(space) = tag.space {
        let _ = write!(a, " data-space=\"{space}\"");
    }
    a
}

fn fill_attrs(s: &mut String, fill: Option<Rgba>) {
    match fill {
        Some(c) => {
            let _ = write!(s, " fill=\"{}\"", c.hex());
            if c.0[3] != 255 {
                let _ = write!(s, " fill-opacity=\"{}\"", num(c.opacity()));
            }
        }
        None => s.push_str(" fill=\"none\""),
    }
}

fn stroke_attrs(s: &mut String, stroke: Option<&Stroke>) {
    let Some(st) = stroke else {
        s.push_str(" stroke=\"none\"");
        return;
    };
    let _ = write!(
        s,
        " stroke=\"{}\" stroke-width=\"{}\"",
        st.colour.hex(),
        num(st.width)
    );
    if st.colour.0[3] != 255 {
        let _ = write!(s, " stroke-opacity=\"{}\"", num(st.colour.opacity()));
    }
    if !st.dash.is_empty() {
        let d: Vec<String> = st.dash.iter().map(|v| num(*v)).collect();
        let _ = write!(s, " stroke-dasharray=\"{}\"", d.join(" "));
    }
}

/// A number with at most two decimals, no trailing zeros.
fn num(v: f64) -> String {
    let r = (v * 100.0).round() / 100.0;
    let r = if r == 0.0 { 0.0 } else { r }; // no "-0"
    let t = format!("{r:.2}");
    t.trim_end_matches('0').trim_end_matches('.').to_string()
}

fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if c.is_control() => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Nrg, Space, SpaceId, SpaceKind};
    use crate::render::{DiffOverlay, OverlaySpace, RenderOptions, RouteOverlay};

    fn svg_of(nrg: &Nrg, route: Option<&RouteOverlay>, diff: Option<&DiffOverlay>) -> String {
        let options = RenderOptions::default();
        render_svg(&Scene {
            nrg,
            map: None,
            route,
            diff,
            options: &options,
        })
        .unwrap()
    }

    #[test]
    fn the_root_carries_the_transform_so_metres_can_be_placed() {
        let nrg = crate::fixtures::corridor_building(2);
        let options = RenderOptions {
            px_per_m: Some(25.0),
            ..RenderOptions::default()
        };
        let svg = render_svg(&Scene {
            nrg: &nrg,
            map: None,
            route: None,
            diff: None,
            options: &options,
        })
        .unwrap();
        let attr = |name: &str| {
            let rest = svg.split(&format!(" {name}=\"")).nth(1).unwrap();
            rest.split('"').next().unwrap().to_string()
        };
        assert_eq!(attr("data-px-per-m"), "25");
        assert_eq!(attr("data-x-min"), "0");
        assert_eq!(attr("data-y-max"), "7");
        // Room 10's anchor (2, 4.6) → (20 + 2·25, 20 + 2.4·25) = (70, 80): its node is there.
        assert!(svg.contains("class=\"node\" data-space=\"10\" cx=\"70\" cy=\"80\""));
    }

    #[test]
    fn numbers_are_short_and_never_negative_zero() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(2.345), "2.35");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(10.5), "10.5");
    }

    #[test]
    fn every_space_is_a_tagged_path_and_names_are_escaped() {
        let mut nrg = crate::fixtures::corridor_building(2);
        let (mut spaces, conns) = nrg.into_parts();
        spaces[1].name = Some("R&D <lab>".into());
        nrg = Nrg::new(spaces, conns).unwrap();
        let svg = svg_of(&nrg, None, None);
        assert_eq!(
            svg.matches("<path class=\"space ").count(),
            nrg.spaces().len()
        );
        assert!(svg.contains("data-space=\"10000\""));
        assert!(svg.contains("R&amp;D &lt;lab&gt;"));
        assert!(!svg.contains("<lab>"));
        assert!(svg.trim_end().ends_with("</svg>"));
        // Balanced: every opened element is closed or self-closing.
        assert_eq!(svg.matches("<text").count(), svg.matches("</text>").count());
    }

    #[test]
    fn route_and_diff_get_their_ids_classes_and_patterns() {
        let nrg = crate::fixtures::corridor_building(2);
        let route = RouteOverlay {
            waypoints: vec![[2.0, 4.6], [2.0, 2.1], [4.0, 1.0]],
            doors: vec![[2.0, 2.1]],
            length_m: 3.6,
            ..RouteOverlay::default()
        };
        let gone = Space::new(
            SpaceId(99),
            SpaceKind::Room,
            [1.0, 9.0],
            vec![[0.0, 8.0], [2.0, 8.0], [2.0, 10.0], [0.0, 10.0]],
        );
        let diff = DiffOverlay {
            removed: vec![OverlaySpace::of(&gone)],
            ..DiffOverlay::default()
        };
        let svg = svg_of(&nrg, Some(&route), Some(&diff));
        assert_eq!(svg.matches("id=\"route\"").count(), 1);
        assert!(svg.contains("class=\"diff removed\" data-space=\"99\""));
        assert!(!svg.contains(">split ("), "no split row without splits");
        let split = DiffOverlay {
            split: vec![OverlaySpace::of(&gone)],
            ..DiffOverlay::default()
        };
        let with_split = svg_of(&nrg, None, Some(&split));
        assert!(with_split.contains("class=\"diff split\" data-space=\"99\""));
        assert!(with_split.contains(">split (1)<"), "legend row");
        assert!(svg.contains("<pattern id=\"hatch0\""));
        assert!(svg.contains("fill=\"url(#hatch0)\""));
        assert!(svg.contains("route 3.6 m"));
    }
}
