//! Doorway geometry, in pixels: where a door border crosses an opening,
//! the opening's narrowest chord (its **throat**: where the doorway is and
//! which way it runs), how far the opening runs through the wall on
//! either side of it (the door's depth, from one face of the wall to the
//! other), and the doorway line: from one jamb to the other through the
//! middle of the wall, as long as the median chord inside the wall.
//!
//! Coordinates are continuous pixel coordinates: pixel `(x, y)` covers
//! `[x, x + 1) × [y, y + 1)`, row 0 at the top. Chords are traced cell by
//! cell (Amanatides & Woo 1987, "A fast voxel traversal algorithm"), so a
//! chord ends exactly on the edge of the first blocked pixel: a run of n
//! free pixels along a row is a chord n pixels long. A chord crosses a
//! speck (a stretch of uncertain pixels up to [`SpanLimits::noise_run`]
//! long with free space after it, see [`Pixel`]); it ends at a wall.

use super::chord_pixels::{Pixel, classifier, obstacle_in_regions};
use super::clear_width::clear_part;
use crate::imaging::Labels;

/// Limits of [`door_span`], in pixels.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SpanLimits {
    /// Longest chord looked at: a wider opening is no doorway.
    pub max_width: f64,
    /// How far from the border's centre, across it, the throat is sought.
    pub search: f64,
    /// Thinnest door: the span is widened to this when the wall is
    /// thinner.
    pub min_depth: f64,
    /// Thickest door: the span stops here (a longer passage of the same
    /// width is a corridor, not a wall).
    pub max_depth: f64,
    /// How much wider than the throat (on either end) the opening may get
    /// and still be inside the wall: anti-aliased or ragged jambs.
    pub slack: f64,
    /// Longest stretch of uncertain pixels a chord crosses (with free space
    /// after it): a jamb is a wall, or a longer stretch of uncertain grey.
    pub noise_run: f64,
}

/// A door's place in its opening (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct DoorSpan {
    /// The doorway line, jamb to jamb, through the middle of the span.
    pub line: [[f64; 2]; 2],
    /// A point of the throat (the origin of `s` and `t` below).
    origin: [f64; 2],
    /// Along the doorway.
    u: [f64; 2],
    /// Across the doorway.
    n: [f64; 2],
    /// The opening along `u`: `[s_lo, s_hi]`.
    s: [f64; 2],
    /// The span along `n`: pixel centres with `t` in `[t_lo, t_hi]`.
    t: [f64; 2],
}

impl DoorSpan {
    /// The span with its doorway line cut to the line's clear part
    /// between the obstacles `blocked` says stand in it (see
    /// [`clear_part`]); its rectangle stays the opening's.
    pub(super) fn clear_of(self, blocked: &impl Fn(i64, i64) -> bool) -> DoorSpan {
        DoorSpan {
            line: clear_part(blocked, self.line),
            ..self
        }
    }

    /// The pixel `(x, y)`'s centre in the span's frame: `(s, t)`.
    fn frame(&self, x: i64, y: i64) -> (f64, f64) {
        let q = [
            x as f64 + 0.5 - self.origin[0],
            y as f64 + 0.5 - self.origin[1],
        ];
        (
            q[0] * self.u[0] + q[1] * self.u[1],
            q[0] * self.n[0] + q[1] * self.n[1],
        )
    }

    /// Whether the pixel `(x, y)`'s centre lies in the door's rectangle.
    pub fn covers(&self, x: i64, y: i64) -> bool {
        let (s, t) = self.frame(x, y);
        (self.s[0] - 1e-9..=self.s[1] + 1e-9).contains(&s)
            && (self.t[0] - 1e-9..=self.t[1] + 1e-9).contains(&t)
    }

