//! The room-label ground truth in the IPA format (`*_gt.png` of the shared
//! maps): a copy of the map where every true room and corridor is white
//! (255) and a black line is drawn across every doorway, so that each room
//! is its own 8-connected white component.
//!
//! Open passages between corridors get no line: evaluation reads every
//! black line across free space as a doorway (door recall, the GT's door
//! connections), and an open passage is none. Corridors joined by open
//! passages are therefore one GT room, as they are one free region of the
//! map with no doorway to split it; [`FloorPlan::truth`] still has them as
//! separate corridors joined by an Open connection.

use super::floor_plan::{FloorPlan, Segment};
use super::log_odds::GreyMap;
use crate::model::{Point, point_in_ring};

/// Grey image (row 0 at the top, same size and frame as `map`): map
/// pixels > 250 outside the true spaces become 205 (so only spaces are
/// white), pixels whose centre lies in a room, corridor or door space
/// become 255, then a line is drawn black, 2 px wide, across every door
/// (not across the open passages between corridors, see the module doc).
pub fn ground_truth_image(plan: &FloorPlan, map: &GreyMap) -> Vec<u8> {
    let mut gt: Vec<u8> = map
        .grey
        .iter()
        .map(|&g| if g > 250 { 205 } else { g })
        .collect();
    let rings = plan
        .corridors
        .iter()
        .chain(&plan.rooms)
        .chain(plan.doors.iter().map(|d| &d.polygon));
    for ring in rings {
        paint(map, &mut gt, bbox(ring), 255, |p| point_in_ring(p, ring));
    }
    let half = map.resolution_m * 1.01;
    let ext = plan.wall_thickness_m / 2.0;
    let lines: Vec<Segment> = plan
        .doors
        .iter()
        .map(|d| {
            let [f, g] = d.faces;
            let mid = |a: Point, b: Point| [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
            [mid(f[0], g[0]), mid(f[1], g[1])]
        })
        .collect();
    for s in lines {
        let Some(s) = extend(s, ext) else { continue };
        let b = bbox(&s);
        let b = [b[0] - half, b[1] - half, b[2] + half, b[3] + half];
        paint(map, &mut gt, b, 0, |p| segment_distance(p, s) <= half);
    }
    gt
}

/// Sets to `value` the pixels inside `bbox` (metres) whose centre passes `inside`.
fn paint(map: &GreyMap, img: &mut [u8], bbox: [f64; 4], value: u8, inside: impl Fn(Point) -> bool) {
    let (w, h) = (map.width as i64, map.height as i64);
    let r = map.resolution_m;
    let col = |x: f64| ((x - map.origin_m[0]) / r).floor() as i64;
    let row_up = |y: f64| ((y - map.origin_m[1]) / r).floor() as i64;
    let (c0, c1) = (col(bbox[0]).max(0), col(bbox[2]).min(w - 1));
    let (u0, u1) = (row_up(bbox[1]).max(0), row_up(bbox[3]).min(h - 1));
    for u in u0..=u1 {
        let y = map.origin_m[1] + (u as f64 + 0.5) * r;
        let top = (h - 1 - u) as usize;
        for c in c0..=c1 {
            let x = map.origin_m[0] + (c as f64 + 0.5) * r;
            if inside([x, y])
                && let Some(px) = img.get_mut(top * w as usize + c as usize)
            {
                *px = value;
            }
        }
    }
}

fn bbox(points: &[Point]) -> [f64; 4] {
    crate::model::bounds(points).unwrap_or([
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ])
}

fn extend(s: Segment, by: f64) -> Option<Segment> {
    let d = [s[1][0] - s[0][0], s[1][1] - s[0][1]];
    let len = d[0].hypot(d[1]);
    if len < 1e-9 {
        return None;
    }
    let u = [d[0] / len * by, d[1] / len * by];
    Some([
        [s[0][0] - u[0], s[0][1] - u[1]],
        [s[1][0] + u[0], s[1][1] + u[1]],
    ])
}

fn segment_distance(p: Point, s: Segment) -> f64 {
    let e = [s[1][0] - s[0][0], s[1][1] - s[0][1]];
    let l2 = e[0] * e[0] + e[1] * e[1];
    let t = if l2 > 0.0 {
        (((p[0] - s[0][0]) * e[0] + (p[1] - s[0][1]) * e[1]) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p[0] - s[0][0] - t * e[0]).hypot(p[1] - s[0][1] - t * e[1])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::FloorPlanParams;

    /// A map of `plan` that is free (254) everywhere, 0.05 m/px, 1 m border.
    fn free_map(plan: &FloorPlan) -> GreyMap {
        let b = plan.bounds();
        let r = 0.05;
        let origin_m = [b[0] - 1.0, b[1] - 1.0];
        let width = ((b[2] - b[0] + 2.0) / r).ceil() as u32;
        let height = ((b[3] - b[1] + 2.0) / r).ceil() as u32;
        GreyMap {
            width,
            height,
            resolution_m: r,
            origin_m,
            grey: vec![254; (width * height) as usize],
        }
    }

    fn pixel(map: &GreyMap, img: &[u8], p: Point) -> u8 {
        let col = ((p[0] - map.origin_m[0]) / map.resolution_m).floor() as usize;
        let up = ((p[1] - map.origin_m[1]) / map.resolution_m).floor() as usize;
        img[(map.height as usize - 1 - up) * map.width as usize + col]
    }

    #[test]
    fn doorways_are_closed_but_open_passages_are_not() {
        let mut params = FloorPlanParams::new(1);
        params.wings = (2, 2);
        let plan = FloorPlan::generate(&params).unwrap();
        assert_eq!(plan.openings.len(), 1);
        let map = free_map(&plan);
        let gt = ground_truth_image(&plan, &map);
        for d in &plan.doors {
            assert_eq!(pixel(&map, &gt, d.centre()), 0, "door at {:?}", d.centre());
        }
        // The middle of the passage between the two corridors stays white:
        // no doorway there, the corridors are one GT room.
        let [a, b] = plan.openings[0].segment;
        let mid = [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
        assert_eq!(pixel(&map, &gt, mid), 255);
    }

    #[test]
    fn distance_to_segment_clamps_to_ends() {
        let s = [[0.0, 0.0], [2.0, 0.0]];
        assert_eq!(segment_distance([1.0, 0.5], s), 0.5);
        assert_eq!(segment_distance([3.0, 0.0], s), 1.0);
    }
}
