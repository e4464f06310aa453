//! The floor-plan generator: corridor wings that turn left off each other,
//! rooms packed along both sides of each corridor (rejected when they would
//! come closer than a wall's thickness to anything), doors, second doors,
//! furniture boxes and the robot's route. A house is one such wing, its
//! corridor a living area furnished by `house.rs`.

use std::f64::consts::FRAC_PI_2;

use super::SimError;
use super::floor_plan::{Door, FloorPlan, FloorPlanParams, Opening, SpaceRef};
use super::prng::SplitMix64;
use super::separation::separation_gap;
use crate::model::{Point, Ring};

/// The narrowest opening in place of a door
/// ([`FloorPlanParams::opening_probability`]).
const OPENING_MIN_M: f64 = 2.0;
/// The widest opening in place of a door.
const OPENING_MAX_M: f64 = 3.2;

/// A rigid local frame: `x` along the corridor, `y` to its left.
#[derive(Debug, Clone, Copy)]
pub(super) struct Frame {
    o: Point,
    d: Point,
}

impl Frame {
    fn new(o: Point, angle: f64) -> Frame {
        Frame {
            o,
            d: [angle.cos(), angle.sin()],
        }
    }
    pub(super) fn at(&self, x: f64, y: f64) -> Point {
        let n = [-self.d[1], self.d[0]];
        [
            self.o[0] + x * self.d[0] + y * n[0],
            self.o[1] + x * self.d[1] + y * n[1],
        ]
    }
    pub(super) fn rect(&self, x0: f64, y0: f64, x1: f64, y1: f64) -> Ring {
        vec![
            self.at(x0, y0),
            self.at(x1, y0),
            self.at(x1, y1),
            self.at(x0, y1),
        ]
    }
    fn angle(&self) -> f64 {
        self.d[1].atan2(self.d[0])
    }
}

/// A corridor wing: the corridor occupies local `x in [0, len]`, `y in [-w, 0]`.
pub(super) struct Wing {
    pub(super) frame: Frame,
    pub(super) len: f64,
}

/// A placed room in its wing's frame, for furniture and the route.
pub(super) struct Slot {
    pub(super) wing: usize,
    pub(super) x0: f64,
    pub(super) x1: f64,
    pub(super) y0: f64,
    pub(super) y1: f64,
    /// Whether the back wall (away from the corridor) is at `y1`.
    pub(super) back_is_high: bool,
}

/// Builds the plan (parameters already validated).
impl FloorPlan {
    /// Generates a plan from `params` (deterministic in `params.seed`).
    ///
    /// ```
    /// use nrgdb::sim::{FloorPlan, FloorPlanParams};
    /// let plan = FloorPlan::generate(&FloorPlanParams::new(3))?;
    /// assert!(!plan.rooms.is_empty());
    /// assert_eq!(plan, FloorPlan::generate(&FloorPlanParams::new(3))?);
    /// # Ok::<(), nrgdb::sim::SimError>(())
    /// ```
    pub fn generate(params: &FloorPlanParams) -> Result<FloorPlan, SimError> {
        params.validate()?;
        Ok(layout(params))
    }
}

