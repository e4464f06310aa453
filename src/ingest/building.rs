//! A building from its floor maps (issue 25): a TOML manifest lists each
//! level's map (a ROS map YAML, extracted, or a model file), its
//! elevation and an optional transform into the building frame, and the
//! stairs and lifts with their positions on the levels they serve. The
//! levels are read, placed and joined into one model: each space gets its
//! level, the space holding a connector's position becomes that connector
//! (kind `stairs` or `elevator`, its name), and vertical connections join
//! its parts (stairs: one flight between two levels; a lift: every pair
//! of levels it serves) with the costs of [`crate::model::stairs_length_m`]
//! and [`crate::model::elevator_length_m`].
//!
//! ```toml
//! name = "Tower"                # optional
//!
//! [[level]]
//! name = "0"
//! elevation_m = 0.0
//! map = "level0.yaml"           # relative to the manifest
//!
//! [[level]]
//! name = "1"
//! elevation_m = 3.5
//! map = "level1.yaml"
//! transform = { x = 0.0, y = 0.0, yaw_deg = 0.0 }   # level frame → building frame
//!
//! [[elevator]]
//! name = "Lift A"
//! at = [12.3, 4.5]              # building frame, metres
//! levels = ["0", "1"]
//!
//! [[stairs]]
//! name = "East"
//! from = { at = [30.1, 2.0], level = "0" }
//! to = { at = [30.1, 6.0], level = "1" }
//! ```
//!
//! Every mistake is an error naming the manifest and the line: a map that
//! is missing, levels with the same name, a connector serving one level,
//! a position outside every space, a transform that is not finite.

use std::collections::HashMap;
use std::ops::Range;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use toml::Spanned;

use super::{IngestError, IngestOptions, Prepared, read_path};
use crate::model::{
    Connection, ConnectionKind, Level, Nrg, Point, Space, SpaceId, SpaceKind, elevator_length_m,
    point_in_ring, stairs_length_m,
};
use crate::store::sha256_hex_of;

/// Most levels a manifest may list.
pub const MAX_LEVELS: usize = 200;

/// Most connectors (stairs and lifts) a manifest may list.
pub const MAX_CONNECTORS: usize = 10_000;

