//! Dead ends of the opening graph: spaces a shortest walk can only enter to
//! reach something inside them. A room behind its door, the door itself
//! once the room is gone, a suite of rooms behind one door: peeling spaces
//! with a single neighbour, again and again, leaves the core (corridors,
//! halls, rooms with two ways in). A search enters a dead end only when one
//! of its end points lies in it, so it never scans the hundreds of doors
//! along a corridor that lead nowhere.
//!
//! A space is peeled only when everything joining it to its last neighbour
//! is one straight opening, so no walk inside that neighbour could be cut
//! short by stepping through it (an L-shaped or split opening could be, and
//! keeps the space in the core). Peeling is exact: it removes no shortest
//! walk between points outside the dead ends.

use std::collections::VecDeque;

use super::mesh::{Mesh, NONE};

/// Which spaces are dead ends, their way out, and the gates of each core
/// space that lead into the core.
#[derive(Debug, Default)]
pub(crate) struct DeadEnds {
    /// For a dead-end space its neighbour toward the core (NONE for a
    /// space with no open way out at all); NONE for a core space.
    pub parent: Vec<u32>,
    /// Whether each space (dense index) is a dead end.
    pub dead: Vec<bool>,
    /// The slots (in `Openings::of_space` order) of each space's open
    /// openings whose other side is a core space.
    pub core_slots: Vec<Vec<u32>>,
}

/// How far an opening may stray from the line between its ends and still
/// count as straight, metres (a doorway traced along pixel edges is a
/// staircase a pixel or two deep).
const STRAIGHT_M: f64 = 0.1;

impl DeadEnds {
    /// Peels the dead ends of `mesh` given which openings are open.
    pub fn new(mesh: &Mesh, open: &[bool]) -> DeadEnds {
        let openings = &mesh.openings;
        let n = mesh.space_ids.len();
        // Distinct open neighbours of each space.
        let neighbours: Vec<Vec<u32>> = (0..n as u32)
            .map(|s| {
                let mut out: Vec<u32> = openings.of_space[s as usize]
                    .iter()
                    .filter(|o| open[**o as usize])
                    .map(|o| openings.other_side(*o, s))
                    .filter(|t| *t != s)
                    .collect();
                out.sort_unstable();
                out.dedup();
                out
            })
            .collect();
        let mut live: Vec<usize> = neighbours.iter().map(Vec::len).collect();
        let mut dead = vec![false; n];
        let mut parent = vec![NONE; n];
        let mut queue: VecDeque<u32> = (0..n as u32).filter(|s| live[*s as usize] <= 1).collect();
        while let Some(s) = queue.pop_front() {
            if dead[s as usize] {
                continue;
            }
            let rest: Vec<u32> = neighbours[s as usize]
                .iter()
                .copied()
                .filter(|t| !dead[*t as usize])
                .collect();
            match rest.as_slice() {
                [] => {}
                [t] if one_straight_opening(mesh, open, s, *t) => parent[s as usize] = *t,
                _ => continue,
            }
            dead[s as usize] = true;
            if let Some(&t) = rest.first() {
                live[t as usize] -= 1;
                if live[t as usize] <= 1 {
                    queue.push_back(t);
                }
            }
        }
        let core_slots = (0..n as u32)
            .map(|s| {
                openings.of_space[s as usize]
                    .iter()
                    .enumerate()
                    .filter(|(_, o)| open[**o as usize])
                    .filter(|(_, o)| !dead[openings.other_side(**o, s) as usize])
                    .map(|(j, _)| j as u32)
                    .collect()
            })
            .collect();
        DeadEnds {
            parent,
            dead,
            core_slots,
        }
    }

    /// The dead-end spaces from `s` out to the core (`s` first), empty
    /// when `s` is in the core.
    pub fn way_out(&self, s: u32) -> Vec<u32> {
        let mut out = Vec::new();
        let mut at = s;
        while self.dead.get(at as usize).copied().unwrap_or(false) && !out.contains(&at) {
            out.push(at);
            at = self.parent[at as usize];
        }
        out
    }
}

/// Whether `s` and `t` are joined by one open opening that runs straight
/// (within [`STRAIGHT_M`] of the line between its ends).
fn one_straight_opening(mesh: &Mesh, open: &[bool], s: u32, t: u32) -> bool {
    let openings = &mesh.openings;
    let mut between = openings.of_space[s as usize]
        .iter()
        .filter(|o| open[**o as usize] && openings.other_side(**o, s) == t);
    let (Some(o), None) = (between.next(), between.next()) else {
        return false;
    };
    let vertices = &openings.list[*o as usize].vertices;
    let (Some(a), Some(b)) = (vertices.first(), vertices.last()) else {
        return false;
    };
    let [a, b] = [*a, *b].map(|v| mesh.point(v));
    let len = (b[0] - a[0]).hypot(b[1] - a[1]);
    len > 0.0
        && vertices.iter().all(|v| {
            let p = mesh.point(*v);
            ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])).abs() / len
                <= STRAIGHT_M
        })
}
