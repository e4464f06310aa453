//! Tests of `wall_support.rs`: the wall support rule, clutter ends and
//! passages, on small hand-made grids.

use super::*;
use crate::extract::furniture::islands;

/// The limits `pixel_config` sets at 0.1 m/px.
const AT_10_CM: SupportLimits = SupportLimits {
    long_run: 15.0,
    pair_run: 10.0,
    tie_run: 3.0,
    gap: 1,
    tolerance: 5,
    reach: 6.0,
    side_line: 1,
    near: 20.0,
    clutter_max: 20.0,
    wall_elongation: 3.0,
    end_reach: 1,
    lines: LineLimits {
        min_run: 25.0,
        gap: 1,
        tolerance: 1,
        piece_min: 7.5,
        piece_gap: 21.0,
    },
};

/// A `w` x `h` grid at 0.1 m/px, walled round, with `wall(x, y)` cells
/// occupied inside.
fn grid(w: usize, h: usize, wall: impl Fn(usize, usize) -> bool) -> WallSupport {
    let rows: Vec<String> = (0..h)
        .map(|y| {
            (0..w)
                .map(|x| {
                    let edge = x == 0 || y == 0 || x == w - 1 || y == h - 1;
                    if edge || wall(x, y) { '#' } else { '.' }
                })
                .collect()
        })
        .collect();
    let g = OccupancyGrid::from_ascii(&rows.join("\n"), 0.1);
    WallSupport::new(&g, &islands(&g), 0.0, &[], AT_10_CM)
}

#[test]
fn an_opening_beside_a_room_corner_crosses_no_passage_there() {
    // A room's 3 m open front (x 20..50 on y = 30) whose right end is
    // 0.4 m from the building's side wall (x = 54), which runs on past
    // both faces: a 0.4 m piece of the front joins them.
    let w = 70;
    let line: Vec<u32> = (20..50).map(|x| (30 * w + x) as u32).collect();
    let room = grid(w, 60, |x, y| {
        (y == 30 && !(20..50).contains(&x) && x < 54) || (x == 19 && y < 30) || x == 54
    });
    // Judged as any line, the side wall passes the end as a corridor's
    // side would.
    assert!(room.crosses_passage(&line, [false; 2]));
    // Known to stand beside a corner (the line's last end), it is the
    // room's own side wall.
    assert!(!room.crosses_passage(&line, [false, true]));
    // The first end is the left one, whichever order the pixels run in.
    assert!(room.crosses_passage(&line, [true, false]));
    let reversed: Vec<u32> = line.iter().rev().copied().collect();
    assert!(!room.crosses_passage(&reversed, [true, false]));
}

#[test]
fn a_line_joining_wall_ends_across_a_corridor_crosses_a_passage() {
    // A 3 m corridor (x 20..50) between walls at x = 19 and 50, rooms
    // either side divided along y = 30: the line across the corridor
    // between the dividers' ends has the corridor's walls going on
    // past both its faces.
    let w = 70;
    let line: Vec<u32> = (20..50).map(|x| (30 * w + x) as u32).collect();
    let corridor = grid(w, 60, |x, y| {
        x == 19 || x == 50 || (y == 30 && !(19..=50).contains(&x))
    });
    assert!(corridor.crosses_passage(&line, [false; 2]));
    // With a corner at each end it is still a line from one side of the
    // corridor to the other.
    assert!(corridor.crosses_passage(&line, [true, true]));
    // A room's 3 m open front: the room's side wall meets the front
    // and stops there.
    let front = grid(w, 60, |x, y| {
        (y == 30 && !(20..50).contains(&x)) || (x == 19 && y < 30)
    });
    assert!(!front.crosses_passage(&line, [false; 2]));
    // The same front with a 0.5 m x 0.8 m table standing in the room
    // below, 0.6 m from the line's end, in line with the side wall:
    // furniture is no passage's side wall. (Within `tolerance` of the
    // end, 0.5 m, the end would stand on it and its faces count.)
    let table = |x: usize, y: usize| (17..22).contains(&x) && (36..44).contains(&y);
    let furnished = grid(w, 60, |x, y| {
        (y == 30 && !(20..50).contains(&x)) || (x == 19 && y < 30) || table(x, y)
    });
    assert!(!furnished.crosses_passage(&line, [false; 2]));
    // A wall piece as long standing there (3 m) is one: the line
    // would cross a passage between it and the side wall.
    let piece = grid(w, 60, |x, y| {
        (y == 30 && !(20..50).contains(&x))
            || (x == 19 && y < 30)
            || ((18..20).contains(&x) && (33..58).contains(&y))
    });
    assert!(piece.crosses_passage(&line, [false; 2]));
    // The same piece 0.4 m further into the room below (as the jamb of
    // the next room's front, say): the side wall above and the piece pass
    // the end on two lines, no passage's one side wall.
    let offset = grid(w, 60, |x, y| {
        (y == 30 && !(20..50).contains(&x))
            || (x == 19 && y < 30)
            || ((23..25).contains(&x) && (33..58).contains(&y))
    });
    assert!(!offset.crosses_passage(&line, [false; 2]));
}

