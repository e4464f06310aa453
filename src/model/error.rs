//! Errors raised when a model breaks one of its invariants.

use super::SpaceId;

/// A model that is not a well-formed NRG.
#[derive(Debug, thiserror::Error, PartialEq)]
#[non_exhaustive]
pub enum ModelError {
    /// Two spaces share an id.
    #[error("space id {0} is used twice (ids must be unique)")]
    DuplicateSpace(SpaceId),
    /// A connection names a space that is not in the model.
    #[error("connection {a}-{b} names space {missing}, which is not in the model")]
    UnknownSpace {
        /// First end of the connection.
        a: SpaceId,
        /// Second end of the connection.
        b: SpaceId,
        /// The end that does not exist.
        missing: SpaceId,
    },
    /// A connection joins a space to itself.
    #[error("connection {0}-{0} joins a space to itself")]
    SelfLoop(SpaceId),
    /// Two connections join the same pair of spaces.
    #[error("spaces {a} and {b} are connected twice (at most one connection a pair)")]
    DuplicateConnection {
        /// First end.
        a: SpaceId,
        /// Second end.
        b: SpaceId,
    },
    /// A space's level is not usable.
    #[error("space {id}: {source}")]
    Level {
        /// The space concerned.
        id: SpaceId,
        /// Why.
        source: super::LevelError,
    },
    /// Levels that do not fit together: one name with two elevations,
    /// spaces with and without a level in one model.
    #[error("{0}")]
    Levels(String),
    /// A connection whose kind does not fit the levels of its ends.
    #[error("connection {a}-{b}: {why}")]
    LevelConnection {
        /// First end.
        a: SpaceId,
        /// Second end.
        b: SpaceId,
        /// What is wrong.
        why: String,
    },
    /// A coordinate or length is NaN or infinite.
    #[error("{what} of space {id} is not a finite number")]
    NotFinite {
        /// The space concerned.
        id: SpaceId,
        /// Which value is broken.
        what: &'static str,
    },
    /// A coordinate lies too far from the origin to be a building.
    #[error(
        "{what} of space {id} lies more than {limit_m} m from the origin; coordinates are metres in the map frame"
    )]
    TooFar {
        /// The space concerned.
        id: SpaceId,
        /// Which value is out of range.
        what: &'static str,
        /// The limit, metres.
        limit_m: f64,
    },
    /// A space name longer than a name can sensibly be.
    #[error("the name of space {id} has {chars} characters; at most {limit} are allowed")]
    NameTooLong {
        /// The space concerned.
        id: SpaceId,
        /// Its name's length in characters.
        chars: usize,
        /// The limit.
        limit: usize,
    },
    /// A connection length is negative or not finite.
    #[error("connection {a}-{b} has length {length_m} m; it must be finite and >= 0")]
    BadLength {
        /// First end.
        a: SpaceId,
        /// Second end.
        b: SpaceId,
        /// The offending length.
        length_m: f64,
    },
    /// A polygon ring with fewer than three distinct points.
    #[error("polygon of space {0} has fewer than 3 points")]
    DegeneratePolygon(SpaceId),
}
