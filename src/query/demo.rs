//! A generated demo building for tests, benches, golden queries and the
//! REPL: rooms on both sides of a corridor, joined by door spaces.

use serde_json::{Map, Value};

use crate::model::{Connection, ConnectionKind, Nrg, Point, Space, SpaceId, SpaceKind};

/// Names given to some rooms, by (column, above?).
const NAMES: [(usize, bool, &str); 5] = [
    (0, true, "Kitchen"),
    (0, false, "Library"),
    (2, true, "Lounge"),
    (3, false, "Office"),
    (5, true, "Printer Room"),
];

/// A building of `columns` corridor segments, each 4 m long, with a room
/// above and a room below joined to it by a door space. Every third room
/// pair above the corridor (columns 1–2, 4–5, …) also shares a side door, so
/// some routes have alternatives. A shaft (`Other`, with no connection) sits at
/// the east end. Spaces: `5 × columns + ⌊(columns + 1) / 3⌋ + 1`, roughly.
///
/// Ids: column `i` holds corridor `5i+1`, upper door `5i+2`, upper room
/// `5i+3`, lower door `5i+4`, lower room `5i+5`; side doors and the shaft
/// follow. Doors of even columns carry a `width_m` attribute; rooms carry
/// `seats`. Lengths are straight distances between anchors.
///
/// ```
/// let nrg = nrgdb::query::demo::building(3);
/// assert_eq!(nrg.spaces().iter().filter(|s| s.label() == "Kitchen").count(), 1);
/// ```
pub fn building(columns: usize) -> Nrg {
    let columns = columns.max(1);
    let mut spaces = Vec::new();
    let mut connections = Vec::new();
    let id = |i: usize, k: usize| SpaceId((5 * i + k) as u32);
    for i in 0..columns {
        let x = 4.0 * i as f64;
        spaces.push(rect(
            id(i, 1),
            SpaceKind::Corridor,
            [x, 5.0],
            [x + 4.0, 7.0],
        ));
        let mut upper_door = rect(id(i, 2), SpaceKind::Door, [x + 1.5, 7.0], [x + 2.5, 7.3]);
        let mut lower_door = rect(id(i, 4), SpaceKind::Door, [x + 1.4, 4.7], [x + 2.6, 5.0]);
        if i % 2 == 0 {
            upper_door
                .attributes
                .insert("width_m".into(), Value::from(0.9));
            lower_door
                .attributes
                .insert("width_m".into(), Value::from(1.2));
        }
        spaces.push(upper_door);
        spaces.push(room(id(i, 3), [x + 0.15, 7.3], [x + 3.85, 11.0], i));
        spaces.push(lower_door);
        spaces.push(room(id(i, 5), [x + 0.15, 1.0], [x + 3.85, 4.7], i + 1));
        for (a, b, kind) in [
            (1, 2, ConnectionKind::Door),
            (2, 3, ConnectionKind::Door),
            (1, 4, ConnectionKind::Door),
            (4, 5, ConnectionKind::Door),
        ] {
            connections.push((id(i, a), id(i, b), kind));
        }
        if i + 1 < columns {
            connections.push((id(i, 1), id(i + 1, 1), ConnectionKind::Open));
            connections.push((id(i, 5), id(i + 1, 5), ConnectionKind::Adjacent));
            if i % 3 != 1 {
                connections.push((id(i, 3), id(i + 1, 3), ConnectionKind::Adjacent));
            }
        }
    }
    let mut next = 5 * columns as u32 + 1;
    for i in (1..columns.saturating_sub(1)).filter(|i| i % 3 == 1) {
        let x = 4.0 * i as f64;
        let side = SpaceId(next);
        next += 1;
        spaces.push(rect(
            side,
            SpaceKind::Door,
            [x + 3.85, 8.6],
            [x + 4.15, 9.6],
        ));
        connections.push((id(i, 3), side, ConnectionKind::Door));
        connections.push((side, id(i + 1, 3), ConnectionKind::Door));
    }
    let x = 4.0 * columns as f64;
    let mut shaft = rect(SpaceId(next), SpaceKind::Other, [x, 5.0], [x + 1.0, 7.0]);
    shaft.name = Some("Shaft".into());
    spaces.push(shaft);
    connections.push((id(columns - 1, 1), SpaceId(next), ConnectionKind::Adjacent));
    for s in &mut spaces {
        let above = s.kind == SpaceKind::Room && s.id.0 % 5 == 3;
        let column = (s.id.0 as usize).saturating_sub(1) / 5;
        if let Some((_, _, name)) = NAMES
            .iter()
            .find(|(c, up, _)| s.kind == SpaceKind::Room && *c == column && *up == above)
        {
            s.name = Some((*name).into());
        }
    }
    let anchor_of = |spaces: &[Space], id: SpaceId| {
        spaces
            .iter()
            .find(|s| s.id == id)
            .map_or([0.0, 0.0], |s| s.anchor)
    };
    let mut anchors = std::collections::HashMap::new();
    for s in &spaces {
        anchors.insert(s.id, s.anchor);
    }
    let connections = connections
        .into_iter()
        .map(|(a, b, kind)| {
            let (pa, pb) = (
                anchors
                    .get(&a)
                    .copied()
                    .unwrap_or_else(|| anchor_of(&spaces, a)),
                anchors
                    .get(&b)
                    .copied()
                    .unwrap_or_else(|| anchor_of(&spaces, b)),
            );
            Connection {
                a,
                b,
                kind,
                length_m: distance(pa, pb),
            }
        })
        .collect();
    // The generated model satisfies every invariant; fall back to an empty
    // model rather than panic if that ever changes.
    Nrg::new(spaces, connections).unwrap_or_default()
}

fn distance(a: Point, b: Point) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

fn rect(id: SpaceId, kind: SpaceKind, lo: Point, hi: Point) -> Space {
    let anchor = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0];
    let polygon = vec![lo, [hi[0], lo[1]], hi, [lo[0], hi[1]]];
    Space::new(id, kind, anchor, polygon)
}

fn room(id: SpaceId, lo: Point, hi: Point, seats: usize) -> Space {
    let mut s = rect(id, SpaceKind::Room, lo, hi);
    let mut attributes = Map::new();
    attributes.insert("seats".into(), Value::from(seats % 7 * 2));
    s.attributes = attributes;
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_match_the_doc() {
        assert_eq!(building(28).spaces().len(), 28 * 5 + 9 + 1);
        let big = building(1875);
        assert!((9_900..=10_100).contains(&big.spaces().len()));
    }
}
