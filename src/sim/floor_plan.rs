//! A generated floor plan: rooms along corridors, doors, clutter, and the
//! robot's route, all in metres. [`FloorPlan::truth`] gives the true NRG.

use serde_json::Value;

use super::SimError;
use crate::model::{Connection, ConnectionKind, Nrg, Point, Ring, Space, SpaceId, SpaceKind};

/// A wall as a line segment in metres.
pub type Segment = [Point; 2];

/// What [`FloorPlan::generate`] builds. Ranges are `(min, max)` in metres.
#[derive(Debug, Clone, PartialEq)]
pub struct FloorPlanParams {
    /// Seed of the generator: the same seed gives the same plan.
    pub seed: u64,
    /// Number of corridor wings (each turns left off the previous one's end).
    pub wings: (usize, usize),
    /// Corridor length of each wing.
    pub corridor_length_m: (f64, f64),
    /// Corridor width (one width for the whole building).
    pub corridor_width_m: (f64, f64),
    /// Room width along the corridor.
    pub room_width_m: (f64, f64),
    /// Room depth away from the corridor.
    pub room_depth_m: (f64, f64),
    /// Clear door width.
    pub door_width_m: (f64, f64),
    /// Wall thickness between spaces.
    pub wall_thickness_m: f64,
    /// Probability that a room gets a second door.
    pub second_door_probability: f64,
    /// Probability that a room's doorway onto the corridor (a house's
    /// living area) is a wide opening instead of a door: 2-3.2 m, as far as
    /// the room's width allows, as an alcove or a dining nook opens onto a
    /// living room. 0 for office floors.
    pub opening_probability: f64,
    /// Put boxes (furniture) into rooms, away from doors.
    pub furniture: bool,
    /// Turn wings by 25-65 degrees instead of 90 (non-Manhattan walls).
    pub non_manhattan: bool,
    /// Put what real robot maps show into rooms: rows of shelves with
    /// door-wide aisles, desk clusters with chairs, kitchen counters along
    /// a wall with a table (see `sim::clutter`).
    pub clutter: bool,
    /// Direction of the first corridor, degrees counter-clockwise from the
    /// map's x axis: the whole building turned, as a robot's map seldom
    /// lies square to the walls (0: walls along the map's axes). Only the
    /// geometry turns; the same seed gives the same building.
    pub heading_deg: f64,
    /// A house instead of an office floor: one open-plan living area
    /// (living room, kitchen and dining in one space, with a sofa, a
    /// counter and a dining table with chairs; see `sim::house`) with the
    /// bedrooms and bathrooms opening off it. The living area is a room in
    /// the truth. [`FloorPlanParams::house`] sets the sizes of a house.
    pub house: bool,
}

impl FloorPlanParams {
    /// Defaults: 1-3 wings of 12-30 m, 3-6 m wide rooms, 0.8-1.6 m doors.
    pub fn new(seed: u64) -> FloorPlanParams {
        FloorPlanParams {
            seed,
            wings: (1, 3),
            corridor_length_m: (12.0, 30.0),
            corridor_width_m: (1.8, 2.6),
            room_width_m: (3.0, 6.0),
            room_depth_m: (3.5, 6.0),
            door_width_m: (0.8, 1.6),
            wall_thickness_m: 0.2,
            second_door_probability: 0.3,
            opening_probability: 0.0,
            furniture: false,
            non_manhattan: false,
            clutter: false,
            heading_deg: 0.0,
            house: false,
        }
    }

    /// A furnished house: one open-plan living area 8-12 m long and
    /// 4.6-6 m deep, 2.8-4.5 m wide bedrooms and bathrooms 3-4.5 m deep on
    /// both sides of it through 0.75-1 m doors (one in five a 2-3.2 m
    /// opening instead), furniture boxes in them.
    ///
    /// ```
    /// use nrgdb::sim::{FloorPlan, FloorPlanParams};
    /// let plan = FloorPlan::generate(&FloorPlanParams::house(4))?;
    /// assert_eq!(plan.corridors.len(), 1, "one living area");
    /// assert!(plan.open_plan && plan.rooms.len() >= 4);
    /// # Ok::<(), nrgdb::sim::SimError>(())
    /// ```
    pub fn house(seed: u64) -> FloorPlanParams {
        FloorPlanParams {
            wings: (1, 1),
            corridor_length_m: (8.0, 12.0),
            corridor_width_m: (4.6, 6.0),
            room_width_m: (2.8, 4.5),
            room_depth_m: (3.0, 4.5),
            door_width_m: (0.75, 1.0),
            second_door_probability: 0.15,
            opening_probability: 0.2,
            furniture: true,
            house: true,
            ..FloorPlanParams::new(seed)
        }
    }

