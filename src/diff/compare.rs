//! The change-set service: what changed between two revisions, end to
//! end. [`compare`] is the one function that computes a change set for
//! callers: `nrgdb diff`, the query language's `DIFF`, the server's
//! `GET /diff`, and the pictures (`render --diff`, the viewer's `?diff=`),
//! which draw the change set it returns and never diff by themselves. It
//! takes both revisions (model, source grid when known, a label) and
//! [`DiffOptions`] (alignment mode, thresholds), decides whether the
//! frames differ, aligns when needed, then [`diff`]s.
//!
//! Frames differ when, at the identity transform, fewer than
//! `AlignParams::min_inliers` of B's wall points lie within the inlier
//! tolerance of A's walls, and fewer than that share of A's walls near
//! B's ([`alignment_quality`] both ways: a building extended or cut down
//! in the same frame still agrees one way). Walls come from the
//! occupancy grids the revisions were extracted from when both have one,
//! else, for both alike, from the boundary of the union of their space
//! polygons rasterised at 0.1 m ([`model_grid`]).
//!
//! Uses the aligner, the detector and the grid; must not use store, query
//! or anything above them (the query layer loads revisions with their
//! grids through its `Source` and calls this).

use super::align::{Alignment, align_grids, alignment_quality};
use super::change_set::ChangeSet;
use super::detect::diff_within;
use super::error::DiffError;
use super::matching::MAX_MATCH_PAIRS;
use super::params::{AlignMode, DiffOptions};
use super::transform::RigidTransform;
use crate::grid::{Cell, OccupancyGrid};
use crate::model::{Nrg, point_in_ring};

/// One side of a comparison: a model, the occupancy grid it was extracted
/// from when known, and a label for the change set (`from` / `to`).
///
/// ```
/// use nrgdb::diff::Revision;
/// let nrg = nrgdb::fixtures::corridor_building(2);
/// let side = Revision::new(&nrg).with_label("building@1");
/// assert!(side.grid.is_none());
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Revision<'a> {
    /// The model.
    pub nrg: &'a Nrg,
    /// Its source grid, if any.
    pub grid: Option<&'a OccupancyGrid>,
    /// What to call it in the change set (`map@rev`, a file name), if
    /// anything.
    pub label: Option<&'a str>,
}