    /// Which side of the door the pixel `(x, y)` is on, if its centre lies
    /// in the opening's width within `reach` beyond a face: `Some(false)`
    /// behind (the border's first region's side), `Some(true)` in front.
    pub fn side(&self, x: i64, y: i64, reach: f64) -> Option<bool> {
        let (s, t) = self.frame(x, y);
        if !(self.s[0] - 1e-9..=self.s[1] + 1e-9).contains(&s) {
            return None;
        }
        if t > self.t[1] + 1e-9 && t <= self.t[1] + reach {
            Some(true)
        } else if t < self.t[0] - 1e-9 && t >= self.t[0] - reach {
            Some(false)
        } else {
            None
        }
    }

    /// The pixels whose centres may lie within `reach` of the rectangle,
    /// `[x0, y0, x1, y1]` (inclusive, unclipped).
    pub fn bounds(&self, reach: f64) -> [i64; 4] {
        let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
        for s in self.s {
            for t in [self.t[0] - reach, self.t[1] + reach] {
                let c = [
                    self.origin[0] + s * self.u[0] + t * self.n[0],
                    self.origin[1] + s * self.u[1] + t * self.n[1],
                ];
                for k in 0..2 {
                    lo[k] = lo[k].min(c[k]);
                    hi[k] = hi[k].max(c[k]);
                }
            }
        }
        [
            lo[0].floor() as i64 - 1,
            lo[1].floor() as i64 - 1,
            hi[0].ceil() as i64,
            hi[1].ceil() as i64,
        ]
    }
}

/// The span of the door across the border between `pair` whose pixels
/// (on both sides) are `pixels`, in the free space of `labels` (non-zero
/// = free): the throat nearest the border's centre and the opening
/// through the wall around it. `outside` says what each pixel outside
/// `labels` is to a chord (see
/// [`outside_pixels`](super::chord_pixels::outside_pixels)); with `None`
/// every pixel outside `labels` is a wall. The doorway line is the clear
/// part of the opening's (see [`DoorSpan::clear_of`]). None when the
/// border crosses no bounded opening (no chord through its centre shorter
/// than `max_width`).
pub(crate) fn door_span(
    labels: &Labels,
    outside: Option<&[Pixel]>,
    pair: (u32, u32),
    pixels: &[u32],
    limits: &SpanLimits,
) -> Option<DoorSpan> {
    let pixel = classifier(labels, outside);
    let (centre, normal) = border_frame(labels, pair, pixels)?;
    let throat = throat(&pixel, centre, normal, limits)?;
    let span = span(&pixel, &throat, limits);
    Some(span.clear_of(&obstacle_in_regions(labels, outside)))
}

/// The doorway line of a border that crosses no bounded opening: the
/// diameter, along the border, of the widest circle centred on it (`dist`:
/// each pixel's distance to the nearest obstacle), the width the door
/// rule measured.
pub(crate) fn border_line(
    labels: &Labels,
    pair: (u32, u32),
    pixels: &[u32],
    dist: &[f32],
) -> Option<[[f64; 2]; 2]> {
    let w = labels.width as usize;
    let (_, normal) = border_frame(labels, pair, pixels)?;
    let &widest = pixels.iter().max_by(|&&a, &&b| {
        let d = |p: u32| dist.get(p as usize).copied().unwrap_or(0.0);
        d(a).total_cmp(&d(b)).then(b.cmp(&a))
    })?;
    let r = f64::from(dist.get(widest as usize).copied().unwrap_or(0.0));
    let c = [
        (widest as usize % w) as f64 + 0.5,
        (widest as usize / w) as f64 + 0.5,
    ];
    let u = [-normal[1], normal[0]];
    Some([
        [c[0] - r * u[0], c[1] - r * u[1]],
        [c[0] + r * u[0], c[1] + r * u[1]],
    ])
}