#[test]
fn a_border_ending_on_clutter_lacks_support() {
    // A 6 m room; a 0.6 m desk (x 30..36, y 20..26) stands 0.9 m from
    // the wall at y = 10: the border between them (x 33, y 11..20)
    // ends on the desk.
    let desk = |x: usize, y: usize| (30..36).contains(&x) && (20..26).contains(&y);
    let border: Vec<u32> = (11..20).map(|y| (y * 70 + 33) as u32).collect();
    let s = grid(70, 60, |x, y| y == 10 || desk(x, y));
    assert!(s.lacks(&border));
    // A free-standing piece of wall as long (3 m, 0.2 m thick) is a
    // jamb: the border's ends are judged by the runs, as before.
    let piece = |x: usize, y: usize| (18..48).contains(&x) && (20..22).contains(&y);
    let w = grid(70, 60, |x, y| y == 10 || piece(x, y));
    assert!(!w.on_clutter([33.0, 19.0], false));
    // The same desk against the wall is the wall's: no clutter.
    let against = grid(70, 60, |x, y| {
        y == 10 || ((30..36).contains(&x) && (11..17).contains(&y))
    });
    assert!(!against.on_clutter([33.0, 17.0], false));
}

#[test]
fn a_doorway_in_a_long_wall_is_supported() {
    // Two 4 m rooms: a wall at x = 40, its doorway y 30..38 (0.8 m).
    let s = grid(81, 60, |x, y| x == 40 && !(30..38).contains(&y));
    assert_eq!(s.supported([40.0, 30.0], [40.0, 37.0], false), Some(true));
}

#[test]
fn aligned_wall_ends_support_a_doorway_as_a_pair() {
    // A 1.1 m wall piece each side of a 0.8 m opening, standing free
    // 2 m into a 6 m room: short, but in line and facing each other.
    let piece = |x: usize, y: usize| y == 20 && ((9..20).contains(&x) || (28..39).contains(&x));
    let s = grid(60, 60, piece);
    assert_eq!(s.supported([20.0, 20.0], [27.0, 20.0], false), Some(true));
    // One end alone is not enough.
    let one = grid(60, 60, |x, y| y == 20 && (9..20).contains(&x));
    assert_eq!(
        one.supported([20.0, 20.0], [27.0, 20.0], false),
        Some(false)
    );
}

#[test]
fn a_partition_tied_to_the_walls_at_both_ends_supports_its_doorway_gap() {
    // Two 2 m rooms; the wall between them (x = 22) runs 0.6 m from
    // each outer wall to a 0.8 m doorway (y 7..15).
    let s = grid(45, 22, |x, y| x == 22 && !(7..15).contains(&y));
    assert_eq!(s.supported([22.0, 7.0], [22.0, 14.0], true), Some(true));
    // As a border, ties do not count.
    assert_eq!(s.supported([22.0, 7.0], [22.0, 14.0], false), Some(false));
    // Tied at one end only: a stub, not a partition.
    let stub = grid(45, 22, |x, y| x == 22 && y < 7);
    assert_eq!(stub.supported([22.0, 7.0], [22.0, 14.0], true), Some(false));
}

