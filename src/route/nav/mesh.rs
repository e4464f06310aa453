//! The triangulated free space of a floor: one constrained Delaunay
//! triangulation (the `spade` crate) of every space's rings, each triangle
//! tagged with the space it lies in, each triangle edge classified as open
//! (inside one space), a gate (a doorway or open boundary between two spaces
//! that the model connects navigably) or a wall.

use std::collections::HashMap;

use rustc_hash::FxHashMap;

use spade::handles::FixedVertexHandle;
use spade::{ConstrainedDelaunayTriangulation, Point2, PositionInTriangulation, Triangulation};

use super::gate::GateView;
use super::noding;
use super::openings::Openings;
use super::regions::{self, Ring};
use crate::model::{Nrg, Point, Space, SpaceId};

pub(crate) use super::gate::{Gate, NONE};

/// What lies across one edge of a triangle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Across {
    /// Another triangle of the same space.
    Inside(u32),
    /// A triangle of another space, through gate `gate`.
    Gate { tri: u32, gate: u32 },
    /// A wall: outside every space, or a space not navigably connected.
    Wall,
}

/// One triangle: vertices counter-clockwise; edge `i` runs from `v[i]` to
/// `v[(i + 1) % 3]`.
#[derive(Debug, Clone)]
pub(crate) struct Tri {
    pub v: [u32; 3],
    pub across: [Across; 3],
    /// Dense index of its space.
    pub space: u32,
}

/// The triangulated floor.
#[derive(Debug)]
pub(crate) struct Mesh {
    pub points: Vec<Point>,
    pub tris: Vec<Tri>,
    pub gates: Vec<Gate>,
    /// Space ids by dense index, and the index by id.
    pub space_ids: Vec<SpaceId>,
    pub space_index: HashMap<SpaceId, u32>,
    /// Triangles of each space.
    pub space_tris: Vec<Vec<u32>>,
    /// Whether a vertex touches a wall edge (an obstacle corner).
    pub obstacle: Vec<bool>,
    /// The gates joined into openings.
    pub openings: Openings,
    /// Map from spade's inner face index to our triangle (NONE: outside).
    face_tri: Vec<u32>,
    cdt: ConstrainedDelaunayTriangulation<Point2<f64>>,
}

/// Vertices are snapped to this grid (per metre): a micrometre.
const SNAP_PER_M: f64 = 1.0e6;

fn snap(p: Point) -> Point {
    p.map(|c| (c * SNAP_PER_M).round() / SNAP_PER_M)
}

/// Constrained Delaunay triangulation of `points` with `edges` as
/// constraints; edges crossing one already added go to `conflicts`.
fn triangulate(
    points: &[Point],
    edges: Vec<[usize; 2]>,
    conflicts: &mut Vec<[usize; 2]>,
) -> ConstrainedDelaunayTriangulation<Point2<f64>> {
    let vertices: Vec<Point2<f64>> = points.iter().map(|p| Point2::new(p[0], p[1])).collect();
    ConstrainedDelaunayTriangulation::<Point2<f64>>::try_bulk_load_cdt(vertices, edges, |e| {
        conflicts.push(e)
    })
    .unwrap_or_default()
}

/// Largest coordinate magnitude accepted (spade needs finite, bounded input;
/// a building is far smaller).
const MAX_COORD: f64 = 1.0e7;

impl Mesh {
    /// Triangulates `nrg`'s spaces. Spaces with fewer than three points or
    /// with coordinates beyond ±10 000 km are left out (they cannot be
    /// walked).
    pub fn new(nrg: &Nrg) -> Mesh {
        let (points, cdt, rings) = laid(nrg);
        let face_space = regions::face_spaces(nrg.spaces(), &cdt, &points, rings.as_deref());
        Mesh::tag(nrg, points, cdt, face_space)
    }

