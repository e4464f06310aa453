//! Random buildings with exactly known geometry for routing tests: a
//! corridor cut into open segments, a row of rooms on each side behind a
//! 0.1 m wall, each room with a door strip through the wall at a random
//! place and width, some rooms with a furniture block (a hole), some joined
//! to their right-hand neighbour by a second door. Every shared boundary
//! is the same edge in both polygons.

use nrgdb::model::{
    Connection, ConnectionKind, Nrg, Point, Space, SpaceId, SpaceKind, point_in_ring,
    segment_distance,
};
use nrgdb::sim::SplitMix64;
use proptest::prelude::*;

/// A generated building and its rooms.
#[derive(Debug, Clone)]
pub struct Building {
    pub nrg: Nrg,
    pub rooms: Vec<SpaceId>,
}

const WALL: f64 = 0.1;

struct Rng(SplitMix64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0.next_f64()
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        // Centimetre steps keep coordinates tidy.
        ((lo + self.next() * (hi - lo)) * 100.0).round() / 100.0
    }
}

struct Builder {
    spaces: Vec<Space>,
    connections: Vec<Connection>,
    next: u32,
}

impl Builder {
    fn add(&mut self, kind: SpaceKind, ring: Vec<Point>, anchor: Point) -> SpaceId {
        let id = SpaceId(self.next);
        self.next += 1;
        let mut ring = ring;
        ring.dedup();
        self.spaces.push(Space::new(id, kind, anchor, ring));
        id
    }
    fn join(&mut self, a: SpaceId, b: SpaceId, kind: ConnectionKind) {
        self.connections.push(Connection {
            a,
            b,
            kind,
            length_m: 1.0,
        });
    }
}

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<Point> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

/// One building from a seed.
pub fn generate(seed: u64) -> Building {
    let mut rng = Rng(SplitMix64::new(seed));
    let mut b = Builder {
        spaces: Vec::new(),
        connections: Vec::new(),
        next: 1,
    };
    let hc = rng.range(1.5, 2.5);
    // Rooms: (x0, x1, y0, y1, north, door x0, door x1).
    let mut rows: Vec<Vec<[f64; 4]>> = Vec::new();
    let mut length: f64 = 0.0;
    for _ in 0..2 {
        let count = 2 + (rng.next() * 4.0) as usize;
        let mut x = rng.range(0.0, 1.0);
        let mut row = Vec::new();
        for _ in 0..count {
            let w = rng.range(2.5, 6.0);
            let depth = rng.range(3.0, 6.0);
            row.push([x, x + w, depth, 0.0]);
            x += w + WALL;
        }
        length = length.max(x + rng.range(0.0, 2.0));
        rows.push(row);
    }
    let mut rooms = Vec::new();
    // Door intervals on the corridor's top (north) and bottom (south).
    let mut corridor_doors: Vec<(f64, f64, bool, SpaceId)> = Vec::new();
    for (r, row) in rows.iter().enumerate() {
        let north = r == 0;
        // Side doors to the right-hand neighbour: (y0, y1) in room depth.
        let side: Vec<Option<(f64, f64)>> = (0..row.len())
            .map(|i| {
                let depth = row[i][2].min(row.get(i + 1).map_or(0.0, |n| n[2]));
                (i + 1 < row.len() && rng.next() < 0.4 && depth > 2.0).then(|| {
                    let w = rng.range(0.8, 1.2);
                    let y = rng.range(0.5, depth - w - 0.3);
                    (y, y + w)
                })
            })
            .collect();
        let mut ids = Vec::new();
        for (i, room) in row.iter().enumerate() {
            let [x0, x1, depth, _] = *room;
            let dw = rng.range(0.7, (x1 - x0 - 0.4).min(1.5));
            let d0 = rng.range(x0 + 0.1, x1 - 0.1 - dw);
            let d1 = d0 + dw;
            // Depth coordinate t in [0, depth] from the wall: y = base + s * t.
            let (base, s) = if north {
                (hc + WALL, 1.0)
            } else {
                (-WALL, -1.0)
            };
            let y = |t: f64| base + s * t;
            let right = side[i];
            let left = if i > 0 { side[i - 1] } else { None };
            // Walk the outline along the wall, the right side, the back, the left side.
            let mut ring = vec![[x0, y(0.0)], [d0, y(0.0)], [d1, y(0.0)], [x1, y(0.0)]];
            if let Some((a, c)) = right {
                ring.extend([[x1, y(a)], [x1, y(c)]]);
            }
            ring.extend([[x1, y(depth)], [x0, y(depth)]]);
            if let Some((a, c)) = left {
                ring.extend([[x0, y(c)], [x0, y(a)]]);
            }
            if !north {
                ring.reverse();
            }
            let furnished = x1 - x0 > 3.5 && depth > 3.5 && rng.next() < 0.5;
            let anchor = if furnished {
                [x0 + 0.3, y(depth / 2.0)]
            } else {
                [(x0 + x1) / 2.0, y(depth / 2.0)]
            };
            let id = b.add(SpaceKind::Room, ring, anchor);
            if furnished {
                let (fx0, fx1) = (x0 + 0.8, x1 - 0.8);
                let (t0, t1) = (1.0, depth - 1.0);
                let mut hole = rect(fx0, y(t0).min(y(t1)), fx1, y(t0).max(y(t1)));
                hole.reverse();
                if let Some(space) = b.spaces.last_mut() {
                    space.holes.push(hole);
                    space.update_area();
                }
            }
            let strip = if north {
                rect(d0, hc, d1, hc + WALL)
            } else {
                rect(d0, -WALL, d1, 0.0)
            };
            let door = b.add(SpaceKind::Door, strip, [(d0 + d1) / 2.0, y(-WALL / 2.0)]);
            b.join(id, door, ConnectionKind::Door);
            corridor_doors.push((d0, d1, north, door));
            ids.push(id);
            rooms.push(id);
        }
        for (i, s) in side.iter().enumerate() {
            let Some((a, c)) = s else { continue };
            let xw = row[i][1];
            let (base, sg) = if north {
                (hc + WALL, 1.0)
            } else {
                (-WALL, -1.0)
            };
            let (ya, yc) = (base + sg * a, base + sg * c);
            let door = b.add(
                SpaceKind::Door,
                rect(xw, ya.min(yc), xw + WALL, ya.max(yc)),
                [xw + WALL / 2.0, (ya + yc) / 2.0],
            );
            b.join(ids[i], door, ConnectionKind::Door);
            b.join(ids[i + 1], door, ConnectionKind::Door);
        }
    }
    // Corridor cuts away from doors.
    let mut cuts = vec![0.0];
    let mut x = 0.0;
    loop {
        x += rng.range(4.0, 12.0);
        if x > length - 2.0 {
            break;
        }
        if corridor_doors
            .iter()
            .all(|(d0, d1, _, _)| x < d0 - 0.05 || x > d1 + 0.05)
        {
            cuts.push(x);
        }
    }
    cuts.push(length);
    let mut previous: Option<SpaceId> = None;
    for w in cuts.windows(2) {
        let (c0, c1) = (w[0], w[1]);
        let inside = |d: &&(f64, f64, bool, SpaceId)| d.0 > c0 && d.1 < c1;
        let mut bottom: Vec<&(f64, f64, bool, SpaceId)> = corridor_doors
            .iter()
            .filter(|d| !d.2)
            .filter(inside)
            .collect();
        bottom.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut top: Vec<&(f64, f64, bool, SpaceId)> = corridor_doors
            .iter()
            .filter(|d| d.2)
            .filter(inside)
            .collect();
        top.sort_by(|a, b| b.0.total_cmp(&a.0));
        let mut ring = vec![[c0, 0.0]];
        for d in &bottom {
            ring.extend([[d.0, 0.0], [d.1, 0.0]]);
        }
        ring.extend([[c1, 0.0], [c1, hc]]);
        for d in &top {
            ring.extend([[d.1, hc], [d.0, hc]]);
        }
        ring.push([c0, hc]);
        let id = b.add(SpaceKind::Corridor, ring, [(c0 + c1) / 2.0, hc / 2.0]);
        for d in bottom.iter().chain(&top) {
            b.join(id, d.3, ConnectionKind::Door);
        }
        if let Some(p) = previous {
            b.join(p, id, ConnectionKind::Open);
        }
        previous = Some(id);
    }
    let nrg = Nrg::new(b.spaces, b.connections).expect("a valid generated building");
    Building { nrg, rooms }
}