    /// Checks every range; the error names the field.
    pub fn validate(&self) -> Result<(), SimError> {
        let ranges = [
            ("corridor_length_m", self.corridor_length_m, 6.0),
            ("corridor_width_m", self.corridor_width_m, 1.0),
            ("room_width_m", self.room_width_m, 2.2),
            ("room_depth_m", self.room_depth_m, 2.2),
            ("door_width_m", self.door_width_m, 0.5),
        ];
        for (name, (lo, hi), min) in ranges {
            if !(lo.is_finite() && hi.is_finite() && lo >= min && hi >= lo && hi < 1000.0) {
                return Err(SimError::BadParameter {
                    name,
                    value: format!("({lo}, {hi})"),
                    expected: "a finite range (min, max) with min <= max",
                    hint: "see FloorPlanParams::new for sensible values",
                });
            }
        }
        for (name, value) in [
            ("second_door_probability", self.second_door_probability),
            ("opening_probability", self.opening_probability),
        ] {
            if !(0.0..=1.0).contains(&value) {
                return Err(SimError::BadParameter {
                    name,
                    value: value.to_string(),
                    expected: "a probability in [0, 1]",
                    hint: "0 never, 1 always",
                });
            }
        }
        if !(self.wall_thickness_m > 0.0 && self.wall_thickness_m < 2.0) {
            return Err(SimError::BadParameter {
                name: "wall_thickness_m",
                value: self.wall_thickness_m.to_string(),
                expected: "in (0, 2) m",
                hint: "0.2 is typical",
            });
        }
        if !(self.heading_deg.is_finite() && self.heading_deg.abs() <= 360.0) {
            return Err(SimError::BadParameter {
                name: "heading_deg",
                value: self.heading_deg.to_string(),
                expected: "degrees in [-360, 360]",
                hint: "0 draws the walls along the map's axes",
            });
        }
        if self.wings.0 == 0 || self.wings.1 < self.wings.0 || self.wings.1 > 8 {
            return Err(SimError::BadParameter {
                name: "wings",
                value: format!("{:?}", self.wings),
                expected: "(min, max) with 1 <= min <= max <= 8",
                hint: "(1, 3) is the default",
            });
        }
        Ok(())
    }
}

/// A heading for building `seed` of a benchmark of turned buildings
/// (`FloorPlanParams::heading_deg`): seeds 1, 2, 3, … spread evenly over
/// [3°, 87°) (the golden-ratio sequence), so that no run of seeds keeps
/// near one angle and none lies within 3° of the map's axes.
///
/// ```
/// use nrgdb::sim::spread_heading_deg;
/// let h: Vec<f64> = (1..=50).map(spread_heading_deg).collect();
/// assert!(h.iter().all(|d| (3.0..87.0).contains(d)));
/// assert!(h.iter().filter(|&&d| d < 45.0).count().abs_diff(25) <= 2);
/// ```
pub fn spread_heading_deg(seed: u64) -> f64 {
    let golden = 0.618_033_988_749_894_9_f64;
    3.0 + 84.0 * (seed as f64 * golden).fract()
}

/// A space of the plan, by kind and index.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpaceRef {
    /// Index into [`FloorPlan::corridors`].
    Corridor(usize),
    /// Index into [`FloorPlan::rooms`].
    Room(usize),
}

/// A door: the opening through a wall between two spaces.
#[derive(Debug, Clone, PartialEq)]
pub struct Door {
    /// The door space: a rectangle spanning the wall (CCW).
    pub polygon: Ring,
    /// The space on one side.
    pub a: SpaceRef,
    /// The space on the other side.
    pub b: SpaceRef,
    /// Clear width in metres.
    pub width_m: f64,
    /// The two faces of the door space that are open: facing `a`, facing `b`.
    pub faces: [Segment; 2],
}

impl Door {
    /// The doorway line: from one jamb to the other through the middle of
    /// the wall.
    pub fn doorway(&self) -> [Point; 2] {
        let [f, g] = &self.faces;
        let mid = |p: Point, q: Point| [(p[0] + q[0]) / 2.0, (p[1] + q[1]) / 2.0];
        [mid(f[0], g[0]), mid(f[1], g[1])]
    }

    /// The centre of the doorway.
    pub fn centre(&self) -> Point {
        let [f, g] = &self.faces;
        [
            (f[0][0] + f[1][0] + g[0][0] + g[1][0]) / 4.0,
            (f[0][1] + f[1][1] + g[0][1] + g[1][1]) / 4.0,
        ]
    }
}

