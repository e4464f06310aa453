//! A loaded revision with the indexes queries need: the route graph, an
//! R*-tree of polygon envelopes (for LOCATE and point references) and names.

use std::collections::HashMap;

use rstar::RTree;
use rstar::primitives::{GeomWithData, Rectangle};

use super::ast::SpaceRef;
use super::error::QueryError;
use super::suggest::suggest;
use crate::model::{Nrg, Point, Space, SpaceId, point_in_ring};
use std::sync::Arc;

use crate::route::{NavMesh, RouteError, RouteGraph};

type Envelope = GeomWithData<Rectangle<[f64; 2]>, usize>;

/// One revision of one map, indexed. Built once when a revision is selected.
#[derive(Debug)]
pub struct IndexedRevision {
    /// The map's name.
    pub map: String,
    /// The revision number.
    pub revision: u64,
    /// The model.
    pub nrg: Arc<Nrg>,
    /// Navigable adjacency (NEIGHBOURS).
    pub graph: RouteGraph,
    /// The navigation layer (ROUTE, REACHABLE).
    pub nav: NavMesh,
    envelopes: RTree<Envelope>,
    names: HashMap<String, Vec<SpaceId>>,
}

impl IndexedRevision {
    /// Indexes `nrg` as `map` at `revision`.
    pub fn new(map: &str, revision: u64, nrg: Nrg) -> IndexedRevision {
        let graph = RouteGraph::new(&nrg);
        let nrg = Arc::new(nrg);
        let nav = NavMesh::new(nrg.clone());
        let envelopes = nrg
            .spaces()
            .iter()
            .enumerate()
            .filter(|(_, s)| !s.polygon.is_empty())
            .map(|(i, s)| {
                let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
                for p in &s.polygon {
                    for k in 0..2 {
                        lo[k] = lo[k].min(p[k]);
                        hi[k] = hi[k].max(p[k]);
                    }
                }
                GeomWithData::new(Rectangle::from_corners(lo, hi), i)
            })
            .collect();
        let mut names: HashMap<String, Vec<SpaceId>> = HashMap::new();
        for s in nrg.spaces() {
            if let Some(n) = &s.name {
                names.entry(n.to_lowercase()).or_default().push(s.id);
            }
        }
        IndexedRevision {
            map: map.to_string(),
            revision,
            nrg,
            graph,
            nav,
            envelopes: RTree::bulk_load(envelopes),
            names,
        }
    }

    /// The space containing `p` (R*-tree on envelopes, then point-in-polygon
    /// with holes); the smallest by area when several overlap.
    pub fn locate(&self, p: Point) -> Option<&Space> {
        self.envelopes
            .locate_all_at_point(&p)
            .filter_map(|e| self.nrg.spaces().get(e.data))
            .filter(|s| {
                point_in_ring(p, &s.polygon) && !s.holes.iter().any(|h| point_in_ring(p, h))
            })
            .min_by(|a, b| a.area_m2.total_cmp(&b.area_m2).then(a.id.cmp(&b.id)))
    }

    /// The spaces containing `p`: on `level` only when given, else the
    /// smallest on each level (one for a model without levels), lowest
    /// level first.
    pub fn locate_on(&self, p: Point, level: Option<&str>) -> Vec<&Space> {
        let mut best: Vec<&Space> = Vec::new();
        let containing = self
            .envelopes
            .locate_all_at_point(&p)
            .filter_map(|e| self.nrg.spaces().get(e.data))
            .filter(|s| {
                level.is_none_or(|l| s.level.as_ref().is_some_and(|m| m.name == l))
                    && point_in_ring(p, &s.polygon)
                    && !s.holes.iter().any(|h| point_in_ring(p, h))
            });
        for s in containing {
            let same =
                |b: &&Space| b.level.as_ref().map(|l| &l.name) == s.level.as_ref().map(|l| &l.name);
            match best.iter_mut().find(|b| same(b)) {
                Some(b) if (s.area_m2, s.id) < (b.area_m2, b.id) => *b = s,
                Some(_) => {}
                None => best.push(s),
            }
        }
        best.sort_by(|a, b| {
            let e = |s: &Space| s.level.as_ref().map_or(0.0, |l| l.elevation_m);
            e(a).total_cmp(&e(b))
        });
        best
    }

