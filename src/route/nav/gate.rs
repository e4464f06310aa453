//! Gates: the passable triangle edges between two spaces, and the view of
//! them (with the vertices they need) from which openings are built. Its
//! own file so the mesh and the openings both use it without importing
//! each other.

use crate::model::Point;

/// "No triangle" / "no space" in the dense index arrays.
pub(crate) const NONE: u32 = u32::MAX;

/// A passable triangle edge between two spaces.
#[derive(Debug, Clone)]
pub(crate) struct Gate {
    /// The edge's end points (vertex indices).
    pub ends: [u32; 2],
    /// The triangle on each side and its space: `(tri, space)`.
    pub sides: [(u32, u32); 2],
}

/// The gates of a mesh with the vertex positions and obstacle flags they
/// refer to.
#[derive(Debug, Clone, Copy)]
pub(crate) struct GateView<'a> {
    /// Vertex positions.
    pub points: &'a [Point],
    /// Whether each vertex touches a wall edge.
    pub obstacle: &'a [bool],
    /// The gates.
    pub gates: &'a [Gate],
    /// How many spaces the mesh has.
    pub spaces: usize,
}

impl GateView<'_> {
    /// The position of vertex `v`.
    pub fn point(&self, v: u32) -> Point {
        self.points[v as usize]
    }
}