/// An open passage between two corridors (no door).
#[derive(Debug, Clone, PartialEq)]
pub struct Opening {
    /// Index of one corridor.
    pub a: usize,
    /// Index of the other corridor.
    pub b: usize,
    /// The shared edge.
    pub segment: Segment,
}

/// A generated building: exact geometry in metres plus the robot's route.
#[derive(Debug, Clone, PartialEq)]
pub struct FloorPlan {
    /// Corridor polygons (CCW, convex).
    pub corridors: Vec<Ring>,
    /// Room polygons (CCW rectangles).
    pub rooms: Vec<Ring>,
    /// Doors between rooms and corridors or between rooms.
    pub doors: Vec<Door>,
    /// Open passages between consecutive corridors.
    pub openings: Vec<Opening>,
    /// Furniture boxes (solid, CCW).
    pub furniture: Vec<Ring>,
    /// Waypoints of a route through every room (corridor centre line plus a
    /// detour through each corridor door to the room centre and back).
    pub route: Vec<Point>,
    /// Wall thickness in metres.
    pub wall_thickness_m: f64,
    /// Whether the corridors are a house's open-plan living area
    /// ([`FloorPlanParams::house`]): rooms in the truth.
    pub open_plan: bool,
}

impl FloorPlan {
    /// Every wall as a segment: the space outlines with door faces and
    /// corridor openings cut out, plus the furniture outlines.
    pub fn walls(&self) -> Vec<Segment> {
        let mut cuts: Vec<Segment> = self.doors.iter().flat_map(|d| d.faces).collect();
        cuts.extend(self.openings.iter().map(|o| o.segment));
        let rings = self
            .corridors
            .iter()
            .chain(&self.rooms)
            .chain(self.doors.iter().map(|d| &d.polygon));
        let mut walls = Vec::new();
        for ring in rings {
            for i in 0..ring.len() {
                let edge = [ring[i], ring[(i + 1) % ring.len()]];
                subtract_cuts(edge, &cuts, &mut walls);
            }
        }
        for ring in &self.furniture {
            for i in 0..ring.len() {
                walls.push([ring[i], ring[(i + 1) % ring.len()]]);
            }
        }
        walls
    }

    /// The true corridors: none in a house, whose living area is a room.
    pub fn true_corridors(&self) -> &[Ring] {
        if self.open_plan { &[] } else { &self.corridors }
    }

    /// The true rooms: the rooms, and a house's living area.
    pub fn true_rooms(&self) -> Vec<Ring> {
        let living = if self.open_plan {
            &self.corridors[..]
        } else {
            &[]
        };
        living.iter().chain(&self.rooms).cloned().collect()
    }

    /// `[min_x, min_y, max_x, max_y]` of every space, in metres.
    pub fn bounds(&self) -> [f64; 4] {
        let mut b = [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ];
        let rings = self.corridors.iter().chain(&self.rooms);
        for p in rings.flatten() {
            b = [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ];
        }
        b
    }

    /// The id a space gets in [`FloorPlan::truth`]: corridors first, then
    /// rooms, then doors, numbered from 1.
    pub fn space_id(&self, space: SpaceRef) -> SpaceId {
        let n = match space {
            SpaceRef::Corridor(i) => i,
            SpaceRef::Room(i) => self.corridors.len() + i,
        };
        SpaceId(n as u32 + 1)
    }

    /// The true NRG: corridors, rooms and door spaces with their exact
    /// polygons; a Door connection from each door space to both sides and
    /// an Open connection between consecutive corridors, `length_m` being
    /// the distance between anchors (polygon centroids).
    pub fn truth(&self) -> Result<Nrg, SimError> {
        let mut spaces = Vec::new();
        let mut push = |kind: SpaceKind, name: String, ring: &Ring| -> Point {
            let anchor = crate::model::polygon_centroid(ring).unwrap_or(ring[0]);
            let id = SpaceId(spaces.len() as u32 + 1);
            let mut s = Space::new(id, kind, anchor, ring.clone());
            s.name = Some(name);
            spaces.push(s);
            anchor
        };
        let mut anchors = Vec::new();
        for (i, r) in self.corridors.iter().enumerate() {
            anchors.push(if self.open_plan {
                push(SpaceKind::Room, format!("living area {}", i + 1), r)
            } else {
                push(SpaceKind::Corridor, format!("corridor {}", i + 1), r)
            });
        }
        for (i, r) in self.rooms.iter().enumerate() {
            anchors.push(push(SpaceKind::Room, format!("room {}", i + 1), r));
        }
        let mut connections = Vec::new();
        for (i, d) in self.doors.iter().enumerate() {
            let anchor = push(SpaceKind::Door, format!("door {}", i + 1), &d.polygon);
            let id = SpaceId((anchors.len() + i) as u32 + 1);
            for side in [d.a, d.b] {
                let other = self.space_id(side);
                let at = anchors[other.0 as usize - 1];
                connections.push(Connection {
                    a: id,
                    b: other,
                    kind: ConnectionKind::Door,
                    length_m: distance(anchor, at),
                });
            }
        }
        for (s, d) in spaces.iter_mut().skip(anchors.len()).zip(&self.doors) {
            s.attributes
                .insert("width_m".into(), Value::from(round_mm(d.width_m)));
            s.doorway = Some(d.doorway());
        }
        for o in &self.openings {
            let (a, b) = (SpaceRef::Corridor(o.a), SpaceRef::Corridor(o.b));
            connections.push(Connection {
                a: self.space_id(a),
                b: self.space_id(b),
                kind: ConnectionKind::Open,
                length_m: distance(anchors[o.a], anchors[o.b]),
            });
        }
        Ok(Nrg::new(spaces, connections)?)
    }
}