    /// The mesh of `cdt` whose faces lie in the spaces `face_space` says.
    fn tag(
        nrg: &Nrg,
        points: Vec<Point>,
        cdt: ConstrainedDelaunayTriangulation<Point2<f64>>,
        face_space: Vec<u32>,
    ) -> Mesh {
        let spaces = nrg.spaces();
        let space_ids: Vec<SpaceId> = spaces.iter().map(|s| s.id).collect();
        let space_index: HashMap<SpaceId, u32> = space_ids
            .iter()
            .enumerate()
            .map(|(i, id)| (*id, i as u32))
            .collect();
        let nfaces = face_space.len();
        let mut face_tri = vec![NONE; nfaces];
        let mut tris = Vec::new();
        for face in cdt.inner_faces() {
            let f = face.fix().index();
            if face_space[f] != NONE {
                face_tri[f] = tris.len() as u32;
                let v = face.vertices().map(|v| v.fix().index() as u32);
                tris.push(Tri {
                    v,
                    across: [Across::Wall; 3],
                    space: face_space[f],
                });
            }
        }
        let navigable = |a: u32, b: u32| {
            nrg.connection(space_ids[a as usize], space_ids[b as usize])
                .is_some_and(|c| c.kind.is_navigable())
        };
        let mut gates: Vec<Gate> = Vec::new();
        // The gate of each undirected edge (by spade's index), NONE if none.
        let mut gate_of_edge = vec![NONE; cdt.num_undirected_edges()];
        let mut obstacle = vec![false; points.len()];
        for face in cdt.inner_faces() {
            let t = face_tri[face.fix().index()];
            if t == NONE {
                for e in face.adjacent_edges() {
                    // The edge bounds a space only if the other side is one.
                    if let Some(g) = e.rev().face().as_inner()
                        && face_tri[g.fix().index()] != NONE
                    {
                        for v in e.vertices() {
                            obstacle[v.fix().index()] = true;
                        }
                    }
                }
                continue;
            }
            let space = tris[t as usize].space;
            for (i, e) in face.adjacent_edges().into_iter().enumerate() {
                let other = e
                    .rev()
                    .face()
                    .as_inner()
                    .map_or(NONE, |g| face_tri[g.fix().index()]);
                let across = if other == NONE {
                    Across::Wall
                } else {
                    let os = tris[other as usize].space;
                    if os == space {
                        Across::Inside(other)
                    } else if navigable(space, os) {
                        let slot = &mut gate_of_edge[e.as_undirected().fix().index()];
                        if *slot == NONE {
                            let [p, q] = e.vertices().map(|v| v.fix().index() as u32);
                            gates.push(Gate {
                                ends: [p, q],
                                sides: [(t, space), (other, os)],
                            });
                            *slot = (gates.len() - 1) as u32;
                        }
                        let gate = *slot;
                        Across::Gate { tri: other, gate }
                    } else {
                        Across::Wall
                    }
                };
                if across == Across::Wall {
                    for v in e.vertices() {
                        obstacle[v.fix().index()] = true;
                    }
                }
                tris[t as usize].across[i] = across;
            }
        }
        let mut space_tris = vec![Vec::new(); space_ids.len()];
        for (t, tri) in tris.iter().enumerate() {
            space_tris[tri.space as usize].push(t as u32);
        }
        let mut mesh = Mesh {
            points,
            tris,
            gates,
            space_ids,
            space_index,
            space_tris,
            obstacle,
            openings: Openings::default(),
            face_tri,
            cdt,
        };
        mesh.openings = Openings::new(&mesh.gate_view());
        mesh
    }

    /// The triangle containing `p`, preferring one of space `prefer` when
    /// `p` lies on an edge or a vertex. `None` outside every space.
    pub fn locate(&self, p: Point, prefer: Option<u32>) -> Option<u32> {
        if !(p[0].is_finite() && p[1].is_finite())
            || p[0].abs() > MAX_COORD
            || p[1].abs() > MAX_COORD
        {
            return None;
        }
        let q = Point2::new(p[0], p[1]);
        let candidates: Vec<u32> = match self.cdt.locate(q) {
            PositionInTriangulation::OnFace(f) => vec![self.face_tri[f.index()]],
            PositionInTriangulation::OnEdge(e) => {
                let e = self.cdt.directed_edge(e);
                [e.face(), e.rev().face()]
                    .iter()
                    .filter_map(|f| f.as_inner())
                    .map(|f| self.face_tri[f.fix().index()])
                    .collect()
            }
            PositionInTriangulation::OnVertex(v) => self
                .cdt
                .vertex(v)
                .out_edges()
                .filter_map(|e| e.face().as_inner())
                .map(|f| self.face_tri[f.fix().index()])
                .collect(),
            _ => Vec::new(),
        };
        let found: Vec<u32> = candidates.into_iter().filter(|t| *t != NONE).collect();
        found
            .iter()
            .copied()
            .find(|t| Some(self.tris[*t as usize].space) == prefer)
            .or_else(|| found.first().copied())
    }

