//! The metrics: room segmentation (IPA), doors and connections.

use std::collections::{BTreeSet, HashMap};

use serde::Serialize;

use super::GroundTruth;
use super::door_widths::{WidthScores, door_widths, width_scores};
use crate::extract::Extraction;
use crate::imaging::{Labels, Mask, squared_distance_to_foreground};
use crate::model::{ConnectionKind, SpaceId, SpaceKind};

/// Room-segmentation scores of BENCHMARK.md §1.1 (IPA `computePrecisionRecall`).
/// IPA's "micro" is the per-room mean; "macro" the pixel-weighted ratio.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RoomScores {
    /// Mean over GT rooms of max overlap / room size.
    pub recall_micro: f64,
    /// Mean over segments of max overlap / segment size.
    pub precision_micro: f64,
    /// Σ max overlap / Σ room size.
    pub recall_macro: f64,
    /// Σ max overlap / Σ segment size.
    pub precision_macro: f64,
    /// GT rooms counted (> 100 px).
    pub gt_rooms: usize,
    /// Segments counted (> 100 px).
    pub segments: usize,
}

/// Recall and precision of a detection task.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Detection {
    /// Matched GT items / GT items (1 when there are none).
    pub recall: f64,
    /// Matched detections / detections (1 when there are none).
    pub precision: f64,
    /// Number of GT items.
    pub gt: usize,
    /// Number of detections.
    pub detected: usize,
}

/// All scores of one map.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Evaluation {
    /// Room segmentation.
    pub rooms: RoomScores,
    /// Doors.
    pub doors: Detection,
    /// Connections between rooms through doors.
    pub connections: Detection,
    /// Width errors of the doors matched to GT doorway lines.
    pub widths: WidthScores,
}

/// IPA recall/precision of `segments` (0 = none) against `gt` rooms (0 = none).
/// Segments and rooms of ≤ 100 px are ignored.
///
/// ```
/// use nrgdb::eval::room_scores;
/// use nrgdb::imaging::Labels;
/// let gt = Labels { width: 300, height: 1, data: [vec![1; 150], vec![2; 150]].concat(), count: 2 };
/// let seg = Labels { width: 300, height: 1, data: vec![1; 300], count: 1 };
/// let s = room_scores(&gt, &seg);
/// assert_eq!(s.recall_micro, 1.0);
/// assert_eq!(s.precision_micro, 0.5);
/// ```
pub fn room_scores(gt: &Labels, segments: &Labels) -> RoomScores {
    let gt_area = gt.areas();
    let seg_area = segments.areas();
    let mut overlap: HashMap<(u32, u32), usize> = HashMap::new();
    for (&s, &g) in segments.data.iter().zip(&gt.data) {
        if s != 0 && g != 0 {
            *overlap.entry((s, g)).or_insert(0) += 1;
        }
    }
    let mut best_for_seg = vec![0usize; seg_area.len()];
    let mut best_for_gt = vec![0usize; gt_area.len()];
    for (&(s, g), &n) in &overlap {
        if gt_area[g as usize] > 100 && seg_area[s as usize] > 100 {
            best_for_seg[s as usize] = best_for_seg[s as usize].max(n);
            best_for_gt[g as usize] = best_for_gt[g as usize].max(n);
        }
    }
    let ratio = |best: &[usize], area: &[usize]| {
        let (mut sum, mut k, mut num, mut den) = (0.0, 0usize, 0usize, 0usize);
        for l in 1..area.len() {
            if area[l] > 100 {
                sum += best[l] as f64 / area[l] as f64;
                k += 1;
                num += best[l];
                den += area[l];
            }
        }
        let micro = if k == 0 { 0.0 } else { sum / k as f64 };
        let macro_ = if den == 0 {
            0.0
        } else {
            num as f64 / den as f64
        };
        (micro, macro_, k)
    };
    let (recall_micro, recall_macro, gt_rooms) = ratio(&best_for_gt, &gt_area);
    let (precision_micro, precision_macro, segments) = ratio(&best_for_seg, &seg_area);
    RoomScores {
        recall_micro,
        precision_micro,
        recall_macro,
        precision_macro,
        gt_rooms,
        segments,
    }
}

