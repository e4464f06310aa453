//! Wall-stub openings: the opening between the free end of a thin wall
//! and the wall it points at. A partition that stops short of the wall
//! across leaves one opening between the two rooms it divides; the
//! ground truths draw it as the partition's line carried on to that wall,
//! as ROSE² (Luperto et al., RA-L 2022) extends walls into lines. The
//! doorway scan of `wall_gaps.rs` cannot see it: the wall across goes on
//! past both faces of such a line, as a corridor's side wall does beside a
//! corridor piece.
//!
//! A stub is found along the map's two dominant directions. It is thin
//! ([`WallStubLimits::thick`]) over its first [`WallStubLimits::head`]
//! and over most of [`WallStubLimits::length`], so the foot of a T (a
//! wall meeting another, whose ragged face looks like a short end) is no
//! stub. Its line runs from the end along the stub to the first wall, that
//! wall running on across it to both sides, with floor on both sides of
//! the line. A stub with a piece of wall across near its end
//! ([`WallStubLimits::front_run`] within [`WallStubLimits::front_reach`]) is
//! a divider between bays whose open fronts face a passage, and its line
//! would cross the passage: none is drawn.

use super::wall_gaps::{WallGap, turned_gaps};
use crate::imaging::Mask;

/// The limits of [`wall_stub_openings`], in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct WallStubLimits {
    /// Narrowest and widest opening.
    pub width: (usize, usize),
    /// Thickest stub.
    pub thick: usize,
    /// How far from its end a stub is looked at.
    pub length: usize,
    /// Share of `length` over which the stub is thin with free space
    /// beside it (a wall may touch it further on).
    pub thin_share: f64,
    /// How far from its end a stub is thin all the way.
    pub head: usize,
    /// Lines beyond each side of the opening's line with floor across
    /// nine tenths of them.
    pub face: usize,
    /// Shortest piece of wall across near the stub's end that makes a
    /// front.
    pub front_run: usize,
    /// How far to either side of the stub a front is looked for.
    pub front_reach: usize,
    /// How far across its end a front's pieces may lie; the pipeline also
    /// keeps a line this far from the doorway gaps and openings already
    /// found, but for the opening it ends on (`stub_openings.rs`).
    pub tolerance: usize,
}

/// The wall-stub openings of `free` (non-zero = free), along its dominant
/// directions `deg` (degrees, see `imaging::dominant_orientation`): lines
/// of free pixels from a thin wall's end to the wall it points at (see the
/// module doc).
pub(crate) fn wall_stub_openings(free: &Mask, deg: f64, limits: &WallStubLimits) -> Vec<WallGap> {
    turned_gaps(free, deg, |m| axis_stub_openings(m, limits))
}

/// One of the four ways a stub may point, as a frame in which it points
/// up (towards row 0): frame `(x, y)` is image pixel [`Frame::pixel`].
#[derive(Debug, Clone, Copy)]
enum Frame {
    Up,
    Down,
    Left,
    Right,
}

impl Frame {
    /// The frame's width and height for a `w` × `h` image.
    fn size(self, w: i64, h: i64) -> (i64, i64) {
        match self {
            Frame::Up | Frame::Down => (w, h),
            Frame::Left | Frame::Right => (h, w),
        }
    }

    /// The image pixel at frame pixel `(x, y)` of a `w` × `h` image.
    fn pixel(self, x: i64, y: i64, w: i64, h: i64) -> (i64, i64) {
        match self {
            Frame::Up => (x, y),
            Frame::Down => (x, h - 1 - y),
            Frame::Left => (y, x),
            Frame::Right => (w - 1 - y, x),
        }
    }

    /// Whether the frame's rows run the other way from those of its
    /// upright image (`Down` of the image, `Right` of the transposed one).
    fn flipped(self) -> bool {
        matches!(self, Frame::Down | Frame::Right)
    }

    /// Whether the frame reads the image transposed (rows are columns).
    fn transposed(self) -> bool {
        matches!(self, Frame::Left | Frame::Right)
    }
}

/// The `w` × `h` image `data` transposed (`h` × `w`), in 32-pixel tiles so
/// that reads and writes both stay in cache.
fn transpose(data: &[u8], w: usize, h: usize) -> Vec<u8> {
    const TILE: usize = 32;
    let mut out = vec![0u8; w * h];
    for y0 in (0..h).step_by(TILE) {
        for x0 in (0..w).step_by(TILE) {
            for y in y0..(y0 + TILE).min(h) {
                for x in x0..(x0 + TILE).min(w) {
                    out[x * h + y] = data[y * w + x];
                }
            }
        }
    }
    out
}

