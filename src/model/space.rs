//! A space (an IndoorGML cell and its dual state): a room, a corridor or a door.

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

use super::doorway::{Doorway, door_doorway};
use super::geometry::{Point, Ring, polygon_area};
use super::level::Level;

/// Stable integer identity of a space within one map.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(transparent)]
pub struct SpaceId(pub u32);

impl fmt::Display for SpaceId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.0)
    }
}

/// What a space is used for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SpaceKind {
    /// A room: a space people stay in (IndoorGML `GeneralSpace`).
    Room,
    /// A corridor: a space people pass through (IndoorGML `TransitionSpace`).
    Corridor,
    /// A door or doorway (IndoorGML `ConnectionSpace`, the thick-door model).
    Door,
    /// A stairway between levels (IndoorGML `TransitionSpace`); joined to
    /// its part on another level by a vertical connection.
    Stairs,
    /// A lift (elevator) car's stop on a level (IndoorGML
    /// `TransitionSpace`); joined to its stops on other levels by vertical
    /// connections.
    Elevator,
    /// Anything else (IndoorGML `CellSpace`); navigable where its
    /// connections say so.
    Other,
}

impl SpaceKind {
    /// All kinds, in a fixed order.
    pub const ALL: [SpaceKind; 6] = [
        SpaceKind::Room,
        SpaceKind::Corridor,
        SpaceKind::Door,
        SpaceKind::Stairs,
        SpaceKind::Elevator,
        SpaceKind::Other,
    ];

    /// The lower-case name used in JSON, queries and the CLI.
    pub fn as_str(self) -> &'static str {
        match self {
            SpaceKind::Room => "room",
            SpaceKind::Corridor => "corridor",
            SpaceKind::Door => "door",
            SpaceKind::Stairs => "stairs",
            SpaceKind::Elevator => "elevator",
            SpaceKind::Other => "other",
        }
    }
}

impl fmt::Display for SpaceKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for SpaceKind {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        SpaceKind::ALL
            .into_iter()
            .find(|k| k.as_str().eq_ignore_ascii_case(s))
            .ok_or_else(|| {
                format!("unknown space kind '{s}' (expected room, corridor, door, stairs, elevator or other)")
            })
    }
}

/// One space of the NRG: a cell of the primal space and its node in the graph.
///
/// The polygon is the space's 2D footprint in metres in the map frame: an
/// open ring (the first point is not repeated), counter-clockwise, with
/// optional clockwise holes. The anchor is the node's position, a point
/// inside the space that routes pass through. Read from JSON, the derived
/// fields (`area_m2`, `width_m`, a door's missing `doorway`) are computed
/// afresh.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(from = "SpaceJson")]
pub struct Space {
    /// Stable id, unique within the model.
    pub id: SpaceId,
    /// Room, corridor, door or other.
    pub kind: SpaceKind,
    /// Human-readable name ("Kitchen"), if one was given.
    #[serde(default)]
    pub name: Option<String>,
    /// The node's position in metres.
    pub anchor: Point,
    /// Area of the polygon in square metres (derived from `polygon` and
    /// `holes`; ignored when read).
    #[serde(default, skip_deserializing)]
    pub area_m2: f64,
    /// For a door: its width in metres, the doorway line's length unless a
    /// `width_m` attribute declares it (derived, see
    /// [`doorway`](super::doorway()); ignored when read). None for other kinds.
    #[serde(default, skip_deserializing, skip_serializing_if = "Option::is_none")]
    pub width_m: Option<f64>,
    /// For a door: its doorway line, from one jamb to the other through the
    /// middle of the wall, in metres. A door read without one gets the
    /// midline of its polygon's minimum-area rectangle; None for other
    /// kinds (see [`doorway`](super::doorway())).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub doorway: Option<[Point; 2]>,
    /// Exterior ring in metres.
    pub polygon: Ring,
    /// Interior rings (obstacles inside the space), if any.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub holes: Vec<Ring>,
    /// Free attributes (JSON values), kept through every format.
    #[serde(default)]
    pub attributes: Map<String, Value>,
    /// The level the space is on; None in a model without levels (one
    /// floor).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub level: Option<Level>,
}

/// The fields of a [`Space`] that JSON gives; the rest is derived.
#[derive(Deserialize)]
struct SpaceJson {
    id: SpaceId,
    kind: SpaceKind,
    #[serde(default)]
    name: Option<String>,
    anchor: Point,
    #[serde(default)]
    doorway: Option<[Point; 2]>,
    polygon: Ring,
    #[serde(default)]
    holes: Vec<Ring>,
    #[serde(default)]
    attributes: Map<String, Value>,
    #[serde(default)]
    level: Option<Level>,
}