fn round_mm(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0
}

/// Euclidean distance between two points.
pub(crate) fn distance(a: Point, b: Point) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

/// Pushes the parts of `edge` not covered by any collinear cut.
fn subtract_cuts(edge: Segment, cuts: &[Segment], out: &mut Vec<Segment>) {
    let [p, q] = edge;
    let e = [q[0] - p[0], q[1] - p[1]];
    let len2 = e[0] * e[0] + e[1] * e[1];
    if len2 < 1e-18 {
        return;
    }
    let len = len2.sqrt();
    let on_line = |c: Point| ((c[0] - p[0]) * e[1] - (c[1] - p[1]) * e[0]).abs() / len < 1e-6;
    let param = |c: Point| ((c[0] - p[0]) * e[0] + (c[1] - p[1]) * e[1]) / len2;
    let mut removed: Vec<(f64, f64)> = cuts
        .iter()
        .filter(|c| on_line(c[0]) && on_line(c[1]))
        .map(|c| {
            let (a, b) = (param(c[0]), param(c[1]));
            (a.min(b).max(0.0), a.max(b).min(1.0))
        })
        .filter(|(a, b)| b > a)
        .collect();
    removed.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut t = 0.0;
    let at = |s: f64| [p[0] + s * e[0], p[1] + s * e[1]];
    for (a, b) in removed {
        if (a - t) * len > 1e-6 {
            out.push([at(t), at(a)]);
        }
        t = t.max(b);
    }
    if (1.0 - t) * len > 1e-6 {
        out.push([at(t), q]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cut_in_the_middle_leaves_two_pieces() {
        let mut out = Vec::new();
        subtract_cuts(
            [[0.0, 0.0], [4.0, 0.0]],
            &[[[2.5, 0.0], [1.5, 0.0]]],
            &mut out,
        );
        assert_eq!(
            out,
            vec![[[0.0, 0.0], [1.5, 0.0]], [[2.5, 0.0], [4.0, 0.0]]]
        );
    }

    #[test]
    fn parallel_offset_cut_is_ignored() {
        let mut out = Vec::new();
        subtract_cuts(
            [[0.0, 0.0], [4.0, 0.0]],
            &[[[1.0, 0.2], [2.0, 0.2]]],
            &mut out,
        );
        assert_eq!(out.len(), 1);
    }

    #[test]
    fn truth_has_every_space_and_door_links() {
        for seed in 0..20 {
            let plan = FloorPlan::generate(&FloorPlanParams::new(seed)).unwrap();
            let nrg = plan.truth().unwrap();
            let n = plan.corridors.len() + plan.rooms.len() + plan.doors.len();
            assert_eq!(nrg.spaces().len(), n);
            assert_eq!(
                nrg.connections().len(),
                2 * plan.doors.len() + plan.openings.len()
            );
            for s in nrg.spaces() {
                assert!(s.area_m2 > 0.0, "seed {seed}: {} has no area", s.label());
            }
            // Each door's doorway runs jamb to jamb: as long as it is wide,
            // its middle the door's anchor.
            for s in nrg.spaces().iter().filter(|s| s.kind == SpaceKind::Door) {
                let d = crate::model::doorway(s).unwrap();
                assert!(
                    (d.length_m() - d.width_m).abs() < 1e-3,
                    "seed {seed}: {d:?}"
                );
                let m = d.middle();
                assert!(distance(m, s.anchor) < 1e-9, "seed {seed}: {d:?}");
            }
        }
    }

    #[test]
    fn bad_params_are_named() {
        let mut p = FloorPlanParams::new(1);
        p.door_width_m = (2.0, 1.0);
        let e = FloorPlan::generate(&p).unwrap_err().to_string();
        assert!(e.contains("door_width_m"), "{e}");
    }
}