    /// The gate edges with the vertices they need, for [`Openings`].
    pub fn gate_view(&self) -> GateView<'_> {
        GateView {
            points: &self.points,
            obstacle: &self.obstacle,
            gates: &self.gates,
            spaces: self.space_ids.len(),
        }
    }

    /// The position of vertex `v`.
    pub fn point(&self, v: u32) -> Point {
        self.points[v as usize]
    }

    /// The centroid of triangle `t`.
    pub fn centroid(&self, t: u32) -> Point {
        let [a, b, c] = self.tris[t as usize].v.map(|v| self.point(v));
        [(a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0]
    }

    /// The edge of `t` shared with `u` as (right, left) end points seen when
    /// walking from `t` into `u`; `None` when they are not neighbours.
    pub fn portal(&self, t: u32, u: u32) -> Option<(Point, Point)> {
        self.portal_vertices(t, u)
            .map(|(a, b)| (self.point(a), self.point(b)))
    }

    /// [`Mesh::portal`] as vertex indices.
    pub fn portal_vertices(&self, t: u32, u: u32) -> Option<(u32, u32)> {
        let tri = &self.tris[t as usize];
        (0..3).find_map(|i| {
            let next = match tri.across[i] {
                Across::Inside(n) => n,
                Across::Gate { tri, .. } => tri,
                Across::Wall => return None,
            };
            (next == u).then(|| (tri.v[i], tri.v[(i + 1) % 3]))
        })
    }

    /// The dense index of a space.
    pub fn space(&self, id: SpaceId) -> Option<u32> {
        self.space_index.get(&id).copied()
    }
}

/// The triangulation of a model's rings: its vertices, and the rings as
/// laid into it when spade took every ring edge as it is (no crossings).
type Laid = (
    Vec<Point>,
    ConstrainedDelaunayTriangulation<Point2<f64>>,
    Option<Vec<Ring>>,
);

/// Triangulates the rings of `nrg`'s spaces (see [`Laid`]). Spaces with
/// fewer than three points or coordinates out of range are left out.
pub(super) fn laid(nrg: &Nrg) -> Laid {
    let spaces = nrg.spaces();
    // Fx: ring vertices are hashed once each (10 000 on willow-full), and
    // SipHash cost a millisecond of the layer's build there.
    let mut vertex_of: FxHashMap<[u64; 2], u32> = FxHashMap::default();
    let mut points: Vec<Point> = Vec::new();
    let mut edges: Vec<[usize; 2]> = Vec::new();
    let mut rings: Vec<Ring> = Vec::new();
    for (s, space) in spaces.iter().enumerate() {
        if space.polygon.len() < 3 || !in_range(space) {
            continue;
        }
        for (r, ring) in std::iter::once(&space.polygon)
            .chain(&space.holes)
            .enumerate()
        {
            let mut ids: Vec<u32> = ring
                .iter()
                .map(|p| {
                    // Points closer than a micrometre are one vertex
                    // (sums like 14.6 + 0.1 differ in the last bit).
                    let snapped = snap(*p);
                    let key = snapped.map(f64::to_bits);
                    *vertex_of.entry(key).or_insert_with(|| {
                        points.push(snapped);
                        (points.len() - 1) as u32
                    })
                })
                .collect();
            // Vertices that snapped together are one.
            ids.dedup();
            while ids.len() > 1 && ids.first() == ids.last() {
                ids.pop();
            }
            if ids.len() > 1 {
                for i in 0..ids.len() {
                    let (a, b) = (ids[i], ids[(i + 1) % ids.len()]);
                    edges.push([a.min(b) as usize, a.max(b) as usize]);
                }
            }
            rings.push(Ring {
                space: s as u32,
                hole: r > 0,
                vertices: ids,
            });
        }
    }
    edges.sort_unstable();
    edges.dedup();
    let mut conflicts = Vec::new();
    let mut cdt = triangulate(&points, edges.clone(), &mut conflicts);
    let clean = conflicts.is_empty();
    if !clean {
        // Edges crossing others (overlapping or touching rings of an
        // imported model, a repaired overlap): node them ourselves and
        // triangulate again (see `noding`).
        let noded = noding::node(
            &edges,
            &mut noding::Vertices {
                points: &mut points,
                index: &mut vertex_of,
                snap,
            },
        );
        conflicts.clear();
        cdt = triangulate(&points, noded, &mut conflicts);
        // What noding could not resolve (a crossing its snapping made)
        // is added where it does not cross; never split by spade,
        // which can panic there.
        for [a, b] in conflicts {
            if a < cdt.num_vertices() && b < cdt.num_vertices() {
                cdt.try_add_constraint(
                    FixedVertexHandle::from_index(a),
                    FixedVertexHandle::from_index(b),
                );
            }
        }
    }
    let points: Vec<Point> = cdt
        .vertices()
        .map(|v| [v.position().x, v.position().y])
        .collect();
    (points, cdt, clean.then_some(rings))
}

fn in_range(space: &Space) -> bool {
    std::iter::once(&space.polygon)
        .chain(&space.holes)
        .flatten()
        .all(|p| p[0].abs() <= MAX_COORD && p[1].abs() <= MAX_COORD)
}
