//! Which space each face of a floor's triangulation lies in.
//!
//! Faces fall into regions: the sets of faces joined across edges that are
//! not constraints (no ring edge between them). Each edge of a space's ring
//! claims the face on the space's side of it (the left of an outer ring
//! drawn counter-clockwise, the right of a hole drawn so); a region takes
//! the space that claims it, and a region nothing claims lies outside every
//! space (the outside, a hole, a courtyard). Where claims cannot decide, a
//! region's centre is tested against the spaces instead ([`Containment`];
//! the smallest space holding it wins, then the lowest id): when the rings
//! were not all laid down as they are (spade reported crossings, a ring
//! touches itself) or when two spaces claim one region (overlapping
//! spaces). On a clean model both give the same tags; claims cost one edge
//! lookup per ring edge instead of an edge index per space.

use rstar::RTree;
use rstar::primitives::{GeomWithData, Rectangle};
use spade::handles::{FixedFaceHandle, FixedVertexHandle, InnerTag};
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

use super::containment::Containment;
use super::gate::NONE;
use crate::model::{Point, Space, polygon_area};

/// A claim made by two different spaces.
const CLASH: u32 = u32::MAX - 1;

/// One ring of a space as laid into the triangulation.
#[derive(Debug, Clone)]
pub(crate) struct Ring {
    /// Index of its space in the model's spaces.
    pub space: u32,
    /// Whether it is a hole.
    pub hole: bool,
    /// Its vertices (triangulation indices), consecutive repeats removed.
    pub vertices: Vec<u32>,
}

type Envelope = GeomWithData<Rectangle<[f64; 2]>, usize>;

/// The space index of every face of `cdt` (by spade's face index; NONE
/// outside every space and for the outer face). `rings` are the spaces'
/// rings when every one of their edges is an edge of `cdt` (no crossings
/// were re-noded); `None` tests every region's centre.
pub(crate) fn face_spaces(
    spaces: &[Space],
    cdt: &ConstrainedDelaunayTriangulation<Point2<f64>>,
    points: &[Point],
    rings: Option<&[Ring]>,
) -> Vec<u32> {
    let nfaces = cdt.all_faces().len();
    let claims = rings.and_then(|r| claims(cdt, points, r, nfaces));
    let mut tester: Option<Tester<'_>> = None;
    let mut face_space = vec![NONE; nfaces];
    let mut seen = vec![false; nfaces];
    let mut members: Vec<FixedFaceHandle<InnerTag>> = Vec::new();
    for face in cdt.inner_faces() {
        let f = face.fix().index();
        if seen[f] {
            continue;
        }
        // The region of `face`, and the one space that claims it.
        members.clear();
        members.push(face.fix());
        seen[f] = true;
        let mut claim = NONE;
        let mut i = 0;
        while let Some(&h) = members.get(i) {
            i += 1;
            if let Some(c) = &claims {
                claim = match (claim, c[h.index()]) {
                    (a, NONE) => a,
                    (NONE, b) => b,
                    (a, b) if a == b => a,
                    _ => CLASH,
                };
            }
            for e in cdt.face(h).adjacent_edges() {
                if e.is_constraint_edge() {
                    continue;
                }
                if let Some(g) = e.rev().face().as_inner()
                    && !seen[g.fix().index()]
                {
                    seen[g.fix().index()] = true;
                    members.push(g.fix());
                }
            }
        }
        let space = if claims.is_some() && claim != CLASH {
            claim
        } else {
            let [a, b, c] = face.positions();
            let centre = [(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0];
            tester
                .get_or_insert_with(|| Tester::new(spaces))
                .space_at(spaces, centre)
        };
        for h in &members {
            face_space[h.index()] = space;
        }
    }
    face_space
}

/// Per face: the space whose ring edge claims it (NONE, or CLASH when two
/// do). `None` when a ring cannot claim reliably: an edge missing from the
/// triangulation, a ring through one vertex twice, or no area.
fn claims(
    cdt: &ConstrainedDelaunayTriangulation<Point2<f64>>,
    points: &[Point],
    rings: &[Ring],
    nfaces: usize,
) -> Option<Vec<u32>> {
    let mut claims = vec![NONE; nfaces];
    let mut visited = vec![false; points.len()];
    for ring in rings {
        let v = &ring.vertices;
        if v.len() < 3 {
            continue;
        }
        for &i in v {
            let slot = visited.get_mut(i as usize)?;
            if *slot {
                // Touches itself: its loops may turn either way.
                v.iter().for_each(|&j| visited[j as usize] = false);
                return None;
            }
            *slot = true;
        }
        v.iter().for_each(|&j| visited[j as usize] = false);
        let ring_points: Vec<Point> = v.iter().map(|&i| points[i as usize]).collect();
        let area = polygon_area(&ring_points);
        if area == 0.0 || !area.is_finite() {
            return None;
        }
        let left = (area > 0.0) != ring.hole;
        for k in 0..v.len() {
            let (a, b) = (v[k] as usize, v[(k + 1) % v.len()] as usize);
            let e = cdt.get_edge_from_neighbors(
                FixedVertexHandle::from_index(a),
                FixedVertexHandle::from_index(b),
            )?;
            let side = if left { e.face() } else { e.rev().face() };
            if let Some(f) = side.as_inner() {
                let c = &mut claims[f.fix().index()];
                *c = match *c {
                    NONE => ring.space,
                    s if s == ring.space => s,
                    _ => CLASH,
                };
            }
        }
    }
    Some(claims)
}

/// Point-in-space tests for the regions claims do not decide, built on
/// first need.
struct Tester<'a> {
    envelopes: RTree<Envelope>,
    containment: Containment<'a>,
}

