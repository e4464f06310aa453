//! Tests of `wall_gaps.rs` for openings wider than doorways: their own
//! scan, the stack's stop at an alcove, narrow faces, jambs behind a
//! reveal and past a ragged bump, openings beside a room's corner, borders
//! crossing a gap's line, on small hand-made masks.

use super::*;

/// A 30 x 14 px floor with a wall in rows 6-7 that has a 12 px
/// opening (x 8..20), and `extra(x, y)` walls besides.
fn front(extra: impl Fn(usize, usize) -> bool) -> Mask {
    Mask::from_fn(30, 14, |x, y| {
        let (x, y) = (x as usize, y as usize);
        let wall = (6..8).contains(&y) && !(8..20).contains(&x);
        image::Luma([if wall || extra(x, y) { 0 } else { 255 }])
    })
}

const OPENINGS: GapLimits = GapLimits {
    width: (9, 16),
    jamb: 4,
    depth: 3,
    kind: GapKind::Opening {
        face: 2,
        step: 2,
        near_margin: 2,
    },
};

/// [`OPENINGS`] up to 24 px wide: an alcove's rows are gaps too.
const ALCOVE_OPENINGS: GapLimits = GapLimits {
    width: (9, 24),
    ..OPENINGS
};

#[test]
fn an_opening_wider_than_any_doorway_is_found_by_its_own_scan() {
    let g = axis_gaps(&front(|_, _| false), OPENINGS);
    assert_eq!(g.len(), 1, "{g:?}");
    assert_eq!(g[0].width_px, 12);
    // Jamb to jamb, along row 7 (the middle of the 2-row stack).
    assert_eq!(g[0].ends(30), Some([[8.0, 7.5], [20.0, 7.5]]));
    let index = GapIndex::new(&g, 30);
    assert_eq!(index.crossed(&g[0].line[..6]), Some(&g[0]));
    assert_eq!(index.crossed(&g[0].line[..5]), None);
    // The doorway scan takes none so wide.
    let doorways = GapLimits {
        width: (2, 8),
        kind: GapKind::Doorway,
        ..OPENINGS
    };
    assert!(axis_gaps(&front(|_, _| false), doorways).is_empty());
    // A wall hugging one face (row 9, x 12..20) leaves no opening.
    let hugged = front(|x, y| y == 9 && (12..20).contains(&x));
    assert!(axis_gaps(&hugged, OPENINGS).is_empty());
}

#[test]
fn a_border_ragged_by_a_pixel_about_a_gap_line_crosses_it() {
    let g = axis_gaps(&front(|_, _| false), OPENINGS);
    assert_eq!(g.len(), 1, "{g:?}");
    let index = GapIndex::new(&g, 30);
    let at = |x: u32, y: u32| y * 30 + x;
    // Along row 7 (the line) for x 15..20 and a row below it for x 8..15:
    // on the line for less than half of it, beside it for the rest.
    let ragged: Vec<u32> = (8..15)
        .map(|x| at(x, 8))
        .chain((15..20).map(|x| at(x, 7)))
        .collect();
    assert_eq!(index.crossed(&ragged), Some(&g[0]));
    // Two rows below for x 8..15: no more than the five pixels on it.
    let apart: Vec<u32> = (8..15)
        .map(|x| at(x, 9))
        .chain((15..20).map(|x| at(x, 7)))
        .collect();
    assert_eq!(index.crossed(&apart), None);
}

#[test]
fn an_opening_into_an_alcove_no_wider_than_an_opening_ends_at_the_step() {
    // The front of `front`, and below it an alcove 20 px wide (x
    // 4..24) down to the edge: every alcove row is itself a gap no
    // wider than an opening may be.
    let alcove = front(|x, y| y >= 8 && !(4..24).contains(&x));
    let limits = ALCOVE_OPENINGS;
    let g = axis_gaps(&alcove, limits);
    assert_eq!(g.len(), 1, "{g:?}");
    assert_eq!(g[0].ends(30), Some([[8.0, 7.5], [20.0, 7.5]]));
    // Without the stop the stack runs 8 rows deep, past any wall.
    let no_stop = GapLimits {
        kind: GapKind::Opening {
            face: 2,
            step: 5,
            near_margin: 2,
        },
        ..limits
    };
    assert!(axis_gaps(&alcove, no_stop).is_empty());
}

#[test]
fn an_opening_from_an_alcove_ends_where_the_wall_begins() {
    // The front of `front`, and above it an alcove 20 px wide (x
    // 4..24) up to the edge: the stack of its rows steps in at the
    // wall, whose own rows are the opening.
    let alcove = front(|x, y| y < 6 && !(4..24).contains(&x));
    let limits = ALCOVE_OPENINGS;
    let g = axis_gaps(&alcove, limits);
    assert_eq!(g.len(), 1, "{g:?}");
    assert_eq!(g[0].ends(30), Some([[8.0, 7.5], [20.0, 7.5]]));
    assert!(!g[0].narrow_faces);
}

