//! The geometric gate a model passes before it is stored or written: the
//! checks `nrgdb check` runs on the model's IndoorGML form (rings closed
//! and simple, holes inside their shell, no two cells of the layer
//! overlapping), the repairs that keep the model's meaning
//! ([`repair_geometry`]) when they fail, and a refusal naming what is
//! still wrong when the repairs are not enough. One gate for extraction,
//! `import`, `convert` and uploads, so a file our checker calls broken
//! does not enter the database or leave `extract`.

use crate::indoorgml::{self, Finding};
use crate::model::{Nrg, Repair, repair_geometry};

use super::IngestError;

/// A model that passed the gate and what was repaired on the way.
#[derive(Debug, Clone, PartialEq)]
pub struct Validated {
    /// The model, repaired if needed.
    pub nrg: Nrg,
    /// What was repaired (empty for a model that was valid as read).
    pub repairs: Vec<Repair>,
    /// Findings kept because the caller allowed an invalid model (empty
    /// otherwise).
    pub kept: Vec<Finding>,
}

/// What `nrgdb check` finds in `nrg` (written as IndoorGML): empty for a
/// valid model.
///
/// ```
/// let nrg = nrgdb::fixtures::corridor_building(3);
/// assert!(nrgdb::ingest::findings(&nrg).is_empty());
/// ```
pub fn findings(nrg: &Nrg) -> Vec<Finding> {
    indoorgml::check(&indoorgml::from_nrg(nrg))
}

/// Passes `nrg` (read from `source`) through the gate: returned as it is
/// when valid, repaired when [`repair_geometry`] makes it valid, and
/// otherwise refused with the findings that remain — or, when
/// `allow_invalid`, kept as repaired with those findings listed.
///
/// ```
/// use nrgdb::ingest::validate;
/// let nrg = nrgdb::fixtures::corridor_building(3);
/// let done = validate(nrg.clone(), "lab.json", false)?;
/// assert_eq!(done.nrg, nrg);
/// assert!(done.repairs.is_empty());
/// # Ok::<(), nrgdb::ingest::IngestError>(())
/// ```
pub fn validate(nrg: Nrg, source: &str, allow_invalid: bool) -> Result<Validated, IngestError> {
    if findings(&nrg).is_empty() {
        return Ok(Validated {
            nrg,
            repairs: Vec::new(),
            kept: Vec::new(),
        });
    }
    let (repaired, repairs) = repair_geometry(&nrg).map_err(|e| IngestError::Invalid {
        source_name: source.to_string(),
        repaired: 0,
        findings: vec![Finding {
            code: "invalid-model",
            element: String::new(),
            line: 0,
            message: e.to_string(),
        }],
    })?;
    let left = findings(&repaired);
    if left.is_empty() || allow_invalid {
        return Ok(Validated {
            nrg: repaired,
            repairs,
            kept: left,
        });
    }
    Err(IngestError::Invalid {
        source_name: source.to_string(),
        repaired: repairs.len(),
        findings: left,
    })
}