/// Generated buildings for proptest.
pub fn building() -> impl Strategy<Value = Building> {
    any::<u64>().prop_map(generate)
}

fn on_edge(p: Point, ring: &[Point]) -> bool {
    (0..ring.len()).any(|i| segment_distance(p, ring[i], ring[(i + 1) % ring.len()]) < 1e-6)
}

/// Whether `p` lies in some space (its boundary counts as inside).
pub fn inside_any(nrg: &Nrg, p: Point) -> bool {
    nrg.spaces().iter().any(|s| {
        std::iter::once(&s.polygon)
            .chain(&s.holes)
            .any(|r| on_edge(p, r))
            || (point_in_ring(p, &s.polygon) && !s.holes.iter().any(|h| point_in_ring(p, h)))
    })
}

/// How many samples, every `step` metres along `line`, lie outside every space.
pub fn outside_samples(nrg: &Nrg, line: &[Point], step: f64) -> usize {
    let mut outside = 0;
    for w in line.windows(2) {
        let len = (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
        let n = (len / step).ceil().max(1.0) as usize;
        for k in 0..=n {
            let t = k as f64 / n as f64;
            let p = [
                w[0][0] + t * (w[1][0] - w[0][0]),
                w[0][1] + t * (w[1][1] - w[0][1]),
            ];
            if !inside_any(nrg, p) {
                outside += 1;
            }
        }
    }
    outside
}

#[test]
fn generated_buildings_are_valid_models() {
    for seed in 0..20 {
        let b = generate(seed);
        assert!(b.rooms.len() >= 4);
        for s in b.nrg.spaces() {
            assert!(s.area_m2 > 0.0, "space {} of seed {seed}", s.id);
            assert!(
                inside_any(&b.nrg, s.anchor),
                "anchor of {} (seed {seed})",
                s.id
            );
        }
    }
}
