//! Doorway gaps in straight walls: a short run of free pixels along a row
//! (or column) with a wall run on either side, through a wall no thicker
//! than a limit, with free space on both faces of the wall. Such a gap is a
//! doorway even when it is as wide as the corridor it opens onto, where the
//! distance transform shows no constriction.

use std::collections::{HashMap, HashSet};

use super::interior::neighbours;
use crate::imaging::{Labels, Mask, line_pixels, turn_mask};

/// One doorway gap: the line across it (pixels, row-major indices) at the
/// middle of the wall's thickness, and its width in pixels.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct WallGap {
    /// The pixels of the line across the doorway.
    pub line: Vec<u32>,
    /// The doorway's width (pixels along the line).
    pub width_px: usize,
    /// An opening whose floor goes on past it on some face by less than a
    /// jamb (`GapKind::Opening::near_margin`, not `GapLimits::jamb`): a
    /// room hardly wider than its open front. Such a line is an opening
    /// only between walls the sensor saw, which the scan cannot tell
    /// from what it never saw (the pipeline checks).
    pub narrow_faces: bool,
    /// Whether the line's first and last end stand beside a room's corner
    /// (see `GapKind::Opening`): the wall across there is the room's side,
    /// tied to the opening's end by a thin piece of the opening's wall.
    pub corner_ends: [bool; 2],
}

impl WallGap {
    /// The gap's line from jamb to jamb (pixel coordinates, corners at
    /// whole numbers) in a `width`-wide image: the outer edges of its end
    /// pixels along the line.
    pub(crate) fn ends(&self, width: u32) -> Option<[[f64; 2]; 2]> {
        let centre = |p: u32| [f64::from(p % width) + 0.5, f64::from(p / width) + 0.5];
        let (a, b) = (centre(*self.line.first()?), centre(*self.line.last()?));
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        if len <= 0.0 {
            return None;
        }
        let u = [(b[0] - a[0]) / len * 0.5, (b[1] - a[1]) / len * 0.5];
        Some([[a[0] - u[0], a[1] - u[1]], [b[0] + u[0], b[1] + u[1]]])
    }
}

/// Which gap a border between two regions crosses: a gap at least half of
/// whose line pixels the border runs on or beside (a 4-neighbour: a border
/// ragged by a pixel about the line, where splitting off a passage moved a
/// few of the doorway's pixels to the other side). Built once over a set of
/// gaps in a `width`-wide image, asked per border.
pub(crate) struct GapIndex<'a> {
    gaps: &'a [WallGap],
    /// The gap each line pixel belongs to.
    at: HashMap<u32, usize>,
    width: u32,
}

impl<'a> GapIndex<'a> {
    /// The index of `gaps`' line pixels in a `width`-wide image.
    pub(crate) fn new(gaps: &'a [WallGap], width: u32) -> GapIndex<'a> {
        let at = gaps
            .iter()
            .enumerate()
            .flat_map(|(k, g)| g.line.iter().map(move |&p| (p, k)))
            .collect();
        GapIndex { gaps, at, width }
    }

    /// The gap the border through `pixels` crosses, if any (of several,
    /// the one it runs along furthest).
    pub(crate) fn crossed(&self, pixels: &[u32]) -> Option<&'a WallGap> {
        let w = self.width.max(1);
        // The line pixel at `p`, else one beside it.
        let line_pixel = |p: u32| {
            let beside = [
                (!p.is_multiple_of(w)).then(|| p - 1),
                (p % w + 1 < w).then(|| p + 1),
                p.checked_sub(w),
                p.checked_add(w),
            ];
            std::iter::once(p)
                .chain(beside.into_iter().flatten())
                .find_map(|q| self.at.get(&q).map(|&k| (q, k)))
        };
        let mut passed: HashSet<u32> = HashSet::new();
        let mut hits: HashMap<usize, usize> = HashMap::new();
        for (q, k) in pixels.iter().filter_map(|&p| line_pixel(p)) {
            if passed.insert(q) {
                *hits.entry(k).or_default() += 1;
            }
        }
        hits.into_iter()
            .filter(|&(k, n)| 2 * n >= self.gaps[k].line.len())
            .max_by_key(|&(k, n)| (n, std::cmp::Reverse(k)))
            .map(|(k, _)| &self.gaps[k])
    }
}