/// Largest manifest read, bytes.
const MAX_MANIFEST_BYTES: u64 = 1 << 20;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Manifest {
    #[serde(default)]
    #[allow(dead_code)]
    name: Option<String>,
    #[serde(default)]
    level: Vec<Spanned<LevelEntry>>,
    #[serde(default)]
    elevator: Vec<Spanned<ElevatorEntry>>,
    #[serde(default)]
    stairs: Vec<Spanned<StairsEntry>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LevelEntry {
    name: String,
    elevation_m: f64,
    map: PathBuf,
    #[serde(default)]
    transform: Option<Transform>,
}

/// A level frame's place in the building frame: turned by `yaw_deg`
/// (counter-clockwise) about its origin, then moved by `(x, y)`.
#[derive(Deserialize, Clone, Copy)]
#[serde(deny_unknown_fields)]
struct Transform {
    #[serde(default)]
    x: f64,
    #[serde(default)]
    y: f64,
    #[serde(default)]
    yaw_deg: f64,
}

impl Transform {
    fn apply(&self, p: Point) -> Point {
        let (s, c) = self.yaw_deg.to_radians().sin_cos();
        [p[0] * c - p[1] * s + self.x, p[0] * s + p[1] * c + self.y]
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ElevatorEntry {
    name: String,
    at: [f64; 2],
    levels: Vec<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct StairsEntry {
    name: String,
    from: Stop,
    to: Stop,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Stop {
    at: [f64; 2],
    level: String,
}

/// A building manifest's levels read and joined (see the module docs).
pub(super) fn read_building(path: &Path, options: &IngestOptions) -> Result<Prepared, IngestError> {
    let bytes = crate::format::read_bytes(path, MAX_MANIFEST_BYTES)?;
    let text = std::str::from_utf8(&bytes).map_err(|e| IngestError::Manifest {
        path: path.into(),
        line: line_of(&bytes, e.valid_up_to()),
        message: "not UTF-8 text".into(),
    })?;
    let fail = |span: Range<usize>, message: String| IngestError::Manifest {
        path: path.into(),
        line: line_of(text.as_bytes(), span.start),
        message,
    };
    let manifest: Manifest = toml::from_str(text).map_err(|e| {
        let span = e.span().unwrap_or(0..0);
        fail(span, e.message().to_string())
    })?;
    if manifest.level.is_empty() {
        return Err(fail(0..0, "no [[level]]: list each level's map".into()));
    }
    if manifest.level.len() > MAX_LEVELS {
        return Err(fail(
            manifest.level[MAX_LEVELS].span(),
            format!("more than {MAX_LEVELS} levels"),
        ));
    }
    if manifest.elevator.len() + manifest.stairs.len() > MAX_CONNECTORS {
        return Err(fail(
            0..0,
            format!("more than {MAX_CONNECTORS} stairs and lifts"),
        ));
    }
    // Check every level before reading any map.
    let mut levels: Vec<(Level, &LevelEntry, Range<usize>)> = Vec::new();
    for entry in &manifest.level {
        let span = entry.span();
        let e = entry.get_ref();
        let level = Level::new(&e.name, e.elevation_m)
            .map_err(|err| fail(span.clone(), err.to_string()))?;
        if levels.iter().any(|(l, _, _)| l.name == level.name) {
            return Err(fail(
                span,
                format!("level {:?} is listed twice", level.name),
            ));
        }
        if let Some(t) = e.transform
            && !(t.x.is_finite() && t.y.is_finite() && t.yaw_deg.is_finite())
        {
            return Err(fail(
                span,
                format!(
                    "level {:?}: the transform has a value that is not a finite number",
                    level.name
                ),
            ));
        }
        levels.push((level, e, span));
    }
    let base = path.parent().unwrap_or(Path::new("."));
    let mut spaces: Vec<Space> = Vec::new();
    let mut connections: Vec<Connection> = Vec::new();
    let mut offset = 0u32;
    let mut sources = Vec::new();
    for (level, entry, span) in &levels {
        let map_path = base.join(&entry.map);
        if !map_path.exists() {
            return Err(fail(
                span.clone(),
                format!(
                    "level {:?}: map {} does not exist",
                    level.name,
                    map_path.display()
                ),
            ));
        }
        let read = read_path(&map_path, options)
            .map_err(|e| fail(span.clone(), format!("level {:?}: {e}", level.name)))?;
        sources.push(read.source_sha256.clone());
        let transform = entry.transform.unwrap_or(Transform {
            x: 0.0,
            y: 0.0,
            yaw_deg: 0.0,
        });
        let (level_spaces, level_connections) = read.nrg.into_parts();
        let top = level_spaces.iter().map(|s| s.id.0).max().unwrap_or(0);
        for mut s in level_spaces {
            s.id = SpaceId(offset + s.id.0);
            s.level = Some(level.clone());
            place(&mut s, &transform);
            spaces.push(s);
        }
        connections.extend(level_connections.into_iter().map(|c| Connection {
            a: SpaceId(offset + c.a.0),
            b: SpaceId(offset + c.b.0),
            ..c
        }));
        offset = offset
            .checked_add(top)
            .ok_or_else(|| fail(span.clone(), "too many spaces".into()))?;
    }
    let by_name: HashMap<&str, &Level> = levels
        .iter()
        .map(|(l, _, _)| (l.name.as_str(), l))
        .collect();
    let mut order: Vec<&Level> = levels.iter().map(|(l, _, _)| l).collect();
    order.sort_by(|a, b| a.elevation_m.total_cmp(&b.elevation_m));
    let rank = |name: &str| order.iter().position(|l| l.name == name).unwrap_or(0);
    let mut vertical: Vec<Connection> = Vec::new();
    for entry in &manifest.elevator {
        let span = entry.span();
        let e = entry.get_ref();
        let mut served: Vec<&str> = Vec::new();
        for l in &e.levels {
            if !by_name.contains_key(l.as_str()) {
                return Err(fail(
                    span,
                    format!("elevator {:?}: no level {l:?} in the manifest", e.name),
                ));
            }
            if !served.contains(&l.as_str()) {
                served.push(l);
            }
        }
        if served.len() < 2 {
            return Err(fail(
                span,
                format!(
                    "elevator {:?} serves {} level; a lift joins two or more",
                    e.name,
                    served.len()
                ),
            ));
        }
        let mut stops = Vec::new();
        for l in &served {
            let id = connector(&mut spaces, l, e.at, SpaceKind::Elevator, &e.name)
                .map_err(|m| fail(span.clone(), m))?;
            stops.push((id, rank(l)));
        }
        for (i, &(a, ra)) in stops.iter().enumerate() {
            for &(b, rb) in &stops[i + 1..] {
                vertical.push(Connection {
                    a,
                    b,
                    kind: ConnectionKind::Vertical,
                    length_m: elevator_length_m(ra.abs_diff(rb)),
                });
            }
        }
    }
    for entry in &manifest.stairs {
        let span = entry.span();
        let e = entry.get_ref();
        let (Some(lo), Some(hi)) = (
            by_name.get(e.from.level.as_str()),
            by_name.get(e.to.level.as_str()),
        ) else {
            return Err(fail(
                span,
                format!(
                    "stairs {:?}: a level they name is not in the manifest",
                    e.name
                ),
            ));
        };
        if lo.name == hi.name {
            return Err(fail(
                span,
                format!(
                    "stairs {:?} start and end on level {}; stairs join two levels",
                    e.name, lo.name
                ),
            ));
        }
        let a = connector(&mut spaces, &lo.name, e.from.at, SpaceKind::Stairs, &e.name)
            .map_err(|m| fail(span.clone(), m))?;
        let b = connector(&mut spaces, &hi.name, e.to.at, SpaceKind::Stairs, &e.name)
            .map_err(|m| fail(span.clone(), m))?;
        let run = (e.from.at[0] - e.to.at[0]).hypot(e.from.at[1] - e.to.at[1]);
        vertical.push(Connection {
            a,
            b,
            kind: ConnectionKind::Vertical,
            length_m: stairs_length_m(hi.elevation_m - lo.elevation_m) + run,
        });
    }
    for c in vertical {
        let key = c.key();
        match connections.iter_mut().find(|k| k.key() == key) {
            Some(k) => k.length_m = k.length_m.min(c.length_m),
            None => connections.push(c),
        }
    }
    let nrg = Nrg::new(spaces, connections).map_err(|e| fail(0..0, e.to_string()))?;
    let label = path.display().to_string();
    let valid = super::validate(nrg, &label, options.allow_invalid)?;
    Ok(Prepared {
        nrg: valid.nrg,
        grid: None,
        params: Some(options.params.clone()),
        weights_fixed: Default::default(),
        repairs: valid.repairs,
        kept: valid.kept,
        georef: None,
        source_name: path
            .file_name()
            .map_or(label.clone(), |n| n.to_string_lossy().into_owned()),
        source_sha256: sha256_hex_of(&[&bytes, sources.join("").as_bytes()]),
    })
}

/// Moves a space from its level's frame into the building frame.
fn place(s: &mut Space, t: &Transform) {
    s.anchor = t.apply(s.anchor);
    s.polygon.iter_mut().for_each(|p| *p = t.apply(*p));
    for h in &mut s.holes {
        h.iter_mut().for_each(|p| *p = t.apply(*p));
    }
    if let Some(line) = &mut s.doorway {
        *line = line.map(|p| t.apply(p));
    }
}

/// The space on `level` holding `at` becomes the connector `name` of
/// `kind`; its id, or why not.
fn connector(
    spaces: &mut [Space],
    level: &str,
    at: Point,
    kind: SpaceKind,
    name: &str,
) -> Result<SpaceId, String> {
    if !(at[0].is_finite() && at[1].is_finite()) {
        return Err(format!(
            "{kind} {name:?}: the position is not a finite number"
        ));
    }
    let inside = |s: &Space| {
        s.level.as_ref().is_some_and(|l| l.name == level)
            && point_in_ring(at, &s.polygon)
            && !s.holes.iter().any(|h| point_in_ring(at, h))
    };
    let Some(s) = spaces
        .iter_mut()
        .filter(|s| inside(s))
        .min_by(|a, b| a.area_m2.total_cmp(&b.area_m2))
    else {
        return Err(format!(
            "{kind} {name:?} at ({:.2}, {:.2}) on level {level} lies outside every space of that level",
            at[0], at[1]
        ));
    };
    if matches!(s.kind, SpaceKind::Stairs | SpaceKind::Elevator)
        && (s.kind != kind || s.name.as_deref() != Some(name))
    {
        return Err(format!(
            "{kind} {name:?} at ({:.2}, {:.2}) on level {level} lies in the space already taken by {} {:?}; give each connector its own space",
            at[0],
            at[1],
            s.kind,
            s.name.as_deref().unwrap_or("")
        ));
    }
    if s.kind == SpaceKind::Door {
        return Err(format!(
            "{kind} {name:?} at ({:.2}, {:.2}) on level {level} lies in a doorway; put it inside the stairwell or lift",
            at[0], at[1]
        ));
    }
    s.kind = kind;
    s.name = Some(name.to_string());
    Ok(s.id)
}

/// The 1-based line of byte `offset`.
fn line_of(bytes: &[u8], offset: usize) -> usize {
    1 + bytes[..offset.min(bytes.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
}
