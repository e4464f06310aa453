//! A house's open-plan living area ([`FloorPlanParams::house`]): living
//! room, kitchen and dining in one space, the way real house maps show it
//! (aws_small_house): a kitchen counter along one end wall, a sofa against
//! the other, a dining table with a chair at each end standing free. All
//! of it keeps clear of the doors and of the robot's route (the living
//! area's middle line and the walks from it to each door).
//!
//! [`FloorPlanParams::house`]: super::FloorPlanParams::house

use super::floor_plan::FloorPlan;
use super::layout::Wing;
use super::prng::SplitMix64;
use super::separation::separation_gap;
use crate::model::{Point, Ring};

/// Distance furniture keeps from a door space.
const DOOR_CLEARANCE_M: f64 = 0.8;
/// Distance furniture keeps from the robot's route.
const ROUTE_CLEARANCE_M: f64 = 0.45;
/// Distance between two pieces of furniture.
const PIECE_GAP_M: f64 = 0.3;
/// Depth of the kitchen counter.
const COUNTER_DEPTH_M: f64 = 0.6;
/// Depth of the sofa.
const SOFA_DEPTH_M: f64 = 0.9;

/// Furnishes the living area of `wing` (local `x` in `0..len` along it,
/// `y` in `-w..0` across), whose doors are `doors` (`(x of the door's
/// middle, door index)`). Returns the stretch `(start, end)` of the middle
/// line the robot drives, clear of the counter and the sofa.
pub(super) fn furnish_living(
    plan: &mut FloorPlan,
    wing: &Wing,
    w: f64,
    doors: &[(f64, usize)],
    rng: &mut SplitMix64,
) -> (f64, f64) {
    let len = wing.len;
    let frame = wing.frame;
    let (start, end) = (
        SOFA_DEPTH_M + ROUTE_CLEARANCE_M + 0.05,
        len - COUNTER_DEPTH_M - ROUTE_CLEARANCE_M - 0.05,
    );
    let mut room = Living {
        doors: doors
            .iter()
            .filter_map(|&(_, i)| plan.doors.get(i).map(|d| d.polygon.clone()))
            .collect(),
        route: std::iter::once([frame.at(start, -w / 2.0), frame.at(end, -w / 2.0)])
            .chain(doors.iter().filter_map(|&(x, i)| {
                let door = plan.doors.get(i)?;
                Some([frame.at(x.clamp(start, end), -w / 2.0), door.centre()])
            }))
            .collect(),
        pieces: Vec::new(),
    };
    // The counter along the far end wall, from one corner or the other.
    let counter = rng.range(2.0, 3.5).min(w - 1.2);
    let corners = [(-w, -w + counter), (-counter, 0.0)];
    let first = usize::from(rng.chance(0.5));
    for (y0, y1) in [corners[first], corners[1 - first]] {
        if room.try_place(frame.rect(len - COUNTER_DEPTH_M, y0, len, y1)) {
            break;
        }
    }
    // The sofa against the near end wall.
    let sofa = rng.range(1.8, 2.4).min(w - 1.2);
    for _try in 0..8 {
        let y = rng.range(-w + 0.4, -0.4 - sofa);
        if room.try_place(frame.rect(0.0, y, SOFA_DEPTH_M, y + sofa)) {
            break;
        }
    }
    // The dining table in one half, off the middle line, a chair at each
    // end; some tries along the living area.
    let (tw, td) = (rng.range(1.0, 1.6), rng.range(0.8, 1.0));
    let chair = 0.45;
    for _try in 0..24 {
        let x = rng.range(start, (end - tw).max(start));
        let off = rng.range(0.6, (w / 2.0 - 0.35 - td).max(0.6));
        let (ty0, ty1) = if rng.chance(0.5) {
            (-w / 2.0 + off, -w / 2.0 + off + td)
        } else {
            (-w / 2.0 - off - td, -w / 2.0 - off)
        };
        let table = frame.rect(x, ty0, x + tw, ty1);
        let cy = (ty0 + ty1) / 2.0 - chair / 2.0;
        let chairs = [
            frame.rect(x - 0.2 - chair, cy, x - 0.2, cy + chair),
            frame.rect(x + tw + 0.2, cy, x + tw + 0.2 + chair, cy + chair),
        ];
        if room.clear(&table) && chairs.iter().all(|c| room.clear(c)) {
            room.pieces.push(table);
            room.pieces.extend(chairs);
            break;
        }
    }
    plan.furniture.extend(room.pieces);
    (start, end)
}

/// The living area being furnished: what furniture must keep clear of.
struct Living {
    doors: Vec<Ring>,
    /// The route's legs in the living area, as segments.
    route: Vec<[Point; 2]>,
    pieces: Vec<Ring>,
}

impl Living {
    /// Whether `ring` keeps clear of the doors, the route and the pieces
    /// already placed.
    fn clear(&self, ring: &Ring) -> bool {
        self.doors
            .iter()
            .all(|d| separation_gap(d, ring) >= DOOR_CLEARANCE_M)
            && self
                .route
                .iter()
                .all(|leg| separation_gap(leg, ring) >= ROUTE_CLEARANCE_M)
            && self
                .pieces
                .iter()
                .all(|p| separation_gap(p, ring) >= PIECE_GAP_M)
    }

    /// Adds `ring` when it is clear; whether it was.
    fn try_place(&mut self, ring: Ring) -> bool {
        let clear = self.clear(&ring);
        if clear {
            self.pieces.push(ring);
        }
        clear
    }
}

#[cfg(test)]
mod tests {
    use crate::model::{SpaceKind, point_in_ring, polygon_centroid};
    use crate::sim::{FloorPlan, FloorPlanParams, separation_gap};

    /// Every house has its living area as a room of the truth, furniture
    /// in it standing inside it, off the route and clear of the doors; some
    /// rooms open onto it through openings.
    #[test]
    fn the_living_area_is_a_furnished_room_the_route_passes_clear_of() {
        let (mut tables, mut openings) = (0, 0);
        for seed in 1..=20 {
            let plan = FloorPlan::generate(&FloorPlanParams::house(seed)).expect("plan");
            openings += plan.doors.iter().filter(|d| d.width_m >= 2.0).count();
            let living = &plan.corridors[0];
            let truth = plan.truth().expect("truth");
            assert!(
                truth.spaces().iter().all(|s| s.kind != SpaceKind::Corridor),
                "seed {seed}: no corridor in a house"
            );
            let in_living: Vec<_> = plan
                .furniture
                .iter()
                .filter(|f| {
                    let c = polygon_centroid(f).expect("centroid");
                    point_in_ring(c, living)
                })
                .collect();
            assert!(!in_living.is_empty(), "seed {seed}: a bare living area");
            // A dining table with its two chairs: three pieces besides the
            // counter and the sofa.
            tables += usize::from(in_living.len() >= 4);
            for f in &in_living {
                for d in &plan.doors {
                    assert!(separation_gap(&d.polygon, f) >= 0.8 - 1e-9, "seed {seed}");
                }
                for leg in plan.route.windows(2) {
                    assert!(
                        separation_gap(&[leg[0], leg[1]], f) >= 0.45 - 1e-9,
                        "seed {seed}: furniture on the route"
                    );
                }
            }
        }
        assert!(tables >= 10, "{tables} of 20 houses have a dining table");
        // One room front in five opens through an opening, not a door.
        assert!(
            (5..=40).contains(&openings),
            "{openings} openings in 20 houses"
        );
    }
}