    /// The error for a point outside every space, naming the nearest one.
    pub fn outside(&self, p: Point) -> RouteError {
        self.nav.outside(p)
    }

    /// Resolves a reference to a space id, with helpful errors.
    pub fn resolve(&self, r: &SpaceRef) -> Result<SpaceId, QueryError> {
        match r {
            SpaceRef::Id { kind, id } => {
                let s = self.nrg.space(*id).ok_or(QueryError::UnknownId(*id))?;
                match kind {
                    Some(k) if *k != s.kind => Err(QueryError::WrongKind {
                        id: *id,
                        expected: k.to_string(),
                        actual: s.kind.to_string(),
                    }),
                    _ => Ok(*id),
                }
            }
            SpaceRef::Name(name) => match self.names.get(&name.to_lowercase()) {
                Some(ids) if !ids.is_empty() => Ok(ids[0]),
                _ => Err(QueryError::UnknownName {
                    name: name.clone(),
                    suggestion: suggest(
                        name,
                        self.nrg.spaces().iter().filter_map(|s| s.name.as_deref()),
                    )
                    .map(str::to_string),
                }),
            },
            SpaceRef::Point(p) => self
                .locate(*p)
                .map(|s| s.id)
                .ok_or(QueryError::NoSpaceAt { x: p[0], y: p[1] }),
            SpaceRef::PointOn { at, level } => match self.point_on(*at, level)? {
                crate::route::Endpoint::PointIn(_, id) => Ok(id),
                _ => Err(QueryError::NoSpaceAt { x: at[0], y: at[1] }),
            },
        }
    }

    /// The point `at` on level `level` as a route's end (in the space
    /// holding it there); errors name the level, or the levels the map
    /// has when it has not this one.
    pub fn point_on(&self, at: Point, level: &str) -> Result<crate::route::Endpoint, QueryError> {
        let outside = |hint: String| QueryError::NoSpaceOnLevel {
            x: at[0],
            y: at[1],
            level: level.to_string(),
            hint,
        };
        let levels = self.nrg.levels();
        if !levels.iter().any(|l| l.name == level) {
            let names: Vec<&str> = levels.iter().map(|l| l.name.as_str()).collect();
            return Err(outside(if names.is_empty() {
                ": this map has no levels".to_string()
            } else {
                format!(
                    ": the map has no level {level} (it has {})",
                    names.join(", ")
                )
            }));
        }
        // The revision's own index, not a scan of every space.
        self.locate_on(at, Some(level))
            .first()
            .map(|s| crate::route::Endpoint::PointIn(at, s.id))
            .ok_or_else(|| outside(String::new()))
    }

    /// The label of a space ("Kitchen", "door 7"), or "space N" if missing.
    pub fn label(&self, id: SpaceId) -> String {
        self.nrg
            .space(id)
            .map_or_else(|| format!("space {id}"), Space::label)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::query::demo;

    #[test]
    fn locate_and_resolve() {
        let idx = IndexedRevision::new("demo", 1, demo::building(3));
        let kitchen = idx.resolve(&SpaceRef::Name("kitchen".into())).unwrap();
        assert_eq!(idx.locate([2.0, 9.0]).map(|s| s.id), Some(kitchen));
        assert!(idx.locate([-5.0, 9.0]).is_none());
        let e = idx.resolve(&SpaceRef::Name("Kitchn".into())).unwrap_err();
        assert_eq!(
            e.to_string(),
            "no space named 'Kitchn'; did you mean 'Kitchen'?"
        );
    }

    #[test]
    fn width_is_the_declared_width_else_the_doorway() {
        // Door 2 declares 0.9 m; door 7 is a 1.0 m opening through a
        // 0.3 m wall and declares nothing: its width is the opening, the
        // long side of its rectangle (was the 0.3 m depth).
        let nrg = demo::building(2);
        let d0 = nrg.space(SpaceId(2)).unwrap();
        assert_eq!(d0.width_m, Some(0.9));
        let d1 = nrg.space(SpaceId(7)).unwrap();
        assert!((d1.width_m.unwrap() - 1.0).abs() < 1e-9, "{:?}", d1.width_m);
        let room = nrg.space(SpaceId(3)).unwrap();
        assert_eq!(room.width_m, None);
    }
}
