//! Errors of reading and writing IndoorGML.

use std::path::PathBuf;

/// Why an IndoorGML document could not be read or written. Messages name
/// the line and element, what was expected, and a hint.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum IndoorGmlError {
    /// The file could not be opened, read or written.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// The file is larger than the configured limit.
    #[error(
        "{path}: the file is {size} bytes, above the limit of {limit} bytes (raise it with --max-bytes)"
    )]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// Its size.
        size: u64,
        /// The limit.
        limit: u64,
    },
    /// The bytes are not UTF-8.
    #[error("line {line}: the file is not UTF-8 text (IndoorGML is XML in UTF-8)")]
    NotUtf8 {
        /// Line of the first bad byte.
        line: usize,
    },
    /// Not well-formed XML.
    #[error("line {line}: malformed XML: {message}")]
    Xml {
        /// Line of the problem.
        line: usize,
        /// What the XML parser said.
        message: String,
    },
    /// The root element is not an IndoorGML 1.0 `IndoorFeatures`.
    #[error(
        "line {line}: the root element is {found}, expected core:IndoorFeatures in namespace {}{hint}",
        super::dom::NS_CORE
    )]
    UnknownRoot {
        /// Line of the root.
        line: usize,
        /// The root's qualified name.
        found: String,
        /// Extra advice for known cases.
        hint: String,
    },
    /// An element that does not belong where it stands.
    #[error("line {line}: unexpected element {found} in {parent}; expected {expected}")]
    Unexpected {
        /// Line of the element.
        line: usize,
        /// What was found.
        found: String,
        /// Its parent element.
        parent: String,
        /// What the schema allows there.
        expected: String,
    },
    /// A required element or attribute is missing.
    #[error("line {line}: {element} has no {missing}")]
    Missing {
        /// Line of the element.
        line: usize,
        /// The element lacking something.
        element: String,
        /// What it lacks.
        missing: String,
    },
    /// A number that does not parse or is not finite.
    #[error("line {line}: {element}: '{text}' is not a finite number")]
    BadNumber {
        /// Line of the element.
        line: usize,
        /// The element holding the number.
        element: String,
        /// The offending text.
        text: String,
    },
    /// Coordinates whose count does not fit the dimension.
    #[error("line {line}: {element} has {count} numbers, not a multiple of its dimension {dim}")]
    BadCoordinates {
        /// Line of the element.
        line: usize,
        /// The element.
        element: String,
        /// How many numbers.
        count: usize,
        /// The dimension.
        dim: usize,
    },
    /// An `srsName` whose positions cannot be placed.
    #[error("srsName {name}: {why}")]
    Crs {
        /// The `srsName`.
        name: String,
        /// Why.
        why: String,
    },
    /// The document cannot be turned into an NRG.
    #[error("{0}")]
    Model(String),
}