#[test]
fn doorway_gaps_in_a_wall_of_short_pieces_are_anchored() {
    // A 5 m wide building; the wall at y = 20 has a 0.8 m and a 1.5 m
    // doorway, with pieces of 0.7 m (to the outer wall), 1.1 m and
    // 0.7 m (to the outer wall): no piece is long, none pairs.
    let wall = |x: usize, y: usize| y == 20 && !((8..16).contains(&x) || (27..42).contains(&x));
    let s = grid(50, 40, wall);
    assert_eq!(s.supported([8.0, 20.0], [15.0, 20.0], true), Some(true));
    assert_eq!(s.supported([27.0, 20.0], [41.0, 20.0], true), Some(true));
    // Judged as a border, the first is unsupported.
    assert_eq!(s.supported([8.0, 20.0], [15.0, 20.0], false), Some(false));
}

#[test]
fn a_gap_between_clutter_near_walls_is_unsupported() {
    // Two 0.5 m blocks 0.8 m apart, 1.5 m from a 6 m room's wall.
    let blocks = |x: usize, y: usize| {
        (14..19).contains(&y) && ((20..25).contains(&x) || (33..38).contains(&x))
    };
    let s = grid(60, 60, blocks);
    assert_eq!(s.supported([25.0, 16.0], [32.0, 16.0], false), Some(false));
    // As a doorway gap's line of pixels (row 16, columns 25..=32): the
    // gap is dropped.
    let line: Vec<u32> = (25..=32).map(|x| 16 * 60 + x).collect();
    assert!(s.lacks_gap(&line));
    assert!(!s.lacks(&[]), "no border, nothing to judge");
}

#[test]
fn clutter_on_the_wall_lines_is_a_doorway_gaps_jamb() {
    // An 8 m building; its 0.4 m wall at y 19..23 runs 3 m from the
    // west wall to a 0.8 m doorway (x 30..38), stands as a 1 m block
    // (x 38..48), and after a second doorway (x 48..56) goes on to the
    // east wall. The block is small and blocky: clutter by its shape.
    let in_wall = |x: usize, y: usize| {
        (19..23).contains(&y) && !((30..38).contains(&x) || (48..56).contains(&x))
    };
    let s = grid(80, 40, in_wall);
    let doorway: Vec<u32> = (30..38).map(|x| 21 * 80 + x).collect();
    assert!(!s.lacks_gap(&doorway), "the block is the doorway's jamb");
    // The watershed's border there ends on clutter all the same.
    assert!(s.lacks(&doorway));
    // The same block 0.4 m off the wall's line is a desk: a gap from
    // it lacks support, though the wall beside it is long.
    let desk = |x: usize, y: usize| {
        ((19..23).contains(&y) && !(30..56).contains(&x))
            || ((38..48).contains(&x) && (27..31).contains(&y))
    };
    let off = grid(80, 40, desk);
    let to_desk: Vec<u32> = (30..38).map(|x| 29 * 80 + x).collect();
    assert!(off.lacks_gap(&to_desk));
}

#[test]
fn a_doorway_in_a_wall_along_a_further_direction_is_judged_along_it() {
    // A diagonal wall (45 degrees, 2 px thick) across an 8 m room, with
    // a doorway 0.8 m along it.
    let rows: Vec<String> = (0..81)
        .map(|y| {
            (0..81)
                .map(|x| {
                    let edge = x == 0 || y == 0 || x == 80 || y == 80;
                    let diagonal = (x == y || x == y + 1) && !(30..38).contains(&y);
                    if edge || diagonal { '#' } else { '.' }
                })
                .collect()
        })
        .collect();
    let g = OccupancyGrid::from_ascii(&rows.join("\n"), 0.1);
    let (a, b) = ([30.0, 30.0], [37.0, 37.0]);
    // Along the dominant directions only, the rule abstains…
    let along_axes = WallSupport::new(&g, &islands(&g), 0.0, &[], AT_10_CM);
    assert_eq!(along_axes.supported(a, b, true), None);
    // …with the wall's own direction, the wall going on beyond both
    // ends supports the doorway.
    let along_wall = WallSupport::new(&g, &islands(&g), 0.0, &[45.0], AT_10_CM);
    assert_eq!(along_wall.supported(a, b, true), Some(true));
}

#[test]
fn the_rule_abstains_off_the_walls_directions_and_far_from_walls() {
    let s = grid(60, 60, |_, _| false);
    // A diagonal doorway line.
    assert_eq!(s.supported([20.0, 20.0], [25.0, 25.0], false), None);
    // A doorway line in the middle of a 10 m hall, 4.5 m from its walls.
    let hall = grid(101, 101, |_, _| false);
    assert_eq!(hall.supported([46.0, 50.0], [54.0, 50.0], false), None);
}
