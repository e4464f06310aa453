//! Wall-stub openings among the openings already found: a stub's line
//! runs from its end to the first wall, and an opening's line counts as
//! wall, the wall line it carries on across the opening (ROSE², Luperto
//! et al., RA-L 2022, extends walls into lines that meet other lines).
//! Where a stub's line ends on an opening, that opening is cut in two
//! there: a partition behind an open front (a corridor wall the sensor
//! saw only in pieces) divides the front into one opening per room.

use std::collections::HashSet;

use super::wall_gaps::{WallGap, near_lines};
use super::wall_stubs::{WallStubLimits, wall_stub_openings};
use crate::imaging::Mask;

/// The wall-stub openings of `clean` (non-zero = free) along its dominant
/// directions `deg`, with `openings` closed (see the module doc), each
/// passing no line of `openings` or `doorways` within
/// `limits.tolerance` but the opening it ends on, and `supported`. The
/// openings a kept stub's line ends on are cut there (see
/// [`cut_at`]).
pub(crate) fn stub_openings(
    clean: &Mask,
    deg: f64,
    limits: &WallStubLimits,
    openings: &mut Vec<WallGap>,
    doorways: &[WallGap],
    supported: impl Fn(&WallGap) -> bool,
) -> Vec<WallGap> {
    let width = clean.width();
    let mut closed = clean.clone();
    for &p in openings.iter().flat_map(|g| &g.line) {
        closed.as_mut()[p as usize] = 0;
    }
    let near_all = near_lines(openings.iter().chain(doorways), width, limits.tolerance);
    // Per opening: the indices along its line where kept stubs end.
    let mut cuts: Vec<Vec<usize>> = vec![Vec::new(); openings.len()];
    let mut kept = Vec::new();
    for stub in wall_stub_openings(&closed, deg, limits) {
        let meets = meeting(openings, &stub, width);
        let near_others: HashSet<u32>;
        let near = match meets {
            None => &near_all,
            Some((k, _)) => {
                let others = openings.iter().enumerate().filter(|&(j, _)| j != k);
                near_others = near_lines(
                    others.map(|(_, g)| g).chain(doorways),
                    width,
                    limits.tolerance,
                );
                &near_others
            }
        };
        if stub.line.iter().any(|p| near.contains(p)) || !supported(&stub) {
            continue;
        }
        if let Some((k, at)) = meets {
            cuts[k].push(at);
        }
        kept.push(stub);
    }
    let min = limits.width.0;
    *openings = openings
        .iter()
        .zip(&cuts)
        .flat_map(|(g, at)| cut_at(g, at, min))
        .collect();
    kept
}

/// The opening (index in `openings`) a stub's line ends on, and the index
/// along its line of the pixel it meets: the pixel of an opening's line
/// nearest the point a pixel beyond the stub line's first end (the end at
/// the wall it reached, see `wall_stubs`), if within a pixel and a half.
fn meeting(openings: &[WallGap], stub: &WallGap, width: u32) -> Option<(usize, usize)> {
    let centre = |p: u32| [f64::from(p % width) + 0.5, f64::from(p / width) + 0.5];
    let (a, b) = (centre(*stub.line.first()?), centre(*stub.line.last()?));
    let len = (a[0] - b[0]).hypot(a[1] - b[1]);
    if len <= 0.0 {
        return None;
    }
    let hit = [a[0] + (a[0] - b[0]) / len, a[1] + (a[1] - b[1]) / len];
    openings
        .iter()
        .enumerate()
        .flat_map(|(k, g)| {
            g.line.iter().enumerate().map(move |(i, &p)| {
                let c = centre(p);
                ((c[0] - hit[0]).hypot(c[1] - hit[1]), k, i)
            })
        })
        .filter(|&(d, _, _)| d <= 1.5)
        .min_by(|x, y| x.0.total_cmp(&y.0))
        .map(|(_, k, i)| (k, i))
}