fn layout(p: &FloorPlanParams) -> FloorPlan {
    let mut rng = SplitMix64::new(p.seed);
    let t = p.wall_thickness_m;
    let w = rng.range(p.corridor_width_m.0, p.corridor_width_m.1);
    let mut n_wings = rng.int(p.wings.0, p.wings.1);
    if p.house {
        n_wings = 1;
    } else if p.non_manhattan {
        n_wings = n_wings.max(2);
    }
    let mut plan = FloorPlan {
        corridors: Vec::new(),
        rooms: Vec::new(),
        doors: Vec::new(),
        openings: Vec::new(),
        furniture: Vec::new(),
        route: Vec::new(),
        wall_thickness_m: t,
        open_plan: p.house,
    };
    let len0 = rng.range(p.corridor_length_m.0, p.corridor_length_m.1);
    let first = Frame::new([0.0, 0.0], p.heading_deg.to_radians());
    let mut wings = vec![Wing {
        frame: first,
        len: len0,
    }];
    plan.corridors.push(first.rect(0.0, -w, len0, 0.0));
    for k in 1..n_wings {
        let prev = &wings[k - 1];
        let turn = if p.non_manhattan && (k == 1 || rng.chance(0.5)) {
            rng.range(25f64.to_radians(), 65f64.to_radians())
        } else {
            FRAC_PI_2
        };
        let frame = Frame::new(prev.frame.at(prev.len, 0.0), prev.frame.angle() + turn);
        let b = prev.frame.at(prev.len, -w);
        let e = intersect(b, prev.frame.d, frame.at(0.0, -w), frame.d);
        let mut len = rng.range(p.corridor_length_m.0, p.corridor_length_m.1);
        let mut placed = None;
        while len >= 6.0 {
            let poly = vec![b, e, frame.at(len, -w), frame.at(len, 0.0), frame.o];
            let clear = plan.corridors[..k - 1]
                .iter()
                .all(|c| separation_gap(c, &poly) >= 2.0 * t);
            if clear {
                placed = Some(poly);
                break;
            }
            len *= 0.7;
        }
        let Some(poly) = placed else { break };
        plan.openings.push(Opening {
            a: k - 1,
            b: k,
            segment: [b, frame.o],
        });
        plan.corridors.push(poly);
        wings.push(Wing { frame, len });
    }
    let mut slots = Vec::new();
    let mut wing_doors: Vec<Vec<(f64, usize)>> = vec![Vec::new(); wings.len()];
    for (k, wing) in wings.iter().enumerate() {
        for left in [true, false] {
            let depth = rng.range(p.room_depth_m.0, p.room_depth_m.1);
            let (y0, y1) = if left {
                (t, t + depth)
            } else {
                (-w - t - depth, -w - t)
            };
            let mut x = rng.range(0.0, 1.0);
            let mut prev: Option<(usize, f64)> = None;
            while x + p.room_width_m.0 <= wing.len {
                let mut rw = rng.range(p.room_width_m.0, p.room_width_m.1);
                if x + rw > wing.len {
                    rw = wing.len - x;
                }
                let poly = wing.frame.rect(x, y0, x + rw, y1);
                let fits = plan
                    .corridors
                    .iter()
                    .chain(&plan.rooms)
                    .all(|other| separation_gap(other, &poly) >= t - 1e-6);
                if !fits {
                    x += 1.0;
                    prev = None;
                    continue;
                }
                let room = plan.rooms.len();
                plan.rooms.push(poly);
                slots.push(Slot {
                    wing: k,
                    x0: x,
                    x1: x + rw,
                    y0,
                    y1,
                    back_is_high: left,
                });
                let (fy0, fy1) = if left { (0.0, t) } else { (-w - t, -w) };
                let second = rng.chance(p.second_door_probability);
                let two_front = second && rw / 2.0 - 0.75 >= p.door_width_m.0 && rng.chance(0.5);
                let halves: &[(f64, f64)] = if two_front {
                    &[(x, x + rw / 2.0 - 0.15), (x + rw / 2.0 + 0.15, x + rw)]
                } else {
                    &[(x, x + rw)]
                };
                // An alcove open to the corridor along most of its width
                // (asked for only when it may be, so that office floors
                // draw the same numbers as before).
                let open_front = !two_front
                    && p.opening_probability > 0.0
                    && rw - 0.6 >= OPENING_MIN_M
                    && rng.chance(p.opening_probability);
                for &(lo, hi) in halves {
                    let widths = if open_front {
                        (OPENING_MIN_M, OPENING_MAX_M)
                    } else {
                        p.door_width_m
                    };
                    let dw = rng.range(widths.0, widths.1).min(hi - lo - 0.6);
                    let dx = rng.range(lo + 0.3 + dw / 2.0, hi - 0.3 - dw / 2.0);
                    let (a, b) = (dx - dw / 2.0, dx + dw / 2.0);
                    let corridor_face = if left { fy0 } else { fy1 };
                    let room_face = if left { fy1 } else { fy0 };
                    wing_doors[k].push((dx, plan.doors.len()));
                    plan.doors.push(Door {
                        polygon: wing.frame.rect(a, fy0, b, fy1),
                        a: SpaceRef::Room(room),
                        b: SpaceRef::Corridor(k),
                        width_m: dw,
                        faces: [
                            [wing.frame.at(a, room_face), wing.frame.at(b, room_face)],
                            [
                                wing.frame.at(a, corridor_face),
                                wing.frame.at(b, corridor_face),
                            ],
                        ],
                    });
                }
                if let Some((prev_room, prev_end)) = prev
                    && second
                    && !two_front
                    && ((x - t) - prev_end).abs() < 1e-9
                {
                    let dw = rng
                        .range(p.door_width_m.0, p.door_width_m.1)
                        .min(depth - 0.6);
                    let dy = rng.range(y0 + 0.3 + dw / 2.0, y1 - 0.3 - dw / 2.0);
                    let (a, b) = (dy - dw / 2.0, dy + dw / 2.0);
                    plan.doors.push(Door {
                        polygon: wing.frame.rect(prev_end, a, x, b),
                        a: SpaceRef::Room(prev_room),
                        b: SpaceRef::Room(room),
                        width_m: dw,
                        faces: [
                            [wing.frame.at(prev_end, a), wing.frame.at(prev_end, b)],
                            [wing.frame.at(x, a), wing.frame.at(x, b)],
                        ],
                    });
                }
                prev = Some((room, x + rw));
                x += rw + t;
            }
        }
    }
    if p.furniture {
        furnish(&mut plan, &wings, &slots, &mut rng);
    }
    let detours = if p.clutter {
        super::clutter::clutter(&mut plan, &wings, &slots, &mut rng)
    } else {
        Vec::new()
    };
    // A house's living area: the robot drives its middle line between the
    // sofa and the counter.
    let span = if p.house {
        Some(super::house::furnish_living(
            &mut plan,
            &wings[0],
            w,
            &wing_doors[0],
            &mut rng,
        ))
    } else {
        None
    };
    plan.route = route(&plan, &wings, &mut wing_doors, w, &detours, span);
    plan
}