/// Limits of [`wall_gaps`], in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct GapLimits {
    /// Narrowest and widest doorway.
    pub width: (usize, usize),
    /// Wall run needed on either side of the gap (the door jambs).
    pub jamb: usize,
    /// Thickest wall a doorway may pass through.
    pub depth: usize,
    /// Doorways or wider openings.
    pub kind: GapKind,
}

/// What a scan looks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum GapKind {
    /// Doorway gaps: the checks of [`wall_gaps`].
    Doorway,
    /// Openings wider than doorways, judged harder. A jamb that is a wall
    /// going on in line is as thick as the stack (the opening's two jambs
    /// are the ends of one wall, not walls offset across the line, as
    /// where a slanted wall runs past a doorway); and the floor goes on
    /// for `face` lines beyond both faces across nine tenths of the
    /// opening's width (a wall hugging the line leaves no opening).
    /// A stack stops where the next line's gap steps out by `step` on
    /// either side of the line before it: there the wall's face ends and
    /// a room begins that is itself no wider than an opening (an alcove,
    /// a narrow room whose whole front is open), whose lines would
    /// otherwise carry the stack far deeper than any wall. It stops where
    /// the gap steps in by `step` too: there such a room ends at the
    /// wall's face, and the wall's own lines start a stack of their own.
    /// On each face the floor must be wider than the opening by a jamb;
    /// by `near_margin` only, the gap is kept as
    /// [`WallGap::narrow_faces`]. The wall in line may be thicker at its
    /// first pixel (a ragged bump) if not at the next. A jamb may also be
    /// a **reveal**: a wall in line shorter than a jamb, as thin as the
    /// opening's wall, that meets a wall across (a stub or door frame
    /// hanging from the wall the opening's line ends at, which the sensor
    /// saw). Measured on the 19 development buildings and 400 simulated
    /// ones (benches/README.md, "Openings behind a reveal" and "A ragged
    /// bump at an opening's jamb"): intel_map, intel_carmen and two houses
    /// gain doorways, nothing else changes; without the thinness of its
    /// first two pixels, shelves standing from a wall and ragged wall
    /// faces on turned maps pass as reveals. Beside a room's **corner**
    /// the floor on a face may end short of a jamb past the opening's end,
    /// where a piece of the opening's wall, as thin, longer than a ragged
    /// wall's end ([`RAGGED`]) and shorter than a jamb, runs into a wall
    /// across (at the floor's end or, behind a ragged face, up to
    /// `RAGGED` further) that reaches from the face line through the
    /// stack ("An opening beside a room's corner": six houses gain their
    /// openings; "A corner's wall is no passage's side": a ragged pixel
    /// is no piece). Such an end is kept in [`WallGap::corner_ends`].
    Opening {
        /// Lines looked at beyond each face.
        face: usize,
        /// Smallest step out or in from one line's gap to the next that
        /// ends a stack.
        step: usize,
        /// The least the floor on a face may be wider than the opening
        /// (a wall stub's length, less than a jamb).
        near_margin: usize,
    },
}

/// Finds doorway gaps in the walls of `free` (non-zero = free; everything
/// else is wall for this purpose) that run along the map's two dominant
/// directions (`deg` and a quarter turn from it, degrees, see
/// `imaging::dominant_orientation`): the map is turned so they lie along rows and columns, gaps
/// are found there and their lines drawn back into the map (4-connected,
/// reaching a pixel and a half into the jambs, free pixels only).
pub(crate) fn wall_gaps(free: &Mask, deg: f64, limits: GapLimits) -> Vec<WallGap> {
    turned_gaps(free, deg, |m| axis_gaps(m, limits))
}

