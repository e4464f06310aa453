//! XSD validation against the OGC IndoorGML schemas, by running the
//! offline `validate.sh` (xmllint) of the shared reference set when it is
//! available. nrgdb does not ship the schemas.

use std::path::{Path, PathBuf};
use std::process::Command;

use super::{Finding, finding};

/// The outcome of schema validation.
#[derive(Debug, Clone, PartialEq)]
pub enum SchemaVerdict {
    /// Valid against the IndoorGML 1.0.3 schemas.
    Valid,
    /// Invalid: one finding per validator error.
    Invalid(Vec<Finding>),
    /// No validator could be run; the reason.
    Unavailable(String),
}

/// Finds `validate.sh`: `$NRGDB_VALIDATE`, else
/// `$NRGDB_SHARED/indoorgml/validate.sh` (default `../shared`).
pub fn find_validator() -> Option<PathBuf> {
    if let Some(p) = std::env::var_os("NRGDB_VALIDATE") {
        return Some(PathBuf::from(p));
    }
    let shared =
        std::env::var_os("NRGDB_SHARED").map_or_else(|| PathBuf::from("../shared"), PathBuf::from);
    let script = shared.join("indoorgml").join("validate.sh");
    script.is_file().then_some(script)
}

/// Validates `file` with `validate.sh`, if one is found.
pub fn validate(file: &Path) -> SchemaVerdict {
    let Some(script) = find_validator() else {
        return SchemaVerdict::Unavailable(
            "validate.sh not found (set NRGDB_SHARED to the shared reference set, or NRGDB_VALIDATE to the script)".into(),
        );
    };
    let output = match Command::new("bash")
        .arg(&script)
        .arg("--quiet")
        .arg(file)
        .output()
    {
        Ok(o) => o,
        Err(e) => {
            return SchemaVerdict::Unavailable(format!("could not run {}: {e}", script.display()));
        }
    };
    match output.status.code() {
        Some(0) => SchemaVerdict::Valid,
        Some(1) => {
            let stderr = String::from_utf8_lossy(&output.stderr);
            SchemaVerdict::Invalid(stderr.lines().filter_map(|l| error_line(l, file)).collect())
        }
        _ => SchemaVerdict::Unavailable(format!(
            "{} could not validate: {}",
            script.display(),
            String::from_utf8_lossy(&output.stderr).trim()
        )),
    }
}

/// Turns `FILE:LINE: element X: Schemas validity error : …` into a finding.
fn error_line(line: &str, file: &Path) -> Option<Finding> {
    if line.starts_with("INVALID ") {
        return None;
    }
    let file = file.to_string_lossy();
    let rest = line
        .strip_prefix(file.as_ref())
        .and_then(|r| r.strip_prefix(':'))
        .unwrap_or(line);
    let (num, msg) = rest.split_once(':').unwrap_or(("0", rest));
    let n = num.trim().parse().unwrap_or(0);
    let msg = msg.trim();
    let element = msg
        .strip_prefix("element ")
        .and_then(|m| m.split(':').next())
        .unwrap_or("")
        .to_string();
    Some(finding("schema", &element, n, msg.to_string()))
}
