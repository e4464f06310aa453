//! `nrgdb check`: conformance findings for an IndoorGML document, 2D or 3D.
//!
//! What the OGC test suite checks (root, thick/thin doors, inter-layer
//! connections, solids with surfaces) plus what it does not: dangling
//! hrefs, duality that does not point back, `connects` naming non-States,
//! unclosed / self-intersecting / wrongly oriented polygons, and cells
//! overlapping inside one layer. Schema validity is checked separately by
//! [`schema::validate`] when a validator is available.

mod geometry;
mod overlap;
mod refs;
pub mod schema;

use std::fmt;

use super::Document;

/// One problem found in a document.
#[derive(Debug, Clone, PartialEq, Eq, Hash, serde::Serialize)]
pub struct Finding {
    /// Short machine-readable code, e.g. `dangling-href`.
    pub code: &'static str,
    /// The `gml:id` of the element concerned ("" for the document).
    pub element: String,
    /// Its line in the file (0 when unknown).
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for Finding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line > 0 {
            write!(f, "line {}: ", self.line)?;
        }
        if !self.element.is_empty() {
            write!(f, "{} ", self.element)?;
        }
        write!(f, "[{}]: {}", self.code, self.message)
    }
}

/// Puts findings from several checks (the checks, the schema validator)
/// in one report: ordered by line, each distinct finding once.
pub fn tidy(findings: Vec<Finding>) -> Vec<Finding> {
    let mut seen = std::collections::HashSet::new();
    let mut out: Vec<Finding> = findings
        .into_iter()
        .filter(|f| seen.insert(f.clone()))
        .collect();
    out.sort_by(|a, b| (a.line, &a.element, a.code).cmp(&(b.line, &b.element, b.code)));
    out
}

/// Every finding for `doc`, sorted by line.
pub fn check(doc: &Document) -> Vec<Finding> {
    let mut out = Vec::new();
    refs::check_ids(doc, &mut out);
    refs::check_references(doc, &mut out);
    refs::check_doors(doc, &mut out);
    geometry::check_geometry(doc, &mut out);
    overlap::check_overlaps(doc, &mut out);
    tidy(out)
}

fn finding(code: &'static str, element: &str, line: usize, message: String) -> Finding {
    Finding {
        code,
        element: element.to_string(),
        line,
        message,
    }
}
