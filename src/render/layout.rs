//! Layout: a [`Scene`] in metres → a [`Drawing`] in pixels. Picks the
//! scale, places the map area, the legend panel and the scale bar, and
//! turns spaces, graph, route and diff into styled items through one
//! [`MapTransform`].

use super::drawing::{Anchor, Drawing, Item, Rgba, Stroke, Tag};
use super::error::RenderError;
use super::legend::{LEGEND_WIDTH_PX, SCALE_BAR_HEIGHT_PX, legend, scale_bar};
use super::scene::{LabelMode, OverlaySpace, Scene};
use super::style::{self, Change, okabe_ito};
use super::transform::MapTransform;
use crate::model::{Point, Ring, SpaceKind, doorway};

/// Space around the map area (px).
pub const MARGIN_PX: f64 = 20.0;
/// Height of the title line (px).
const TITLE_HEIGHT_PX: f64 = 24.0;
/// Label text size (px).
pub const LABEL_SIZE_PX: f64 = 10.0;

/// Lays `scene` out as a drawing.
///
/// ```
/// use nrgdb::render::{RenderOptions, Scene, layout};
/// let nrg = nrgdb::fixtures::corridor_building(2);
/// let options = RenderOptions { px_per_m: Some(10.0), ..RenderOptions::default() };
/// let scene = Scene { nrg: &nrg, map: None, route: None, diff: None, options: &options };
/// let drawing = layout(&scene)?;
/// assert!(drawing.width > 80 && drawing.height > 70); // 8 m × 7 m at 10 px/m, plus margins
/// # Ok::<(), nrgdb::render::RenderError>(())
/// ```
pub fn layout(scene: &Scene<'_>) -> Result<Drawing, RenderError> {
    let opts = scene.options;
    let [x0, y0, x1, y1] = bounds(scene)?;
    let (span_w, span_h) = ((x1 - x0).max(1.0), (y1 - y0).max(1.0));
    let s = match opts.px_per_m {
        Some(s) => s,
        None => opts.target_px / span_w.max(span_h),
    };
    if !(s.is_finite() && s > 0.0) {
        return Err(RenderError::BadScale(s));
    }
    let top = MARGIN_PX
        + if opts.title.is_some() {
            TITLE_HEIGHT_PX
        } else {
            0.0
        };
    let (map_w, map_h) = ((span_w * s).ceil(), (span_h * s).ceil());
    let legend_w = if opts.legend { LEGEND_WIDTH_PX } else { 0.0 };
    let bar_h = if opts.legend {
        SCALE_BAR_HEIGHT_PX
    } else {
        0.0
    };
    let width = MARGIN_PX * 2.0 + map_w + legend_w;
    let legend_items = if opts.legend {
        legend(scene, [MARGIN_PX * 2.0 + map_w, top])
    } else {
        (Vec::new(), top)
    };
    let height = (top + map_h + MARGIN_PX + bar_h).max(legend_items.1 + MARGIN_PX);
    let limit = opts.max_px as f64;
    if width > limit || height > limit {
        return Err(RenderError::TooLarge {
            width: width as u64,
            height: height as u64,
            limit: opts.max_px,
            // The scale at which the map area fits beside the fixed parts.
            suggest: ((limit - 2.0 * MARGIN_PX - legend_w) / span_w)
                .min((limit - top - MARGIN_PX - bar_h) / span_h)
                .max(0.1),
        });
    }
    let t = MapTransform {
        x_min: x0,
        y_max: y1,
        px_per_m: s,
        offset: [MARGIN_PX, top],
    };
    let mut items = Vec::new();
    if let Some(map) = scene.map {
        items.push(Item::Raster {
            width: map.width,
            height: map.height,
            grey: map.cells.iter().map(|c| style::map_grey(*c)).collect(),
            affine: t.grid_affine(map),
        });
    }
    spaces(scene, &t, &mut items);
    if let Some(diff) = scene.diff {
        for (change, list) in [
            (Change::Removed, &diff.removed),
            (Change::Changed, &diff.changed),
            (Change::Merged, &diff.merged),
            (Change::Split, &diff.split),
            (Change::Added, &diff.added),
        ] {
            for o in list {
                items.push(overlay_item(o, change, &t));
            }
        }
    }
    if opts.graph {
        graph(scene, &t, &mut items);
    }
    if let Some(route) = scene.route {
        route_items(route, &t, &mut items);
    }
    labels(scene, &t, &mut items);
    if let Some(title) = &opts.title {
        items.push(Item::Text {
            at: [MARGIN_PX, MARGIN_PX + 14.0],
            text: title.clone(),
            size: 16.0,
            colour: okabe_ito::BLACK,
            anchor: Anchor::Start,
            tag: Tag::class("title"),
        });
    }
    if opts.legend {
        items.extend(legend_items.0);
        items.extend(scale_bar(s, [MARGIN_PX, top + map_h + MARGIN_PX], map_w));
    }
    Ok(Drawing {
        width: width.ceil() as u32,
        height: height.ceil() as u32,
        background: Rgba::rgb(255, 255, 255),
        items,
        transform: Some(t),
    })
}