/// Door recall/precision: a detected door (its pixel centroid) matches a GT
/// doorway line when it lies within `radius_px` of one of the line's pixels.
pub fn door_scores(gt: &GroundTruth, doors: &[[f64; 2]], radius_px: f64) -> Detection {
    let m = door_matches(gt, doors, radius_px);
    let hits = |v: &[bool]| v.iter().filter(|&&b| b).count();
    detection(hits(&m.lines), gt.doors.len(), hits(&m.doors), doors.len())
}

/// Which GT doorway lines and which detected doors matched (see [`door_scores`]).
#[derive(Debug, Clone, PartialEq)]
pub struct DoorMatches {
    /// Per GT doorway line: a detected door lies within the radius.
    pub lines: Vec<bool>,
    /// Per detected door: it lies within the radius of a GT line.
    pub doors: Vec<bool>,
}

/// The matches behind [`door_scores`], item by item.
pub fn door_matches(gt: &GroundTruth, doors: &[[f64; 2]], radius_px: f64) -> DoorMatches {
    let (w, h) = (gt.rooms.width, gt.rooms.height);
    let mut mask = Mask::new(w, h);
    for line in &gt.doors {
        for &p in &line.pixels {
            mask.as_mut()[p as usize] = 255;
        }
    }
    let sq = squared_distance_to_foreground(&mask);
    let r2 = radius_px * radius_px;
    let at = |c: &[f64; 2]| -> Option<usize> {
        let (x, y) = (c[0].round(), c[1].round());
        (x >= 0.0 && y >= 0.0 && x < f64::from(w) && y < f64::from(h))
            .then(|| y as usize * w as usize + x as usize)
    };
    let doors_hit = doors
        .iter()
        .map(|c| at(c).is_some_and(|i| sq[i] <= r2))
        .collect();
    let lines_hit = gt
        .doors
        .iter()
        .map(|line| {
            doors.iter().any(|c| {
                line.pixels.iter().any(|&p| {
                    let (px, py) = (f64::from(p % w), f64::from(p / w));
                    (px - c[0]).powi(2) + (py - c[1]).powi(2) <= r2
                })
            })
        })
        .collect();
    DoorMatches {
        lines: lines_hit,
        doors: doors_hit,
    }
}

fn detection(matched_gt: usize, gt: usize, matched_det: usize, detected: usize) -> Detection {
    Detection {
        recall: if gt == 0 {
            1.0
        } else {
            matched_gt as f64 / gt as f64
        },
        precision: if detected == 0 {
            1.0
        } else {
            matched_det as f64 / detected as f64
        },
        gt,
        detected,
    }
}

/// The room pairs behind [`connection_scores`].
#[derive(Debug, Clone, PartialEq)]
pub struct ConnectionPairs {
    /// GT room pairs joined by a doorway line.
    pub gt: BTreeSet<(u32, u32)>,
    /// GT room pairs joined through a detected door.
    pub detected: BTreeSet<(u32, u32)>,
    /// The GT room each extracted space overlaps most (index = label; 0 =
    /// none).
    pub best_room: Vec<u32>,
}

/// The GT room pairs joined by a doorway line and those joined through a
/// detected door, each space mapped to the GT room it overlaps most.
pub fn connection_pairs(gt: &GroundTruth, x: &Extraction) -> ConnectionPairs {
    let mut gt_pairs: BTreeSet<(u32, u32)> = BTreeSet::new();
    for line in &gt.doors {
        for (i, &a) in line.rooms.iter().enumerate() {
            for &b in &line.rooms[i + 1..] {
                gt_pairs.insert((a.min(b), a.max(b)));
            }
        }
    }
    let n = x.labels.count as usize + 1;
    let mut overlap: HashMap<(u32, u32), usize> = HashMap::new();
    for (&s, &g) in x.labels.data.iter().zip(&gt.rooms.data) {
        if s != 0 && g != 0 {
            *overlap.entry((s, g)).or_insert(0) += 1;
        }
    }
    let mut best = vec![(0usize, 0u32); n];
    for (&(s, g), &c) in &overlap {
        if (c, g) > best[s as usize] {
            best[s as usize] = (c, g);
        }
    }
    let mut det_pairs: BTreeSet<(u32, u32)> = BTreeSet::new();
    for door in x.nrg.spaces().iter().filter(|s| s.kind == SpaceKind::Door) {
        let sides: Vec<u32> = x
            .nrg
            .connections_of(door.id)
            .filter(|c| c.kind == ConnectionKind::Door)
            .filter_map(|c| c.other(door.id))
            .filter_map(|SpaceId(s)| best.get(s as usize).map(|b| b.1))
            .filter(|&g| g != 0)
            .collect();
        for (i, &a) in sides.iter().enumerate() {
            for &b in &sides[i + 1..] {
                if a != b {
                    det_pairs.insert((a.min(b), a.max(b)));
                }
            }
        }
    }
    ConnectionPairs {
        gt: gt_pairs,
        detected: det_pairs,
        best_room: best.into_iter().map(|b| b.1).collect(),
    }
}

