//! Comparing two revisions of a stored map: each revision is loaded from a
//! [`Source`] with the occupancy grid it was extracted from, labelled
//! `map@rev`, and handed to [`crate::diff::compare`], the change-set
//! service. `DIFF` runs on this, and so do the server's `GET /diff`, the
//! viewer's `?diff=` and the CLI's `nrgdb diff NAME A B` and
//! `render --diff`, so a pair of revisions gives one change set wherever it
//! is asked for.
//!
//! Uses the source and diff; must not use store, server or the terminal.

use super::error::QueryError;
use super::source::Source;
use crate::diff::{Comparison, DiffOptions, Revision, compare};
use crate::grid::OccupancyGrid;
use crate::model::Nrg;

/// One revision as a side of a comparison: its model, its source grid
/// when the source keeps one, and its label.
#[derive(Debug, Clone)]
pub struct LoadedRevision {
    /// `map@rev`.
    pub label: String,
    /// The model.
    pub nrg: Nrg,
    /// The grid it was extracted from, if the source has it.
    pub grid: Option<OccupancyGrid>,
}

impl LoadedRevision {
    /// Loads revision `revision` of `map` with its grid.
    ///
    /// ```
    /// use nrgdb::query::{LoadedRevision, MemorySource, demo};
    /// let mut source = MemorySource::new();
    /// source.insert("demo", demo::building(2));
    /// let rev = LoadedRevision::load(&source, "demo", 1)?;
    /// assert_eq!(rev.label, "demo@1");
    /// assert!(rev.grid.is_none());
    /// # Ok::<(), nrgdb::query::SourceError>(())
    /// ```
    pub fn load<S: Source + ?Sized>(
        source: &S,
        map: &str,
        revision: u64,
    ) -> Result<LoadedRevision, super::SourceError> {
        Ok(LoadedRevision {
            label: format!("{map}@{revision}"),
            nrg: source.load(map, revision)?,
            grid: source.grid(map, revision)?,
        })
    }

    /// This revision as a side of [`compare`].
    pub fn side(&self) -> Revision<'_> {
        Revision::new(&self.nrg)
            .with_grid(self.grid.as_ref())
            .with_label(&self.label)
    }
}

/// Two revisions and what changed between them.
#[derive(Debug, Clone)]
pub struct RevisionComparison {
    /// The base revision (A).
    pub old: LoadedRevision,
    /// The revision compared with it (B), in its own frame.
    pub new: LoadedRevision,
    /// The change set, alignment and B in A's frame.
    pub comparison: Comparison,
}

/// What changed from revision `from` to revision `to` of `map`: both
/// loaded with their grids ([`LoadedRevision::load`]) and compared with
/// `options` by [`crate::diff::compare`].
///
/// ```
/// use nrgdb::diff::DiffOptions;
/// use nrgdb::query::{MemorySource, compare_revisions};
/// let mut source = MemorySource::new();
/// source.insert("m", nrgdb::fixtures::corridor_building(3));
/// source.insert("m", nrgdb::fixtures::corridor_building(4));
/// let done = compare_revisions(&source, "m", 1, 2, &DiffOptions::default())?;
/// let changes = &done.comparison.changes;
/// assert_eq!((changes.from.as_deref(), changes.summary.added), (Some("m@1"), 2));
/// # Ok::<(), nrgdb::query::QueryError>(())
/// ```
pub fn compare_revisions<S: Source + ?Sized>(
    source: &S,
    map: &str,
    from: u64,
    to: u64,
    options: &DiffOptions,
) -> Result<RevisionComparison, QueryError> {
    let old = LoadedRevision::load(source, map, from)?;
    let new = LoadedRevision::load(source, map, to)?;
    let comparison = compare(old.side(), new.side(), options)?;
    Ok(RevisionComparison {
        old,
        new,
        comparison,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diff::RigidTransform;
    use crate::grid::{Cell, OccupancyGrid};
    use crate::query::MemorySource;

    /// A room with an inner wall, 0.1 m/px, and its model: one room.
    fn room() -> (OccupancyGrid, Nrg) {
        let (w, h) = (60u32, 40u32);
        let mut cells = vec![Cell::Free; (w * h) as usize];
        for r in 0..h {
            for c in 0..w {
                if r == 0 || c == 0 || r == h - 1 || c == w - 1 || (c == 20 && r < 25) {
                    cells[(r * w + c) as usize] = Cell::Occupied;
                }
            }
        }
        let grid = OccupancyGrid::from_cells(w, h, 0.1, [0.0; 3], cells);
        (grid, crate::fixtures::corridor_building(1))
    }

    #[test]
    fn grids_decide_the_alignment() {
        // Two revisions whose models agree but whose grids are in frames
        // 90° apart: with the grids, the diff aligns; the models alone
        // would not (they share a frame).
        let (grid, nrg) = room();
        let mut turned = grid.clone();
        turned.origin = [1.0, 0.0, 90f64.to_radians()];
        let mut source = MemorySource::new();
        source.insert_with_grid("m", nrg.clone(), grid);
        source.insert_with_grid("m", nrg.clone(), turned);
        let done = compare_revisions(&source, "m", 1, 2, &DiffOptions::default()).unwrap();
        let al = done.comparison.alignment.expect("aligned on the grids");
        let want = RigidTransform::from_degrees(90.0, 1.0, 0.0).inverse();
        assert!(
            (al.transform.rotation_deg() - want.rotation_deg()).abs() < 0.5,
            "{al:?}"
        );
        assert_eq!(done.comparison.changes.to.as_deref(), Some("m@2"));
        assert!(done.new.grid.is_some() && done.old.grid.is_some());
    }
}