/// The centre of a border (mean of its pixels' centres) and its normal
/// (the mean direction of its 4-neighbour crossings from `pair.0` to
/// `pair.1`; a staircase along a diagonal averages to the diagonal).
pub(super) fn border_frame(
    labels: &Labels,
    pair: (u32, u32),
    pixels: &[u32],
) -> Option<([f64; 2], [f64; 2])> {
    let w = labels.width as usize;
    let h = labels.height as usize;
    let (mut c, mut n) = ([0.0f64; 2], [0.0f64; 2]);
    for &p in pixels {
        let p = p as usize;
        let (x, y) = (p % w, p / w);
        c[0] += x as f64 + 0.5;
        c[1] += y as f64 + 0.5;
        if labels.data.get(p) != Some(&pair.0) {
            continue;
        }
        for (dx, dy) in [(1i64, 0i64), (-1, 0), (0, 1), (0, -1)] {
            let (nx, ny) = (x as i64 + dx, y as i64 + dy);
            let inside = nx >= 0 && ny >= 0 && (nx as usize) < w && (ny as usize) < h;
            if inside && labels.data[ny as usize * w + nx as usize] == pair.1 {
                n[0] += dx as f64;
                n[1] += dy as f64;
            }
        }
    }
    let k = pixels.len() as f64;
    let len = n[0].hypot(n[1]);
    (k > 0.0 && len > 0.0).then(|| ([c[0] / k, c[1] / k], [n[0] / len, n[1] / len]))
}

/// Distance from `p` along the unit vector `d` to the edge of the first
/// wall pixel, or to the start of a stretch of noise pixels longer than
/// `noise_run` (pixels along `d`); None beyond `max` (0 when `p` is not
/// free).
fn exit_distance(
    pixel: &impl Fn(i64, i64) -> Pixel,
    p: [f64; 2],
    d: [f64; 2],
    max: f64,
    noise_run: f64,
) -> Option<f64> {
    let (mut ix, mut iy) = (p[0].floor() as i64, p[1].floor() as i64);
    if pixel(ix, iy) != Pixel::Free {
        return Some(0.0);
    }
    let axis = |pos: f64, cell: i64, dir: f64| -> (i64, f64, f64) {
        if dir > 0.0 {
            (1, (cell as f64 + 1.0 - pos) / dir, 1.0 / dir)
        } else if dir < 0.0 {
            (-1, (pos - cell as f64) / -dir, -1.0 / dir)
        } else {
            (0, f64::INFINITY, f64::INFINITY)
        }
    };
    let (step_x, mut next_x, delta_x) = axis(p[0], ix, d[0]);
    let (step_y, mut next_y, delta_y) = axis(p[1], iy, d[1]);
    // Where the noise pixels just crossed began.
    let mut noise: Option<f64> = None;
    loop {
        let t = if next_x < next_y {
            ix += step_x;
            let t = next_x;
            next_x += delta_x;
            t
        } else {
            iy += step_y;
            let t = next_y;
            next_y += delta_y;
            t
        };
        if t > max {
            return None;
        }
        match (pixel(ix, iy), noise) {
            (Pixel::Free, _) => noise = None,
            // (The classifier calls an obstacle a wall; a hand-made
            // classifier may not.)
            (Pixel::Wall | Pixel::Obstacle, run) => return Some(run.unwrap_or(t)),
            (Pixel::Noise, None) => noise = Some(t),
            (Pixel::Noise, Some(at)) if t - at >= noise_run - 1e-9 => return Some(at),
            (Pixel::Noise, Some(_)) => {}
        }
    }
}

/// The chord through `p` along `u`: `(s_lo, s_hi)` with `s_lo ≤ 0 ≤ s_hi`,
/// or None if it is longer than `limits.max_width` or `p` is blocked;
/// stretches of noise up to `limits.noise_run` are crossed.
pub(super) fn chord(
    pixel: &impl Fn(i64, i64) -> Pixel,
    p: [f64; 2],
    u: [f64; 2],
    limits: &SpanLimits,
) -> Option<(f64, f64)> {
    let (max, run) = (limits.max_width, limits.noise_run);
    let hi = exit_distance(pixel, p, u, max, run)?;
    let lo = exit_distance(pixel, p, [-u[0], -u[1]], max - hi, run)?;
    (hi > 0.0 && lo + hi <= max).then_some((-lo, hi))
}