/// Puts 1-3 boxes into the back half of most rooms, 0.8 m clear of doors.
fn furnish(plan: &mut FloorPlan, wings: &[Wing], slots: &[Slot], rng: &mut SplitMix64) {
    for (i, s) in slots.iter().enumerate() {
        if !rng.chance(0.7) {
            continue;
        }
        let frame = wings[s.wing].frame;
        let doors: Vec<&Ring> = plan
            .doors
            .iter()
            .filter(|d| d.a == SpaceRef::Room(i) || d.b == SpaceRef::Room(i))
            .map(|d| &d.polygon)
            .collect();
        let mut boxes: Vec<Ring> = Vec::new();
        for _ in 0..rng.int(1, 3) {
            for _try in 0..10 {
                let bw = rng.range(0.4, 1.2);
                let bh = rng.range(0.4, 1.2).min((s.y1 - s.y0) / 2.0 - 0.5);
                if bh < 0.3 || s.x1 - s.x0 < bw + 0.3 {
                    break;
                }
                let bx = rng.range(s.x0 + 0.15, s.x1 - 0.15 - bw);
                let room_for = (s.y1 - s.y0) / 2.0 - 0.45 - bh;
                let v = rng.range(0.0, room_for);
                let (by0, by1) = if s.back_is_high {
                    (s.y1 - 0.15 - bh - v, s.y1 - 0.15 - v)
                } else {
                    (s.y0 + 0.15 + v, s.y0 + 0.15 + v + bh)
                };
                let b = frame.rect(bx, by0, bx + bw, by1);
                let clear = doors.iter().all(|d| separation_gap(d, &b) >= 0.8)
                    && boxes.iter().all(|o| separation_gap(o, &b) >= 0.3);
                if clear {
                    boxes.push(b);
                    break;
                }
            }
        }
        plan.furniture.extend(boxes);
    }
}

