//! The change set: what changed between two models, as data (serde, JSON
//! with stable ids) complete enough to replay the change ([`super::apply`]).
//!
//! Ids: `old` is a space's id in the base model A, `new` its id in the
//! changed model B. Removed connections are given in A's ids, added and
//! changed ones in B's.

use serde::{Deserialize, Serialize};

use super::transform::RigidTransform;
use crate::model::{Connection, ConnectionKind, Space, SpaceId, SpaceKind};

/// The format tag written into every change set.
pub const CHANGESET_FORMAT: &str = "nrgdb-changeset/1";

/// Everything that changed from a base model A to a model B.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ChangeSet {
    /// Always [`CHANGESET_FORMAT`].
    pub format: String,
    /// What A is (e.g. `willow@1` or a file name), set by the caller.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub from: Option<String>,
    /// What B is.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub to: Option<String>,
    /// The rigid transform that was applied to B to bring it into A's
    /// frame before comparing (B below means the transformed B).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alignment: Option<RigidTransform>,
    /// Counts of the reported changes.
    pub summary: Summary,
    /// One entry per space of A and of B: matched pairs (both ids),
    /// removed (old only), added (new only). Sorted by (old, new).
    pub spaces: Vec<SpaceChange>,
    /// Spaces of A split into several spaces of B.
    #[serde(default)]
    pub splits: Vec<Split>,
    /// Spaces of A merged into one space of B.
    #[serde(default)]
    pub merges: Vec<Merge>,
    /// Connections added, removed or changed.
    #[serde(default)]
    pub connections: Vec<ConnectionChange>,
}

/// Counts of reported changes (geometry jitter below the thresholds is not
/// counted, though the change set still carries it).
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Summary {
    /// Matched spaces with no reported change.
    pub unchanged: usize,
    /// Spaces only in B (split parts not counted).
    pub added: usize,
    /// Spaces only in A (merged parts not counted).
    pub removed: usize,
    /// Matched spaces whose area changed beyond the threshold.
    pub resized: usize,
    /// Spaces of A split.
    pub split: usize,
    /// Spaces of B made by merging.
    pub merged: usize,
    /// Matched spaces whose kind changed.
    pub rekinded: usize,
    /// Matched spaces whose name changed.
    pub renamed: usize,
    /// Matched doors whose width changed beyond the threshold.
    pub door_width: usize,
    /// Connections only in B.
    pub connections_added: usize,
    /// Connections only in A.
    pub connections_removed: usize,
    /// Connections whose kind changed.
    pub connections_rekinded: usize,
}

impl Summary {
    /// Whether no structural or semantic change is reported.
    pub fn is_empty(&self) -> bool {
        self.added
            + self.removed
            + self.resized
            + self.split
            + self.merged
            + self.rekinded
            + self.renamed
            + self.door_width
            + self.connections_added
            + self.connections_removed
            + self.connections_rekinded
            == 0
    }
}

/// A reported change of one space.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SpaceChangeKind {
    /// Only in B.
    Added,
    /// Only in A.
    Removed,
    /// Area changed beyond the threshold.
    Resized,
    /// A's space was split; this entry is one of its parts.
    Split,
    /// Several spaces of A were merged; this entry is one of them or the
    /// result.
    Merged,
    /// Kind changed (room ↔ corridor …).
    Rekinded,
    /// Name changed.
    Renamed,
    /// Door width changed beyond the threshold.
    DoorWidth,
}

impl SpaceChangeKind {
    /// The lower-case name used in JSON and tables.
    pub fn as_str(self) -> &'static str {
        match self {
            SpaceChangeKind::Added => "added",
            SpaceChangeKind::Removed => "removed",
            SpaceChangeKind::Resized => "resized",
            SpaceChangeKind::Split => "split",
            SpaceChangeKind::Merged => "merged",
            SpaceChangeKind::Rekinded => "rekinded",
            SpaceChangeKind::Renamed => "renamed",
            SpaceChangeKind::DoorWidth => "door_width",
        }
    }
}

/// One space of A, of B, or a matched pair.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SpaceChange {
    /// Id in A (absent: added).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub old: Option<SpaceId>,
    /// Id in B (absent: removed).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub new: Option<SpaceId>,
    /// Reported changes; empty for an unchanged matched pair.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub changes: Vec<SpaceChangeKind>,
    /// B's label (A's for removed spaces), e.g. "Kitchen" or "room 12".
    pub label: String,
    /// Intersection over union of the matched pair.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub iou: Option<f64>,
    /// Kind in A, or B's for an added space.
    pub kind: SpaceKind,
    /// Kind in B, when it differs.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub new_kind: Option<SpaceKind>,
    /// Area in A (m²), absent for added spaces.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub old_area_m2: Option<f64>,
    /// Area in B (m²), absent for removed spaces.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub new_area_m2: Option<f64>,
    /// Names in A and B, when they differ.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub names: Option<[Option<String>; 2]>,
    /// Door widths in A and B (m), for matched doors whose width changed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub door_width_m: Option<[f64; 2]>,
    /// The space's level (B's; A's for a removed space), in a building
    /// with levels.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub level: Option<String>,
    /// B's space (with B's id) whenever it is not A's space bit for bit
    /// under a new id: always for added spaces, and for matched spaces
    /// whose geometry, kind, name or attributes differ at all.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub space: Option<Space>,
}