/// The narrowest chord found near the border.
#[derive(Debug, Clone, Copy)]
pub(super) struct Throat {
    centre: [f64; 2],
    u: [f64; 2],
    n: [f64; 2],
    s: (f64, f64),
}

impl Throat {
    /// The chord's length, pixels.
    pub(super) fn length(&self) -> f64 {
        self.s.1 - self.s.0
    }

    /// The chord's middle.
    pub(super) fn middle(&self) -> [f64; 2] {
        let m = (self.s.0 + self.s.1) / 2.0;
        [
            self.centre[0] + m * self.u[0],
            self.centre[1] + m * self.u[1],
        ]
    }
}

fn turned(v: [f64; 2], deg: f64) -> [f64; 2] {
    let (s, c) = deg.to_radians().sin_cos();
    [c * v[0] - s * v[1], s * v[0] + c * v[1]]
}

/// The shortest chord through points `centre + t·normal` (`|t| ≤
/// search`, half-pixel steps, each side only as far as the opening goes
/// on: every offset up to there has a bounded chord) in directions within
/// 60° of the border's line; among chords within half a pixel of the
/// shortest, the one nearest the centre (a thick wall has many equal
/// ones).
pub(super) fn throat(
    pixel: &impl Fn(i64, i64) -> Pixel,
    centre: [f64; 2],
    normal: [f64; 2],
    limits: &SpanLimits,
) -> Option<Throat> {
    let along = [-normal[1], normal[0]];
    let steps = (limits.search * 2.0).round().max(0.0) as i64;
    // The shortest chord through the point at offset t: (length, angle).
    let shortest_at = |t: f64| -> Option<(f64, f64)> {
        let p = [centre[0] + t * normal[0], centre[1] + t * normal[1]];
        let length = |deg: f64| chord(pixel, p, turned(along, deg), limits).map(|(lo, hi)| hi - lo);
        let mut found: Option<(f64, f64)> = None;
        for a in (-30..=30).map(|a| f64::from(a) * 2.0) {
            if let Some(l) = length(a)
                && found.is_none_or(|(fl, _)| l < fl)
            {
                found = Some((l, a));
            }
        }
        let (mut l, mut a) = found?;
        for f in (-8..=8).map(|f| f64::from(f) * 0.25) {
            if let Some(fl) = length(a + f)
                && fl < l - 1e-9
            {
                (l, a) = (fl, a + f);
            }
        }
        Some((l, a))
    };
    // Per offset: (length, angle, t).
    let mut best: Vec<(f64, f64, f64)> = Vec::new();
    for sign in [1i64, -1] {
        for k in 0..=steps {
            if sign < 0 && k == 0 {
                continue;
            }
            let t = (sign * k) as f64 / 2.0;
            match shortest_at(t) {
                Some((l, a)) => best.push((l, a, t)),
                None => break,
            }
        }
    }
    let shortest = best.iter().map(|b| b.0).fold(f64::INFINITY, f64::min);
    let &(_, a, t) = best
        .iter()
        .filter(|b| b.0 <= shortest + 0.5)
        .min_by(|x, y| x.2.abs().total_cmp(&y.2.abs()))?;
    let p = [centre[0] + t * normal[0], centre[1] + t * normal[1]];
    // Pixel steps on a slanted jamb make the very shortest chord lean a
    // few degrees off the opening's direction: take the middle of the
    // directions whose chords are within half a pixel of the shortest (a
    // plateau symmetric about the direction across the opening).
    let lengths: Vec<(f64, f64)> = (-80..=80)
        .map(|f| a + f64::from(f) * 0.25)
        .filter_map(|deg| {
            chord(pixel, p, turned(along, deg), limits).map(|(lo, hi)| (deg, hi - lo))
        })
        .collect();
    let least = lengths.iter().map(|l| l.1).fold(f64::INFINITY, f64::min);
    let plateau: Vec<f64> = lengths
        .iter()
        .filter(|l| l.1 <= least + 0.5)
        .map(|l| l.0)
        .collect();
    let a = plateau.get(plateau.len() / 2).copied().unwrap_or(a);
    let u = turned(along, a);
    let s = chord(pixel, p, u, limits)?;
    // Across the doorway, on the border normal's side.
    let mut n = [u[1], -u[0]];
    if n[0] * normal[0] + n[1] * normal[1] < 0.0 {
        n = [-n[0], -n[1]];
    }
    Some(Throat { centre: p, u, n, s })
}