impl<'a> Tester<'a> {
    fn new(spaces: &'a [Space]) -> Tester<'a> {
        Tester {
            envelopes: RTree::bulk_load(
                spaces
                    .iter()
                    .enumerate()
                    .filter_map(|(i, s)| envelope(s, i))
                    .collect(),
            ),
            containment: Containment::new(spaces),
        }
    }

    /// The smallest space (then lowest id) holding `p`, NONE if none.
    fn space_at(&self, spaces: &[Space], p: Point) -> u32 {
        self.envelopes
            .locate_all_at_point(&p)
            .map(|e| e.data)
            .filter(|&i| self.containment.contains(i, p))
            .min_by(|&i, &j| {
                spaces[i]
                    .area_m2
                    .total_cmp(&spaces[j].area_m2)
                    .then(spaces[i].id.cmp(&spaces[j].id))
            })
            .map_or(NONE, |i| i as u32)
    }
}

fn envelope(space: &Space, i: usize) -> Option<Envelope> {
    if space.polygon.is_empty() {
        return None;
    }
    let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
    for p in &space.polygon {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    Some(GeomWithData::new(Rectangle::from_corners(lo, hi), i))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Nrg, SpaceId, SpaceKind};
    use crate::route::nav::mesh::laid;
    use crate::sim::{FloorPlan, FloorPlanParams};

    /// Tags by claims and by testing every region give the same spaces.
    fn agree(nrg: &Nrg) -> usize {
        let (points, cdt, rings) = laid(nrg);
        let rings = rings.expect("a clean model lays every ring edge");
        let by_claims = face_spaces(nrg.spaces(), &cdt, &points, Some(&rings));
        let by_tests = face_spaces(nrg.spaces(), &cdt, &points, None);
        assert_eq!(by_claims, by_tests);
        by_claims.iter().filter(|s| **s != NONE).count()
    }

    #[test]
    fn claims_tag_as_containment_does() {
        assert!(agree(&crate::query::demo::building(7)) > 100);
        for seed in 1..6 {
            let plan = FloorPlan::generate(&FloorPlanParams::new(seed)).unwrap();
            assert!(agree(&plan.truth().unwrap()) > 50);
        }
        if let Some(nrg) = crate::fixtures::shared_map_nrg("willow-full") {
            assert!(agree(&nrg) > 10_000);
        }
    }

    fn square(id: u32, lo: Point, size: f64, clockwise: bool) -> Space {
        let mut ring = vec![
            lo,
            [lo[0] + size, lo[1]],
            [lo[0] + size, lo[1] + size],
            [lo[0], lo[1] + size],
        ];
        if clockwise {
            ring.reverse();
        }
        let anchor = [lo[0] + size / 2.0, lo[1] + size / 2.0];
        Space::new(SpaceId(id), SpaceKind::Room, anchor, ring)
    }

    #[test]
    fn rings_either_way_round_and_holes_inside() {
        // A room drawn clockwise with a hole drawn counter-clockwise, a
        // room in that hole, and a neighbour drawn counter-clockwise.
        let mut a = square(1, [0.0, 0.0], 10.0, true);
        let mut hole = vec![[3.0, 3.0], [7.0, 3.0], [7.0, 7.0], [3.0, 7.0]];
        a.holes = vec![hole.clone()];
        let b = square(2, [4.0, 4.0], 2.0, false);
        let c = square(3, [10.0, 0.0], 5.0, false);
        let nrg = Nrg::new(vec![a.clone(), b.clone(), c.clone()], vec![]).unwrap();
        let tagged = agree(&nrg);
        // Eight triangles round the hole, two in the inner room, two or more
        // in the neighbour (its side meets the room's corner).
        assert!(tagged >= 8 + 2 + 2, "{tagged}");
        // The same with the hole drawn the other way.
        hole.reverse();
        a.holes = vec![hole];
        agree(&Nrg::new(vec![a, b, c], vec![]).unwrap());
    }

    #[test]
    fn a_region_two_spaces_claim_goes_to_the_smaller() {
        // Two spaces with the same outline: both claim every face; the
        // tests decide (equal areas: the lower id).
        let nrg = Nrg::new(
            vec![
                square(4, [0.0, 0.0], 3.0, false),
                square(2, [0.0, 0.0], 3.0, true),
            ],
            vec![],
        )
        .unwrap();
        let (points, cdt, rings) = laid(&nrg);
        let rings = rings.unwrap();
        let tags = face_spaces(nrg.spaces(), &cdt, &points, Some(&rings));
        let lower = nrg
            .spaces()
            .iter()
            .position(|s| s.id == SpaceId(2))
            .unwrap() as u32;
        let inner: Vec<u32> = cdt.inner_faces().map(|f| tags[f.fix().index()]).collect();
        assert!(!inner.is_empty());
        assert!(inner.iter().all(|t| *t == lower), "{inner:?}");
    }
}
