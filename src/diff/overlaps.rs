//! The overlaps between the spaces of two revisions ([`Overlaps`]) and
//! the doorway of each door ([`DoorSide`]): the data the matcher
//! ([`super::matching`]), the door matcher ([`super::door_match`]) and the
//! split/merge finder ([`super::split_merge`]) share. Types only: the
//! overlaps are measured in `matching`, the doorways found in `door_match`.
//!
//! Uses `model`. Must not use the other diff files, so that none of them
//! imports another in a circle.

use crate::model::{Point, SpaceId, segment_distance};

/// The positive-area overlaps between the spaces of two models: every pair
/// whose polygons share area, with both areas (holes excluded); and, for
/// the doors, their doorway lines and how much of each lies inside the
/// other model's non-door spaces.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Overlaps {
    /// Ids of the old model's spaces (in its order).
    pub old_ids: Vec<SpaceId>,
    /// Ids of the new model's spaces (in its order).
    pub new_ids: Vec<SpaceId>,
    /// Area in m² of each old space.
    pub old_area: Vec<f64>,
    /// Area in m² of each new space.
    pub new_area: Vec<f64>,
    /// `(old index, new index, intersection area m²)`, intersection > 0.
    pub pairs: Vec<(usize, usize, f64)>,
    /// `(old index, new index, share)` for a door of one model and a
    /// non-door space of the other: the share (0..1] of the door's doorway
    /// line inside the space, share > 0.
    pub door_shares: Vec<(usize, usize, f64)>,
    /// Per old space: its doorway and neighbours when it is a door.
    pub(crate) old_sides: Vec<Option<DoorSide>>,
    /// Per new space: its doorway and neighbours when it is a door.
    pub(crate) new_sides: Vec<Option<DoorSide>>,
}

impl Overlaps {
    /// Whether old space `i` is a door.
    pub fn old_is_door(&self, i: usize) -> bool {
        self.old_sides.get(i).is_some_and(Option::is_some)
    }

    /// Whether new space `j` is a door.
    pub fn new_is_door(&self, j: usize) -> bool {
        self.new_sides.get(j).is_some_and(Option::is_some)
    }

    /// Intersection over union of pair `(i, j, inter)`.
    pub fn iou(&self, i: usize, j: usize, inter: f64) -> f64 {
        let union = self.old_area[i] + self.new_area[j] - inter;
        if union > 0.0 && inter.is_finite() {
            (inter / union).clamp(0.0, 1.0)
        } else {
            0.0
        }
    }
}

/// A door's doorway line and the non-door spaces it opens onto.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct DoorSide {
    /// The doorway line (see the module doc); None for an empty polygon.
    pub(crate) line: Option<[Point; 2]>,
    /// Indices (into the model's spaces) of the non-door spaces it joins.
    pub(crate) neighbours: Vec<usize>,
}

impl DoorSide {
    /// The middle of the doorway line.
    pub(crate) fn centre(&self) -> Option<Point> {
        self.line
            .map(|[a, b]| [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0])
    }

    /// How far apart two doorways are: their centres' distance, or, when
    /// less, the distance from the shorter line's centre to the longer
    /// line (a doorway widened on one side, its old line inside the new).
    pub(crate) fn distance(&self, other: &DoorSide) -> Option<f64> {
        let (a, b) = (self.line?, other.line?);
        let (ca, cb) = (self.centre()?, other.centre()?);
        let length = |[p, q]: [Point; 2]| (q[0] - p[0]).hypot(q[1] - p[1]);
        let (short_centre, long) = if length(a) <= length(b) {
            (ca, b)
        } else {
            (cb, a)
        };
        let centres = (ca[0] - cb[0]).hypot(ca[1] - cb[1]);
        Some(centres.min(segment_distance(short_centre, long[0], long[1])))
    }
}