/// The gaps `axis` finds in `free` turned so that `deg` (degrees) lies
/// along its rows, drawn back into `free` as [`wall_gaps`] draws its own.
pub(crate) fn turned_gaps(
    free: &Mask,
    deg: f64,
    axis: impl Fn(&Mask) -> Vec<WallGap>,
) -> Vec<WallGap> {
    if deg.min(90.0 - deg) < 0.5 {
        return axis(free);
    }
    let (turned, turn) = turn_mask(free, deg);
    let tw = turned.width() as usize;
    let centre = |i: u32| {
        [
            (i as usize % tw) as f64 + 0.5,
            (i as usize / tw) as f64 + 0.5,
        ]
    };
    axis(&turned)
        .into_iter()
        .filter_map(|g| {
            let (a, b) = (centre(*g.line.first()?), centre(*g.line.last()?));
            let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2))
                .sqrt()
                .max(1e-9);
            let u = [(b[0] - a[0]) / len * 1.5, (b[1] - a[1]) / len * 1.5];
            let (a, b) = ([a[0] - u[0], a[1] - u[1]], [b[0] + u[0], b[1] + u[1]]);
            let line: Vec<u32> =
                line_pixels(turn.back(a), turn.back(b), free.width(), free.height())
                    .into_iter()
                    .filter(|&p| free.as_raw()[p as usize] != 0)
                    .collect();
            (!line.is_empty()).then_some(WallGap {
                line,
                width_px: g.width_px,
                narrow_faces: g.narrow_faces,
                corner_ends: g.corner_ends,
            })
        })
        .collect()
}

/// [`wall_gaps`] for walls along rows and columns.
fn axis_gaps(free: &Mask, limits: GapLimits) -> Vec<WallGap> {
    let (w, h) = (free.width() as usize, free.height() as usize);
    let data = free.as_raw();
    let mut out = scan(
        h,
        w,
        |line, k| data[line * w + k] != 0,
        limits,
        |line, k| (line * w + k) as u32,
    );
    out.extend(scan(
        w,
        h,
        |line, k| data[k * w + line] != 0,
        limits,
        |line, k| (k * w + line) as u32,
    ));
    out
}

/// Closes each gap's line in the free mask and the reachable pixels, so
/// the segmentation treats it as wall.
pub(crate) fn close_gaps(clean: &mut Mask, reachable: &mut [bool], gaps: &[WallGap]) {
    for &p in gaps.iter().flat_map(|g| &g.line) {
        clean.as_mut()[p as usize] = 0;
        reachable[p as usize] = false;
    }
}

/// The pixels (row-major in a `width`-wide image) within `reach` (a
/// square) of the lines of `gaps`.
pub(crate) fn near_lines<'a>(
    gaps: impl Iterator<Item = &'a WallGap>,
    width: u32,
    reach: usize,
) -> HashSet<u32> {
    let (w, r) = (i64::from(width), reach as i64);
    let mut near = HashSet::new();
    for &p in gaps.flat_map(|g| &g.line) {
        let (x, y) = (i64::from(p) % w, i64::from(p) / w);
        for dy in -r..=r {
            for dx in -r..=r {
                let (nx, ny) = (x + dx, y + dy);
                if (0..w).contains(&nx) && ny >= 0 {
                    near.insert((ny * w + nx) as u32);
                }
            }
        }
    }
    near
}

/// Gives each closed line pixel the smallest label among its 4-neighbours
/// off the line, so the two sides of a doorway meet along its line.
pub(crate) fn reopen_gaps(labels: &mut Labels, gaps: &[WallGap]) {
    let (w, h) = (labels.width as usize, labels.height as usize);
    for gap in gaps {
        for &p in &gap.line {
            let i = p as usize;
            let best = neighbours(i, w, h)
                .filter(|j| !gap.line.contains(&(*j as u32)))
                .map(|j| labels.data[j])
                .filter(|&l| l != 0)
                .min();
            if let Some(l) = best {
                labels.data[i] = l;
            }
        }
    }
}

/// How many pixels a wall's face or end may stand out by where the map is
/// ragged (a wall's `thin` check and a room's `corner` piece allow for it).
const RAGGED: usize = 2;

/// A gap in one scan line: `[start, end)` along the line.
type Run = (usize, usize);