/// The route: along each corridor's centre line, with a detour through
/// every corridor door to its room's centre and back; from the centre of
/// room `r` also through `detours[r]` (the aisles of its shelves) and back.
/// With `span`, the only wing's middle line runs from `span.0` to `span.1`
/// (a house's living area, clear of its furniture).
fn route(
    plan: &FloorPlan,
    wings: &[Wing],
    wing_doors: &mut [Vec<(f64, usize)>],
    w: f64,
    detours: &[Vec<Point>],
    span: Option<(f64, f64)>,
) -> Vec<Point> {
    let mut pts = Vec::new();
    let last = wings.len().saturating_sub(1);
    for (k, wing) in wings.iter().enumerate() {
        let start = match span {
            Some((start, _)) => start,
            None if k == 0 => 0.4,
            None => 0.0,
        };
        let end = match span {
            Some((_, end)) => end,
            None if k == last => wing.len - 0.4,
            None => wing.len,
        };
        pts.push(wing.frame.at(start, -w / 2.0));
        wing_doors[k].sort_by(|a, b| a.0.total_cmp(&b.0));
        for &(dx, di) in &wing_doors[k] {
            let Some(door) = plan.doors.get(di) else {
                continue;
            };
            let SpaceRef::Room(r) = door.a else { continue };
            let Some(room) = plan.rooms.get(r) else {
                continue;
            };
            let centre = crate::model::polygon_centroid(room).unwrap_or(room[0]);
            let c = wing
                .frame
                .at(dx.clamp(start, span.map_or(wing.len, |s| s.1)), -w / 2.0);
            pts.extend([c, door.centre(), centre]);
            if let Some(detour) = detours.get(r).filter(|d| !d.is_empty()) {
                pts.extend(detour.iter().copied());
                pts.push(centre);
            }
            pts.extend([door.centre(), c]);
        }
        pts.push(wing.frame.at(end, -w / 2.0));
    }
    pts
}