/// `[x_min, y_min, x_max, y_max]` of everything drawn, in metres.
fn bounds(scene: &Scene<'_>) -> Result<[f64; 4], RenderError> {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    let mut add = |p: Point| {
        b = [
            b[0].min(p[0]),
            b[1].min(p[1]),
            b[2].max(p[0]),
            b[3].max(p[1]),
        ];
    };
    for space in scene.nrg.spaces() {
        if space
            .polygon
            .iter()
            .chain([&space.anchor])
            .any(|p| !(p[0].is_finite() && p[1].is_finite()))
        {
            return Err(RenderError::NotFinite(space.id));
        }
        space.polygon.iter().for_each(|p| add(*p));
        add(space.anchor);
    }
    if let Some(diff) = scene.diff {
        for o in &diff.removed {
            if o.polygon
                .iter()
                .any(|p| !(p[0].is_finite() && p[1].is_finite()))
            {
                return Err(RenderError::NotFinite(o.id));
            }
            o.polygon.iter().for_each(|p| add(*p));
        }
    }
    if let Some(map) = scene.map {
        let (w, h) = (f64::from(map.width), f64::from(map.height));
        for (c, r) in [(0.0, 0.0), (w, 0.0), (0.0, h), (w, h)] {
            add(map.pixel_to_metres(c, r));
        }
    }
    if let Some([x0, y0, x1, y1]) = scene.options.frame_m
        && [x0, y0, x1, y1].iter().all(|v| v.is_finite())
    {
        add([x0, y0]);
        add([x1, y1]);
    }
    if b[0] > b[2] || b[1] > b[3] {
        return Err(RenderError::NothingToDraw);
    }
    Ok(b)
}

fn rings(polygon: &Ring, holes: &[Ring], t: &MapTransform) -> Vec<Vec<[f64; 2]>> {
    std::iter::once(polygon)
        .chain(holes)
        .map(|r| r.iter().map(|p| t.apply(*p)).collect())
        .collect()
}

fn spaces(scene: &Scene<'_>, t: &MapTransform, items: &mut Vec<Item>) {
    for space in scene.nrg.spaces() {
        items.push(Item::Polygon {
            rings: rings(&space.polygon, &space.holes, t),
            fill: Some(style::kind_fill(space.kind)),
            hatch: None,
            stroke: Some(style::space_outline()),
            tag: Tag {
                class: format!("space {}", space.kind.as_str()),
                id: None,
                space: Some(space.id),
            },
        });
    }
    // Doorway lines over the spaces: each door's opening, jamb to jamb.
    for space in scene.nrg.spaces() {
        if let Some(d) = doorway(space) {
            items.push(Item::Line {
                points: d.line.iter().map(|p| t.apply(*p)).collect(),
                stroke: style::doorway_stroke(),
                tag: Tag {
                    class: "doorway".into(),
                    id: None,
                    space: Some(space.id),
                },
            });
        }
    }
}

fn overlay_item(o: &OverlaySpace, change: Change, t: &MapTransform) -> Item {
    Item::Polygon {
        rings: rings(&o.polygon, &o.holes, t),
        fill: None,
        hatch: Some(change.hatch()),
        stroke: Some(change.stroke()),
        tag: Tag {
            class: format!("diff {}", change.as_str()),
            id: None,
            space: Some(o.id),
        },
    }
}

