//! IndoorGML 1.0.x and 1.1: read any 1.0.1 / 1.0.2 / 1.0.3 / 1.1
//! document, write 1.0.3 (or 1.1 on request), read and write the
//! IndoorGML 2.0 draft's JSON encoding ([`json2`], IndoorJSON2), convert to and from the [`Nrg`] model, and check a document's
//! conformance.
//!
//! Owns the XML side of the model: [`Document`] (a faithful picture of the
//! file, so 3D geometry, several layers and inter-layer connections
//! survive a round trip), the reader ([`read_str`], [`read_file`]), the
//! writer ([`write_string`], [`write_file`]), the mapping to and from the
//! model ([`from_nrg`], [`to_nrg`]) and the checker ([`check`]). Uses
//! quick-xml and the model; knows nothing of SQL, HTTP or the terminal,
//! nor of routing: walked Transition paths are passed in
//! ([`from_nrg_with_paths`]), and weights a document lacks are reported
//! ([`to_nrg_fixing`]) for the caller to walk.

pub mod check;
mod convert;
pub mod document;
mod dom;
mod error;
mod gml_read;
pub mod json2;
mod levels;
pub mod placed;
mod read;
mod version;
mod write;
mod xml_out;

use std::path::Path;

pub use check::{Finding, check, tidy};
pub use convert::{WeightFixes, from_nrg, from_nrg_with_paths, to_nrg, to_nrg_fixing};
pub use document::Document;
pub use dom::{NS_CORE, NS_GML, NS_NAVI};
pub use error::IndoorGmlError;
pub use levels::FLOOR_GAP_M;
pub use version::IndoorGmlVersion;

use crate::model::Nrg;

/// Files above this size are refused unless the caller raises the limit.
pub const DEFAULT_MAX_BYTES: u64 = 1 << 30;

/// Reads a document from XML text.
pub fn read_str(text: &str) -> Result<Document, IndoorGmlError> {
    read::read_document(text)
}

/// Reads a document from a file of at most `max_bytes` bytes.
pub fn read_file(path: &Path, max_bytes: u64) -> Result<Document, IndoorGmlError> {
    let text = read_text(path, max_bytes)?;
    read_str(&text)
}

/// Reads a file as UTF-8 text, refusing files above `max_bytes`.
pub fn read_text(path: &Path, max_bytes: u64) -> Result<String, IndoorGmlError> {
    let io = |source| IndoorGmlError::Io {
        path: path.to_path_buf(),
        source,
    };
    let size = std::fs::metadata(path).map_err(io)?.len();
    if size > max_bytes {
        return Err(IndoorGmlError::TooLarge {
            path: path.to_path_buf(),
            size,
            limit: max_bytes,
        });
    }
    let bytes = std::fs::read(path).map_err(io)?;
    String::from_utf8(bytes).map_err(|e| {
        let valid = e.utf8_error().valid_up_to();
        let line = 1 + e
            .as_bytes()
            .get(..valid)
            .map_or(0, |b| b.iter().filter(|&&c| c == b'\n').count());
        IndoorGmlError::NotUtf8 { line }
    })
}

/// The document as IndoorGML text of the version it was read as
/// (1.0.3 for a document built in memory).
pub fn write_string(doc: &Document) -> String {
    write_string_as(doc, doc.version)
}

/// The document as IndoorGML `version` text.
pub fn write_string_as(doc: &Document, version: IndoorGmlVersion) -> String {
    let bytes = write::write_document_as(doc, version, Vec::new()).unwrap_or_default();
    String::from_utf8(bytes).unwrap_or_default()
}

/// Writes the document to `path` atomically (temp file + rename), in the
/// version it was read as.
pub fn write_file(doc: &Document, path: &Path) -> Result<(), IndoorGmlError> {
    write_file_as(doc, doc.version, path)
}

/// Writes the document to `path` atomically as IndoorGML `version`.
pub fn write_file_as(
    doc: &Document,
    version: IndoorGmlVersion,
    path: &Path,
) -> Result<(), IndoorGmlError> {
    crate::atomic::write_with(path, |w| {
        write::write_document_as(doc, version, w).map(|_| ())
    })
    .map_err(|source| IndoorGmlError::Io {
        path: path.to_path_buf(),
        source,
    })
}

/// Reads an IndoorGML file straight into a model.
pub fn read_nrg_file(path: &Path, max_bytes: u64) -> Result<Nrg, IndoorGmlError> {
    to_nrg(&read_file(path, max_bytes)?)
}

/// Writes a model as an IndoorGML file, atomically.
pub fn write_nrg_file(nrg: &Nrg, path: &Path) -> Result<(), IndoorGmlError> {
    write_file(&from_nrg(nrg), path)
}
