//! What real robot maps show in rooms, for the simulator: rows of shelves
//! with door-wide aisles between them (a shop, a store room, a library),
//! desk clusters with chairs (an office), a kitchen counter along a wall
//! with a table. On real maps these are the clutter that the furniture
//! filter keeps as walls (they are larger than `furniture_max_m`) and
//! whose gaps pass for doorways (issue 20, mode 4); the simulated
//! buildings make that failure countable on as many buildings as wanted.
//!
//! Everything stands in the back half of its room, 0.45 m short of the
//! middle, like the boxes of `furnish`: the robot's route runs from each
//! corridor door to the room's middle, and clutter must not stand on it.
//! From the middle the robot also walks into every aisle between shelves
//! and out again (as robots mapping a shop or a library do), so the aisles
//! are mapped free, not left unknown. Nothing comes closer than
//! [`DOOR_CLEARANCE_M`] to a door of its room.

use super::floor_plan::{FloorPlan, SpaceRef};
use super::layout::{Slot, Wing};
use super::prng::SplitMix64;
use super::separation::separation_gap;
use crate::model::{Point, Ring};

/// Least distance from a piece of clutter to a door of its room.
const DOOR_CLEARANCE_M: f64 = 0.8;

/// Least distance between two pieces (shelves stand an aisle apart,
/// wider than this).
const PIECE_GAP_M: f64 = 0.3;

/// Distance the clutter keeps from the room's middle line (the route's
/// end), as `furnish` does.
const ROUTE_CLEARANCE_M: f64 = 0.45;

/// Puts one kind of clutter into most rooms (85 %): shelves, a desk
/// cluster or a kitchen, a third each. Returns per room (index of
/// `slots`) the robot's detour from the room's middle through its aisles.
pub(super) fn clutter(
    plan: &mut FloorPlan,
    wings: &[Wing],
    slots: &[Slot],
    rng: &mut SplitMix64,
) -> Vec<Vec<Point>> {
    let mut detours = vec![Vec::new(); slots.len()];
    for (i, slot) in slots.iter().enumerate() {
        if !rng.chance(0.85) {
            continue;
        }
        let doors: Vec<Ring> = plan
            .doors
            .iter()
            .filter(|d| d.a == SpaceRef::Room(i) || d.b == SpaceRef::Room(i))
            .map(|d| d.polygon.clone())
            .collect();
        let mut room = Room {
            wing: &wings[slot.wing],
            slot,
            doors,
            pieces: Vec::new(),
        };
        match rng.int(0, 2) {
            0 => detours[i] = shelves(&mut room, rng),
            1 => desks(&mut room, rng),
            _ => kitchen(&mut room, rng),
        }
        plan.furniture.extend(room.pieces);
    }
    detours
}

/// One room being cluttered: coordinates are `u` along the corridor
/// (`slot.x0..slot.x1`) and `d`, the distance from the back wall.
struct Room<'a> {
    wing: &'a Wing,
    slot: &'a Slot,
    doors: Vec<Ring>,
    pieces: Vec<Ring>,
}

impl Room<'_> {
    /// Depth from the back wall that clutter may reach.
    fn reach(&self) -> f64 {
        (self.slot.y1 - self.slot.y0) / 2.0 - ROUTE_CLEARANCE_M
    }

    /// The wing frame's `y` at depth `d` from the back wall.
    fn y(&self, d: f64) -> f64 {
        let s = self.slot;
        if s.back_is_high { s.y1 - d } else { s.y0 + d }
    }

    /// The point `(u, d)` in the map frame.
    fn at(&self, u: f64, d: f64) -> Point {
        self.wing.frame.at(u, self.y(d))
    }

    /// The box `u0..u1` × `d0..d1` as a ring in the map frame.
    fn ring(&self, u0: f64, u1: f64, d0: f64, d1: f64) -> Ring {
        let (ya, yb) = (self.y(d0), self.y(d1));
        self.wing.frame.rect(u0, ya.min(yb), u1, ya.max(yb))
    }

    /// Adds the box when it lies in the room's allowed part, clear of the
    /// doors and `gap` clear of every piece already there.
    fn try_place(&mut self, u0: f64, u1: f64, d0: f64, d1: f64, gap: f64) -> bool {
        let s = self.slot;
        let inside = u0 >= s.x0 - 1e-9 && u1 <= s.x1 + 1e-9 && d0 >= -1e-9 && d1 <= self.reach();
        if !inside || u1 - u0 < 0.2 || d1 - d0 < 0.2 {
            return false;
        }
        let ring = self.ring(u0, u1, d0, d1);
        let clear = self
            .doors
            .iter()
            .all(|d| separation_gap(d, &ring) >= DOOR_CLEARANCE_M)
            && self
                .pieces
                .iter()
                .all(|p| separation_gap(p, &ring) >= gap - 1e-9);
        if clear {
            self.pieces.push(ring);
        }
        clear
    }
}

