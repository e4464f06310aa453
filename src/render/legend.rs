//! The legend panel (kinds, connection kinds, route, changes: only what
//! the picture shows) and the scale bar in metres.

use super::drawing::{Anchor, Item, Rgba, Stroke, Tag};
use super::scene::Scene;
use super::style::{self, Change, okabe_ito};
use crate::model::{ConnectionKind, SpaceKind};

/// Width of the legend panel (px).
pub const LEGEND_WIDTH_PX: f64 = 170.0;
/// Height of the scale bar strip below the map (px).
pub const SCALE_BAR_HEIGHT_PX: f64 = 30.0;
const ROW_PX: f64 = 18.0;
const TEXT_PX: f64 = 10.0;

/// The legend's items, top-left at `at`, and the y where it ends.
pub fn legend(scene: &Scene<'_>, at: [f64; 2]) -> (Vec<Item>, f64) {
    let mut items = Vec::new();
    let [x, mut y] = at;
    let text = |items: &mut Vec<Item>, y: f64, s: String| {
        items.push(Item::Text {
            at: [x + 26.0, y + 9.0],
            text: s,
            size: TEXT_PX,
            colour: okabe_ito::BLACK,
            anchor: Anchor::Start,
            tag: Tag::class("legend-text"),
        });
    };
    let swatch = |y: f64| vec![[x, y], [x + 18.0, y], [x + 18.0, y + 10.0], [x, y + 10.0]];
    let nrg = scene.nrg;
    for kind in SpaceKind::ALL {
        if !nrg.spaces().iter().any(|s| s.kind == kind) {
            continue;
        }
        items.push(Item::Polygon {
            rings: vec![swatch(y)],
            fill: Some(style::kind_fill(kind)),
            hatch: None,
            stroke: Some(style::space_outline()),
            tag: Tag::class("legend"),
        });
        text(&mut items, y, kind.as_str().to_string());
        y += ROW_PX;
    }
    if nrg.spaces().iter().any(|s| s.kind == SpaceKind::Door) {
        items.push(Item::Line {
            points: vec![[x, y + 5.0], [x + 18.0, y + 5.0]],
            stroke: style::doorway_stroke(),
            tag: Tag::class("legend"),
        });
        text(&mut items, y, "doorway".to_string());
        y += ROW_PX;
    }
    if scene.options.graph {
        for (kind, what) in [
            (ConnectionKind::Door, "through a door"),
            (ConnectionKind::Open, "open passage"),
            (ConnectionKind::Adjacent, "adjacent (wall)"),
        ] {
            if !nrg.connections().iter().any(|c| c.kind == kind) {
                continue;
            }
            items.push(Item::Line {
                points: vec![[x, y + 5.0], [x + 18.0, y + 5.0]],
                stroke: style::edge_stroke(kind),
                tag: Tag::class("legend"),
            });
            text(&mut items, y, what.to_string());
            y += ROW_PX;
        }
    }
    if let Some(route) = scene.route {
        items.push(Item::Line {
            points: vec![[x, y + 5.0], [x + 18.0, y + 5.0]],
            stroke: style::route_stroke(),
            tag: Tag::class("legend"),
        });
        text(&mut items, y, format!("route {:.1} m", route.length_m));
        y += ROW_PX;
        items.push(Item::Circle {
            centre: [x + 9.0, y + 5.0],
            radius: 5.0,
            fill: Some(Rgba::rgb(255, 255, 255)),
            stroke: Some(Stroke::solid(okabe_ito::VERMILLION, 2.5)),
            tag: Tag::class("legend"),
        });
        text(
            &mut items,
            y,
            format!("door on route ({})", route.doors.len()),
        );
        y += ROW_PX;
    }
    if let Some(diff) = scene.diff {
        // Split and merged get a row only when there are any.
        let rows = [
            (Change::Added, diff.added.len()),
            (Change::Removed, diff.removed.len()),
            (Change::Changed, diff.changed.len()),
            (Change::Split, diff.split.len()),
            (Change::Merged, diff.merged.len()),
        ];
        for (change, n) in rows
            .into_iter()
            .filter(|&(c, n)| n > 0 || !matches!(c, Change::Split | Change::Merged))
        {
            items.push(Item::Polygon {
                rings: vec![swatch(y)],
                fill: None,
                hatch: Some(change.hatch()),
                stroke: Some(change.stroke()),
                tag: Tag::class("legend"),
            });
            text(&mut items, y, format!("{} ({n})", change.as_str()));
            y += ROW_PX;
        }
    }
    (items, y)
}

/// The longest "nice" length (1, 2 or 5 × 10ⁿ m) at most `max_px` long at
/// `px_per_m`.
///
/// ```
/// assert_eq!(nrgdb::render::nice_length_m(10.0, 120.0), 10.0);
/// assert_eq!(nrgdb::render::nice_length_m(10.0, 49.0), 2.0);
/// ```
pub fn nice_length_m(px_per_m: f64, max_px: f64) -> f64 {
    let max_m = (max_px / px_per_m).max(1e-9);
    let p = 10f64.powf(max_m.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|k| k * p)
        .find(|l| *l <= max_m)
        .unwrap_or(p)
}

/// A scale bar (two black/white halves and its length in metres) at `at`,
/// at most a third of `map_w_px` long (and at least 40 px when it fits).
pub fn scale_bar(px_per_m: f64, at: [f64; 2], map_w_px: f64) -> Vec<Item> {
    let len_m = nice_length_m(px_per_m, (map_w_px / 3.0).max(40.0));
    let len_px = len_m * px_per_m;
    let [x, y] = at;
    let half = |x0: f64, x1: f64, fill: Rgba| Item::Polygon {
        rings: vec![vec![[x0, y], [x1, y], [x1, y + 6.0], [x0, y + 6.0]]],
        fill: Some(fill),
        hatch: None,
        stroke: Some(Stroke::solid(okabe_ito::BLACK, 1.0)),
        tag: Tag::class("scale-bar"),
    };
    let label = if len_m >= 1.0 {
        format!("{len_m} m")
    } else {
        format!("{} cm", (len_m * 100.0).round())
    };
    vec![
        half(x, x + len_px / 2.0, okabe_ito::BLACK),
        half(x + len_px / 2.0, x + len_px, Rgba::rgb(255, 255, 255)),
        Item::Text {
            at: [x + len_px + 6.0, y + 8.0],
            text: label,
            size: TEXT_PX,
            colour: okabe_ito::BLACK,
            anchor: Anchor::Start,
            tag: Tag::class("scale-bar"),
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_lengths_are_one_two_five() {
        assert_eq!(nice_length_m(1.0, 7.0), 5.0);
        assert_eq!(nice_length_m(100.0, 30.0), 0.2);
        assert_eq!(nice_length_m(0.5, 600.0), 1000.0);
    }

    #[test]
    fn the_scale_bar_says_its_length() {
        let items = scale_bar(20.0, [0.0, 0.0], 300.0);
        let Some(Item::Text { text, .. }) = items.last() else {
            panic!("no text")
        };
        assert_eq!(text, "5 m"); // 100 px at most → 5 m = 100 px
    }
}
