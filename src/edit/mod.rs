//! Corrections people make to a model where extraction got it wrong: merge
//! spaces, split one along a line (optionally with a doorway in it), add or
//! remove a door, change a space's kind, set or unset an attribute (issue
//! 22).
//!
//! Owns [`Edit`] (one correction, naming spaces by id and places by map
//! coordinates in metres), [`apply`] (the model after the edit, or an
//! [`EditError`] saying why it is refused) and [`Rule`] (an edit kept with
//! the footprints of the spaces it names, so that it can be re-applied to
//! a re-mapped revision whose ids and outlines differ: [`Rule::reapply`]).
//!
//! Every edit is validated: the geometry it makes passes the checks
//! `nrgdb check` runs (the same [`crate::indoorgml::check`]), the graph
//! stays a well-formed [`Nrg`], and a refusal names the space and the
//! reason ("the line crosses the outline of Office 3 4 times…").
//!
//! Uses `model`, `indoorgml` (the checker) and `geo`; knows nothing of
//! storage, HTTP or the terminal. Connection lengths it makes are straight
//! anchor-to-anchor distances: the caller walks them
//! ([`crate::route::walked_model`]) before storing, as for any import.
//!
//! ```
//! use nrgdb::edit::{Edit, apply};
//! use nrgdb::model::SpaceId;
//! let nrg = nrgdb::fixtures::corridor_building(3);
//! // Rooms 10 and 11 share a 0.2 m wall: give them a door at x = 4.
//! let edit = Edit::AddDoor { a: SpaceId(10), b: SpaceId(11), at: [4.0, 4.0], width_m: None };
//! let done = apply(&nrg, &edit, nrg.next_id())?;
//! let door = done.nrg.space(done.created[0]).unwrap();
//! assert!((door.width_m.unwrap() - 0.9).abs() < 1e-9);
//! assert!(done.nrg.connection(SpaceId(10), door.id).is_some());
//! # Ok::<(), nrgdb::edit::EditError>(())
//! ```

mod attributes;
mod door;
mod error;
mod merge;
mod rule;
mod shape;
mod split;
mod validate;

use serde::{Deserialize, Serialize};
use serde_json::Value;

pub use error::EditError;
pub use rule::{Footprint, Reapplied, Rule};

use crate::model::{Nrg, Point, SpaceId, SpaceKind};

/// Width of a door added without one, metres.
pub const DEFAULT_DOOR_WIDTH_M: f64 = 0.9;
/// Narrowest door an edit may add, metres.
pub const MIN_DOOR_WIDTH_M: f64 = 0.3;
/// Widest door an edit may add, metres (wider openings are open
/// boundaries: split without a door).
pub const MAX_DOOR_WIDTH_M: f64 = 5.0;
/// Depth of a door laid on a split line or between touching spaces,
/// metres (the door space spans this much across the line).
pub const DOOR_DEPTH_M: f64 = 0.2;
/// Farthest two spaces may be apart (a wall's thickness) for a door
/// between them, metres.
pub const MAX_WALL_GAP_M: f64 = 0.6;
/// Most spaces one MERGE may name.
pub const MAX_MERGED: usize = 64;

/// One correction to a model. Spaces are named by id, places by map-frame
/// coordinates in metres.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "edit", rename_all = "snake_case")]
pub enum Edit {
    /// One space from several: their union, with the doors between them
    /// absorbed. The first space listed keeps its id; the kind is that of
    /// the largest; `name` names the result.
    Merge {
        /// The spaces (at least two).
        spaces: Vec<SpaceId>,
        /// The merged space's name.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        name: Option<String>,
    },
    /// A space cut in two by a line that enters its outline once and
    /// leaves it once. The pieces meet along the line as an open boundary,
    /// or, with `door`, as a wall with that doorway in it.
    Split {
        /// The space to cut.
        space: SpaceId,
        /// The cutting line's two ends, outside the space.
        line: [Point; 2],
        /// A doorway on the line.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        door: Option<NewDoor>,
    },
    /// A door between two spaces that touch, or face each other across a
    /// wall at most [`MAX_WALL_GAP_M`] thick, at the boundary nearest `at`.
    AddDoor {
        /// One side.
        a: SpaceId,
        /// The other side.
        b: SpaceId,
        /// Where the door is.
        at: Point,
        /// Its width (default [`DEFAULT_DOOR_WIDTH_M`]).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        width_m: Option<f64>,
    },
    /// A door space removed with its connections; the spaces it joined
    /// become adjacent (a wall between them).
    RemoveDoor {
        /// The door.
        door: SpaceId,
    },
    /// A space's kind changed (room, corridor or other; doors stay doors).
    SetKind {
        /// The space.
        space: SpaceId,
        /// Its new kind.
        kind: SpaceKind,
    },
    /// An attribute set on a space.
    SetAttribute {
        /// The space.
        space: SpaceId,
        /// The attribute's name.
        key: String,
        /// Its value (text, number or true/false).
        value: Value,
    },
    /// An attribute removed from a space.
    UnsetAttribute {
        /// The space.
        space: SpaceId,
        /// The attribute's name.
        key: String,
    },
}

