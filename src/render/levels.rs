//! A building with levels drawn one level at a time: a route's pieces on
//! a level, the doors passed there and marks where it leaves for another
//! level or arrives from one; pictures of several levels side by side
//! (a route's levels, a diff's changed levels).

use super::drawing::Drawing;
use super::error::RenderError;
use super::layout::layout;
use super::scene::{DiffOverlay, LevelMark, RenderOptions, RouteOverlay, Scene};
use crate::model::{Nrg, SpaceKind};
use crate::route::Route;

/// A route through a building drawn level by level: one panel for each
/// level it is on (lowest first), side by side, each titled with its
/// level, all in one frame (the whole building's) and at one scale, the
/// legend beside the last. A route without levels is one panel.
///
/// ```
/// use nrgdb::route::{shortest_route, Budget, NavMesh, RouteRequest};
/// use nrgdb::model::SpaceId;
/// use nrgdb::render::{route_by_level, RenderOptions};
/// let nrg = std::sync::Arc::new(nrgdb::fixtures::storeys(3, 2));
/// let nav = NavMesh::new(nrg.clone());
/// let request = RouteRequest::new(SpaceId(10), SpaceId(200_011));
/// let route = &shortest_route(&nav, &request, &Budget::unlimited())?[0];
/// let drawing = route_by_level(&nrg, route, &RenderOptions::default())?;
/// let titles = drawing.items.iter().filter(|i| matches!(i, nrgdb::render::Item::Text { tag, .. } if tag.class == "title")).count();
/// assert_eq!(titles, 3); // levels 0, 1 and 2
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn route_by_level(
    nrg: &Nrg,
    route: &Route,
    options: &RenderOptions,
) -> Result<Drawing, RenderError> {
    if route.levels.is_empty() {
        let overlay = RouteOverlay::of_route(nrg, route);
        return layout(&Scene {
            nrg,
            map: None,
            route: Some(&overlay),
            diff: None,
            options,
        });
    }
    let levels: Vec<String> = nrg
        .levels()
        .into_iter()
        .filter(|l| route.levels.iter().any(|s| s.level == l.name))
        .map(|l| l.name)
        .collect();
    beside(
        nrg,
        &levels,
        options,
        |level| nrg.level_model(level),
        |level| (RouteOverlay::on_level(nrg, route, level), None),
    )
}

/// The changes from `old` to `new` of a building drawn level by level:
/// one panel for each level in `levels` (e.g. the change set's
/// [`crate::diff::ChangeSet::changed_levels`]), lowest first, side by
/// side in the building's frame, each with that level's part of `diff`.
pub fn diff_by_level(
    old: &Nrg,
    new: &Nrg,
    diff: &DiffOverlay,
    levels: &[String],
    options: &RenderOptions,
) -> Result<Drawing, RenderError> {
    let levels: Vec<String> = new
        .levels()
        .into_iter()
        .chain(old.levels())
        .map(|l| l.name)
        .filter(|l| levels.contains(l))
        .fold(Vec::new(), |mut v, l| {
            if !v.contains(&l) {
                v.push(l);
            }
            v
        });
    // A level that is gone in `new` is drawn as `old` had it, with its
    // removed spaces.
    beside(
        new,
        &levels,
        options,
        |level| new.level_model(level).or_else(|| old.level_model(level)),
        |level| (None, Some(diff.on_level(old, new, level))),
    )
}

/// One panel for each of `levels` (the model `floor_of` gives for it),
/// side by side, in `nrg`'s frame at one scale, each titled with its
/// level and drawn with the overlays `overlays` gives for it; the legend
/// beside the last.
fn beside(
    nrg: &Nrg,
    levels: &[String],
    options: &RenderOptions,
    floor_of: impl Fn(&str) -> Option<Nrg>,
    overlays: impl Fn(&str) -> (Option<RouteOverlay>, Option<DiffOverlay>),
) -> Result<Drawing, RenderError> {
    let frame = nrg.extent();
    let floors: Vec<(&String, Nrg)> = levels
        .iter()
        .filter_map(|l| Some((l, floor_of(l)?)))
        .collect();
    let mut panels = Vec::new();
    for (k, (level, floor)) in floors.iter().enumerate() {
        let (route, diff) = overlays(level);
        let title = match &options.title {
            Some(t) => format!("{t} level {level}"),
            None => format!("level {level}"),
        };
        let panel_options = RenderOptions {
            title: Some(title),
            legend: options.legend && k + 1 == floors.len(),
            frame_m: frame,
            ..options.clone()
        };
        panels.push(layout(&Scene {
            nrg: floor,
            map: None,
            route: route.as_ref(),
            diff: diff.as_ref(),
            options: &panel_options,
        })?);
    }
    if panels.is_empty() {
        return Err(RenderError::NothingToDraw);
    }
    let (width, height) = panels.iter().fold((0u64, 0u64), |(w, h), p| {
        (w + u64::from(p.width), h.max(u64::from(p.height)))
    });
    let scale = panels
        .first()
        .and_then(|p| p.transform)
        .map_or(1.0, |t| t.px_per_m);
    Drawing::beside(panels, options.max_px).ok_or(RenderError::TooLarge {
        width,
        height,
        limit: options.max_px,
        suggest: (scale * options.max_px as f64 / width.max(height).max(1) as f64).max(0.1),
    })
}