/// Connection recall/precision: GT room pairs joined by a doorway line
/// against pairs of spaces joined through a detected door, each space mapped
/// to the GT room it overlaps most.
pub fn connection_scores(gt: &GroundTruth, x: &Extraction) -> Detection {
    let pairs = connection_pairs(gt, x);
    let hit = pairs.detected.intersection(&pairs.gt).count();
    detection(hit, pairs.gt.len(), hit, pairs.detected.len())
}

/// Per label of the extraction's label image (index = label): whether it
/// is a door space.
pub(crate) fn door_labels(x: &Extraction) -> Vec<bool> {
    (0..=x.labels.count)
        .map(|l| {
            x.nrg
                .space(SpaceId(l))
                .is_some_and(|s| s.kind == SpaceKind::Door)
        })
        .collect()
}

/// Pixel centroids (`[col, row]`) of the extraction's door spaces.
pub fn door_centroids(x: &Extraction) -> Vec<[f64; 2]> {
    x.nrg
        .spaces()
        .iter()
        .filter(|s| s.kind == SpaceKind::Door)
        .filter_map(|s| x.pixel_centroids.get(&s.id).copied())
        .collect()
}

/// The door matching radius, 0.5 m, in pixels of a map of `resolution` m/px.
pub fn door_radius_px(resolution: f64) -> f64 {
    0.5 / resolution
}

/// Every score for one extraction. `resolution` converts the 0.5 m door
/// radius to pixels and the GT doorway lines' lengths to metres.
pub fn evaluate(gt: &GroundTruth, x: &Extraction, resolution: f64) -> Evaluation {
    let mut segments = x.labels.clone();
    let is_door = door_labels(x);
    for l in &mut segments.data {
        if is_door.get(*l as usize).copied().unwrap_or(false) {
            *l = 0;
        }
    }
    Evaluation {
        rooms: room_scores(&gt.rooms, &segments),
        doors: door_scores(gt, &door_centroids(x), door_radius_px(resolution)),
        connections: connection_scores(gt, x),
        widths: width_scores(&door_widths(gt, x, resolution, door_radius_px(resolution))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::eval::DoorLine;

    #[test]
    fn ipa_micro_and_macro() {
        // GT: room 1 = 200 px, room 2 = 200 px. Segments: 1 covers room 1 and
        // half of room 2, 2 covers the other half of room 2.
        let gt = Labels {
            width: 400,
            height: 1,
            data: [vec![1; 200], vec![2; 200]].concat(),
            count: 2,
        };
        let seg = Labels {
            width: 400,
            height: 1,
            data: [vec![1; 300], vec![2; 100]].concat(),
            count: 2,
        };
        let s = room_scores(&gt, &seg);
        assert_eq!(s.recall_micro, (1.0 + 0.5) / 2.0);
        assert_eq!(s.recall_macro, 300.0 / 400.0);
        // segment 2 has 100 px: ignored (≤ 100).
        assert_eq!(s.segments, 1);
        assert!((s.precision_micro - 200.0 / 300.0).abs() < 1e-12);
    }

    #[test]
    fn door_matching_radius() {
        let rooms = Labels::new(20, 20);
        let gt = GroundTruth {
            rooms,
            doors: vec![DoorLine {
                pixels: vec![10 * 20 + 10, 11 * 20 + 10, 12 * 20 + 10],
                rooms: vec![1, 2],
            }],
        };
        let d = door_scores(&gt, &[[10.0, 14.0], [2.0, 2.0]], 2.5);
        assert_eq!(d.recall, 1.0);
        assert_eq!(d.precision, 0.5);
    }
}
