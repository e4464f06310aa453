//! Levels in IndoorGML (issue 25). Written: a space on a level has its
//! polygon and State point at the level's elevation (z, `srsDimension`
//! 3) and the level in its cell's description (`"nrgdb:level": {"name",
//! "elevation_m"}`). Read: that description gives the level; a document
//! without it whose cells lie at several heights (3D files such as the
//! stacked floors of sample 201) gets its levels from the geometry: each
//! cell's floor is its lowest z, floors more than [`FLOOR_GAP_M`] apart
//! are different levels, named "0", "1", … from the lowest (elevation:
//! the lowest floor of the level) unless the cells name their storey in
//! their description (`storey="2"`, as the InFactory/KU tools write it):
//! when every described cell of a floor names the same storey, and the
//! floors' storeys differ, the storeys are the levels' names. A document
//! with one floor keeps no levels. Connections that join two levels become vertical; adjacency
//! (a shared wall) between levels is dropped.

use serde_json::{Map, Value};

use super::document::{Cell, CellGeometry};
use crate::model::{Connection, ConnectionKind, Level, Space, level_name};

/// The description key of a space's level.
pub(super) const LEVEL_KEY: &str = "nrgdb:level";

/// Floors closer than this (metres) are one level: a step, a raised
/// floor; storeys are 2.5 m apart or more.
pub const FLOOR_GAP_M: f64 = 1.5;

/// Puts `space`'s level into the attributes its description is written
/// from.
pub(super) fn describe(space: &Space, attributes: &mut Map<String, Value>) {
    if let Some(level) = &space.level
        && let Ok(value) = serde_json::to_value(level)
    {
        attributes.insert(LEVEL_KEY.into(), value);
    }
}

/// The z a space's geometry is written at: its level's elevation.
pub(super) fn elevation(space: &Space) -> Option<f64> {
    space.level.as_ref().map(|l| l.elevation_m)
}

/// Gives each space read from `cells` (same order) its level: from the
/// description nrgdb wrote, else from the cells' heights (see the module
/// docs).
pub(super) fn assign(cells: &[Cell], spaces: &mut [Space]) {
    let mut described = false;
    for space in spaces.iter_mut() {
        if let Some(value) = space.attributes.remove(LEVEL_KEY) {
            space.level = serde_json::from_value::<Level>(value).ok();
            described = true;
        }
    }
    if described {
        return;
    }
    let floors: Vec<Option<f64>> = cells.iter().map(floor_z).collect();
    let mut heights: Vec<f64> = floors.iter().flatten().copied().collect();
    heights.sort_by(f64::total_cmp);
    // The lowest floor of each level.
    let mut levels: Vec<f64> = Vec::new();
    let mut last = f64::NEG_INFINITY;
    for z in heights {
        if z - last > FLOOR_GAP_M {
            levels.push(z);
        }
        last = z;
    }
    if levels.len() < 2 {
        return;
    }
    let level_of: Vec<usize> = floors
        .iter()
        .map(|floor| {
            let z = floor.unwrap_or(levels[0]);
            levels.iter().rposition(|&l| l <= z + 1e-9).unwrap_or(0)
        })
        .collect();
    let names = storey_names(spaces, &level_of, levels.len())
        .unwrap_or_else(|| (0..levels.len()).map(|k| k.to_string()).collect());
    for (space, k) in spaces.iter_mut().zip(level_of) {
        space.level = Some(Level {
            name: names[k].clone(),
            elevation_m: levels[k],
        });
    }
}

/// The storey a cell's description names (`storey="2":indoor="room":`).
fn described_storey(space: &Space) -> Option<&str> {
    let text = space.attributes.get("description")?.as_str()?;
    let rest = &text[text.find("storey=\"")? + "storey=\"".len()..];
    let name = &rest[..rest.find('"')?];
    (!name.trim().is_empty()).then_some(name.trim())
}

/// The name of each of `count` floors from its cells' storeys, when every
/// described cell of a floor agrees, every floor has one, and no two
/// floors share one; else None.
fn storey_names(spaces: &[Space], level_of: &[usize], count: usize) -> Option<Vec<String>> {
    let mut names: Vec<Option<&str>> = vec![None; count];
    for (space, &k) in spaces.iter().zip(level_of) {
        let Some(storey) = described_storey(space) else {
            continue;
        };
        match names[k] {
            None => names[k] = Some(storey),
            Some(name) if name == storey => {}
            Some(_) => return None,
        }
    }
    let names: Vec<String> = names
        .into_iter()
        .map(|n| n.map(str::to_string))
        .collect::<Option<_>>()?;
    let mut distinct = names.clone();
    distinct.sort();
    distinct.dedup();
    (distinct.len() == names.len()).then_some(names)
}

/// Connections between two levels become vertical; adjacency between
/// levels is dropped (walls do not join floors).
pub(super) fn fit_connections(spaces: &[Space], connections: &mut Vec<Connection>) {
    let by_id: std::collections::HashMap<_, _> = spaces
        .iter()
        .map(|s| (s.id, level_name(s.level.as_ref())))
        .collect();
    connections.retain_mut(|c| {
        if by_id.get(&c.a) == by_id.get(&c.b) {
            return true;
        }
        match c.kind {
            ConnectionKind::Adjacent => false,
            _ => {
                c.kind = ConnectionKind::Vertical;
                true
            }
        }
    });
}

/// A cell's floor: the lowest z of its geometry (None in 2D).
fn floor_z(cell: &Cell) -> Option<f64> {
    let coords: Vec<&super::document::Coords> = match &cell.geometry {
        Some(CellGeometry::Surface(p)) => vec![&p.exterior],
        Some(CellGeometry::Solid(s)) => s.exterior.iter().map(|p| &p.exterior).collect(),
        None => Vec::new(),
    };
    coords
        .into_iter()
        .filter(|c| c.dim >= 3)
        .flat_map(|c| c.z())
        .filter(|z| z.is_finite())
        .reduce(f64::min)
}