impl RouteOverlay {
    /// The overlay of a whole route (every level, one line): what
    /// [`RouteOverlay::along`] makes of its spaces and waypoints.
    pub fn of_route(nrg: &Nrg, route: &Route) -> RouteOverlay {
        RouteOverlay::along(nrg, &route.spaces, route.waypoints.clone(), route.length_m)
    }

    /// The part of `route` on level `level` of a building: its stretches
    /// there (one piece of line each), the doors passed on that level,
    /// start and goal only when they are on it, and a mark at each end of
    /// a stretch where the route changes level ("up to level 2", "from
    /// level 0"). None when the route never is on `level`, or has no
    /// levels.
    ///
    /// ```
    /// use nrgdb::route::{shortest_route, Budget, NavMesh, RouteRequest};
    /// use nrgdb::model::SpaceId;
    /// use nrgdb::render::RouteOverlay;
    /// let nrg = std::sync::Arc::new(nrgdb::fixtures::storeys(3, 2));
    /// let nav = NavMesh::new(nrg.clone());
    /// // Room 10 on level 0 to room 200 011 on level 2.
    /// let request = RouteRequest::new(SpaceId(10), SpaceId(200_011));
    /// let route = &shortest_route(&nav, &request, &Budget::unlimited())?[0];
    /// let ground = RouteOverlay::on_level(&nrg, route, "0").unwrap();
    /// assert!(ground.goal_elsewhere && !ground.start_elsewhere);
    /// assert!(ground.level_changes[0].text.starts_with("up to level"));
    /// let top = RouteOverlay::on_level(&nrg, route, "2").unwrap();
    /// assert!(top.start_elsewhere && !top.goal_elsewhere);
    /// # Ok::<(), nrgdb::route::RouteError>(())
    /// ```
    pub fn on_level(nrg: &Nrg, route: &Route, level: &str) -> Option<RouteOverlay> {
        let spans = &route.levels;
        if !spans.iter().any(|s| s.level == level) {
            return None;
        }
        let n = route.waypoints.len();
        let end_of = |k: usize| spans.get(k + 1).map_or(n, |s| s.from_waypoint.min(n));
        let mut out = RouteOverlay {
            length_m: route.length_m,
            start_elsewhere: spans.first().is_some_and(|s| s.level != level),
            goal_elsewhere: spans.last().is_some_and(|s| s.level != level),
            ..RouteOverlay::default()
        };
        for (k, span) in spans.iter().enumerate() {
            let (from, to) = (span.from_waypoint.min(n), end_of(k));
            if span.level != level || from >= to {
                continue;
            }
            if !out.waypoints.is_empty() {
                out.breaks.push(out.waypoints.len());
            }
            out.waypoints.extend_from_slice(&route.waypoints[from..to]);
            let way = |other: &crate::route::LevelSpan| {
                if other.elevation_m > span.elevation_m {
                    "up"
                } else {
                    "down"
                }
            };
            if let Some(before) = k.checked_sub(1).and_then(|b| spans.get(b)) {
                out.level_changes.push(LevelMark {
                    at: route.waypoints[from],
                    text: format!("from level {}", before.level),
                });
            }
            if let Some(after) = spans.get(k + 1) {
                out.level_changes.push(LevelMark {
                    at: route.waypoints[to - 1],
                    text: format!("{} to level {}", way(after), after.level),
                });
            }
        }
        // Two marks at one place (a stretch of one point, passing through
        // a level on the stairs) read as one.
        let mut marks: Vec<LevelMark> = Vec::new();
        for m in out.level_changes.drain(..) {
            match marks.last_mut() {
                Some(last) if last.at == m.at => last.text = format!("{}, {}", last.text, m.text),
                _ => marks.push(m),
            }
        }
        out.level_changes = marks;
        out.doors = route
            .spaces
            .iter()
            .filter_map(|id| nrg.space(*id))
            .filter(|s| {
                s.kind == SpaceKind::Door && s.level.as_ref().is_some_and(|l| l.name == level)
            })
            .map(|s| s.anchor)
            .collect();
        Some(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::SpaceId;
    use crate::route::{Budget, NavMesh, RouteRequest, shortest_route};

    fn route(nrg: &std::sync::Arc<Nrg>, from: u32, to: u32) -> Route {
        let nav = NavMesh::new(nrg.clone());
        let request = RouteRequest::new(SpaceId(from), SpaceId(to));
        shortest_route(&nav, &request, &Budget::unlimited()).unwrap()[0].clone()
    }

    #[test]
    fn the_levels_pieces_put_together_are_the_whole_walk() {
        let nrg = std::sync::Arc::new(crate::fixtures::storeys(3, 3));
        let r = route(&nrg, 10, 200_012);
        // Two flights of stairs (28 m) beat the lift (56 m): level 1 is
        // passed on the stairs.
        let names: Vec<&str> = r.levels.iter().map(|s| s.level.as_str()).collect();
        assert_eq!(names, ["0", "1", "2"]);
        let mut joined = Vec::new();
        for level in ["0", "1", "2"] {
            let o = RouteOverlay::on_level(&nrg, &r, level).unwrap();
            assert!(o.breaks.is_empty(), "one stretch on level {level}");
            joined.extend(o.waypoints);
        }
        assert_eq!(joined, r.waypoints);
        let ground = RouteOverlay::on_level(&nrg, &r, "0").unwrap();
        let middle = RouteOverlay::on_level(&nrg, &r, "1").unwrap();
        let top = RouteOverlay::on_level(&nrg, &r, "2").unwrap();
        let texts = |o: &RouteOverlay| -> Vec<String> {
            o.level_changes.iter().map(|m| m.text.clone()).collect()
        };
        assert_eq!(texts(&ground), ["up to level 1"]);
        assert_eq!(texts(&middle), ["from level 0, up to level 2"]);
        assert_eq!(texts(&top), ["from level 1"]);
        assert_eq!(
            (ground.start_elsewhere, ground.goal_elsewhere),
            (false, true)
        );
        assert_eq!(
            (middle.start_elsewhere, middle.goal_elsewhere),
            (true, true)
        );
        assert_eq!((top.start_elsewhere, top.goal_elsewhere), (true, false));
        // Doors are drawn on their own level: the route leaves room 10
        // by its door on level 0 and enters room 200 012 by one on 2.
        assert_eq!(ground.doors.len(), 1);
        assert!(middle.doors.is_empty());
        assert_eq!(top.doors.len(), 1);
        assert!(RouteOverlay::on_level(&nrg, &r, "7").is_none());
    }

    #[test]
    fn a_level_that_is_gone_is_drawn_from_the_old_model() {
        use crate::diff::{DiffParams, diff};
        let old = crate::fixtures::storeys(3, 2);
        let new = crate::fixtures::storeys(2, 2);
        let changes = diff(&old, &new, &DiffParams::default());
        let levels = changes.changed_levels();
        assert!(levels.contains(&"2".to_string()), "{levels:?}");
        let overlay = crate::render::diff_overlay(&changes, &old, &new);
        let d = diff_by_level(&old, &new, &overlay, &levels, &RenderOptions::default()).unwrap();
        let titles: Vec<&str> = d
            .items
            .iter()
            .filter_map(|i| match i {
                crate::render::Item::Text { tag, text, .. } if tag.class == "title" => {
                    Some(text.as_str())
                }
                _ => None,
            })
            .collect();
        assert_eq!(titles.last(), Some(&"level 2"), "{titles:?}");
        let removed = d
            .items
            .iter()
            .filter(|i| matches!(i, crate::render::Item::Polygon { tag, .. } if tag.class == "diff removed"))
            .count();
        assert_eq!(removed, old.level_model("2").unwrap().spaces().len());
    }

    #[test]
    fn a_route_that_comes_back_to_a_level_is_drawn_in_pieces() {
        let nrg = std::sync::Arc::new(crate::fixtures::storeys(2, 3));
        // Room 10 to room 11 (both on level 0) through room 100 011 on
        // level 1, with the lift refused: up the stairs and down again.
        let nav = NavMesh::new(nrg.clone());
        let mut request = RouteRequest::new(SpaceId(10), SpaceId(11));
        request.via = vec![crate::route::Endpoint::Space(SpaceId(100_011))];
        request.profile.no_elevator = true;
        let r = shortest_route(&nav, &request, &Budget::unlimited()).unwrap()[0].clone();
        let ground = RouteOverlay::on_level(&nrg, &r, "0").unwrap();
        assert_eq!(ground.breaks.len(), 1, "{:?}", r.levels);
        assert!(!ground.start_elsewhere && !ground.goal_elsewhere);
        // Up and back down the same stairs: one mark says both.
        let texts: Vec<&str> = ground
            .level_changes
            .iter()
            .map(|m| m.text.as_str())
            .collect();
        assert_eq!(texts, ["up to level 1, from level 1"]);
    }
}