#[test]
fn an_opening_into_a_room_hardly_wider_than_it_has_narrow_faces() {
    // Below the front of `front` a room 15 px wide (x 6..21): the
    // floor beyond that face is wider than the 12 px opening by 3 px,
    // less than the 4 px jamb, at least the near margin of 2.
    let room = front(|x, y| y >= 8 && !(6..21).contains(&x));
    let g = axis_gaps(&room, OPENINGS);
    assert_eq!(g.len(), 1, "{g:?}");
    assert_eq!(g[0].ends(30), Some([[8.0, 7.5], [20.0, 7.5]]));
    assert!(g[0].narrow_faces);
    // Floor a jamb wider on both faces: no narrow faces.
    let open = axis_gaps(&front(|_, _| false), OPENINGS);
    assert_eq!(open.len(), 1, "{open:?}");
    assert!(!open[0].narrow_faces);
    // A near margin above 3 px leaves no opening.
    let strict = GapLimits {
        kind: GapKind::Opening {
            face: 2,
            step: 2,
            near_margin: 4,
        },
        ..OPENINGS
    };
    assert!(axis_gaps(&room, strict).is_empty());
}

/// The opening of [`front`] with the wall left of it cut back to a stub
/// (x 6..8, rows `stub_rows`) standing from a wall across at x 5 (rows
/// 0..8; none without `behind`): a room's side wall, the floor beyond it
/// and below the opening's wall a corridor.
fn reveal(stub_rows: std::ops::Range<usize>, behind: bool) -> Mask {
    Mask::from_fn(30, 14, |x, y| {
        let (x, y) = (x as usize, y as usize);
        let right = (6..8).contains(&y) && x >= 20;
        let stub = stub_rows.contains(&y) && (6..8).contains(&x);
        image::Luma([if right || stub || (behind && x == 5 && y < 8) {
            0
        } else {
            255
        }])
    })
}

#[test]
fn an_opening_may_end_at_a_reveal_standing_from_a_wall_across() {
    // A 2 px stub as thick as the wall: with the wall across, 3 px of
    // wall in line, short of the 4 px jamb.
    let g = axis_gaps(&reveal(6..8, true), OPENINGS);
    assert_eq!(g.len(), 1, "{g:?}");
    assert_eq!(g[0].ends(30), Some([[8.0, 7.5], [20.0, 7.5]]));
    // The stub with no wall behind it is no jamb.
    assert!(axis_gaps(&reveal(6..8, false), OPENINGS).is_empty());
    // A block 5 rows thick (a shelf standing from the wall) is no reveal:
    // thicker than the opening's wall, too short to be a wall across.
    assert!(axis_gaps(&reveal(4..9, true), OPENINGS).is_empty());
    // Doorway gaps take no reveals.
    let doorways = GapLimits {
        kind: GapKind::Doorway,
        ..OPENINGS
    };
    assert!(axis_gaps(&reveal(6..8, true), doorways).is_empty());
}

#[test]
fn a_ragged_bump_at_the_end_of_the_wall_in_line_is_still_its_jamb() {
    // The wall right of the opening is 5 rows thick at its first column
    // (x 20, rows 5..10): thicker than the opening's wall, too short to be
    // a wall across. The next column is the wall's own 2 rows.
    let bump = front(|x, y| x == 20 && (5..10).contains(&y));
    let g = axis_gaps(&bump, OPENINGS);
    assert_eq!(g.len(), 1, "{g:?}");
    assert_eq!(g[0].ends(30), Some([[8.0, 7.5], [20.0, 7.5]]));
    // Two such columns: a wall offset from the opening's, no jamb.
    let block = front(|x, y| (20..22).contains(&x) && (5..10).contains(&y));
    assert!(axis_gaps(&block, OPENINGS).is_empty());
}

#[test]
fn an_opening_beside_a_room_corner_ends_on_the_short_piece_of_wall_there() {
    // The front of `front`, with the building's side wall from x = 23 on:
    // right of the opening a 3 px piece of the front (x 20..23, shorter
    // than a jamb) runs into it, and on neither face does the floor go a
    // jamb past the opening's right end.
    let corner = front(|x, _| x >= 23);
    let g = axis_gaps(&corner, OPENINGS);
    assert_eq!(g.len(), 1, "{g:?}");
    assert_eq!(g[0].ends(30), Some([[8.0, 7.5], [20.0, 7.5]]));
    // The right end (the line's last) stands beside the corner, the left
    // on a jamb.
    assert_eq!(g[0].corner_ends, [false, true]);
    // The side wall's face ragged (x = 23 free at rows 4 and 9, so the
    // face column is broken within the depth and a jamb): the wall across
    // stands a pixel further in.
    let ragged_face = front(|x, y| x >= 24 || (x == 23 && y != 4 && y != 9));
    let g = axis_gaps(&ragged_face, OPENINGS);
    assert_eq!(g.len(), 1, "{g:?}");
    assert_eq!(g[0].corner_ends, [false, true]);
    // A 2 px piece (x 20..22) is no more than a ragged wall's end.
    let ragged = front(|x, _| x >= 22);
    assert!(axis_gaps(&ragged, OPENINGS).is_empty());
    // The piece's third column 5 px thick (rows 5..10, thicker than the
    // opening's wall): a block standing in the corner, no piece of the
    // front (the first column is still the opening's thin jamb).
    let block = front(|x, y| x >= 23 || (x == 22 && (5..10).contains(&y)));
    assert!(axis_gaps(&block, OPENINGS).is_empty());
    // A piece as long as a jamb (x 20..24) is a jamb anyway, no corner.
    let long = front(|x, _| x >= 24);
    let g = axis_gaps(&long, OPENINGS);
    assert_eq!(g.len(), 1, "{g:?}");
    assert_eq!(g[0].corner_ends, [false, false]);
}
