//! A generated building NRG for the store tests and benches: a corridor of
//! `segments` pieces along x, each with a room above and below it reached
//! through a door space. Five spaces and nine connections per segment
//! (`segments = 30` is willow-sized: 150 spaces, ~265 connections).
//! Shared with `benches/store.rs` through `#[path]`.

use nrgdb::model::{Connection, ConnectionKind, Nrg, Ring, Space, SpaceId, SpaceKind};

/// Width of one segment along x, metres.
pub const SEGMENT_M: f64 = 4.0;

/// The building with `segments` corridor pieces. `jitter_m` moves every
/// vertex by up to that much (deterministic in `seed`), as a re-mapping of
/// the same building would.
pub fn building(segments: u32, jitter_m: f64, seed: u64) -> Nrg {
    let mut rng = Lcg(seed.wrapping_mul(6364136223846793005).wrapping_add(1));
    let mut spaces = Vec::new();
    let mut links = Vec::new();
    let id = |seg: u32, k: u32| SpaceId(seg * 5 + k + 1);
    for seg in 0..segments {
        let x = f64::from(seg) * SEGMENT_M;
        let corridor = id(seg, 0);
        let rooms = [
            (id(seg, 1), id(seg, 2), 2.2, 6.2, 2.0),
            (id(seg, 3), id(seg, 4), -4.2, -0.2, -0.2),
        ];
        spaces.push(space(
            corridor,
            SpaceKind::Corridor,
            rect(x, 0.0, x + SEGMENT_M, 2.0),
            jitter_m,
            &mut rng,
        ));
        for (room, door, y0, y1, dy) in rooms {
            let mut r = space(
                room,
                SpaceKind::Room,
                rect(x, y0, x + SEGMENT_M, y1),
                jitter_m,
                &mut rng,
            );
            r.attributes.insert("floor".into(), serde_json::json!(0));
            spaces.push(r);
            spaces.push(space(
                door,
                SpaceKind::Door,
                rect(x + 1.5, dy, x + 2.5, dy + 0.2),
                jitter_m * 0.1,
                &mut rng,
            ));
            links.push(link(room, door, ConnectionKind::Door, 2.1));
            links.push(link(door, corridor, ConnectionKind::Door, 1.1));
            links.push(link(room, corridor, ConnectionKind::Adjacent, 3.2));
            if seg > 0 {
                links.push(link(
                    SpaceId(room.0 - 5),
                    room,
                    ConnectionKind::Adjacent,
                    SEGMENT_M,
                ));
            }
        }
        if seg > 0 {
            links.push(link(
                id(seg - 1, 0),
                corridor,
                ConnectionKind::Open,
                SEGMENT_M,
            ));
        }
    }
    Nrg::new(spaces, links).expect("generated building is a valid NRG")
}

/// `nrg` with room `room` split across x into two rooms, 60 % (keeping the
/// id) and 40 % (id `new_id`), the smaller part joined to the larger by an
/// open connection.
pub fn split_room(nrg: &Nrg, room: SpaceId, new_id: SpaceId) -> Nrg {
    let (mut spaces, mut links) = nrg.clone().into_parts();
    let i = spaces
        .iter()
        .position(|s| s.id == room)
        .expect("room exists");
    let old = spaces[i].clone();
    let (min, max) = bbox(&old.polygon);
    let cut = min[0] + 0.6 * (max[0] - min[0]);
    spaces[i] = Space::new(
        room,
        old.kind,
        [(min[0] + cut) / 2.0, old.anchor[1]],
        rect(min[0], min[1], cut, max[1]),
    );
    spaces[i].attributes = old.attributes.clone();
    spaces.push(Space::new(
        new_id,
        old.kind,
        [(cut + max[0]) / 2.0, old.anchor[1]],
        rect(cut, min[1], max[0], max[1]),
    ));
    links.push(link(room, new_id, ConnectionKind::Open, 1.0));
    Nrg::new(spaces, links).expect("split building is a valid NRG")
}

/// `nrg` with every vertex of space `id` moved right by `dx_m`.
pub fn nudge(nrg: &Nrg, id: SpaceId, dx_m: f64) -> Nrg {
    let (mut spaces, links) = nrg.clone().into_parts();
    for s in spaces.iter_mut().filter(|s| s.id == id) {
        for p in &mut s.polygon {
            p[0] += dx_m;
        }
        s.anchor[0] += dx_m;
    }
    Nrg::new(spaces, links).expect("nudged building is a valid NRG")
}

fn bbox(ring: &Ring) -> ([f64; 2], [f64; 2]) {
    let mut min = [f64::INFINITY; 2];
    let mut max = [f64::NEG_INFINITY; 2];
    for p in ring {
        for k in 0..2 {
            min[k] = min[k].min(p[k]);
            max[k] = max[k].max(p[k]);
        }
    }
    (min, max)
}

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Ring {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

fn space(id: SpaceId, kind: SpaceKind, mut ring: Ring, jitter_m: f64, rng: &mut Lcg) -> Space {
    for p in &mut ring {
        p[0] += jitter_m * rng.unit();
        p[1] += jitter_m * rng.unit();
    }
    let (min, max) = bbox(&ring);
    Space::new(
        id,
        kind,
        [(min[0] + max[0]) / 2.0, (min[1] + max[1]) / 2.0],
        ring,
    )
}

fn link(a: SpaceId, b: SpaceId, kind: ConnectionKind, length_m: f64) -> Connection {
    Connection {
        a,
        b,
        kind,
        length_m,
    }
}

/// A tiny deterministic generator (no dependency): uniform in [-1, 1).
struct Lcg(u64);

impl Lcg {
    fn unit(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
}