fn graph(scene: &Scene<'_>, t: &MapTransform, items: &mut Vec<Item>) {
    let nrg = scene.nrg;
    for c in nrg.connections() {
        let (Some(a), Some(b)) = (nrg.space(c.a), nrg.space(c.b)) else {
            continue;
        };
        items.push(Item::Line {
            points: vec![t.apply(a.anchor), t.apply(b.anchor)],
            stroke: style::edge_stroke(c.kind),
            tag: Tag::class(format!("edge {}", c.kind.as_str())),
        });
    }
    for space in nrg.spaces() {
        let door = space.kind == SpaceKind::Door;
        items.push(Item::Circle {
            centre: t.apply(space.anchor),
            radius: if door { 2.5 } else { 3.0 },
            fill: Some(if door {
                Rgba::rgb(255, 255, 255)
            } else {
                okabe_ito::BLACK
            }),
            stroke: Some(Stroke::solid(
                if door {
                    okabe_ito::BLACK
                } else {
                    Rgba::rgb(255, 255, 255)
                },
                1.0,
            )),
            tag: Tag {
                class: "node".into(),
                id: None,
                space: Some(space.id),
            },
        });
    }
}

fn route_items(route: &super::scene::RouteOverlay, t: &MapTransform, items: &mut Vec<Item>) {
    let points: Vec<[f64; 2]> = route.waypoints.iter().map(|p| t.apply(*p)).collect();
    let (Some(first), Some(last)) = (points.first().copied(), points.last().copied()) else {
        return;
    };
    // One line a piece (the route on another level in between); the
    // first piece carries the id.
    let mut cuts: Vec<usize> = route
        .breaks
        .iter()
        .copied()
        .filter(|&b| b > 0 && b < points.len())
        .collect();
    cuts.sort_unstable();
    cuts.dedup();
    let mut start = 0;
    for end in cuts.into_iter().chain([points.len()]) {
        items.push(Item::Line {
            points: points[start..end].to_vec(),
            stroke: style::route_stroke(),
            tag: Tag {
                class: "route".into(),
                id: (start == 0).then(|| "route".into()),
                space: None,
            },
        });
        start = end;
    }
    for door in &route.doors {
        items.push(Item::Circle {
            centre: t.apply(*door),
            radius: 5.0,
            fill: Some(Rgba::rgb(255, 255, 255)),
            stroke: Some(Stroke::solid(okabe_ito::VERMILLION, 2.5)),
            tag: Tag::class("route-door"),
        });
    }
    for mark in &route.level_changes {
        let [u, v] = t.apply(mark.at);
        items.push(Item::Circle {
            centre: [u, v],
            radius: 9.0,
            fill: Some(Rgba::rgb(255, 255, 255)),
            stroke: Some(Stroke::solid(okabe_ito::BLACK, 3.0)),
            tag: Tag::class("route-level"),
        });
        // Below the mark, centred, on a white box so it reads over
        // outlines and labels.
        let (size, at) = (12.0, [u, v + 25.0]);
        let half = 0.36 * size * mark.text.chars().count() as f64 + 4.0;
        let (top, bottom) = (at[1] - size - 1.0, at[1] + 4.0);
        items.push(Item::Polygon {
            rings: vec![vec![
                [at[0] - half, top],
                [at[0] + half, top],
                [at[0] + half, bottom],
                [at[0] - half, bottom],
            ]],
            fill: Some(Rgba::rgb(255, 255, 255).with_alpha(225)),
            hatch: None,
            stroke: Some(Stroke::solid(okabe_ito::BLACK, 1.0)),
            tag: Tag::class("route-level-box"),
        });
        items.push(Item::Text {
            at,
            text: mark.text.clone(),
            size,
            colour: okabe_ito::BLACK,
            anchor: Anchor::Middle,
            tag: Tag::class("route-level-text"),
        });
    }
    for (centre, class, fill, shown) in [
        (
            first,
            "route-start",
            okabe_ito::VERMILLION,
            !route.start_elsewhere,
        ),
        (last, "route-goal", okabe_ito::BLACK, !route.goal_elsewhere),
    ] {
        if !shown {
            continue;
        }
        items.push(Item::Circle {
            centre,
            radius: 7.0,
            fill: Some(fill),
            stroke: Some(Stroke::solid(Rgba::rgb(255, 255, 255), 2.0)),
            tag: Tag::class(class),
        });
    }
}