/// `gap` cut after each index of `at` along its line (the pixel met stays
/// with the first piece, so the line stays closed there), where both
/// pieces keep at least `min` pixels; each piece as wide as its pixels.
fn cut_at(gap: &WallGap, at: &[usize], min: usize) -> Vec<WallGap> {
    let mut at = at.to_vec();
    at.sort_unstable();
    at.dedup();
    let n = gap.line.len();
    let piece = |from: usize, to: usize| WallGap {
        line: gap.line[from..to].to_vec(),
        width_px: to - from,
        narrow_faces: gap.narrow_faces,
    };
    if at.is_empty() {
        return vec![gap.clone()];
    }
    let mut pieces = Vec::new();
    let mut start = 0;
    for i in at {
        let end = i + 1;
        if end >= start + min && n >= end + min {
            pieces.push(piece(start, end));
            start = end;
        }
    }
    pieces.push(piece(start, n));
    pieces
}

#[cfg(test)]
mod tests {
    use super::super::wall_stubs::tests::{AT_5_CM, mask};
    use super::*;

    /// The opening along row `y` from column `x0` to `x1` (exclusive) of a
    /// `w`-wide image.
    fn opening(w: u32, y: u32, x0: u32, x1: u32) -> WallGap {
        WallGap {
            line: (x0..x1).map(|x| y * w + x).collect(),
            width_px: (x1 - x0) as usize,
            narrow_faces: false,
        }
    }

    /// A corridor (y 1..20) along two rooms whose front wall (y = 20) the
    /// sensor saw only at its ends (x 1..10 and 70..83): a 3 m opening
    /// between them (x 10..70). The partition between the rooms (x 40..43)
    /// runs from the south wall to y = 40, 1 m short of the front.
    fn front_with_a_partition() -> Mask {
        mask(84, 81, |x, y| {
            (y == 20 && !(10..70).contains(&x)) || ((40..43).contains(&x) && y >= 40)
        })
    }

    #[test]
    fn a_partition_behind_an_open_front_ends_on_it_and_cuts_it() {
        let m = front_with_a_partition();
        let mut openings = vec![opening(84, 20, 10, 70)];
        let stubs = stub_openings(&m, 0.0, &AT_5_CM, &mut openings, &[], |_| true);
        // The partition's line runs from its end up to the front (y 21..40),
        // not on across the corridor.
        assert_eq!(stubs.len(), 1, "{stubs:?}");
        assert_eq!(stubs[0].width_px, 19);
        assert!(
            stubs[0]
                .line
                .iter()
                .all(|&p| p % 84 == 41 && (21..40).contains(&(p / 84)))
        );
        // The front is cut where the partition's line meets it: one
        // opening to each room.
        let widths: Vec<usize> = openings.iter().map(|g| g.width_px).collect();
        assert_eq!(widths, vec![32, 28], "{openings:?}");
        assert!(openings[0].line.contains(&(20 * 84 + 41)));
    }

    #[test]
    fn without_the_front_found_the_partition_line_crosses_the_corridor() {
        // The same map with no opening found: the line runs on to the
        // corridor's far wall and no front is cut.
        let m = front_with_a_partition();
        let mut openings = Vec::new();
        let stubs = stub_openings(&m, 0.0, &AT_5_CM, &mut openings, &[], |_| true);
        assert_eq!(stubs.len(), 1, "{stubs:?}");
        assert_eq!(stubs[0].width_px, 39, "from y = 1 to 39");
    }

    #[test]
    fn a_stub_beside_a_doorway_already_found_draws_no_line() {
        // A doorway gap found beside the partition's end (x 43..60 on
        // row 39): the stub's line would pass within the tolerance of it.
        let m = front_with_a_partition();
        let mut openings = vec![opening(84, 20, 10, 70)];
        let doorway = opening(84, 39, 43, 60);
        let stubs = stub_openings(&m, 0.0, &AT_5_CM, &mut openings, &[doorway], |_| true);
        assert!(stubs.is_empty(), "{stubs:?}");
        assert_eq!(openings.len(), 1, "the front stays whole");
    }

    #[test]
    fn a_cut_leaving_a_piece_shorter_than_an_opening_is_not_made() {
        let g = opening(84, 20, 10, 30);
        // At index 3: the first piece would be 4 pixels, under 6.
        assert_eq!(cut_at(&g, &[3], 6), vec![g.clone()]);
        let pieces = cut_at(&g, &[9, 9], 6);
        assert_eq!(pieces.len(), 2);
        assert_eq!((pieces[0].width_px, pieces[1].width_px), (10, 10));
        assert_eq!(pieces[0].line.last(), Some(&(20 * 84 + 19)));
    }
}