/// How far the opening runs on either side of the throat: chords along
/// the throat's direction, half a pixel apart, while each end stays
/// within `slack` of the throat's (still between the jambs), up to
/// `max_depth` in all; each face lies halfway between the last such chord
/// and the first that is not. Without both faces within `max_depth` the
/// opening is a passage and the span has no depth. Then widened to
/// `min_depth`. The doorway line is the median-length chord inside the
/// wall, moved to the middle of the span.
pub(super) fn span(
    pixel: &impl Fn(i64, i64) -> Pixel,
    th: &Throat,
    limits: &SpanLimits,
) -> DoorSpan {
    const STEP: f64 = 0.5;
    let (s_lo, s_hi) = th.s;
    let mut extent = [s_lo, s_hi];
    let mut chords: Vec<(f64, f64)> = vec![(s_lo, s_hi)];
    // Per side (backwards, forwards): the last offset still inside the
    // wall, and the face once found.
    let mut reach = [0.0f64, 0.0f64];
    let mut face = [None::<f64>, None::<f64>];
    let mut k = 1.0;
    while face.iter().any(Option::is_none) && reach[0] + reach[1] + STEP <= limits.max_depth {
        for side in 0..2 {
            if face[side].is_some() || reach[0] + reach[1] + STEP > limits.max_depth {
                continue;
            }
            // A hair towards the throat, so that a chord along a pixel edge
            // reads the pixels on the throat's side (no bias by direction).
            let t = (k * STEP - 1e-6) * if side == 0 { -1.0 } else { 1.0 };
            let p = [th.centre[0] + t * th.n[0], th.centre[1] + t * th.n[1]];
            let inside = chord(pixel, p, th.u, limits)
                .filter(|&(a, b)| a >= s_lo - limits.slack && b <= s_hi + limits.slack);
            match inside {
                Some((a, b)) => {
                    reach[side] = k * STEP;
                    extent = [extent[0].min(a), extent[1].max(b)];
                    chords.push((a, b));
                }
                None => face[side] = Some(k * STEP - STEP / 2.0),
            }
        }
        k += 1.0;
    }
    // An opening that runs on past `max_depth` on either side is a
    // passage, not a wall: the door is as thin as doors get, at the border
    // (a corridor stub's door at its mouth, a door mid-corridor).
    let (mut t_lo, mut t_hi) = match face {
        [Some(back), Some(front)] => (-back, front),
        _ => (0.0, 0.0),
    };
    let short = limits.min_depth - (t_hi - t_lo);
    if short > 0.0 {
        t_lo -= short / 2.0;
        t_hi += short / 2.0;
    }
    // The opening's width: the median of its chords inside the wall (on
    // slanted jambs the pixel steps make the single narrowest one short by
    // up to a pixel; through a straight wall they are all equal).
    chords.sort_by(|x, y| (x.1 - x.0).total_cmp(&(y.1 - y.0)));
    let (a, b) = chords
        .get(chords.len() / 2)
        .copied()
        .unwrap_or((s_lo, s_hi));
    let mid = (t_lo + t_hi) / 2.0;
    let at = |s: f64| {
        [
            th.centre[0] + s * th.u[0] + mid * th.n[0],
            th.centre[1] + s * th.u[1] + mid * th.n[1],
        ]
    };
    let line = [at(a), at(b)];
    DoorSpan {
        line: super::along_wall::along_wall(pixel, line, limits).unwrap_or(line),
        origin: th.centre,
        u: th.u,
        n: th.n,
        s: extent,
        t: [t_lo, t_hi],
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::imaging::ascii_labels;

    pub(in crate::extract) fn border(l: &Labels) -> Vec<u32> {
        let w = l.width as usize;
        (0..l.data.len())
            .filter(|&i| {
                let v = l.data[i];
                // Sideways only within the row.
                let left = (i % w > 0).then(|| i - 1);
                let right = (i % w + 1 < w).then_some(i + 1);
                v != 0
                    && [i.checked_sub(w), Some(i + w), left, right]
                        .into_iter()
                        .flatten()
                        .any(|j| l.data.get(j).is_some_and(|&o| o != 0 && o != v))
            })
            .map(|i| i as u32)
            .collect()
    }

    pub(in crate::extract) const LIMITS: SpanLimits = SpanLimits {
        max_width: 40.0,
        search: 4.0,
        min_depth: 2.0,
        max_depth: 24.0,
        slack: 1.5,
        noise_run: 2.0,
    };

    #[test]
    fn a_doorway_through_a_thick_wall_spans_it() {
        // Room a above, b below, a wall 4 rows thick with a 5-pixel
        // doorway (columns 6..=10); the border lies mid-wall.
        let mut rows = vec!["aaaaaaaaaaaaaaaaaaaaaaaaaaaaaa"; 12];
        rows.extend([
            "######aaaaa###################",
            "######aaaaa###################",
            "######bbbbb###################",
            "######bbbbb###################",
        ]);
        rows.extend(vec!["bbbbbbbbbbbbbbbbbbbbbbbbbbbbbb"; 12]);
        let l = ascii_labels(&rows);
        let span = door_span(&l, None, (1, 2), &border(&l), &LIMITS).unwrap();
        let [p, q] = span.line;
        let len = (q[0] - p[0]).hypot(q[1] - p[1]);
        assert!((len - 5.0).abs() < 1e-9, "{span:?}");
        // Through the middle of the wall (rows 12..=15: y from 12 to 16).
        assert!(
            (p[1] - 14.0).abs() < 1e-9 && (q[1] - 14.0).abs() < 1e-9,
            "{span:?}"
        );
        let covered: Vec<(i64, i64)> = (0..28)
            .flat_map(|y| (0..30).map(move |x| (x, y)))
            .filter(|&(x, y)| span.covers(x, y) && l.data[(y * 30 + x) as usize] != 0)
            .collect();
        // The whole opening and nothing of the rooms.
        assert_eq!(covered.len(), 20, "{covered:?}");
        assert!(
            covered
                .iter()
                .all(|&(x, y)| (6..=10).contains(&x) && (12..=15).contains(&y))
        );
    }

    #[test]
    fn a_diagonal_opening_is_measured_between_the_wall_ends() {
        // A thin vertical wall, its upper part ending at row 4 (column 5)
        // and its lower part starting at row 12 (column 9): the opening
        // runs from (6, 5) to (9, 12), about 7.6 pixels, not the 8 rows of
        // the vertical border.
        let mut rows: Vec<String> = Vec::new();
        for y in 0..18 {
            let mut r = String::new();
            for x in 0..16 {
                let wall = (y <= 4 && x == 5) || (y >= 12 && x == 9);
                r.push(if wall {
                    '#'
                } else if x < 7 {
                    'a'
                } else {
                    'b'
                });
            }
            rows.push(r);
        }
        let refs: Vec<&str> = rows.iter().map(String::as_str).collect();
        let l = ascii_labels(&refs);
        let span = door_span(&l, None, (1, 2), &border(&l), &LIMITS).unwrap();
        let len = line_length(&span);
        let truth = 3f64.hypot(7.0);
        assert!((len - truth).abs() < 0.6, "{len} vs {truth}: {span:?}");
    }

    /// Room `a` (10 rows) above, room `b` (10 rows) below and `wall`
    /// between them, 30 columns wide.
    fn through_wall(wall: [&'static str; 3]) -> Vec<&'static str> {
        let mut rows = vec!["aaaaaaaaaaaaaaaaaaaaaaaaaaaaaa"; 10];
        rows.extend(wall);
        rows.extend(vec!["bbbbbbbbbbbbbbbbbbbbbbbbbbbbbb"; 10]);
        rows
    }

    /// What a chord meets at each pixel outside the regions of `rows`:
    /// a wall at `#`, noise anywhere else.
    fn wall_pixels(rows: &[&str]) -> Vec<Pixel> {
        rows.iter()
            .flat_map(|r| r.bytes())
            .map(|b| if b == b'#' { Pixel::Wall } else { Pixel::Noise })
            .collect()
    }

    /// The length of a span's doorway line.
    pub(in crate::extract) fn line_length(span: &DoorSpan) -> f64 {
        let [p, q] = span.line;
        (q[0] - p[0]).hypot(q[1] - p[1])
    }

    /// Uncertain specks inside a doorway (a JPEG-compressed map) are no
    /// jambs: the width runs from wall to wall. Without knowing which
    /// pixels are walls, the specks cut the doorway short.
    #[test]
    fn specks_in_a_doorway_do_not_narrow_it() {
        // Room a above, b below, a wall 3 rows thick with a doorway of
        // 10 pixels (columns 6..=15); `+` are specks (not free, no wall),
        // one or two in a row.
        let rows = through_wall([
            "######aa+aaaa+aa##############",
            "######bbbb++bbbb##############",
            "######bb+bbbbb+b##############",
        ]);
        let l = ascii_labels(&rows);
        let walls = wall_pixels(&rows);
        let length = |walls: Option<&[Pixel]>| {
            line_length(&door_span(&l, walls, (1, 2), &border(&l), &LIMITS).unwrap())
        };
        let with_walls = length(Some(&walls));
        assert!((with_walls - 10.0).abs() < 0.5, "{with_walls}");
        let without = length(None);
        assert!(without < 8.0, "{without}");
        // Three specks in a row are a jamb, as a wall is.
        let mut jamb = rows.clone();
        jamb[10] = "######aa+aaaa+aa##############";
        jamb[11] = "######bbbbbbb+++##############";
        jamb[12] = "######bb+bbbb+++##############";
        let l = ascii_labels(&jamb);
        let span = door_span(&l, Some(&walls), (1, 2), &border(&l), &LIMITS).unwrap();
        let len = line_length(&span);
        assert!(len < 9.0, "{len}: {span:?}");
    }

    /// A cluster of specks standing in a doorway is crossed when it is no
    /// longer than `noise_run`; a longer one is a jamb.
    #[test]
    fn a_speck_cluster_in_a_doorway_is_crossed_up_to_the_noise_run() {
        // A 12-pixel doorway (columns 6..=17) through a wall 3 rows thick;
        // a cluster of specks three pixels long (columns 8..=10) stands
        // in every row of it, free space on both sides.
        let rows = through_wall([
            "######aa+++aaaaaaa############",
            "######bb+++bbbbbbb############",
            "######bb+++bbbbbbb############",
        ]);
        let l = ascii_labels(&rows);
        let walls = wall_pixels(&rows);
        let length = |noise_run: f64| {
            let limits = SpanLimits {
                noise_run,
                ..LIMITS
            };
            line_length(&door_span(&l, Some(&walls), (1, 2), &border(&l), &limits).unwrap())
        };
        let crossed = length(4.0);
        assert!((crossed - 12.0).abs() < 0.5, "{crossed}");
        // Columns 11..=17 only.
        let cut = length(2.0);
        assert!((cut - 7.0).abs() < 0.5, "{cut}");
    }

    #[test]
    fn no_span_in_open_space() {
        let rows = ["aaaaaaaabbbbbbbb"; 6];
        let l = ascii_labels(&rows);
        let wide = SpanLimits {
            max_width: 5.0,
            ..LIMITS
        };
        assert_eq!(door_span(&l, None, (1, 2), &border(&l), &wide), None);
    }
}
