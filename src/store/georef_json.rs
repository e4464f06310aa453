//! A map's georeference as the engines keep it: one JSON text per map.

use super::StoreError;
use crate::model::Georef;

/// The stored text of `g`.
pub(crate) fn encode(g: &Georef) -> String {
    serde_json::to_string(g).unwrap_or_default()
}

/// The georeference stored for `map`, checked as when it was set.
pub(crate) fn decode(map: &str, text: &str) -> Result<Georef, StoreError> {
    let corrupt = |what: String| StoreError::Corrupt {
        map: map.to_string(),
        row: 0,
        what: format!("georeference: {what}"),
    };
    let g: Georef = serde_json::from_str(text).map_err(|e| corrupt(e.to_string()))?;
    g.checked().map_err(|e| corrupt(e.to_string()))
}
