//! Why an edit is refused.

use crate::model::{ModelError, SpaceId};

/// An edit that would make a wrong model, with the reason. Nothing is
/// changed when one is returned.
#[derive(Debug, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum EditError {
    /// A named space is not in the revision.
    #[error("there is no space {0} in this revision")]
    UnknownSpace(SpaceId),
    /// MERGE names fewer than two spaces.
    #[error("MERGE needs at least two spaces")]
    TooFewSpaces,
    /// MERGE names more spaces than it takes.
    #[error("MERGE names {count} spaces; at most {limit} at once")]
    TooManySpaces {
        /// How many were named.
        count: usize,
        /// The limit.
        limit: usize,
    },
    /// A space is named twice.
    #[error("space {0} is named twice")]
    NamedTwice(SpaceId),
    /// The spaces to merge do not form one piece.
    #[error(
        "{labels} do not touch: together they are {pieces} separate pieces (add a door between them first, or name the door between them too)"
    )]
    DoNotTouch {
        /// The spaces, by label.
        labels: String,
        /// How many pieces their union is.
        pieces: usize,
    },
    /// MERGE of doors only.
    #[error("MERGE needs at least one space that is not a door")]
    OnlyDoors,
    /// A number is NaN or infinite.
    #[error("{what} is not a finite number")]
    NotFinite {
        /// Which value.
        what: &'static str,
    },
    /// A split line shorter than a few centimetres.
    #[error("the split line is {length_m:.3} m long; draw it across the space")]
    LineTooShort {
        /// Its length.
        length_m: f64,
    },
    /// A split line that does not enter and leave the outline once each.
    #[error(
        "the line does not cut {label} in two: it crosses its outline {crossings} times (draw it across one part of the space, from wall to wall; its ends may stop up to 1 m short of the walls)"
    )]
    LineDoesNotCross {
        /// The space.
        label: String,
        /// How often it crosses the outline.
        crossings: usize,
    },
    /// A split line whose middle is not in the space.
    #[error(
        "the line's middle ({x:.2}, {y:.2}) is not inside {label}; draw the line across the space"
    )]
    MiddleOutside {
        /// The space.
        label: String,
        /// The middle.
        x: f64,
        /// The middle.
        y: f64,
    },
    /// A split line that runs along the outline.
    #[error("the line runs along the outline of {label}; draw it across the space")]
    LineAlongOutline {
        /// The space.
        label: String,
    },
    /// A split line through one of the space's holes.
    #[error("the line crosses an obstacle inside {label}; draw it around")]
    LineCrossesHole {
        /// The space.
        label: String,
    },
    /// A piece smaller than a sliver.
    #[error("the cut leaves a piece of {area_m2:.4} m² of {label}; draw the line farther in")]
    Sliver {
        /// The space.
        label: String,
        /// The piece's area.
        area_m2: f64,
    },
    /// A split's door that does not lie on its line.
    #[error(
        "the door at ({x:.2}, {y:.2}) is {off_m:.2} m from the split line; place it on the line, inside the space"
    )]
    DoorOffLine {
        /// Where it was asked for.
        x: f64,
        /// Where it was asked for.
        y: f64,
        /// How far from the cut.
        off_m: f64,
    },
    /// A door width out of range.
    #[error("a door {width_m} m wide: doors are {min} to {max} m wide")]
    DoorWidth {
        /// The width asked for.
        width_m: f64,
        /// Narrowest allowed.
        min: f64,
        /// Widest allowed.
        max: f64,
    },
    /// A door between a space and itself, or naming a door as a side.
    #[error("a door joins two different rooms, corridors or other spaces; {0}")]
    BadDoorSides(String),
    /// Two spaces too far apart for a door.
    #[error(
        "{a} and {b} are {gap_m:.2} m apart near ({x:.2}, {y:.2}); a door joins spaces that touch or face each other across a wall at most {limit} m thick"
    )]
    NotAdjacent {
        /// One side.
        a: String,
        /// The other side.
        b: String,
        /// Their distance there.
        gap_m: f64,
        /// Where the door was asked for.
        x: f64,
        /// Where the door was asked for.
        y: f64,
        /// The thickest wall a door may cross.
        limit: f64,
    },
    /// A door position far from the boundary between its sides.
    #[error(
        "({x:.2}, {y:.2}) is {off_m:.2} m from the boundary between {a} and {b}; put the door on it"
    )]
    FarFromBoundary {
        /// One side.
        a: String,
        /// The other side.
        b: String,
        /// How far.
        off_m: f64,
        /// Where the door was asked for.
        x: f64,
        /// Where the door was asked for.
        y: f64,
    },
    /// A new door that would overlap a third space.
    #[error("the door would overlap {0}; a door lies between its two sides only")]
    DoorOverlaps(String),
    /// A cut that would break a space into pieces.
    #[error("the door would cut {label} into {pieces} pieces")]
    WouldBreak {
        /// The space.
        label: String,
        /// Into how many.
        pieces: usize,
    },
    /// REMOVE DOOR of a space that is not a door.
    #[error("{label} is a {kind}, not a door")]
    NotADoor {
        /// The space.
        label: String,
        /// Its kind.
        kind: String,
    },
    /// A kind change to or from a door.
    #[error(
        "{0}: a door stays a door and other spaces do not become doors (use ADD DOOR and REMOVE DOOR)"
    )]
    DoorKind(String),
    /// An attribute name or value out of bounds.
    #[error("attribute {key:?}: {reason}")]
    BadAttribute {
        /// The name.
        key: String,
        /// What is wrong.
        reason: String,
    },
    /// The edit's geometry fails the checks `nrgdb check` runs.
    #[error("the edit would make geometry that `nrgdb check` rejects: {}", .0.join("; "))]
    Invalid(Vec<String>),
    /// The edited graph breaks an invariant of the model.
    #[error(transparent)]
    Model(#[from] ModelError),
}
