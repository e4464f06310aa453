//! Errors of parsing and executing queries.

use std::fmt;

use crate::model::SpaceId;
use crate::route::RouteError;

/// Where in the query text something went wrong: a byte range and the
/// 1-based line and column (in characters) of its start.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Span {
    /// Byte offset of the first byte.
    pub offset: usize,
    /// Length in bytes (at least 1 except at the end of input).
    pub len: usize,
    /// 1-based line.
    pub line: u32,
    /// 1-based column, in characters.
    pub column: usize,
}

impl fmt::Display for Span {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.line, self.column)
    }
}

/// An error from a [`super::Source`]: missing map or revision, or the
/// backend failing.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum SourceError {
    /// No map of that name.
    #[error("no map named '{name}'{} (see SHOW MAPS)", did_you_mean(suggestion))]
    NoMap {
        /// The name asked for.
        name: String,
        /// A close known name.
        suggestion: Option<String>,
    },
    /// The map has no such revision.
    #[error("map '{map}' has no revision {revision} (see SHOW REVISIONS OF {map})")]
    NoRevision {
        /// The map.
        map: String,
        /// The revision asked for.
        revision: u64,
    },
    /// A correction was refused (the reason names the space).
    #[error(transparent)]
    Edit(#[from] crate::edit::EditError),
    /// A write aimed at a revision that is not the map's latest.
    #[error(
        "revision {revision} is not the latest of '{map}' ({latest}); writes (NAME and the corrections) apply to the latest: USE {map} first"
    )]
    NotLatest {
        /// The map.
        map: String,
        /// The revision in use.
        revision: u64,
        /// The latest.
        latest: u64,
    },
    /// The storage backend failed.
    #[error("storage error: {0}")]
    Backend(Box<dyn std::error::Error + Send + Sync>),
}

fn did_you_mean(s: &Option<String>) -> String {
    s.as_ref()
        .map_or_else(String::new, |s| format!("; did you mean '{s}'?"))
}

/// Anything that stops a query: bad syntax, unknown names, limits, routing.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum QueryError {
    /// The text does not parse; `span` points at the offending token.
    #[error("{span}: {message}")]
    Syntax {
        /// The offending token.
        span: Span,
        /// What was expected and found, with a hint.
        message: String,
    },
    /// No space has this name.
    #[error("no space named '{name}'{}", did_you_mean(suggestion))]
    UnknownName {
        /// The name.
        name: String,
        /// A close existing name.
        suggestion: Option<String>,
    },
    /// No space has this id.
    #[error("no space {0} in this revision (FIND spaces lists them)")]
    UnknownId(SpaceId),
    /// `room 12` names a space of another kind.
    #[error("space {id} is a {actual}, not a {expected}")]
    WrongKind {
        /// The id.
        id: SpaceId,
        /// Kind written in the query.
        expected: String,
        /// Kind of the space.
        actual: String,
    },
    /// A point reference outside every space.
    #[error("no space contains the point ({x}, {y}) (coordinates are metres in the map frame)")]
    NoSpaceAt {
        /// x in metres.
        x: f64,
        /// y in metres.
        y: f64,
    },
    /// A point reference on a level where no space holds it, or on a
    /// level the map does not have.
    #[error("no space on level {level} contains the point ({x}, {y}){hint}")]
    NoSpaceOnLevel {
        /// x in metres.
        x: f64,
        /// y in metres.
        y: f64,
        /// The level named.
        level: String,
        /// What the map has instead (empty when the level exists).
        hint: String,
    },
    /// A statement needs a map and none is selected.
    #[error("no map selected (run USE <map>, or SHOW MAPS to list them)")]
    NoMapSelected,
    /// A statement that is not implemented yet.
    #[error("{0} is not available yet (it arrives with the diff issue)")]
    NotAvailable(&'static str),
    /// A comparison that cannot be evaluated.
    #[error("cannot compare {field} with {value} (hint: {hint})")]
    Type {
        /// The field.
        field: String,
        /// The literal.
        value: String,
        /// What would work.
        hint: &'static str,
    },
    /// A LIKE pattern longer than any name can be.
    #[error(
        "LIKE pattern of {chars} characters: at most {limit} (no name is longer; issue 21: \
         every row would be matched against it)"
    )]
    PatternTooLong {
        /// Its length in characters.
        chars: usize,
        /// The bound ([`crate::model::MAX_NAME_CHARS`]).
        limit: usize,
    },
    /// The time bound ran out.
    #[error("query exceeded its time bound of {0} ms (raise the timeout or narrow the query)")]
    Timeout(u128),
    /// The result is larger than the size bound.
    #[error("result has more than {0} rows (add LIMIT or raise the row bound)")]
    TooManyRows(usize),
    /// The statements run so far returned this many rows in all, the
    /// bound for one run (see `Limits::max_total_rows`).
    #[error(
        "the statements so far returned {0} rows in all, the bound for one request; this statement did not run (ask with LIMIT, or in several requests)"
    )]
    TooManyRowsInAll(usize),
    /// Storage failed or lacks the map/revision.
    #[error(transparent)]
    Source(#[from] SourceError),
    /// Routing failed (a missing route is not an error).
    #[error(transparent)]
    Route(#[from] RouteError),
    /// `DIFF` could not compare the two revisions (e.g. no reliable alignment).
    #[error(transparent)]
    Diff(#[from] crate::diff::DiffError),
}

impl QueryError {
    /// The span of a syntax error.
    pub fn span(&self) -> Option<Span> {
        match self {
            QueryError::Syntax { span, .. } => Some(*span),
            _ => None,
        }
    }
}