/// Scans `lines` lines of `len` pixels (`is_free(line, k)`), finds gaps in
/// each, stacks gaps of consecutive lines that overlap, and keeps stacks
/// thin enough with free space beyond both ends. `index(line, k)` maps back
/// to the image.
fn scan(
    lines: usize,
    len: usize,
    is_free: impl Fn(usize, usize) -> bool,
    limits: GapLimits,
    index: impl Fn(usize, usize) -> u32,
) -> Vec<WallGap> {
    let gaps: Vec<Vec<Run>> = (0..lines)
        .map(|l| gaps_in_line(len, |k| is_free(l, k), limits))
        .collect();
    let mut used: Vec<Vec<bool>> = gaps.iter().map(|g| vec![false; g.len()]).collect();
    let mut out = Vec::new();
    for first in 0..lines {
        for gi in 0..gaps[first].len() {
            if used[first][gi] {
                continue;
            }
            // Follow the stack down through lines whose gap matches this one.
            let (mut lo, mut hi) = gaps[first][gi];
            let mut last = first;
            let mut previous = (lo, hi);
            used[first][gi] = true;
            while last + 1 < lines {
                let next = gaps[last + 1]
                    .iter()
                    .position(|&(s, e)| 2 * (e.min(hi).saturating_sub(s.max(lo))) >= hi - lo);
                let Some(ni) = next else { break };
                if let GapKind::Opening { step, .. } = limits.kind {
                    let (s, e) = gaps[last + 1][ni];
                    let out = s + step <= previous.0 || e >= previous.1 + step;
                    let inward = s >= previous.0 + step || e + step <= previous.1;
                    if out || inward {
                        break;
                    }
                }
                previous = gaps[last + 1][ni];
                used[last + 1][ni] = true;
                (lo, hi) = (lo.max(gaps[last + 1][ni].0), hi.min(gaps[last + 1][ni].1));
                last += 1;
            }
            let depth = last + 1 - first;
            let mid = first + depth / 2;
            // The wall across may start at any line of the stack (a wall's
            // end is ragged by a pixel or two).
            let across = |k: usize| {
                (first..=last).any(|m| {
                    let up = (0..=m).rev().take_while(|&l| !is_free(l, k)).count();
                    let down = (m + 1..lines).take_while(|&l| !is_free(l, k)).count();
                    up + down >= depth + limits.jamb
                })
            };
            // An opening's jamb in line is as thick as its wall (see
            // `GapKind::Opening`), give or take a ragged pixel each side.
            let thin = |k: usize| {
                limits.kind == GapKind::Doorway || {
                    let up = (0..=mid).rev().take_while(|&l| !is_free(l, k)).count();
                    let down = (mid + 1..lines).take_while(|&l| !is_free(l, k)).count();
                    up + down <= depth + RAGGED
                }
            };
            // An opening's floor on a face line `l` that ends at `e` past a
            // jamb short of a jamb's length ends at a room's corner (see
            // `GapKind::Opening`): the jamb is a piece of the opening's wall,
            // as thin, running into a wall across at `e` that reaches from
            // the face line through the stack.
            let corner = |l: usize, e: usize| {
                let piece = if e < lo {
                    e + 1..lo
                } else if e >= hi {
                    hi..e
                } else {
                    return false;
                };
                let to_stack = if l < first { l + 1..first } else { last + 1..l };
                // The wall across stands at `e` or, behind a ragged face, a
                // pixel or two further from the opening.
                let mut wall_across = (0..=RAGGED).filter_map(|d| {
                    if e < lo {
                        e.checked_sub(d)
                    } else {
                        Some(e + d).filter(|&k| k < len)
                    }
                });
                limits.kind != GapKind::Doorway
                    && piece.len() > RAGGED
                    && piece.len() < limits.jamb
                    && piece.clone().all(&thin)
                    && wall_across.any(|k| across(k) && to_stack.clone().all(|m| !is_free(m, k)))
                    && (first..=last).any(|m| piece.clone().chain([e]).all(|k| !is_free(m, k)))
            };
            // The floor through the gap's middle on line `l`: how far it
            // goes to the left and (from the middle on) to the right.
            let floor_run = |l: usize| {
                let mid = (lo + hi) / 2;
                (l < lines && is_free(l, mid)).then(|| {
                    let left = (0..mid).rev().take_while(|&k| is_free(l, k)).count();
                    let right = (mid..len).take_while(|&k| is_free(l, k)).count();
                    (mid, left, right)
                })
            };
            // Whether that floor (`floor_run(l)`) ends at a room's corner
            // past the gap's left or right end.
            let left_corner = |l: usize, mid: usize, left: usize| {
                mid.checked_sub(left + 1).is_some_and(|e| corner(l, e))
            };
            let right_corner =
                |l: usize, mid: usize, right: usize| mid + right < len && corner(l, mid + right);
            // Beyond both faces of the wall (within a jamb's length, for
            // ragged walls and jambs thicker than the doorway) the free run
            // through the gap's middle must be wider than the gap by a jamb,
            // and on at least one face it must reach past both jambs: both
            // jambs end there, as a wall's do. (A corridor piece between two
            // facing doorways has one side wall running on past the piece on
            // both faces.)
            // Per line: None = closed (the floor through the middle no
            // wider than the gap by `margin`); Some(true) = open past both
            // jambs.
            let open_line = |l: usize, margin: usize| -> Option<bool> {
                let (mid, left, right) = floor_run(l)?;
                let past_left = left >= (mid - lo) + limits.jamb || left_corner(l, mid, left);
                let past_right = right >= (hi - mid) + limits.jamb || right_corner(l, mid, right);
                (left + right >= (hi - lo) + margin).then_some(past_left && past_right)
            };
            let reach = limits.jamb.max(2);
            let faces = |margin: usize| {
                let face = |ls: &mut dyn Iterator<Item = usize>| {
                    ls.filter_map(|l| open_line(l, margin)).max()
                };
                let before = face(&mut (1..=reach).filter_map(|d| first.checked_sub(d)));
                let after = face(&mut (1..=reach).map(|d| last + d));
                matches!((before, after), (Some(a), Some(b)) if a || b)
            };
            let mut faces_open = faces(limits.jamb);
            let mut narrow_faces = false;
            if let GapKind::Opening { near_margin, .. } = limits.kind
                && !faces_open
                && faces(near_margin)
            {
                (faces_open, narrow_faces) = (true, true);
            }
            if let GapKind::Opening { face, .. } = limits.kind {
                let floor = |ls: &mut dyn Iterator<Item = usize>| {
                    let (mut n, mut f) = (0usize, 0usize);
                    for l in ls {
                        for k in lo..hi {
                            n += 1;
                            f += usize::from(l < lines && is_free(l, k));
                        }
                    }
                    n > 0 && 10 * f >= 9 * n
                };
                faces_open = faces_open
                    && first >= face
                    && floor(&mut (1..=face).map(|d| first - d))
                    && floor(&mut (1..=face).map(|d| last + d));
            }
            // Which ends stand beside a room's corner, on some face line
            // (the wall across there is no passage's side, see
            // `WallSupport::crosses_passage`).
            let face_lines = (1..=reach)
                .filter_map(|d| first.checked_sub(d))
                .chain((1..=reach).map(|d| last + d));
            let corner_ends = face_lines.fold([false; 2], |[l0, r0], l| {
                let Some((mid, left, right)) = floor_run(l) else {
                    return [l0, r0];
                };
                [
                    l0 || left_corner(l, mid, left),
                    r0 || right_corner(l, mid, right),
                ]
            });
            let wide_enough = hi - lo >= limits.width.0;
            // Each jamb is a wall along the line (at least `jamb` of it, in
            // some line of the stack) or the end of a wall across it that
            // reaches a jamb past the doorway's thickness (a doorway beside
            // a corner, a cubicle's open front), for an opening also behind
            // a reveal (see `GapKind::Opening`); never a speck.
            // A jamb's length of wall from `k` on, stepping by `step`.
            let wall_from = |l: usize, k: usize, step: isize| {
                (0..limits.jamb as isize).all(|i| {
                    k.checked_add_signed(step * i)
                        .is_some_and(|k| k < len && !is_free(l, k))
                })
            };
            let along = |k: usize, step: isize| (first..=last).any(|l| wall_from(l, k, step));
            // The pixel after `k`, stepping by `step`, if in the line.
            let next = |k: usize, step: isize| k.checked_add_signed(step).filter(|&n| n < len);
            // A reveal: wall in line from `k` on (stepping by `step`), as
            // thin as the opening's wall for its first two pixels, that
            // meets a wall across before a jamb's length.
            let reveal = |k: usize, step: isize| {
                limits.kind != GapKind::Doorway
                    && thin(k)
                    && next(k, step).is_some_and(thin)
                    && (first..=last).any(|l| {
                        (0..limits.jamb as isize)
                            .map_while(|i| {
                                k.checked_add_signed(step * i)
                                    .filter(|&k| k < len && !is_free(l, k))
                            })
                            .any(&across)
                    })
            };
            // A wall in line is as thin as the opening's wall at its first
            // pixel or, past a ragged bump there, the next.
            let thin_end = |k: usize, step: isize| thin(k) || next(k, step).is_some_and(thin);
            let jamb = |k: usize, step: isize| {
                (along(k, step) && thin_end(k, step)) || across(k) || reveal(k, step)
            };
            let left_jamb = lo > 0 && jamb(lo - 1, -1);
            let right_jamb = hi < len && jamb(hi, 1);
            if depth <= limits.depth && wide_enough && faces_open && left_jamb && right_jamb {
                out.push(WallGap {
                    line: (lo..hi).map(|k| index(mid, k)).collect(),
                    width_px: hi - lo,
                    narrow_faces,
                    corner_ends,
                });
            }
        }
    }
    out
}

