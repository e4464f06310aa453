//! Change detection between revisions of an NRG.
//!
//! Owns the space matcher ([`match_spaces`]: which space of a new revision
//! continues which space of its parent, by polygon overlap in the map
//! frame, and doors by their doorway line and the spaces they join, so a
//! door strip a pixel deep matches as well as a thick one; the store uses
//! it to keep stable ids), the change detector
//! ([`diff`] → [`ChangeSet`]: unchanged, added, removed, resized, split,
//! merged, re-kinded, renamed spaces; connections added, removed and
//! re-kinded; door width changes), its replay ([`apply`], with
//! `apply(a, &diff(a, b)) == b`), the IndoorGML update ([`update_model`]:
//! B under A's identifiers, only the changed levels of a building) and the alignment of two maps from different
//! mapping runs ([`align_grids`] → [`Alignment`], a rigid transform with a
//! quality score, refused when unreliable). [`compare`] is the change-set
//! service every caller uses (CLI, query `DIFF`, server, the pictures):
//! given both revisions with their grids and [`DiffOptions`], it decides
//! whether their frames differ, aligns, and diffs. Tuning lives in
//! `params.rs`, the overlaps the matchers share in `overlaps.rs`.
//!
//! Uses `model`, `grid` and `imaging` (alignment); `geo` only in tests, as
//! the reference for the exact overlap areas. Must not use store, query,
//! SQL, XML or the terminal.
//!
//! ```
//! use nrgdb::diff::{apply, diff, DiffParams};
//! use nrgdb::fixtures::corridor_building;
//! let (a, b) = (corridor_building(4), corridor_building(3));
//! let changes = diff(&a, &b, &DiffParams::default());
//! println!("{}", changes.table()); // removed room 13, door 10003, links
//! let json = changes.to_json();
//! let back = nrgdb::diff::ChangeSet::from_json(&json)?;
//! assert_eq!(apply(&a, &back)?, b);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod align;
mod apply;
mod change_set;
mod compare;
mod detect;
mod door_match;
mod error;
mod matching;
mod overlap_area;
mod overlaps;
mod params;
mod rebase;
mod report;
mod split_merge;
mod transform;

pub use align::{Alignment, align_grids, alignment_quality, wall_points};
pub use apply::{apply, update_model, with_base_ids};
pub use change_set::{
    CHANGESET_FORMAT, ChangeSet, ConnectionChange, ConnectionChangeKind, Merge, Part, SpaceChange,
    SpaceChangeKind, Split, Summary,
};
pub use compare::{Comparison, MODEL_GRID_M, Revision, compare, model_grid};
pub use detect::diff;
pub use error::DiffError;
pub use matching::{
    MAX_MATCH_PAIRS, MAX_OPTIMAL_COMPONENT, SpaceMatch, match_overlaps, match_spaces,
    match_spaces_within, overlap_iou, overlaps,
};
pub use overlaps::Overlaps;
pub use params::{AlignMode, AlignParams, DiffOptions, DiffParams, MatchParams};
pub use rebase::rebase;
pub use report::ChangeRow;
pub use transform::RigidTransform;