/// Intersection of the lines `p + s u` and `q + r v` (p if parallel).
fn intersect(p: Point, u: Point, q: Point, v: Point) -> Point {
    let den = u[0] * v[1] - u[1] * v[0];
    if den.abs() < 1e-12 {
        return p;
    }
    let s = ((q[0] - p[0]) * v[1] - (q[1] - p[1]) * v[0]) / den;
    [p[0] + s * u[0], p[1] + s * u[1]]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{point_in_ring, ring_is_ccw};

    fn all_params() -> Vec<FloorPlanParams> {
        let mut v = Vec::new();
        for seed in 0..40 {
            let mut p = FloorPlanParams::new(seed);
            p.furniture = seed % 2 == 0;
            p.non_manhattan = seed % 3 == 0;
            v.push(p);
        }
        // Houses, some with openings in place of doors.
        v.extend((0..20).map(FloorPlanParams::house));
        v
    }

    #[test]
    fn a_heading_turns_the_same_building_about_the_first_corridors_start() {
        // Every point of the turned plan is the unturned plan's point turned
        // by the heading about the origin (where the first corridor starts).
        for seed in [1, 7, 12] {
            let mut p = FloorPlanParams::new(seed);
            p.furniture = true;
            p.clutter = seed == 7;
            let square = layout(&p);
            p.heading_deg = 33.0;
            let turned = layout(&p);
            let (s, c) = 33f64.to_radians().sin_cos();
            let turn = |q: &Point| [q[0] * c - q[1] * s, q[0] * s + q[1] * c];
            let points = |f: &FloorPlan| -> Vec<Point> {
                let rings = f.corridors.iter().chain(&f.rooms).chain(&f.furniture);
                let doors = f
                    .doors
                    .iter()
                    .flat_map(|d| d.polygon.iter().chain(d.faces.iter().flatten()));
                rings
                    .flatten()
                    .chain(doors)
                    .chain(&f.route)
                    .copied()
                    .collect()
            };
            let (a, b) = (points(&square), points(&turned));
            assert_eq!(a.len(), b.len(), "seed {seed}");
            for (q, t) in a.iter().zip(&b) {
                let want = turn(q);
                assert!(
                    (want[0] - t[0]).abs() < 1e-9 && (want[1] - t[1]).abs() < 1e-9,
                    "seed {seed}: {q:?} turned is {want:?}, got {t:?}"
                );
            }
        }
    }

    #[test]
    fn spaces_never_overlap_and_keep_a_wall_apart() {
        for p in all_params() {
            let plan = layout(&p);
            let all: Vec<&Ring> = plan.corridors.iter().chain(&plan.rooms).collect();
            for (i, a) in all.iter().enumerate() {
                assert!(ring_is_ccw(a), "seed {}", p.seed);
                for b in &all[i + 1..] {
                    let g = separation_gap(a, b);
                    assert!(g > -1e-9, "seed {}: spaces overlap ({g})", p.seed);
                }
            }
        }
    }

    #[test]
    fn doors_have_the_asked_width_and_furniture_stays_in_rooms() {
        for p in all_params() {
            let plan = layout(&p);
            let within = |w: f64, (lo, hi): (f64, f64)| (lo - 1e-9..=hi + 1e-9).contains(&w);
            for d in &plan.doors {
                let opening = p.opening_probability > 0.0
                    && within(d.width_m, (OPENING_MIN_M, OPENING_MAX_M));
                assert!(
                    within(d.width_m, p.door_width_m) || opening,
                    "{}",
                    d.width_m
                );
            }
            // Furniture stands in rooms, and in a house's living area.
            let spaces = if p.house {
                plan.rooms.iter().chain(&plan.corridors).collect::<Vec<_>>()
            } else {
                plan.rooms.iter().collect()
            };
            for b in &plan.furniture {
                let c = crate::model::polygon_centroid(b).unwrap();
                assert!(spaces.iter().any(|r| point_in_ring(c, r)));
            }
        }
    }

    #[test]
    fn some_plans_have_two_door_rooms_and_diagonal_wings() {
        let mut two_doors = 0;
        let mut diagonal = 0;
        for p in all_params() {
            let plan = layout(&p);
            let mut count = vec![0; plan.rooms.len()];
            for d in &plan.doors {
                for s in [d.a, d.b] {
                    if let SpaceRef::Room(r) = s {
                        count[r] += 1;
                    }
                }
            }
            two_doors += count.iter().filter(|&&c| c >= 2).count();
            for c in &plan.corridors {
                for i in 0..c.len() {
                    let (a, b) = (c[i], c[(i + 1) % c.len()]);
                    let (dx, dy) = ((b[0] - a[0]).abs(), (b[1] - a[1]).abs());
                    if dx > 0.5 && dy > 0.5 {
                        diagonal += 1;
                    }
                }
            }
        }
        assert!(two_doors > 10, "{two_doors}");
        assert!(diagonal > 5, "{diagonal}");
    }

    #[test]
    fn route_stays_inside_spaces() {
        for p in all_params() {
            let plan = layout(&p);
            let inside = |q: Point| {
                plan.corridors
                    .iter()
                    .chain(&plan.rooms)
                    .chain(plan.doors.iter().map(|d| &d.polygon))
                    .any(|r| point_in_ring(q, r) || near_boundary(q, r))
            };
            for q in &plan.route {
                assert!(inside(*q), "seed {}: waypoint {q:?} outside", p.seed);
            }
        }
    }

    fn near_boundary(q: Point, r: &Ring) -> bool {
        (0..r.len()).any(|i| {
            let (a, b) = (r[i], r[(i + 1) % r.len()]);
            let e = [b[0] - a[0], b[1] - a[1]];
            let l2 = e[0] * e[0] + e[1] * e[1];
            let s = (((q[0] - a[0]) * e[0] + (q[1] - a[1]) * e[1]) / l2).clamp(0.0, 1.0);
            let c = [a[0] + s * e[0], a[1] + s * e[1]];
            (c[0] - q[0]).hypot(c[1] - q[1]) < 1e-6
        })
    }
}
