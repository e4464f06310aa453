//! The door scores item by item: each GT doorway line, found or missed,
//! and each detected door, right (with its width against the line's
//! length) or wrong, in metres in the map frame, so that a reader can go
//! to the place in the map.

use serde::Serialize;

use super::door_widths::{door_widths, gt_line_length_px};
use super::ground_truth::GroundTruth;
use super::metrics::{door_centroids, door_matches, door_radius_px};
use crate::extract::Extraction;
use crate::grid::OccupancyGrid;
use crate::model::{SpaceKind, doorway};

/// One GT doorway line.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LineItem {
    /// Its index among the GT's doorway lines.
    pub line: usize,
    /// The middle of its pixels, metres in the map frame.
    pub middle: [f64; 2],
    /// Its length, metres (as the width scores measure it).
    pub length_m: f64,
    /// The GT rooms it touches.
    pub rooms: Vec<u32>,
    /// A detected door lies within the matching radius of it.
    pub found: bool,
}

/// One detected door.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DoorItem {
    /// Its space id.
    pub door: u32,
    /// The middle of its doorway line (or its centroid when it has none),
    /// metres in the map frame.
    pub middle: [f64; 2],
    /// Its reported width, metres, when it has a doorway line.
    pub width_m: Option<f64>,
    /// The nearest GT doorway line within the matching radius: its index
    /// and length (metres). None: a wrong door.
    pub matched: Option<(usize, f64)>,
}

/// Every GT doorway line and every detected door of one extraction.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DoorReport {
    /// The GT's doorway lines, in the GT's order.
    pub lines: Vec<LineItem>,
    /// The detected doors, by space id.
    pub doors: Vec<DoorItem>,
}

impl DoorReport {
    /// The lines no door was found at.
    pub fn missed(&self) -> impl Iterator<Item = &LineItem> {
        self.lines.iter().filter(|l| !l.found)
    }

    /// The doors that match no line.
    pub fn wrong(&self) -> impl Iterator<Item = &DoorItem> {
        self.doors.iter().filter(|d| d.matched.is_none())
    }

    /// The doors that match a line, each with that line's index and length
    /// (metres), largest absolute width error first (a door without a width
    /// counts as no error).
    pub fn right_worst_first(&self) -> Vec<(&DoorItem, usize, f64)> {
        let mut right: Vec<_> = self
            .doors
            .iter()
            .filter_map(|d| d.matched.map(|(line, truth)| (d, line, truth)))
            .collect();
        let error = |d: &DoorItem, truth: f64| d.width_m.map_or(0.0, |w| (w - truth).abs());
        right.sort_by(|a, b| error(b.0, b.2).total_cmp(&error(a.0, a.2)));
        right
    }
}

/// The [`DoorReport`] of `x` against `gt` on `grid` (the map both were
/// made from), under the same matching as [`super::evaluate`].
pub fn door_report(gt: &GroundTruth, x: &Extraction, grid: &OccupancyGrid) -> DoorReport {
    let radius = door_radius_px(grid.resolution);
    let found = door_matches(gt, &door_centroids(x), radius).lines;
    let w = gt.rooms.width.max(1);
    let lines = gt
        .doors
        .iter()
        .enumerate()
        .map(|(k, line)| {
            let n = line.pixels.len().max(1) as f64;
            let (sx, sy) = line.pixels.iter().fold((0.0, 0.0), |(sx, sy), &p| {
                (sx + f64::from(p % w), sy + f64::from(p / w))
            });
            LineItem {
                line: k,
                middle: grid.pixel_to_metres(sx / n + 0.5, sy / n + 0.5),
                length_m: gt_line_length_px(line, w) * grid.resolution,
                rooms: line.rooms.clone(),
                found: found.get(k).copied().unwrap_or(false),
            }
        })
        .collect();
    let matched = door_widths(gt, x, grid.resolution, radius);
    let doors = x
        .nrg
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Door)
        .filter_map(|s| {
            let c = x.pixel_centroids.get(&s.id)?;
            let line = doorway(s);
            Some(DoorItem {
                door: s.id.0,
                // Centroids are means of pixel indices: pixel centres are +0.5.
                middle: line.map_or_else(
                    || grid.pixel_to_metres(c[0] + 0.5, c[1] + 0.5),
                    |d| d.middle(),
                ),
                width_m: line.map(|d| d.width_m),
                matched: matched
                    .iter()
                    .find(|m| m.door == s.id.0)
                    .map(|m| (m.line, m.truth_m)),
            })
        })
        .collect();
    DoorReport { lines, doors }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn door(door: u32, width_m: Option<f64>, matched: Option<(usize, f64)>) -> DoorItem {
        DoorItem {
            door,
            middle: [0.0, 0.0],
            width_m,
            matched,
        }
    }

    #[test]
    fn right_doors_come_by_absolute_width_error_and_wrong_ones_stay_out() {
        let r = DoorReport {
            lines: Vec::new(),
            doors: vec![
                door(1, Some(0.9), Some((0, 1.0))), // 0.1 under
                door(2, Some(1.3), Some((1, 1.0))), // 0.3 over
                door(3, Some(0.5), None),           // wrong
                door(4, Some(0.6), Some((2, 0.8))), // 0.2 under
                door(5, None, Some((3, 0.9))),      // no width: no error
            ],
        };
        let order: Vec<u32> = r.right_worst_first().iter().map(|(d, ..)| d.door).collect();
        assert_eq!(order, [2, 4, 1, 5]);
        assert_eq!(r.wrong().map(|d| d.door).collect::<Vec<_>>(), [3]);
    }
}