fn labels(scene: &Scene<'_>, t: &MapTransform, items: &mut Vec<Item>) {
    for space in scene.nrg.spaces() {
        let text = match scene.options.labels {
            LabelMode::None => continue,
            LabelMode::Ids => space.id.to_string(),
            LabelMode::Names if space.kind == SpaceKind::Door => continue,
            LabelMode::Names => space.name.clone().unwrap_or_else(|| space.id.to_string()),
        };
        let [u, v] = t.apply(space.anchor);
        items.push(Item::Text {
            at: [u + 5.0, v - 4.0],
            text,
            size: LABEL_SIZE_PX,
            colour: okabe_ito::BLACK,
            anchor: Anchor::Start,
            tag: Tag {
                class: "label".into(),
                id: None,
                space: Some(space.id),
            },
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::{RenderOptions, RouteOverlay};

    fn opts(s: f64) -> RenderOptions {
        RenderOptions {
            px_per_m: Some(s),
            ..RenderOptions::default()
        }
    }

    #[test]
    fn the_map_area_is_the_model_at_the_given_scale() {
        let nrg = crate::fixtures::corridor_building(3); // 12 m × 7 m
        let o = RenderOptions {
            legend: false,
            ..opts(10.0)
        };
        let d = layout(&Scene {
            nrg: &nrg,
            map: None,
            route: None,
            diff: None,
            options: &o,
        })
        .unwrap();
        assert_eq!((d.width, d.height), (120 + 40, 70 + 40));
        // The corridor's lower-left corner (0, 0) is at the bottom-left of the map area.
        let Some(Item::Polygon { rings, .. }) = d.items.first() else {
            panic!("no polygon")
        };
        assert_eq!(rings[0][0], [20.0, 90.0]);
    }

    #[test]
    fn a_route_is_one_line_with_its_doors_marked() {
        let nrg = crate::fixtures::corridor_building(2);
        let route = RouteOverlay {
            waypoints: vec![[2.0, 4.6], [2.0, 2.1], [4.0, 1.0]],
            doors: vec![[2.0, 2.1]],
            length_m: 5.0,
            ..RouteOverlay::default()
        };
        let o = opts(10.0);
        let d = layout(&Scene {
            nrg: &nrg,
            map: None,
            route: Some(&route),
            diff: None,
            options: &o,
        })
        .unwrap();
        let lines: Vec<_> = d
            .items
            .iter()
            .filter(|i| matches!(i, Item::Line { tag, .. } if tag.id.as_deref() == Some("route")))
            .collect();
        assert_eq!(lines.len(), 1);
        let doors = d
            .items
            .iter()
            .filter(|i| matches!(i, Item::Circle { tag, .. } if tag.class == "route-door"))
            .count();
        assert_eq!(doors, 1);
    }

    #[test]
    fn empty_model_without_map_is_an_error_and_huge_scale_too() {
        let nrg = crate::model::Nrg::default();
        let o = opts(10.0);
        let err = layout(&Scene {
            nrg: &nrg,
            map: None,
            route: None,
            diff: None,
            options: &o,
        });
        assert!(matches!(err, Err(RenderError::NothingToDraw)));
        let nrg = crate::fixtures::corridor_building(3);
        let o = opts(1e5);
        let err = layout(&Scene {
            nrg: &nrg,
            map: None,
            route: None,
            diff: None,
            options: &o,
        });
        let Err(RenderError::TooLarge { suggest, .. }) = err else {
            panic!("{err:?}")
        };
        // The suggested scale fits.
        let o = opts(suggest);
        let d = layout(&Scene {
            nrg: &nrg,
            map: None,
            route: None,
            diff: None,
            options: &o,
        })
        .unwrap();
        assert!(
            d.width <= 8_192 && d.height <= 8_192,
            "{}×{}",
            d.width,
            d.height
        );
        let o = opts(-1.0);
        let err = layout(&Scene {
            nrg: &nrg,
            map: None,
            route: None,
            diff: None,
            options: &o,
        });
        assert!(matches!(err, Err(RenderError::BadScale(_))));
    }
}