impl<'a> Revision<'a> {
    /// A model without a grid or a label.
    pub fn new(nrg: &'a Nrg) -> Revision<'a> {
        Revision {
            nrg,
            grid: None,
            label: None,
        }
    }

    /// The same side with its source grid (or none).
    pub fn with_grid(self, grid: Option<&'a OccupancyGrid>) -> Revision<'a> {
        Revision { grid, ..self }
    }

    /// The same side with a label.
    pub fn with_label(self, label: &'a str) -> Revision<'a> {
        Revision {
            label: Some(label),
            ..self
        }
    }
}

/// The result of [`compare`].
#[derive(Debug, Clone)]
pub struct Comparison {
    /// The changes from A to B (B moved into A's frame when aligned), with
    /// the two labels as `from` and `to` and the transform as `alignment`.
    pub changes: ChangeSet,
    /// B in A's frame (B itself when not aligned): `apply(A, changes)`.
    pub moved: Nrg,
    /// The alignment used, if any, with its quality.
    pub alignment: Option<Alignment>,
    /// How well the frames agreed before aligning (at the identity, the
    /// larger of the shares of B's walls on A's and of A's on B's); `None`
    /// when that was not measured (`AlignMode::Never` or `Always`).
    pub identity_inliers: Option<f64>,
}

/// What changed from A to B: aligns B to A as `options.align` says
/// (refusing with [`DiffError::Unreliable`] or [`DiffError::TooFewWalls`]
/// when no reliable alignment exists), then diffs with `options.params`.
/// The change set records the transform in `alignment` and the sides'
/// labels in `from` and `to`. See the module doc.
///
/// ```
/// use nrgdb::diff::{compare, DiffOptions, Revision, RigidTransform};
/// let a = nrgdb::fixtures::corridor_building(5);
/// // The same building from another run: turned 30° and moved.
/// let b = RigidTransform::from_degrees(30.0, 2.0, 1.0).apply_to_nrg(&a)?;
/// // No grids: walls from the outlines.
/// let done = compare(Revision::new(&a), Revision::new(&b), &DiffOptions::default())?;
/// assert!(done.alignment.is_some() && done.changes.is_empty());
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn compare(
    a: Revision<'_>,
    b: Revision<'_>,
    options: &DiffOptions,
) -> Result<Comparison, DiffError> {
    let DiffOptions {
        align: mode,
        params,
        align_params: align,
        deadline,
    } = options;
    params.validate()?;
    let past = || deadline.is_some_and(|d| std::time::Instant::now() >= d);
    let mut identity_inliers = None;
    let mut alignment = None;
    if *mode != AlignMode::Never {
        let own;
        let (ga, gb) = match (a.grid, b.grid) {
            (Some(ga), Some(gb)) => (ga, gb),
            _ => {
                own = (
                    model_grid(a.nrg, MODEL_GRID_M),
                    model_grid(b.nrg, MODEL_GRID_M),
                );
                (&own.0, &own.1)
            }
        };
        let needed = *mode == AlignMode::Always || {
            // Both ways: a building extended (B ⊃ A) or cut down (B ⊂ A)
            // in the same frame still agrees in one direction.
            let ba = alignment_quality(ga, gb, RigidTransform::IDENTITY, align).inliers;
            let ab = alignment_quality(gb, ga, RigidTransform::IDENTITY, align).inliers;
            identity_inliers = Some(ba.max(ab));
            ba.max(ab) < align.min_inliers
        };
        if needed {
            alignment = Some(align_grids(ga, gb, align)?);
        }
    }
    if past() {
        return Err(DiffError::TimedOut);
    }
    let moved = match &alignment {
        Some(al) => al.transform.apply_to_nrg(b.nrg)?,
        None => b.nrg.clone(),
    };
    let Some(mut changes) = diff_within(a.nrg, &moved, params, MAX_MATCH_PAIRS, *deadline) else {
        return Err(if past() {
            DiffError::TimedOut
        } else {
            DiffError::TooManyOverlaps {
                limit: MAX_MATCH_PAIRS,
            }
        });
    };
    changes.alignment = alignment.map(|al| al.transform);
    changes.from = a.label.map(str::to_string);
    changes.to = b.label.map(str::to_string);
    Ok(Comparison {
        changes,
        moved,
        alignment,
        identity_inliers,
    })
}

/// Cell size of [`model_grid`], metres.
pub const MODEL_GRID_M: f64 = 0.1;

/// Most cells of a [`model_grid`] (a 200 m × 200 m building at 0.1 m):
/// larger models get larger cells, so a stranger's 2 km model costs no
/// more than a building.
pub const MAX_MODEL_GRID_CELLS: f64 = 4.0e6;

/// A stand-in occupancy grid for a model without one: cells whose centre
/// lies in a space are free, cells next to them occupied (the walls are
/// the boundary of the union of the spaces), the rest unknown. Cells are
/// `cell_m` wide, or wider when the model would need more than
/// [`MAX_MODEL_GRID_CELLS`].
pub fn model_grid(nrg: &Nrg, cell_m: f64) -> OccupancyGrid {
    let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
    for p in nrg.spaces().iter().flat_map(|s| &s.polygon) {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let extent = [hi[0] - lo[0], hi[1] - lo[1]];
    if nrg.spaces().is_empty()
        || !(extent[0].is_finite() && extent[1].is_finite())
        || !(cell_m.is_finite() && cell_m > 0.0)
    {
        return OccupancyGrid::from_cells(0, 0, cell_m.max(1e-3), [0.0; 3], Vec::new());
    }
    // With its two-cell margins, at most about MAX_MODEL_GRID_CELLS.
    let needed = (extent[0] / cell_m + 4.0) * (extent[1] / cell_m + 4.0);
    if !needed.is_finite() {
        return OccupancyGrid::from_cells(0, 0, cell_m.max(1e-3), [0.0; 3], Vec::new());
    }
    let cell_m = if needed > MAX_MODEL_GRID_CELLS {
        cell_m * (needed / MAX_MODEL_GRID_CELLS).sqrt() * 1.01
    } else {
        cell_m
    };
    let margin = 2.0 * cell_m;
    let (x0, y0) = (lo[0] - margin, lo[1] - margin);
    let w = (((hi[0] + margin - x0) / cell_m).ceil() as usize).clamp(1, 20_000);
    let h = (((hi[1] + margin - y0) / cell_m).ceil() as usize).clamp(1, 20_000);
    let mut free = vec![false; w * h];
    for s in nrg.spaces() {
        let (mut slo, mut shi) = ([f64::MAX; 2], [f64::MIN; 2]);
        for p in &s.polygon {
            for k in 0..2 {
                slo[k] = slo[k].min(p[k]);
                shi[k] = shi[k].max(p[k]);
            }
        }
        let c0 = ((slo[0] - x0) / cell_m).floor().max(0.0) as usize;
        let c1 = (((shi[0] - x0) / cell_m).ceil() as usize).min(w);
        // Row 0 is the top (largest y).
        let r0 = ((y0 + h as f64 * cell_m - shi[1]) / cell_m)
            .floor()
            .max(0.0) as usize;
        let r1 = (((y0 + h as f64 * cell_m - slo[1]) / cell_m).ceil() as usize).min(h);
        for r in r0..r1 {
            let y = y0 + (h - r) as f64 * cell_m - cell_m / 2.0;
            for c in c0..c1 {
                let x = x0 + (c as f64 + 0.5) * cell_m;
                if !free[r * w + c]
                    && point_in_ring([x, y], &s.polygon)
                    && !s.holes.iter().any(|hole| point_in_ring([x, y], hole))
                {
                    free[r * w + c] = true;
                }
            }
        }
    }
    let mut cells = vec![Cell::Unknown; w * h];
    for r in 0..h {
        for c in 0..w {
            let i = r * w + c;
            if free[i] {
                cells[i] = Cell::Free;
            } else {
                let near = [(0i64, 1i64), (0, -1), (1, 0), (-1, 0)]
                    .iter()
                    .any(|(dc, dr)| {
                        let (cc, rr) = (c as i64 + dc, r as i64 + dr);
                        cc >= 0
                            && rr >= 0
                            && (cc as usize) < w
                            && (rr as usize) < h
                            && free[rr as usize * w + cc as usize]
                    });
                if near {
                    cells[i] = Cell::Occupied;
                }
            }
        }
    }
    OccupancyGrid::from_cells(w as u32, h as u32, cell_m, [x0, y0, 0.0], cells)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diff::apply;
    use crate::fixtures::corridor_building;

    /// Issue 21: a model 2 km across (two rooms far apart) rasterised at
    /// 0.1 m was 400 million cells, cut off at 20 000 per side; now its
    /// cells grow and both rooms are in it.
    #[test]
    fn a_model_two_kilometres_wide_gets_a_bounded_grid() {
        use crate::model::{Space, SpaceId, SpaceKind};
        let room = |id, x: f64| {
            let poly = vec![[x, 0.0], [x + 10.0, 0.0], [x + 10.0, 8.0], [x, 8.0]];
            Space::new(SpaceId(id), SpaceKind::Room, [x + 5.0, 4.0], poly)
        };
        let nrg = Nrg::new(vec![room(1, 0.0), room(2, 1990.0)], vec![]).unwrap();
        let g = model_grid(&nrg, 0.1);
        let cells = f64::from(g.width) * f64::from(g.height);
        assert!(cells <= MAX_MODEL_GRID_CELLS * 1.05, "{cells} cells");
        for p in [[5.0, 4.0], [1995.0, 4.0]] {
            let px = g.metres_to_pixel(p);
            assert_eq!(
                g.cell(px[0] as u32, px[1] as u32),
                Some(Cell::Free),
                "{p:?}"
            );
        }
    }

    /// Issue 21, defect 7: the comparison stops at its deadline.
    #[test]
    fn a_comparison_past_its_deadline_stops() {
        let (a, b) = (corridor_building(3), corridor_building(4));
        let options = DiffOptions {
            deadline: Some(std::time::Instant::now()),
            ..DiffOptions::default()
        };
        let e = compare(Revision::new(&a), Revision::new(&b), &options).unwrap_err();
        assert!(matches!(e, DiffError::TimedOut), "{e:?}");
        let later = DiffOptions {
            deadline: std::time::Instant::now().checked_add(std::time::Duration::from_secs(60)),
            ..DiffOptions::default()
        };
        assert!(compare(Revision::new(&a), Revision::new(&b), &later).is_ok());
    }

    #[test]
    fn model_grids_make_walls_where_spaces_end() {
        let g = model_grid(&corridor_building(2), 0.1);
        assert!(g.free_count() > 0);
        // (0.05, 1.0) is inside the corridor; (-0.05, 1.0) is its wall.
        let inside = g.metres_to_pixel([0.05, 1.0]);
        let wall = g.metres_to_pixel([-0.05, 1.0]);
        assert_eq!(g.cell(inside[0] as u32, inside[1] as u32), Some(Cell::Free));
        assert_eq!(g.cell(wall[0] as u32, wall[1] as u32), Some(Cell::Occupied));
    }

    #[test]
    fn an_extension_in_the_same_frame_is_not_aligned() {
        let (a, b) = (corridor_building(2), corridor_building(9));
        let rev = Revision::new;
        let done = compare(rev(&a), rev(&b), &DiffOptions::default()).unwrap();
        assert!(done.alignment.is_none());
        assert!(done.changes.summary.added >= 14, "{}", done.changes.table());
    }

    #[test]
    fn auto_aligns_moved_models_and_not_others() {
        let a = corridor_building(6);
        let rev = Revision::new;
        let same = compare(rev(&a), rev(&a), &DiffOptions::default()).unwrap();
        assert!(same.alignment.is_none() && same.changes.is_empty());
        let t = RigidTransform::from_degrees(20.0, 3.0, -2.0);
        let b = t.apply_to_nrg(&a).unwrap();
        let moved = compare(
            rev(&a).with_label("a"),
            rev(&b).with_label("b"),
            &DiffOptions::default(),
        )
        .unwrap();
        assert_eq!(
            (moved.changes.from.as_deref(), moved.changes.to.as_deref()),
            (Some("a"), Some("b"))
        );
        let al = moved.alignment.unwrap();
        assert!(moved.identity_inliers.unwrap() < 0.5);
        assert!(moved.changes.is_empty(), "{}", moved.changes.table());
        let back = al.transform.after(&t);
        assert!(
            back.rotation_deg().abs() < 0.5 && back.tx_m.hypot(back.ty_m) < 0.15,
            "{back:?}"
        );
        assert_eq!(apply(&a, &moved.changes).unwrap(), moved.moved);
    }
}