/// A doorway laid on a split line.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct NewDoor {
    /// Its middle (projected onto the line).
    pub at: Point,
    /// Its width (default [`DEFAULT_DOOR_WIDTH_M`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub width_m: Option<f64>,
}

impl Edit {
    /// The spaces the edit names, in the order written.
    pub fn spaces(&self) -> Vec<SpaceId> {
        match self {
            Edit::Merge { spaces, .. } => spaces.clone(),
            Edit::AddDoor { a, b, .. } => vec![*a, *b],
            Edit::RemoveDoor { door } => vec![*door],
            Edit::Split { space, .. }
            | Edit::SetKind { space, .. }
            | Edit::SetAttribute { space, .. }
            | Edit::UnsetAttribute { space, .. } => vec![*space],
        }
    }

    /// The same edit naming other spaces: `rename` maps each named id.
    pub fn with_spaces(&self, rename: impl Fn(SpaceId) -> SpaceId) -> Edit {
        let mut out = self.clone();
        match &mut out {
            Edit::Merge { spaces, .. } => spaces.iter_mut().for_each(|s| *s = rename(*s)),
            Edit::AddDoor { a, b, .. } => {
                *a = rename(*a);
                *b = rename(*b);
            }
            Edit::RemoveDoor { door } => *door = rename(*door),
            Edit::Split { space, .. }
            | Edit::SetKind { space, .. }
            | Edit::SetAttribute { space, .. }
            | Edit::UnsetAttribute { space, .. } => *space = rename(*space),
        }
        out
    }

    /// A short description naming the spaces by their labels in `nrg`
    /// ("merge of Lobby and Hall").
    pub fn describe(&self, nrg: &Nrg) -> String {
        let label = |id: SpaceId| {
            nrg.space(id)
                .map_or_else(|| format!("space {id}"), |s| s.label())
        };
        match self {
            Edit::Merge { spaces, .. } => format!("merge of {}", wording_list(spaces, label)),
            Edit::Split { space, .. } => format!("split of {}", label(*space)),
            Edit::AddDoor { a, b, .. } => format!("door between {} and {}", label(*a), label(*b)),
            Edit::RemoveDoor { door } => format!("removal of {}", label(*door)),
            Edit::SetKind { space, kind } => format!("{} made a {kind}", label(*space)),
            Edit::SetAttribute { space, key, .. } => format!("{key} set on {}", label(*space)),
            Edit::UnsetAttribute { space, key } => format!("{key} unset on {}", label(*space)),
        }
    }
}

fn wording_list(ids: &[SpaceId], label: impl Fn(SpaceId) -> String) -> String {
    let labels: Vec<String> = ids.iter().map(|&id| label(id)).collect();
    match labels.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        Some((last, _)) => last.clone(),
        None => String::new(),
    }
}

/// A model after an edit.
#[derive(Debug, Clone, PartialEq)]
pub struct Edited {
    /// The edited model.
    pub nrg: Nrg,
    /// Spaces the edit made (a split's second piece, a new door), in
    /// order.
    pub created: Vec<SpaceId>,
    /// Spaces the edit removed (merged away, absorbed doors, a removed
    /// door).
    pub removed: Vec<SpaceId>,
}

/// `nrg` with `edit` applied, validated (see the module doc). New spaces
/// take ids from `next_id` on (a store passes one above every id its map
/// ever used). Nothing is changed when the edit is refused.
pub fn apply(nrg: &Nrg, edit: &Edit, next_id: SpaceId) -> Result<Edited, EditError> {
    for id in edit.spaces() {
        if nrg.space(id).is_none() {
            return Err(EditError::UnknownSpace(id));
        }
    }
    let next_id = SpaceId(next_id.0.max(nrg.next_id().0));
    let edited = match edit {
        Edit::Merge { spaces, name } => merge::merge(nrg, spaces, name.as_deref())?,
        Edit::Split { space, line, door } => split::split(nrg, *space, *line, *door, next_id)?,
        Edit::AddDoor { a, b, at, width_m } => door::add_door(nrg, *a, *b, *at, *width_m, next_id)?,
        Edit::RemoveDoor { door } => door::remove_door(nrg, *door)?,
        Edit::SetKind { space, kind } => attributes::set_kind(nrg, *space, *kind)?,
        Edit::SetAttribute { space, key, value } => {
            attributes::set_attribute(nrg, *space, key, Some(value))?
        }
        Edit::UnsetAttribute { space, key } => attributes::set_attribute(nrg, *space, key, None)?,
    };
    validate::no_new_findings(nrg, &edited)?;
    Ok(edited)
}
