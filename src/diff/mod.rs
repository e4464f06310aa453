//! Change detection between revisions of an NRG.
//!
//! Owns the space matcher ([`match_spaces`]): which space of a new revision
//! continues which space of its parent, by polygon overlap in the map frame.
//! The store uses it to keep stable ids and names across re-mapping; the
//! future change sets (added/removed/moved/renamed) build on it.
//! Uses `model` and the `geo` crate; must not use store, SQL, XML or the
//! terminal.

mod matching;

pub use matching::{MatchParams, SpaceMatch, match_spaces, overlap_iou};