impl From<SpaceJson> for Space {
    fn from(j: SpaceJson) -> Space {
        let mut space = Space {
            id: j.id,
            kind: j.kind,
            name: j.name,
            anchor: j.anchor,
            area_m2: 0.0,
            width_m: None,
            doorway: j.doorway,
            polygon: j.polygon,
            holes: j.holes,
            attributes: j.attributes,
            level: j.level,
        };
        space.update_area();
        space.update_doorway();
        space
    }
}

impl Space {
    /// A space with no name, no holes and no attributes; `area_m2` is computed.
    pub fn new(id: SpaceId, kind: SpaceKind, anchor: Point, polygon: Ring) -> Space {
        let mut space = Space {
            id,
            kind,
            name: None,
            anchor,
            area_m2: 0.0,
            width_m: None,
            doorway: None,
            polygon,
            holes: Vec::new(),
            attributes: Map::new(),
            level: None,
        };
        space.update_area();
        space.update_doorway();
        space
    }

    /// Recomputes `width_m` and, for a door without one, `doorway` (from
    /// the polygon); clears both for other kinds. See
    /// [`doorway`](super::doorway()).
    pub fn update_doorway(&mut self) {
        let d = doorway(self);
        self.doorway = d.map(|d| d.line);
        self.width_m = d.map(|d| d.width_m);
    }

    /// Recomputes `area_m2` from the rings (exterior minus holes).
    pub fn update_area(&mut self) {
        let holes: f64 = self.holes.iter().map(|h| polygon_area(h).abs()).sum();
        self.area_m2 = (polygon_area(&self.polygon).abs() - holes).max(0.0);
    }

    /// Whether `other` equals this space bit for bit (so -0.0 and 0.0
    /// differ; attributes key for key, in order), ids aside.
    pub fn same_but_id(&self, other: &Space) -> bool {
        let bits = |r: &[Point]| -> Vec<u64> {
            r.iter()
                .flat_map(|p| [p[0].to_bits(), p[1].to_bits()])
                .collect()
        };
        self.kind == other.kind
            && self.name == other.name
            && self.anchor.map(f64::to_bits) == other.anchor.map(f64::to_bits)
            && bits(&self.polygon) == bits(&other.polygon)
            && self.doorway.map(|l| bits(&l)) == other.doorway.map(|l| bits(&l))
            && self.holes.len() == other.holes.len()
            && self
                .holes
                .iter()
                .zip(&other.holes)
                .all(|(x, y)| bits(x) == bits(y))
            && self.attributes.iter().eq(other.attributes.iter())
            && self
                .level
                .as_ref()
                .map(|l| (&l.name, l.elevation_m.to_bits()))
                == other
                    .level
                    .as_ref()
                    .map(|l| (&l.name, l.elevation_m.to_bits()))
    }

    /// The name if set, else `"<kind> <id>"` (e.g. "room 12").
    pub fn label(&self) -> String {
        match &self.name {
            Some(n) => n.clone(),
            None => format!("{} {}", self.kind, self.id),
        }
    }
}

/// The doorway of a door space ([`Doorway`]: the line across its opening
/// from jamb to jamb, through the middle of the wall, and its width): its stored
/// [`Space::doorway`] line when it has a finite one, else the midline of
/// its polygon's minimum-area rectangle along the long side; its width is
/// the `width_m` attribute when that is a positive finite number, else the
/// line's length. `None` for other kinds and for doors without points.
///
/// ```
/// use nrgdb::model::{Space, SpaceId, SpaceKind, doorway};
/// // A 0.9 m wide doorway through a 0.3 m wall, turned 30°.
/// let (s, c) = 30f64.to_radians().sin_cos();
/// let turn = |[x, y]: [f64; 2]| [c * x - s * y, s * x + c * y];
/// let ring = [[0.0, 0.0], [0.9, 0.0], [0.9, 0.3], [0.0, 0.3]].map(turn).to_vec();
/// let door = Space::new(SpaceId(1), SpaceKind::Door, turn([0.45, 0.15]), ring);
/// let d = doorway(&door).unwrap();
/// assert!((d.width_m - 0.9).abs() < 1e-9);
/// let m = d.middle();
/// assert!((m[0] - door.anchor[0]).hypot(m[1] - door.anchor[1]) < 1e-9);
/// let room = Space::new(SpaceId(2), SpaceKind::Room, [0.0, 0.0], door.polygon.clone());
/// assert_eq!(doorway(&room), None);
/// ```
pub fn doorway(space: &Space) -> Option<Doorway> {
    if space.kind != SpaceKind::Door {
        return None;
    }
    door_doorway(space.doorway, &space.polygon, &space.attributes)
}
