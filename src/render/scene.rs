//! What a picture shows: a model, an optional occupancy map behind it, an
//! optional route and diff on top, and how to draw it. Plain data; the
//! back ends ([`super::svg`], `png`) draw it through [`super::layout`].

use crate::grid::OccupancyGrid;
use crate::model::{Nrg, Point, Ring, SpaceId, SpaceKind};

/// How spaces are labelled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LabelMode {
    /// The name when the space has one, else the id; doors unlabelled.
    #[default]
    Names,
    /// Every space by its id, doors included.
    Ids,
    /// No labels.
    None,
}

impl std::str::FromStr for LabelMode {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s {
            "names" => Ok(LabelMode::Names),
            "ids" => Ok(LabelMode::Ids),
            "none" => Ok(LabelMode::None),
            _ => Err(format!(
                "unknown label mode '{s}' (expected names, ids or none)"
            )),
        }
    }
}

/// Drawing options.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    /// Pixels per metre; `None` picks one so the longer side is about
    /// [`RenderOptions::target_px`].
    pub px_per_m: Option<f64>,
    /// Longer side of the map area when the scale is picked (px).
    pub target_px: f64,
    /// Largest picture side allowed (px).
    pub max_px: u64,
    /// How spaces are labelled.
    pub labels: LabelMode,
    /// Draw the legend and the scale bar.
    pub legend: bool,
    /// Draw the graph (nodes at anchors, edges by connection kind).
    pub graph: bool,
    /// A title above the picture (e.g. the map name and revision).
    pub title: Option<String>,
    /// An area (metres: x min, y min, x max, y max) the picture covers
    /// at least, so pictures of a building's levels share one frame.
    pub frame_m: Option<[f64; 4]>,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            px_per_m: None,
            target_px: 1200.0,
            max_px: 8_192,
            labels: LabelMode::Names,
            legend: true,
            graph: true,
            title: None,
            frame_m: None,
        }
    }
}

/// A route to draw: waypoints as a thick line, doors marked; on one level
/// of a building, the route's parts on that level and where it changes
/// level (see [`RouteOverlay::on_level`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RouteOverlay {
    /// Waypoints in metres, start first.
    pub waypoints: Vec<Point>,
    /// Anchors of the doors passed, in metres.
    pub doors: Vec<Point>,
    /// The route's length in metres (shown in the legend).
    pub length_m: f64,
    /// Indices into `waypoints` where a new piece of line starts (the
    /// route is on another level in between); empty for one line.
    pub breaks: Vec<usize>,
    /// The route starts on another level: no start marker here.
    pub start_elsewhere: bool,
    /// The route ends on another level: no goal marker here.
    pub goal_elsewhere: bool,
    /// Where the route leaves or reaches this level, and what to say there.
    pub level_changes: Vec<LevelMark>,
}

/// A place where a drawn route changes level.
#[derive(Debug, Clone, PartialEq)]
pub struct LevelMark {
    /// Where, metres.
    pub at: Point,
    /// What to say, e.g. `up to level 2` or `from level 0`.
    pub text: String,
}

impl RouteOverlay {
    /// The overlay of a walked route: its polyline, and the door spaces
    /// among the spaces it passes marked at their anchors; unknown ids are
    /// skipped.
    ///
    /// ```
    /// use nrgdb::model::SpaceId;
    /// let nrg = nrgdb::fixtures::corridor_building(2);
    /// let line = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]];
    /// let r = nrgdb::render::RouteOverlay::along(&nrg, &[SpaceId(10), SpaceId(10_000), SpaceId(1)], line, 3.0);
    /// assert_eq!((r.waypoints.len(), r.doors.len()), (3, 1));
    /// ```
    pub fn along(nrg: &Nrg, path: &[SpaceId], polyline: Vec<Point>, length_m: f64) -> RouteOverlay {
        let spaces: Vec<&crate::model::Space> =
            path.iter().filter_map(|id| nrg.space(*id)).collect();
        RouteOverlay {
            waypoints: polyline,
            doors: spaces
                .iter()
                .filter(|s| s.kind == SpaceKind::Door)
                .map(|s| s.anchor)
                .collect(),
            length_m,
            ..RouteOverlay::default()
        }
    }
}

/// One space of a diff overlay: its outline and where to put its label.
#[derive(Debug, Clone, PartialEq)]
pub struct OverlaySpace {
    /// The space's id (in the revision it comes from).
    pub id: SpaceId,
    /// Its kind.
    pub kind: SpaceKind,
    /// Exterior ring, metres.
    pub polygon: Ring,
    /// Holes, metres.
    pub holes: Vec<Ring>,
}

impl OverlaySpace {
    /// The overlay form of a space.
    pub fn of(space: &crate::model::Space) -> OverlaySpace {
        OverlaySpace {
            id: space.id,
            kind: space.kind,
            polygon: space.polygon.clone(),
            holes: space.holes.clone(),
        }
    }
}

/// The spaces that changed between two revisions: added (only in the new),
/// removed (only in the old, drawn with their old outline), changed
/// (geometry, kind or name; drawn with their new outline), and the parts
/// of split spaces and the results of merges (new outlines).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DiffOverlay {
    /// Spaces only in the new revision.
    pub added: Vec<OverlaySpace>,
    /// Spaces only in the old revision.
    pub removed: Vec<OverlaySpace>,
    /// Spaces in both, changed.
    pub changed: Vec<OverlaySpace>,
    /// The parts an old space was split into.
    pub split: Vec<OverlaySpace>,
    /// The spaces several old spaces were merged into.
    pub merged: Vec<OverlaySpace>,
}

impl DiffOverlay {
    /// Whether nothing changed.
    pub fn is_empty(&self) -> bool {
        self.added.is_empty()
            && self.removed.is_empty()
            && self.changed.is_empty()
            && self.split.is_empty()
            && self.merged.is_empty()
    }
}

/// Everything one picture shows.
#[derive(Debug, Clone, Copy)]
pub struct Scene<'a> {
    /// The model drawn.
    pub nrg: &'a Nrg,
    /// The occupancy map behind it.
    pub map: Option<&'a OccupancyGrid>,
    /// A route on top.
    pub route: Option<&'a RouteOverlay>,
    /// A diff on top.
    pub diff: Option<&'a DiffOverlay>,
    /// How to draw.
    pub options: &'a RenderOptions,
}
