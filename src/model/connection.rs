//! A relation between two spaces: a door, an open boundary or a wall.

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

use super::SpaceId;

/// How two spaces relate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum ConnectionKind {
    /// Through a door (one end is a door space).
    Door,
    /// Through a shared free boundary, no door in between.
    Open,
    /// The spaces share a wall: adjacent, but not navigable.
    Adjacent,
    /// Between levels: a stairway's or a lift's parts on two levels;
    /// `length_m` is the cost of the ride or climb as an equivalent walked
    /// length.
    Vertical,
}

impl ConnectionKind {
    /// All kinds, in a fixed order.
    pub const ALL: [ConnectionKind; 4] = [
        ConnectionKind::Door,
        ConnectionKind::Open,
        ConnectionKind::Adjacent,
        ConnectionKind::Vertical,
    ];

    /// The lower-case name used in JSON, queries and the CLI.
    pub fn as_str(self) -> &'static str {
        match self {
            ConnectionKind::Door => "door",
            ConnectionKind::Open => "open",
            ConnectionKind::Adjacent => "adjacent",
            ConnectionKind::Vertical => "vertical",
        }
    }

    /// Whether a route may use this connection.
    pub fn is_navigable(self) -> bool {
        self != ConnectionKind::Adjacent
    }
}

impl fmt::Display for ConnectionKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for ConnectionKind {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        ConnectionKind::ALL
            .into_iter()
            .find(|k| k.as_str().eq_ignore_ascii_case(s))
            .ok_or_else(|| {
                format!("unknown connection kind '{s}' (expected door, open or adjacent)")
            })
    }
}

/// An undirected edge of the NRG between spaces `a` and `b`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Connection {
    /// One end.
    pub a: SpaceId,
    /// The other end.
    pub b: SpaceId,
    /// Door, open or adjacent.
    pub kind: ConnectionKind,
    /// Length of the edge in metres: the distance walked from `a`'s anchor
    /// to `b`'s anchor (the straight distance unless the source knew better).
    pub length_m: f64,
}

impl Connection {
    /// The two ends as an ordered pair (smaller id first).
    pub fn key(&self) -> (SpaceId, SpaceId) {
        if self.a <= self.b {
            (self.a, self.b)
        } else {
            (self.b, self.a)
        }
    }

    /// The end that is not `id`, if `id` is an end.
    pub fn other(&self, id: SpaceId) -> Option<SpaceId> {
        if self.a == id {
            Some(self.b)
        } else if self.b == id {
            Some(self.a)
        } else {
            None
        }
    }
}

/// The walked polyline of each connection that has one, keyed by
/// [`Connection::key`], running from the smaller id's anchor to the
/// other's. Writers draw a connection with its polyline when given one,
/// else as the straight line between the anchors.
pub type ConnectionPaths = std::collections::BTreeMap<(SpaceId, SpaceId), Vec<super::Point>>;