/// [`wall_stub_openings`] for walls along rows and columns.
fn axis_stub_openings(free: &Mask, limits: &WallStubLimits) -> Vec<WallGap> {
    let (w, h) = (i64::from(free.width()), i64::from(free.height()));
    let data = free.as_raw();
    let mut out = Vec::new();
    let transposed = transpose(data, w as usize, h as usize);
    for frame in [Frame::Up, Frame::Down, Frame::Left, Frame::Right] {
        let (fw, fh) = frame.size(w, h);
        if fw == 0 || fh == 0 {
            continue;
        }
        // The image as the frame sees it, row by row (the rows in reverse
        // order for a flipped frame), so that the scan below reads along
        // its rows whatever way the stub points.
        let upright: &[u8] = if frame.transposed() {
            &transposed
        } else {
            data
        };
        let flip = frame.flipped();
        let row = |y: i64| {
            let r = if flip { fh - 1 - y } else { y } as usize;
            &upright[r * fw as usize..(r + 1) * fw as usize]
        };
        let is_free = |x: i64, y: i64| {
            (0..fw).contains(&x) && (0..fh).contains(&y) && row(y)[x as usize] != 0
        };
        let stubs = StubFinder {
            is_free: &is_free,
            width: fw,
            limits,
        };
        for y in 1..fh {
            let row = row(y);
            let mut x = 0;
            // Each run of wall in the row.
            while let Some(start) = row[x..].iter().position(|&p| p == 0) {
                let x0 = x + start;
                x = row[x0..]
                    .iter()
                    .position(|&p| p != 0)
                    .map_or(row.len(), |e| x0 + e);
                if let Some((mid, hit)) = stubs.opening(x0 as i64, x as i64, y) {
                    out.push(WallGap {
                        line: (hit + 1..y)
                            .map(|r| {
                                let (ix, iy) = frame.pixel(mid, r, w, h);
                                (iy * w + ix) as u32
                            })
                            .collect(),
                        width_px: (y - 1 - hit) as usize,
                        narrow_faces: false,
                        corner_ends: [false; 2],
                    });
                }
            }
        }
    }
    out
}

/// The checks of one frame, in which stubs point up.
struct StubFinder<'a, F: Fn(i64, i64) -> bool> {
    is_free: &'a F,
    width: i64,
    limits: &'a WallStubLimits,
}