/// Rows of shelves standing out from the back wall (some touching it),
/// 0.35-0.6 m deep, with aisles of 0.75-1.1 m: door-wide gaps between
/// obstacles longer than any piece of furniture. Returns the robot's walk
/// into each aisle between two shelves (along its middle, to 0.4 m short
/// of the back) and out, along a line 0.25 m in front of the shelves.
fn shelves(room: &mut Room<'_>, rng: &mut SplitMix64) -> Vec<Point> {
    let depth = rng.range(0.35, 0.6);
    let aisle = rng.range(0.75, 1.1);
    let d0 = if rng.chance(0.5) {
        0.0
    } else {
        rng.range(0.05, 0.2)
    };
    let d1 = room.reach().min(d0 + rng.range(1.2, 2.6));
    let mut u = room.slot.x0 + rng.range(0.1, 0.5);
    let mut placed: Vec<f64> = Vec::new();
    while u + depth <= room.slot.x1 - 0.1 {
        if room.try_place(u, u + depth, d0, d1, PIECE_GAP_M) {
            placed.push(u);
        }
        u += depth + aisle;
    }
    let mut walk = Vec::new();
    for pair in placed.windows(2) {
        if (pair[1] - pair[0] - depth - aisle).abs() > 1e-9 {
            continue;
        }
        let middle = pair[0] + depth + aisle / 2.0;
        let mouth = room.at(middle, d1 + 0.25);
        walk.extend([mouth, room.at(middle, 0.4), mouth]);
    }
    walk
}

/// A cluster of two or three desks side by side (one or two rows, backs
/// together), with a chair in front of each desk of the front row.
fn desks(room: &mut Room<'_>, rng: &mut SplitMix64) {
    let (dw, dd) = (rng.range(1.2, 1.6), rng.range(0.7, 0.8));
    let width = room.slot.x1 - room.slot.x0;
    let mut k = rng.int(2, 3);
    while k > 1 && k as f64 * dw > width - 0.6 {
        k -= 1;
    }
    let chair = 0.45;
    let d0 = rng.range(0.0, 0.4);
    let two_rows = d0 + 2.0 * dd + 0.3 + chair <= room.reach() && rng.chance(0.6);
    let rows = if two_rows { 2.0 } else { 1.0 };
    let u0 = room.slot.x0 + rng.range(0.3, (width - k as f64 * dw - 0.3).max(0.3));
    let block = (u0, u0 + k as f64 * dw, d0, d0 + rows * dd);
    // One box per cluster: desks pushed together are one obstacle on a map.
    if !room.try_place(block.0, block.1, block.2, block.3, PIECE_GAP_M) {
        return;
    }
    for j in 0..k {
        let centre = u0 + (j as f64 + 0.5) * dw;
        let d = block.3 + 0.3;
        room.try_place(
            centre - chair / 2.0,
            centre + chair / 2.0,
            d,
            d + chair,
            PIECE_GAP_M,
        );
    }
}

/// A counter 0.6 m deep along one side wall from the back wall, and a
/// table standing free in the room.
fn kitchen(room: &mut Room<'_>, rng: &mut SplitMix64) {
    let length = room.reach().min(rng.range(1.5, 3.0));
    let (x0, x1) = (room.slot.x0, room.slot.x1);
    let left = rng.chance(0.5);
    let (u0, u1) = if left { (x0, x0 + 0.6) } else { (x1 - 0.6, x1) };
    room.try_place(u0, u1, 0.0, length, PIECE_GAP_M);
    let (tw, td) = (rng.range(0.8, 1.4), rng.range(0.8, 1.2));
    for _try in 0..8 {
        let u = rng.range(x0 + 0.9, (x1 - 0.9 - tw).max(x0 + 0.9));
        let d = rng.range(0.6, (room.reach() - td).max(0.6));
        if room.try_place(u, u + tw, d, d + td, 0.7) {
            break;
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::model::{point_in_ring, polygon_centroid};
    use crate::sim::{FloorPlan, FloorPlanParams};

    fn cluttered(seed: u64) -> FloorPlan {
        let mut p = FloorPlanParams::new(seed);
        p.clutter = true;
        FloorPlan::generate(&p).unwrap()
    }

    #[test]
    fn clutter_stands_in_rooms_off_the_route_and_away_from_doors() {
        let mut pieces = 0;
        for seed in 0..30 {
            let plan = cluttered(seed);
            pieces += plan.furniture.len();
            for piece in &plan.furniture {
                let c = polygon_centroid(piece).unwrap();
                assert!(
                    plan.rooms.iter().any(|r| point_in_ring(c, r)),
                    "seed {seed}: a piece outside every room"
                );
                for d in &plan.doors {
                    let gap = crate::sim::separation::separation_gap(&d.polygon, piece);
                    assert!(gap >= 0.8 - 1e-6, "seed {seed}: {gap} m from a door");
                }
                // The route's points (corridor line, doors, room middles)
                // stay out of every piece.
                for p in &plan.route {
                    assert!(
                        !point_in_ring(*p, piece),
                        "seed {seed}: route point {p:?} in clutter"
                    );
                }
            }
        }
        assert!(pieces > 150, "{pieces} pieces in 30 buildings");
    }

    #[test]
    fn without_clutter_the_plan_is_as_before() {
        // Clutter draws from the generator only when asked for.
        let plain = FloorPlan::generate(&FloorPlanParams::new(7)).unwrap();
        let c = cluttered(7);
        assert_eq!(plain.rooms, c.rooms);
        assert_eq!(plain.doors.len(), c.doors.len());
        assert!(plain.furniture.is_empty() && !c.furniture.is_empty());
    }

    #[test]
    fn shelves_leave_door_wide_aisles() {
        // Some building has two shelves side by side 0.75-1.1 m apart.
        let found = (0..30).any(|seed| {
            let plan = cluttered(seed);
            plan.furniture.iter().enumerate().any(|(i, a)| {
                plan.furniture[i + 1..].iter().any(|b| {
                    let gap = crate::sim::separation::separation_gap(a, b);
                    (0.75..=1.1).contains(&gap)
                })
            })
        });
        assert!(found);
    }
}
