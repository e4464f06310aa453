//! Small generated buildings for tests, benchmarks and examples: known
//! answers without any data files.

use crate::model::{Connection, ConnectionKind, Nrg, Space, SpaceId, SpaceKind};

/// The NRG extracted with default parameters from the shared dev map
/// `$NRGDB_SHARED/maps/<name>.yaml` (default `../shared`), or `None` when
/// that map is not there or does not extract. For benchmarks and tests.
pub fn shared_map_nrg(name: &str) -> Option<Nrg> {
    let shared = std::env::var_os("NRGDB_SHARED")
        .map_or_else(|| "../shared".into(), std::path::PathBuf::from);
    let yaml = shared.join("maps").join(format!("{name}.yaml"));
    let grid = crate::grid::load_map(&yaml, &crate::grid::LoadOptions::default()).ok()?;
    Some(
        crate::extract::extract(&grid, &crate::extract::ExtractParams::default())
            .ok()?
            .nrg,
    )
}

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<[f64; 2]> {
    vec![[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

/// A floor: a corridor along y ∈ [0, 2] with `rooms` rooms above it, each
/// 4 m wide and joined to the corridor by a 1 m door space; neighbouring
/// rooms share a wall (adjacent). Room i is space 10+i, its door 10000+i,
/// the corridor is 1. Every third room has a name, room 10 attributes.
pub fn corridor_building(rooms: usize) -> Nrg {
    let width = 4.0 * rooms as f64;
    let mut corridor = Space::new(
        SpaceId(1),
        SpaceKind::Corridor,
        [width / 2.0, 1.0],
        rect(0.0, 0.0, width, 2.0),
    );
    corridor.name = Some("Main corridor".into());
    let mut spaces = vec![corridor];
    let mut connections = Vec::new();
    for i in 0..rooms {
        let x = 4.0 * i as f64;
        let room_id = SpaceId(10 + i as u32);
        let door_id = SpaceId(10_000 + i as u32);
        let mut room = Space::new(
            room_id,
            SpaceKind::Room,
            [x + 2.0, 4.6],
            rect(x + 0.1, 2.2, x + 3.9, 7.0),
        );
        if i % 3 == 0 {
            room.name = Some(format!("Office {}", i + 1));
        }
        if i == 0 {
            room.attributes.insert("floor".into(), serde_json::json!(2));
            room.attributes
                .insert("use".into(), serde_json::json!("lab & <kitchen>"));
        }
        spaces.push(room);
        spaces.push(Space::new(
            door_id,
            SpaceKind::Door,
            [x + 2.0, 2.1],
            rect(x + 1.5, 2.0, x + 2.5, 2.2),
        ));
        connections.push(Connection {
            a: door_id,
            b: room_id,
            kind: ConnectionKind::Door,
            length_m: 2.5,
        });
        connections.push(Connection {
            a: SpaceId(1),
            b: door_id,
            kind: ConnectionKind::Door,
            length_m: (x + 2.0 - width / 2.0).hypot(1.1),
        });
        if i > 0 {
            connections.push(Connection {
                a: SpaceId(9 + i as u32),
                b: room_id,
                kind: ConnectionKind::Adjacent,
                length_m: 4.0,
            });
        }
    }
    Nrg::new(spaces, connections).unwrap_or_default()
}

/// A building of `levels` floors 3.5 m apart (level names "0", "1", …),
/// each a [`corridor_building`] of `rooms` rooms with its ids plus
/// 100 000 × level, and two vertical connectors at the corridor's ends:
/// stairs west (x ∈ [-3, 0], space 90 000 + 100 000 × level) and a lift
/// east (2 m wide, space 90 001 + 100 000 × level), each open to the
/// corridor. Stairs join consecutive levels, the lift joins every pair,
/// with the costs of [`crate::model::stairs_length_m`] and
/// [`crate::model::elevator_length_m`].
pub fn storeys(levels: usize, rooms: usize) -> Nrg {
    use crate::model::{Level, elevator_length_m, stairs_length_m};
    let floor = corridor_building(rooms);
    let width = 4.0 * rooms as f64;
    let (mut spaces, mut connections) = (Vec::new(), Vec::new());
    let id = |level: usize, id: SpaceId| SpaceId(id.0 + 100_000 * level as u32);
    let (stairs, lift) = (SpaceId(90_000), SpaceId(90_001));
    for k in 0..levels {
        let level = Level {
            name: k.to_string(),
            elevation_m: 3.5 * k as f64,
        };
        for s in floor.spaces() {
            let mut s = s.clone();
            s.id = id(k, s.id);
            if let Some(name) = &s.name {
                s.name = Some(format!("{name} L{k}"));
            }
            s.level = Some(level.clone());
            spaces.push(s);
        }
        for c in floor.connections() {
            connections.push(Connection {
                a: id(k, c.a),
                b: id(k, c.b),
                ..*c
            });
        }
        let mut st = Space::new(
            id(k, stairs),
            SpaceKind::Stairs,
            [-1.5, 1.0],
            rect(-3.0, 0.0, 0.0, 2.0),
        );
        st.name = Some(format!("West stairs L{k}"));
        st.level = Some(level.clone());
        let mut el = Space::new(
            id(k, lift),
            SpaceKind::Elevator,
            [width + 1.0, 1.0],
            rect(width, 0.0, width + 2.0, 2.0),
        );
        el.name = Some(format!("Lift A L{k}"));
        el.level = Some(level);
        spaces.extend([st, el]);
        for (end, x) in [(stairs, -1.5), (lift, width + 1.0)] {
            connections.push(Connection {
                a: id(k, SpaceId(1)),
                b: id(k, end),
                kind: ConnectionKind::Open,
                length_m: (x - width / 2.0).abs(),
            });
        }
        if k > 0 {
            connections.push(Connection {
                a: id(k - 1, stairs),
                b: id(k, stairs),
                kind: ConnectionKind::Vertical,
                length_m: stairs_length_m(3.5),
            });
        }
        for j in 0..k {
            connections.push(Connection {
                a: id(j, lift),
                b: id(k, lift),
                kind: ConnectionKind::Vertical,
                length_m: elevator_length_m(k - j),
            });
        }
    }
    Nrg::new(spaces, connections).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    #[test]
    fn storeys_are_whole_with_their_vertical_links() {
        let nrg = super::storeys(3, 4);
        assert_eq!(nrg.spaces().len(), 3 * (1 + 2 * 4 + 2));
        let levels = nrg.levels();
        assert_eq!(
            levels.iter().map(|l| l.name.as_str()).collect::<Vec<_>>(),
            ["0", "1", "2"]
        );
        let vertical = nrg
            .connections()
            .iter()
            .filter(|c| c.kind == crate::model::ConnectionKind::Vertical)
            .count();
        assert_eq!(vertical, 2 + 3, "stairs 0-1, 1-2; lift 0-1, 0-2, 1-2");
    }

    #[test]
    fn large_buildings_are_generated_whole() {
        let nrg = super::corridor_building(2000);
        assert_eq!(nrg.spaces().len(), 4001);
        assert_eq!(nrg.connections().len(), 2000 * 3 - 1);
    }
}