impl<F: Fn(i64, i64) -> bool> StubFinder<'_, F> {
    /// The opening above the wall run `[x0, x1)` of row `y`, if that run
    /// is a stub's end: the stub's middle column and the row of the wall
    /// its line reaches.
    fn opening(&self, x0: i64, x1: i64, y: i64) -> Option<(i64, i64)> {
        let l = self.limits;
        let free = self.is_free;
        let thick = l.thick as i64;
        // An end: the run is thin, with free space above it and one past
        // either side.
        if x1 - x0 > thick || !(x0 - 1..=x1).all(|k| free(k, y - 1)) {
            return None;
        }
        let mid = (x0 + x1) / 2;
        if !self.is_stub(mid, y) {
            return None;
        }
        let hit = (0..y).rev().find(|&r| !free(mid, r))?;
        let width = (y - 1 - hit) as usize;
        if width < l.width.0 || width > l.width.1 {
            return None;
        }
        // The wall reached runs on across the line to both sides.
        let reach = l.length as i64;
        let across = (x0 - reach..x1 + reach).filter(|&k| !free(k, hit)).count();
        if across < 2 * l.length {
            return None;
        }
        let floor = |side: i64| {
            let cells = (hit + 1..y).flat_map(|r| (1..=l.face as i64).map(move |j| (r, j)));
            let (n, f) = cells.fold((0usize, 0usize), |(n, f), (r, j)| {
                (n + 1, f + usize::from(free(mid + side * j, r)))
            });
            n > 0 && 10 * f >= 9 * n
        };
        if !floor(-1) || !floor(1) || self.front(x0, x1, y) {
            return None;
        }
        Some((mid, hit))
    }

    /// Whether the wall through column `mid` from row `y` down is a stub:
    /// thin over its first `head` rows, and thin with free space beside it
    /// over `thin_share` of its first `length` rows, all of them wall.
    fn is_stub(&self, mid: i64, y: i64) -> bool {
        let l = self.limits;
        let mut thin = 0usize;
        for (i, r) in (y..y + l.length as i64).enumerate() {
            let Some((a, b)) = self.run(mid, r) else {
                return false;
            };
            let narrow = b - a <= l.thick as i64;
            if i < l.head && !narrow {
                return false;
            }
            if narrow && ((self.is_free)(a - 1, r) || (self.is_free)(b, r)) {
                thin += 1;
            }
        }
        thin as f64 >= l.thin_share * l.length as f64
    }

    /// The wall run `[a, b)` of row `y` through column `x`, followed at
    /// most one stub thickness past `x` each way; None on free space.
    fn run(&self, x: i64, y: i64) -> Option<(i64, i64)> {
        let free = self.is_free;
        if free(x, y) {
            return None;
        }
        let thick = self.limits.thick as i64;
        let mut a = x;
        while a > 0 && !free(a - 1, y) && x - a <= thick {
            a -= 1;
        }
        let mut b = x + 1;
        while b < self.width && !free(b, y) && b - x <= thick {
            b += 1;
        }
        Some((a, b))
    }

    /// Whether a piece of wall at least `front_run` long runs across near
    /// the stub's end `[x0, x1)` in row `y`, beside the stub (past twice
    /// its thickness) and within `front_reach` of it on either side.
    fn front(&self, x0: i64, x1: i64, y: i64) -> bool {
        let l = self.limits;
        let (thick, reach, tol) = (l.thick as i64, l.front_reach as i64, l.tolerance as i64);
        let piece = |from: i64, to: i64| {
            (y - tol..=y + tol).any(|r| {
                let mut n = 0usize;
                (from..to).any(|k| {
                    n = if (self.is_free)(k, r) { 0 } else { n + 1 };
                    n >= l.front_run
                })
            })
        };
        piece(x0 - reach, x0 - 2 * thick) || piece(x1 + 2 * thick, x1 + reach)
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// Limits at 0.05 m/px, as `pixel_config` sets them.
    pub(in crate::extract) const AT_5_CM: WallStubLimits = WallStubLimits {
        width: (6, 80),
        thick: 8,
        length: 20,
        thin_share: 0.7,
        head: 6,
        face: 6,
        front_run: 10,
        front_reach: 30,
        tolerance: 2,
    };

    /// A `w` × `h` free mask walled round, with `wall(x, y)` cells wall.
    pub(in crate::extract) fn mask(w: u32, h: u32, wall: impl Fn(u32, u32) -> bool) -> Mask {
        let mut m = Mask::new(w, h);
        for y in 0..h {
            for x in 0..w {
                let edge = x == 0 || y == 0 || x + 1 == w || y + 1 == h;
                if !edge && !wall(x, y) {
                    m.as_mut()[(y * w + x) as usize] = 255;
                }
            }
        }
        m
    }

    #[test]
    fn a_partition_short_of_the_wall_across_leaves_an_opening() {
        // Two 4 m rooms side by side (y 1..80); the 0.15 m partition
        // between them (x 40..43) runs from the south wall to y = 40 and
        // stops 2 m short of the north wall.
        let m = mask(84, 81, |x, y| (40..43).contains(&x) && y >= 40);
        let found = wall_stub_openings(&m, 0.0, &AT_5_CM);
        assert_eq!(found.len(), 1, "{found:?}");
        let g = &found[0];
        assert_eq!(g.width_px, 39, "from y = 1 to 39");
        assert!(
            g.line.iter().all(|&p| p % 84 == 41),
            "along the partition's middle"
        );
    }

    #[test]
    fn a_wall_meeting_another_is_no_stub() {
        // A T: the partition (x 40..43, from y = 41 south) meets a 1.15 m
        // piece of wall across (x 30..53, y 38..41) between two doorways,
        // whose north face is ragged (every third pixel free): the piece of
        // face between two holes above the partition looks like a thin end.
        let m = mask(84, 81, |x, y| {
            ((40..43).contains(&x) && y >= 41)
                || ((30..53).contains(&x) && (39..41).contains(&y))
                || ((30..53).contains(&x) && y == 38 && x % 3 != 0)
        });
        let found = wall_stub_openings(&m, 0.0, &AT_5_CM);
        // The piece's own ends do leave openings, to the outer walls.
        assert_eq!(found.len(), 2, "{found:?}");
        assert!(
            !found
                .iter()
                .any(|g| g.line.iter().any(|&p| p % 84 == 41 && p / 84 < 38)),
            "none northwards from the partition: {found:?}"
        );
    }

    #[test]
    fn a_divider_between_bays_facing_a_passage_draws_no_line() {
        // Bays along a corridor: a divider ends at y = 40 on the bays'
        // front line, with 0.55 m return walls on it at the bays' far
        // corners, 0.85 m to either side (x 12..23 and 60..71); the
        // corridor's far wall at y = 1.
        let m = mask(84, 81, |x, y| {
            ((40..43).contains(&x) && y >= 40)
                || (y == 40 && ((12..23).contains(&x) || (60..71).contains(&x)))
        });
        // Without the returns the line is drawn.
        let open = mask(84, 81, |x, y| (40..43).contains(&x) && y >= 40);
        assert_eq!(wall_stub_openings(&open, 0.0, &AT_5_CM).len(), 1);
        assert!(wall_stub_openings(&m, 0.0, &AT_5_CM).is_empty());
    }

    #[test]
    fn a_cabinet_is_no_stub() {
        // A 0.6 m deep cabinet standing 1.5 m out from the south wall.
        let m = mask(84, 81, |x, y| (35..47).contains(&x) && y >= 50);
        assert!(wall_stub_openings(&m, 0.0, &AT_5_CM).is_empty());
    }
}
