//! Room and corridor labels against a simulated plan, which knows which of
//! its spaces are corridors: each extracted room or corridor takes the
//! kind of the plan space its anchor (an interior point) lies in.

use crate::model::{Nrg, Ring, SpaceKind, point_in_ring};

/// How the extracted rooms and corridors are labelled, counted against the
/// plan (spaces whose anchor lies in no plan space are not counted).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct KindScore {
    /// Plan corridors labelled corridor.
    pub corridor_as_corridor: usize,
    /// Plan corridors labelled room.
    pub corridor_as_room: usize,
    /// Plan rooms labelled corridor.
    pub room_as_corridor: usize,
    /// Plan rooms labelled room.
    pub room_as_room: usize,
}

impl KindScore {
    /// Adds another building's counts.
    pub fn add(&mut self, other: &KindScore) {
        self.corridor_as_corridor += other.corridor_as_corridor;
        self.corridor_as_room += other.corridor_as_room;
        self.room_as_corridor += other.room_as_corridor;
        self.room_as_room += other.room_as_room;
    }

    /// The share of spaces labelled as the plan has them (1 when none).
    pub fn accuracy(&self) -> f64 {
        let right = self.corridor_as_corridor + self.room_as_room;
        let all = right + self.corridor_as_room + self.room_as_corridor;
        if all == 0 {
            1.0
        } else {
            right as f64 / all as f64
        }
    }
}

/// Scores the room and corridor labels of `nrg` against a plan's
/// `corridors` and `rooms` (rings in the map frame, metres).
///
/// ```
/// use nrgdb::eval::kind_score;
/// use nrgdb::model::{Nrg, Space, SpaceId, SpaceKind};
/// let square = |x: f64| vec![[x, 0.0], [x + 4.0, 0.0], [x + 4.0, 4.0], [x, 4.0]];
/// let nrg = Nrg::new(
///     vec![
///         Space::new(SpaceId(1), SpaceKind::Room, [2.0, 2.0], square(0.0)),
///         Space::new(SpaceId(2), SpaceKind::Room, [12.0, 2.0], square(10.0)),
///     ],
///     vec![],
/// )
/// .unwrap();
/// let s = kind_score(&nrg, &[square(10.0)], &[square(0.0)]);
/// assert_eq!((s.room_as_room, s.corridor_as_room), (1, 1));
/// assert_eq!(s.accuracy(), 0.5);
/// ```
pub fn kind_score(nrg: &Nrg, corridors: &[Ring], rooms: &[Ring]) -> KindScore {
    let mut score = KindScore::default();
    for space in nrg.spaces() {
        let labelled_corridor = match space.kind {
            SpaceKind::Corridor => true,
            SpaceKind::Room => false,
            _ => continue,
        };
        let inside = |rings: &[Ring]| rings.iter().any(|r| point_in_ring(space.anchor, r));
        let slot = if inside(corridors) {
            if labelled_corridor {
                &mut score.corridor_as_corridor
            } else {
                &mut score.corridor_as_room
            }
        } else if inside(rooms) {
            if labelled_corridor {
                &mut score.room_as_corridor
            } else {
                &mut score.room_as_room
            }
        } else {
            continue;
        };
        *slot += 1;
    }
    score
}