/// One part of a split or a merge.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Part {
    /// The part's id (in B for a split, in A for a merge).
    pub id: SpaceId,
    /// The share of the whole's area that overlaps this part (0..1).
    pub share: f64,
}

/// A space of A split into several spaces of B.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Split {
    /// The space in A.
    pub old: SpaceId,
    /// Its parts in B, largest first.
    pub parts: Vec<Part>,
}

/// Several spaces of A merged into one space of B.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Merge {
    /// The space in B.
    pub new: SpaceId,
    /// The parts in A, largest first.
    pub parts: Vec<Part>,
}

/// What happened to a connection.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ConnectionChangeKind {
    /// Only in B (a door opened, a wall removed, a new space's links).
    Added,
    /// Only in A (a door closed, a removed space's links).
    Removed,
    /// Both ends matched, the kind differs (door ↔ open ↔ adjacent).
    Rekinded,
    /// Both ends matched, only the length differs (geometry; not reported
    /// in the summary).
    Length,
}

impl ConnectionChangeKind {
    /// The lower-case name used in JSON and tables.
    pub fn as_str(self) -> &'static str {
        match self {
            ConnectionChangeKind::Added => "added",
            ConnectionChangeKind::Removed => "removed",
            ConnectionChangeKind::Rekinded => "rekinded",
            ConnectionChangeKind::Length => "length",
        }
    }
}

/// A connection added, removed or changed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ConnectionChange {
    /// What happened.
    pub change: ConnectionChangeKind,
    /// The connection in A (A's ids); absent when added.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub old: Option<Connection>,
    /// The connection in B (B's ids); absent when removed.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub new: Option<Connection>,
    /// The levels of its two ends (one name for a connection on one
    /// level, two for a vertical one), in a building with levels.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub levels: Vec<String>,
}

impl ConnectionChange {
    /// The kind before and after (for tables).
    pub fn kinds(&self) -> (Option<ConnectionKind>, Option<ConnectionKind>) {
        (
            self.old.as_ref().map(|c| c.kind),
            self.new.as_ref().map(|c| c.kind),
        )
    }
}

impl ChangeSet {
    /// An empty change set (A and B the same empty model).
    pub fn empty() -> ChangeSet {
        ChangeSet {
            format: CHANGESET_FORMAT.to_string(),
            from: None,
            to: None,
            alignment: None,
            summary: Summary::default(),
            spaces: Vec::new(),
            splits: Vec::new(),
            merges: Vec::new(),
            connections: Vec::new(),
        }
    }

    /// Whether no change is reported (see [`Summary::is_empty`]).
    pub fn is_empty(&self) -> bool {
        self.summary.is_empty()
    }

    /// The change set as pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// Reads a change set from JSON (any format tag; [`super::apply`]
    /// checks it).
    pub fn from_json(text: &str) -> Result<ChangeSet, serde_json::Error> {
        let mut cs: ChangeSet = serde_json::from_str(text)?;
        // Areas are derived, not read.
        for s in cs.spaces.iter_mut().filter_map(|e| e.space.as_mut()) {
            s.update_area();
        }
        Ok(cs)
    }

    /// The reported (non-empty) space entries.
    pub fn changed_spaces(&self) -> impl Iterator<Item = &SpaceChange> {
        self.spaces.iter().filter(|s| !s.changes.is_empty())
    }

    /// The reported connection changes (length-only changes left out).
    pub fn changed_connections(&self) -> impl Iterator<Item = &ConnectionChange> {
        self.connections
            .iter()
            .filter(|c| c.change != ConnectionChangeKind::Length)
    }

    /// The levels with a reported change (a space changed on it, or a
    /// connection with an end on it changed), sorted by name; empty
    /// without levels or without changes.
    ///
    /// ```
    /// use nrgdb::diff::{diff, DiffParams};
    /// use nrgdb::fixtures::storeys;
    /// let (a, b) = (storeys(2, 2), storeys(2, 3));
    /// assert_eq!(diff(&a, &b, &DiffParams::default()).changed_levels(), ["0", "1"]);
    /// assert!(diff(&a, &a, &DiffParams::default()).changed_levels().is_empty());
    /// ```
    pub fn changed_levels(&self) -> Vec<String> {
        let mut levels: Vec<String> = self
            .changed_spaces()
            .filter_map(|s| s.level.clone())
            .chain(
                self.changed_connections()
                    .flat_map(|c| c.levels.iter().cloned()),
            )
            .collect();
        levels.sort();
        levels.dedup();
        levels
    }

    /// Matched pairs `(old id, new id)`, sorted by old id.
    pub fn matched(&self) -> Vec<(SpaceId, SpaceId)> {
        self.spaces
            .iter()
            .filter_map(|s| Some((s.old?, s.new?)))
            .collect()
    }
}
