//! Everything that tunes a comparison besides the two revisions: the
//! thresholds of change detection ([`DiffParams`]), of space matching
//! ([`MatchParams`]) and of alignment ([`AlignParams`]), when to align
//! ([`AlignMode`]), and all of these together ([`DiffOptions`], what
//! [`compare`](super::compare) takes). In their own file so that the
//! detector, the matcher, the door matcher, the split/merge finder and the
//! aligner can all read them without importing one another.
//!
//! Uses the diff error type only; must not use the other diff files (they
//! all read this one), so no two of them import each other in a circle.

use serde::{Deserialize, Serialize};

use super::error::DiffError;

/// Tuning of [`match_spaces`](super::match_spaces).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MatchParams {
    /// Smallest intersection-over-union for two spaces to be the same
    /// space (0..1). The default 0.2 tolerates a room split in up to
    /// five parts while refusing a room and the door beside it.
    pub min_iou: f64,
    /// Largest distance in metres between the centres of two doors'
    /// doorway lines for them to be the same door (they must also join
    /// the same spaces; see the door matcher, `diff/door_match.rs`). The
    /// default 0.5 m absorbs re-cutting and alignment error and a door
    /// widened by up to a metre on one side; a door moved farther along
    /// its wall, or to another wall, is removed and added.
    pub door_shift_m: f64,
}

impl Default for MatchParams {
    fn default() -> Self {
        MatchParams {
            min_iou: 0.2,
            door_shift_m: 0.5,
        }
    }
}

/// Thresholds of [`diff`](super::diff).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct DiffParams {
    /// Smallest IoU for two spaces to be the same space (default 0.2, as
    /// the store's matcher).
    pub min_iou: f64,
    /// A matched space is resized when its area changes by more than this
    /// share of its old area (default 0.15) ...
    pub resize_ratio: f64,
    /// ... and by at least this many m² (default 1.0).
    pub resize_min_m2: f64,
    /// A split or merge part lies at least this share of its own area
    /// inside the whole (default 0.5).
    pub part_cover: f64,
    /// ... and overlaps it by at least this many m² (default 0.1: a door
    /// strip 0.9 m × 0.2 m still counts, pixel slivers do not).
    pub min_part_m2: f64,
    /// A door's width changed when it differs by more than this (default
    /// 0.15 m: three pixels at 0.05 m/px, one and a half at 0.1 m/px).
    pub door_width_tol_m: f64,
    /// Two doors joining the same spaces are the same door when their
    /// doorway centres lie at most this far apart (default 0.5 m, as the
    /// store's matcher; see the door matcher, `diff/door_match.rs`).
    pub door_shift_m: f64,
}

impl Default for DiffParams {
    fn default() -> Self {
        DiffParams {
            min_iou: MatchParams::default().min_iou,
            resize_ratio: 0.15,
            resize_min_m2: 1.0,
            part_cover: 0.5,
            min_part_m2: 0.1,
            door_width_tol_m: 0.15,
            door_shift_m: MatchParams::default().door_shift_m,
        }
    }
}

impl DiffParams {
    /// Checks every threshold's range.
    pub fn validate(&self) -> Result<(), DiffError> {
        let checks: [(&'static str, f64, bool, &'static str); 7] = [
            (
                "min_iou",
                self.min_iou,
                self.min_iou > 0.0 && self.min_iou <= 1.0,
                "must be in (0, 1]",
            ),
            (
                "resize_ratio",
                self.resize_ratio,
                self.resize_ratio >= 0.0,
                "must be ≥ 0",
            ),
            (
                "resize_min_m2",
                self.resize_min_m2,
                self.resize_min_m2 >= 0.0,
                "must be ≥ 0",
            ),
            (
                "part_cover",
                self.part_cover,
                self.part_cover > 0.0 && self.part_cover <= 1.0,
                "must be in (0, 1]",
            ),
            (
                "min_part_m2",
                self.min_part_m2,
                self.min_part_m2 >= 0.0,
                "must be ≥ 0",
            ),
            (
                "door_width_tol_m",
                self.door_width_tol_m,
                self.door_width_tol_m >= 0.0,
                "must be ≥ 0",
            ),
            (
                "door_shift_m",
                self.door_shift_m,
                self.door_shift_m >= 0.0,
                "must be ≥ 0",
            ),
        ];
        for (name, value, ok, hint) in checks {
            if !ok || !value.is_finite() {
                return Err(DiffError::BadParam { name, value, hint });
            }
        }
        Ok(())
    }
}

/// Tuning of [`align_grids`](super::align_grids).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AlignParams {
    /// Half-width of the translation search around the centroid fit, m
    /// (default 4).
    pub search_m: f64,
    /// Wall points used (evenly subsampled; default 2000).
    pub max_points: usize,
    /// A wall point is an inlier within this distance of a reference wall;
    /// `None`: twice the coarser map resolution.
    pub inlier_tol_m: Option<f64>,
    /// Smallest inlier share accepted (default 0.5).
    pub min_inliers: f64,
    /// A second, different fit this close to the best makes the alignment
    /// ambiguous (default 0.05).
    pub ambiguity_margin: f64,
}

impl Default for AlignParams {
    fn default() -> Self {
        AlignParams {
            search_m: 4.0,
            max_points: 2000,
            inlier_tol_m: None,
            min_inliers: 0.5,
            ambiguity_margin: 0.05,
        }
    }
}

/// When to align B to A before comparing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum AlignMode {
    /// Never: the two share a frame.
    Never,
    /// When their frames differ (see [`compare`](super::compare)).
    #[default]
    Auto,
    /// Always.
    Always,
}

/// What decides a change set besides the two revisions: when to align,
/// the detection thresholds and the alignment tuning. Every entry point
/// (CLI, query `DIFF`, server, renderer, viewer) passes one to
/// [`compare`](super::compare); the default is what they use unless told
/// otherwise.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DiffOptions {
    /// When to align B to A.
    pub align: AlignMode,
    /// Thresholds of the change detector.
    pub params: DiffParams,
    /// Tuning of the alignment.
    pub align_params: AlignParams,
    /// When to give up ([`DiffError::TimedOut`](super::DiffError::TimedOut)):
    /// a query's or a request's deadline. `None`: no time bound.
    pub deadline: Option<std::time::Instant>,
}
