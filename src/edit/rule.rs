//! Corrections kept as rules: an [`Edit`] with the footprints of the
//! spaces it named when it was made, so that it can be applied again to a
//! re-mapped revision, where the same rooms have other ids and slightly
//! other outlines.
//!
//! A named space is found again by overlap: the space of the new model
//! that holds at least half of the old footprint and whose own area is at
//! least half inside it (doors match doors, other spaces other spaces).
//! When none does, the reason says what happened to it: split, merged into
//! a larger space, or gone.

use geo::{Area, BooleanOps, BoundingRect, Intersects, LineString, Polygon};
use serde::{Deserialize, Serialize};

use super::{Edit, EditError, Edited, apply};
use crate::model::{Nrg, Point, Ring, SpaceId, SpaceKind};

/// Share of a footprint (and of the matching space) that must overlap.
const MATCH_SHARE: f64 = 0.5;
/// Share of a footprint a piece must hold to count as a piece of it.
const PIECE_SHARE: f64 = 0.2;
/// How close (metres) an existing door must be to an added door's
/// position for the addition to be already done.
const SAME_DOOR_M: f64 = 0.5;

/// A space as an edit named it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Footprint {
    /// Its stable id when the edit was made.
    pub id: SpaceId,
    /// Its label then ("Hall", "room 12").
    pub label: String,
    /// Whether it was a door.
    pub door: bool,
    /// Its outline (shell), metres in the map frame.
    pub outline: Ring,
}

/// An edit and the footprints of the spaces it names, as stored with a
/// correction.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Rule {
    /// The edit, naming the ids of the revision it was made on.
    pub edit: Edit,
    /// The named spaces as they were, in the order the edit names them.
    pub footprints: Vec<Footprint>,
}

/// A rule applied to a new model.
#[derive(Debug, Clone, PartialEq)]
pub struct Reapplied {
    /// The model after the edit.
    pub edited: Edited,
    /// Set when there was nothing to do ("already done").
    pub note: Option<String>,
}

impl Rule {
    /// The rule for `edit` made on `nrg` (the model before the edit).
    pub fn record(nrg: &Nrg, edit: &Edit) -> Result<Rule, EditError> {
        let footprints = edit
            .spaces()
            .into_iter()
            .map(|id| {
                let s = nrg.space(id).ok_or(EditError::UnknownSpace(id))?;
                Ok(Footprint {
                    id,
                    label: s.label(),
                    door: s.kind == SpaceKind::Door,
                    outline: s.polygon.clone(),
                })
            })
            .collect::<Result<_, EditError>>()?;
        Ok(Rule {
            edit: edit.clone(),
            footprints,
        })
    }

    /// The edit applied again to `nrg` (a re-mapped revision), its spaces
    /// found by overlap; `Err` with the reason when it no longer fits.
    pub fn reapply(&self, nrg: &Nrg, next_id: SpaceId) -> Result<Reapplied, String> {
        let unchanged = |note: &str| Reapplied {
            edited: Edited {
                nrg: nrg.clone(),
                created: vec![],
                removed: vec![],
            },
            note: Some(note.to_string()),
        };
        let mut found = Vec::with_capacity(self.footprints.len());
        for f in &self.footprints {
            match find(nrg, f) {
                Ok(id) => found.push((f.id, id)),
                // A door that is gone needs no removing.
                Err(_) if matches!(self.edit, Edit::RemoveDoor { .. }) => {
                    return Ok(unchanged("the door is already gone"));
                }
                Err(reason) => return Err(reason),
            }
        }
        let rename = |id: SpaceId| {
            found
                .iter()
                .find(|(old, _)| *old == id)
                .map_or(id, |(_, new)| *new)
        };
        let mut edit = self.edit.with_spaces(rename);
        if let Some(note) = already_done(nrg, &edit) {
            return Ok(unchanged(&note));
        }
        if let Edit::Merge { spaces, name } = &mut edit {
            // Spaces the new map already joined are named once.
            let mut unique: Vec<SpaceId> = Vec::new();
            for s in spaces.iter() {
                if !unique.contains(s) {
                    unique.push(*s);
                }
            }
            if let [one] = unique[..] {
                let edited = renamed(nrg, one, name.as_deref()).map_err(|e| e.to_string())?;
                return Ok(Reapplied {
                    edited,
                    note: Some("already one space".to_string()),
                });
            }
            *spaces = unique;
        }
        apply(nrg, &edit, next_id)
            .map(|edited| Reapplied { edited, note: None })
            .map_err(|e| e.to_string())
    }
}

/// The space of `nrg` that `f` continues, or why there is none.
fn find(nrg: &Nrg, f: &Footprint) -> Result<SpaceId, String> {
    let shape = to_polygon(&f.outline);
    let area = shape.unsigned_area();
    if area <= 0.0 {
        return Err(format!("{} had no area", f.label));
    }
    let bounds = shape.bounding_rect();
    let mut best: Option<(f64, SpaceId)> = None;
    let mut pieces = 0;
    let mut inside: Option<String> = None;
    for s in nrg
        .spaces()
        .iter()
        .filter(|s| (s.kind == SpaceKind::Door) == f.door)
    {
        let other = to_polygon(&s.polygon);
        let near = match (other.bounding_rect(), bounds) {
            (Some(x), Some(y)) => x.intersects(&y),
            _ => false,
        };
        if !near {
            continue;
        }
        let common = other.intersection(&shape).unsigned_area();
        let (share, own) = (common / area, common / s.area_m2.max(f64::MIN_POSITIVE));
        if share >= PIECE_SHARE {
            pieces += 1;
        }
        if share >= MATCH_SHARE && own >= MATCH_SHARE {
            if best.is_none_or(|(c, _)| common > c) {
                best = Some((common, s.id));
            }
        } else if share >= MATCH_SHARE {
            inside = Some(s.label());
        }
    }
    match (best, inside) {
        (Some((_, id)), _) => Ok(id),
        (None, Some(larger)) => Err(format!(
            "{} is now part of a larger space ({larger})",
            f.label
        )),
        (None, None) if pieces >= 2 => Err(format!("{} was split", f.label)),
        (None, None) => Err(format!("{} is no longer in the map", f.label)),
    }
}

/// Why `edit` needs no doing on `nrg`, if so.
fn already_done(nrg: &Nrg, edit: &Edit) -> Option<String> {
    match edit {
        Edit::AddDoor { a, b, at, .. } => {
            let near = |p: Point| (p[0] - at[0]).hypot(p[1] - at[1]) <= SAME_DOOR_M;
            nrg.spaces()
                .iter()
                .filter(|s| s.kind == SpaceKind::Door && near(s.anchor))
                .any(|d| nrg.connection(d.id, *a).is_some() && nrg.connection(d.id, *b).is_some())
                .then(|| "the door is already there".to_string())
        }
        _ => None,
    }
}

/// `nrg` with space `id` named `name` (unchanged without one).
fn renamed(nrg: &Nrg, id: SpaceId, name: Option<&str>) -> Result<Edited, EditError> {
    let (mut spaces, connections) = nrg.clone().into_parts();
    if let Some(name) = name {
        for s in spaces.iter_mut().filter(|s| s.id == id) {
            s.name = Some(name.to_string());
        }
    }
    Ok(Edited {
        nrg: Nrg::new(spaces, connections)?,
        created: vec![],
        removed: vec![],
    })
}

fn to_polygon(ring: &[Point]) -> Polygon {
    Polygon::new(
        LineString::new(
            ring.iter()
                .map(|p| geo::Coord { x: p[0], y: p[1] })
                .collect(),
        ),
        vec![],
    )
}
