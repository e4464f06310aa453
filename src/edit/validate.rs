//! The edit's gate: what `nrgdb check` would newly find.
//!
//! Only the spaces an edit made or changed, and the spaces whose boxes
//! touch them, are checked, before and after: a finding that was there
//! before the edit (an imported model kept with its findings) does not
//! block an unrelated edit, and a large model is not checked whole for
//! every edit.

use std::collections::BTreeSet;

use super::{EditError, Edited};
use crate::model::{Nrg, Space, SpaceId};

/// Refuses `edited` when its changed spaces fail a check that `before`
/// passed.
pub(super) fn no_new_findings(before: &Nrg, edited: &Edited) -> Result<(), EditError> {
    let changed: Vec<&Space> = edited
        .nrg
        .spaces()
        .iter()
        .filter(|s| before.space(s.id).is_none_or(|b| !b.same_but_id(s)))
        .collect();
    if changed.is_empty() {
        return Ok(());
    }
    let boxes: Vec<[f64; 4]> = changed.iter().map(|s| bounds(s)).collect();
    let near = |s: &Space| {
        let b = bounds(s);
        boxes
            .iter()
            .any(|c| b[0] <= c[2] && c[0] <= b[2] && b[1] <= c[3] && c[1] <= b[3])
    };
    let ids: BTreeSet<SpaceId> = edited
        .nrg
        .spaces()
        .iter()
        .chain(before.spaces())
        .filter(|s| near(s))
        .map(|s| s.id)
        .collect();
    let found = |nrg: &Nrg| -> Result<BTreeSet<String>, EditError> {
        let spaces: Vec<Space> = nrg
            .spaces()
            .iter()
            .filter(|s| ids.contains(&s.id))
            .cloned()
            .collect();
        let part = Nrg::new(spaces, vec![])?;
        Ok(crate::indoorgml::check(&crate::indoorgml::from_nrg(&part))
            .into_iter()
            .map(|f| f.message)
            .collect())
    };
    let old = found(before)?;
    let new: Vec<String> = found(&edited.nrg)?
        .into_iter()
        .filter(|m| !old.contains(m))
        .collect();
    if new.is_empty() {
        Ok(())
    } else {
        Err(EditError::Invalid(new))
    }
}

/// `[min x, min y, max x, max y]` of the space's shell.
fn bounds(s: &Space) -> [f64; 4] {
    crate::model::bounds(&s.polygon).unwrap_or([
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ])
}
