//! Errors of change detection, change-set application and alignment.

use crate::model::{ModelError, SpaceId};

/// What can go wrong in [`crate::diff`].
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum DiffError {
    /// The change set was made from another model than the one it is
    /// applied to.
    #[error(
        "change set does not fit this model: {detail} (apply a change set only to the revision \
         it was computed from, its `from`)"
    )]
    BaseMismatch {
        /// What differs.
        detail: String,
    },
    /// A change set that contradicts itself.
    #[error(
        "bad change set: {detail} (was it edited by hand? recompute it with `nrgdb diff --json`)"
    )]
    BadChangeSet {
        /// What is wrong.
        detail: String,
    },
    /// The change set's format version is not one this build reads.
    #[error(
        "change set format '{found}' is not supported, expected '{expected}' (recompute it with this nrgdb)"
    )]
    Format {
        /// The format found.
        found: String,
        /// The format this build writes.
        expected: &'static str,
    },
    /// The result of applying is not a valid model.
    #[error("applying the change set gives an invalid model: {0}")]
    Model(#[from] ModelError),
    /// The two models' spaces pile on each other: matching would measure
    /// more than `limit` pairs.
    #[error(
        "cannot compare these models: more than {limit} pairs of their spaces overlap (are spaces \
         piled on each other?)"
    )]
    TooManyOverlaps {
        /// The bound on overlapping pairs.
        limit: usize,
    },
    /// The comparison ran past its deadline (nothing is returned).
    #[error("the comparison ran past its time bound")]
    TimedOut,
    /// A parameter out of range.
    #[error("diff parameter `{name}` = {value} is out of range: {hint}")]
    BadParam {
        /// The parameter.
        name: &'static str,
        /// Its value.
        value: f64,
        /// What is allowed.
        hint: &'static str,
    },
    /// A grid without enough walls to align.
    #[error(
        "cannot align: the {which} map has {walls} wall pixels, at least {needed} are needed \
         (wall pixels are the cells bordering its free space: does it have any?)"
    )]
    TooFewWalls {
        /// "first" or "second".
        which: &'static str,
        /// Wall pixels found.
        walls: usize,
        /// Needed.
        needed: usize,
    },
    /// No reliable alignment exists.
    #[error(
        "no reliable alignment: best fit has {inliers_pct:.0}% of walls within {tolerance_m} m \
         (needs {needed_pct:.0}%){ambiguity} (are these maps of the same building? diff without \
         alignment if they share a frame)"
    )]
    Unreliable {
        /// Best inlier share, percent.
        inliers_pct: f64,
        /// Needed, percent.
        needed_pct: f64,
        /// Inlier distance, metres.
        tolerance_m: f64,
        /// A note on a second, equally good fit, or empty.
        ambiguity: String,
    },
    /// A space id in the change set that the model lacks.
    #[error("space {id} named in the change set is not in the {side} model")]
    MissingSpace {
        /// The id.
        id: SpaceId,
        /// "base" or "changed".
        side: &'static str,
    },
}