/// Maximal free runs of one line whose width is within the limits, with
/// at least `jamb` wall pixels on one side and some wall on the other
/// (the stack decides whether that is a jamb).
fn gaps_in_line(len: usize, is_free: impl Fn(usize) -> bool, limits: GapLimits) -> Vec<Run> {
    let mut out = Vec::new();
    let mut k = 0;
    // End of the last wall run and its length.
    let mut wall_run = 0usize;
    while k < len {
        if !is_free(k) {
            wall_run += 1;
            k += 1;
            continue;
        }
        let start = k;
        while k < len && is_free(k) {
            k += 1;
        }
        let end = k;
        let width = end - start;
        let after = (end..len.min(end + limits.jamb))
            .take_while(|&j| !is_free(j))
            .count();
        if wall_run.max(after) >= limits.jamb
            && wall_run.min(after) >= 1
            && (limits.width.0..=limits.width.1).contains(&width)
        {
            out.push((start, end));
        }
        wall_run = 0;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::imaging::{ascii_mask, dominant_orientation};

    /// `.` free, `#` wall.
    fn free_mask(text: &str) -> Mask {
        let mut m = ascii_mask(text);
        m.iter_mut().for_each(|p| *p = 255 - *p);
        m
    }

    const LIMITS: GapLimits = GapLimits {
        width: (2, 4),
        jamb: 2,
        depth: 2,
        kind: GapKind::Doorway,
    };

    #[test]
    fn a_doorway_in_a_horizontal_wall() {
        let m = free_mask(
            "..........
             ..........
             ###...####
             ###...####
             ..........
             ..........",
        );
        let g = axis_gaps(&m, LIMITS);
        assert_eq!(g.len(), 1);
        assert_eq!(g[0].width_px, 3);
        // The middle of the two wall rows is the second (row 3).
        assert_eq!(g[0].line, vec![33, 34, 35]);
    }

    #[test]
    fn a_doorway_in_a_vertical_wall() {
        let m = free_mask(
            "...#...
             ...#...
             .......
             .......
             ...#...
             ...#...",
        );
        let g = axis_gaps(&m, LIMITS);
        assert_eq!(g.len(), 1);
        assert_eq!(g[0].line, vec![17, 24]);
    }

    #[test]
    fn a_doorway_in_a_turned_wall() {
        // Two rooms 24 px deep, a wall 3 px thick with a 10 px doorway
        // between them, all turned by 30°.
        let (s, c) = 30f64.to_radians().sin_cos();
        let m = Mask::from_fn(120, 120, |x, y| {
            let (dx, dy) = (f64::from(x) - 60.0, f64::from(y) - 60.0);
            let (u, v) = (dx * c + dy * s, -dx * s + dy * c);
            let inside = u.abs() < 40.0 && v.abs() < 25.0;
            let wall = v.abs() < 1.5 && u.abs() >= 5.0;
            image::Luma([if inside && !wall { 255 } else { 0 }])
        });
        let limits = GapLimits {
            width: (6, 14),
            jamb: 4,
            depth: 4,
            kind: GapKind::Doorway,
        };
        let g = wall_gaps(&m, dominant_orientation(&m), limits);
        assert_eq!(g.len(), 1, "{g:?}");
        assert!((9..=11).contains(&g[0].width_px));
        // The line lies across the doorway: near the centre, 10-14 px long.
        for &p in &g[0].line {
            let (x, y) = (f64::from(p % 120) - 59.5, f64::from(p / 120) - 59.5);
            assert!((x * x + y * y).sqrt() <= 8.0, "pixel ({x}, {y})");
        }
        assert!((8..=16).contains(&g[0].line.len()));
    }

    #[test]
    fn a_doorway_beside_a_corner() {
        // A cubicle open to the corridor above: its front has a jamb on the
        // left only; on the right the opening ends at the cubicle's thin
        // side wall (column 7), which runs across the line, with the next
        // cubicle beyond it.
        let m = free_mask(
            ".............
             .............
             ###....#.....
             #......#.....
             #......#.....
             ########.....",
        );
        let g = axis_gaps(&m, LIMITS_CORNER);
        assert_eq!(g.len(), 1, "{g:?}");
        assert_eq!(g[0].width_px, 4);
        assert_eq!(g[0].line, vec![29, 30, 31, 32]);
        // Without the side wall running down there is no jamb on the right.
        let open = free_mask(
            ".............
             .............
             ###....#.....
             #............
             #............
             ########.....",
        );
        assert!(axis_gaps(&open, LIMITS_CORNER).is_empty());
    }

    #[test]
    fn a_side_wall_with_a_ragged_end_is_a_jamb() {
        // A cubicle's open front (rows 5-7) between a jamb on the right and
        // the cubicle's side wall (columns 4-5) on the left, whose end is a
        // pixel thinner in the front's last two rows, as scanned walls are.
        let m = free_mask(
            "....##........#
             ....##........#
             ....##........#
             ....##........#
             ....##........#
             ....##....#####
             ....#.....#####
             ....#.....#####
             ...............
             ...............",
        );
        let limits = GapLimits {
            width: (2, 6),
            jamb: 3,
            depth: 3,
            kind: GapKind::Doorway,
        };
        let g = axis_gaps(&m, limits);
        assert_eq!(g.len(), 1, "{g:?}");
        assert_eq!(g[0].line, vec![96, 97, 98, 99]);
    }

    #[test]
    fn a_speck_is_no_jamb() {
        // A gap between a wall and a one-pixel speck in open space.
        let m = free_mask(
            "............
             ............
             ####.....#..
             ............
             ............",
        );
        assert!(axis_gaps(&m, LIMITS).is_empty());
    }

    const LIMITS_CORNER: GapLimits = GapLimits {
        width: (2, 6),
        jamb: 2,
        depth: 2,
        kind: GapKind::Doorway,
    };

    #[test]
    fn corridors_niches_and_wide_openings_are_no_doorways() {
        // A vertical corridor 3 wide: every row is a gap, but the stack is
        // too deep.
        let corridor = free_mask(
            "##...##
             ##...##
             ##...##
             ##...##
             ##...##",
        );
        assert!(axis_gaps(&corridor, LIMITS).is_empty());
        // A corridor piece (columns 5-7) between two doorways of a room on
        // the left: its right wall runs on past the piece on both faces.
        let piece = free_mask(
            "........####
             ........####
             ...##...####
             ...##...####
             ........####
             ........####",
        );
        assert!(axis_gaps(&piece, LIMITS).is_empty());
        // A niche: free on one face of the wall only.
        let niche = free_mask(
            "........
             ##...###
             ########",
        );
        assert!(axis_gaps(&niche, LIMITS).is_empty());
        // An opening wider than the widest doorway.
        let wide = free_mask(
            "..........
             ##......##
             ..........",
        );
        assert!(axis_gaps(&wide, LIMITS).is_empty());
    }
}

#[cfg(test)]
#[path = "wall_gaps_opening_tests.rs"]
mod opening_tests;
