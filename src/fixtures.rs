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

#[cfg(test)]
mod tests {
    #[test]
    fn large_buildings_are_generated_whole() {
        let nrg = super::corridor_building(2000);
        assert_eq!(nrg.spaces().len(), 4001);
        assert_eq!(nrg.connections().len(), 2000 * 3 - 1);
    }
}
