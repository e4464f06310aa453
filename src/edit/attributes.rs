//! SET KIND, SET ATTRIBUTE and UNSET ATTRIBUTE.

use serde_json::Value;

use super::{EditError, Edited};
use crate::model::{Nrg, SpaceId, SpaceKind};

/// Longest attribute name, in characters.
pub const MAX_KEY_CHARS: usize = 64;
/// Longest attribute value, in characters of its JSON form.
pub const MAX_VALUE_CHARS: usize = 4_096;

/// `id` with kind `kind`; doors stay doors.
pub(super) fn set_kind(nrg: &Nrg, id: SpaceId, kind: SpaceKind) -> Result<Edited, EditError> {
    let space = nrg.space(id).ok_or(EditError::UnknownSpace(id))?;
    if (space.kind == SpaceKind::Door) != (kind == SpaceKind::Door) {
        return Err(EditError::DoorKind(space.label()));
    }
    replace(nrg, id, |s| s.kind = kind)
}

/// `id` with attribute `key` set to `value` (removed when `None`).
pub(super) fn set_attribute(
    nrg: &Nrg,
    id: SpaceId,
    key: &str,
    value: Option<&Value>,
) -> Result<Edited, EditError> {
    let space = nrg.space(id).ok_or(EditError::UnknownSpace(id))?;
    let bad = |reason: &str| EditError::BadAttribute {
        key: key.chars().take(MAX_KEY_CHARS).collect(),
        reason: reason.to_string(),
    };
    if key.trim().is_empty() {
        return Err(bad("the name is empty"));
    }
    if key.chars().count() > MAX_KEY_CHARS {
        return Err(bad(&format!(
            "names are at most {MAX_KEY_CHARS} characters"
        )));
    }
    if key.chars().any(char::is_control) {
        return Err(bad("the name contains control characters"));
    }
    match value {
        Some(v) => {
            let chars = v.to_string().chars().count();
            if chars > MAX_VALUE_CHARS {
                return Err(bad(&format!(
                    "the value has {chars} characters; at most {MAX_VALUE_CHARS}"
                )));
            }
            if matches!(v, Value::Number(n) if n.as_f64().is_none_or(|f| !f.is_finite())) {
                return Err(bad("the value is not a finite number"));
            }
        }
        None if !space.attributes.contains_key(key) => {
            return Err(bad(&format!("{} has no such attribute", space.label())));
        }
        None => {}
    }
    replace(nrg, id, |s| match value {
        Some(v) => {
            s.attributes.insert(key.to_string(), v.clone());
        }
        None => {
            s.attributes.remove(key);
        }
    })
}

fn replace(
    nrg: &Nrg,
    id: SpaceId,
    change: impl FnOnce(&mut crate::model::Space),
) -> Result<Edited, EditError> {
    let (mut spaces, connections) = nrg.clone().into_parts();
    if let Some(s) = spaces.iter_mut().find(|s| s.id == id) {
        change(s);
        s.update_doorway();
    }
    Ok(Edited {
        nrg: Nrg::new(spaces, connections)?,
        created: vec![],
        removed: vec![],
    })
}
