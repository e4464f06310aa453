//! A doorway line in a wall at a slant to the image, measured along the
//! wall ([`along_wall`]): the one correction the doorway span makes
//! to the shortest chord between the jambs.

use super::chord_pixels::Pixel;
use super::doorway::{SpanLimits, chord};
use crate::imaging::Moments;

/// The doorway line measured along the wall it is in, where the wall by
/// the jambs runs off the line's direction: a wall at a slant to the image
/// ends in jambs cut square to the image, so the shortest chord between
/// them leans across the opening and is short of the doorway. The wall's
/// direction is the principal axis of the wall pixels beyond each end of
/// `line` (within twice the thickest wall's depth, so that any wall looks
/// long there, on the side away from the opening); both ends must show a
/// wall (elongated, the two axes within 10° of each other) at 3°–35° from
/// `line`. Then the line is the chord through `line`'s middle along their
/// mean, if it is no shorter than `line`, within `limits`, and ends on the
/// same jambs (each end within a wall's thickness and two pixels of the end
/// it replaces). None otherwise.
pub(super) fn along_wall(
    pixel: &impl Fn(i64, i64) -> Pixel,
    line: [[f64; 2]; 2],
    limits: &SpanLimits,
) -> Option<[[f64; 2]; 2]> {
    let d = [line[1][0] - line[0][0], line[1][1] - line[0][1]];
    let length = d[0].hypot(d[1]);
    if length <= 0.0 {
        return None;
    }
    let u = [d[0] / length, d[1] / length];
    let reach = 2.0 * limits.max_depth;
    struct Wall {
        along: [f64; 2],
        half_thickness: f64,
    }
    let axis = |end: [f64; 2], out: [f64; 2]| -> Option<Wall> {
        let r = reach.ceil() as i64;
        let (cx, cy) = (end[0].floor() as i64, end[1].floor() as i64);
        let mut sums = Moments::default();
        for y in cy - r..=cy + r {
            for x in cx - r..=cx + r {
                let q = [x as f64 + 0.5 - end[0], y as f64 + 0.5 - end[1]];
                if q[0].hypot(q[1]) > reach
                    || q[0] * out[0] + q[1] * out[1] < 0.0
                    || pixel(x, y) != Pixel::Wall
                {
                    continue;
                }
                sums.add(q);
            }
        }
        // Too few wall pixels to have a direction: fewer than the reach is
        // long (a speck, the tip of a thin wall).
        if sums.count() < reach {
            return None;
        }
        let p = sums.principal()?;
        // Elongated: the long axis's variance at least four times the short's.
        if p.major < 4.0 * p.minor.max(1e-9) {
            return None;
        }
        let a = [p.angle.cos(), p.angle.sin()];
        Some(Wall {
            along: if a[0] * u[0] + a[1] * u[1] < 0.0 {
                [-a[0], -a[1]]
            } else {
                a
            },
            // A band t wide spreads t² / 12 across.
            half_thickness: (3.0 * p.minor).sqrt(),
        })
    };
    let lo = axis(line[0], [-u[0], -u[1]])?;
    let hi = axis(line[1], u)?;
    let cos = |a: [f64; 2], b: [f64; 2]| a[0] * b[0] + a[1] * b[1];
    if cos(lo.along, hi.along) < 10f64.to_radians().cos() {
        return None;
    }
    let w = [lo.along[0] + hi.along[0], lo.along[1] + hi.along[1]];
    let wl = w[0].hypot(w[1]);
    let w = [w[0] / wl, w[1] / wl];
    let off = cos(w, u).clamp(-1.0, 1.0).acos().to_degrees();
    if !(3.0..=35.0).contains(&off) {
        return None;
    }
    let mid = [
        (line[0][0] + line[1][0]) / 2.0,
        (line[0][1] + line[1][1]) / 2.0,
    ];
    let (a, b) = chord(pixel, mid, w, limits)?;
    let along = [
        [mid[0] + a * w[0], mid[1] + a * w[1]],
        [mid[0] + b * w[0], mid[1] + b * w[1]],
    ];
    // On the same jambs: each end stays within a wall's thickness (and two
    // pixels) of the end it replaces; a chord that runs on past a jamb's
    // tip to the wall behind it, or on beside wall ends staggered sideways,
    // measures another opening.
    let near = |old: [f64; 2], new: [f64; 2], wall: &Wall| {
        (new[0] - old[0]).hypot(new[1] - old[1]) <= 2.0 * wall.half_thickness + 2.0
    };
    let kept = b - a >= length && near(line[0], along[0], &lo) && near(line[1], along[1], &hi);
    kept.then_some(along)
}

#[cfg(test)]
mod tests {
    use super::super::doorway::door_span;
    use super::super::doorway::tests::{LIMITS, border, line_length};
    use super::*;
    use crate::imaging::{Labels, ascii_labels};

    /// Walls up to 12 pixels thick: the wall by a jamb is looked at up to
    /// 24 pixels away.
    const SLANT_LIMITS: SpanLimits = SpanLimits {
        max_depth: 12.0,
        ..LIMITS
    };

    /// Labels of a picture drawn by `wall(x, y)` (pixel centres): free
    /// pixels above `split(x)` are room `a`, below it room `b`.
    fn drawn(
        width: usize,
        height: usize,
        wall: impl Fn(f64, f64) -> bool,
        split: impl Fn(f64) -> f64,
    ) -> Labels {
        let rows: Vec<String> = (0..height)
            .map(|y| {
                (0..width)
                    .map(|x| {
                        let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
                        if wall(cx, cy) {
                            '#'
                        } else if cy < split(cx) {
                            'a'
                        } else {
                            'b'
                        }
                    })
                    .collect()
            })
            .collect();
        let refs: Vec<&str> = rows.iter().map(String::as_str).collect();
        ascii_labels(&refs)
    }

    /// A wall at 11° to the image, 7 pixels thick, with a doorway between
    /// jamb faces 22 columns apart; as on a scanned map, one outline of
    /// each wall runs 5 pixels past its jamb's face. The shortest chord
    /// leans from one outline's tip to the other's (about 15 pixels); the
    /// doorway runs along the wall, face to face (22 / cos 11°).
    #[test]
    fn a_doorway_in_a_slanted_wall_is_measured_along_the_wall() {
        let slope = 11f64.to_radians().tan();
        let centre = |x: f64| 20.0 + slope * x;
        let wall = |x: f64, y: f64| {
            let off = y - centre(x);
            let band = off.abs() <= 3.5;
            let left = x < 40.0 || (x < 45.0 && off < -2.5);
            let right = x > 62.0 || (x > 57.0 && off > 2.5);
            band && (left || right)
        };
        let l = drawn(160, 80, |x, y| wall(x, y - 10.0), |x| centre(x) + 10.0);
        let span = door_span(&l, None, (1, 2), &border(&l), &SLANT_LIMITS).unwrap();
        let len = line_length(&span);
        let truth = 22.0 / 11f64.to_radians().cos();
        assert!((len - truth).abs() < 1.0, "{len} vs {truth}: {span:?}");
    }

    /// Two thick walls along the image's columns, their ends staggered
    /// sideways: the doorway is the diagonal between the ends, not a
    /// chord along the walls (which would run on past both).
    #[test]
    fn staggered_wall_ends_keep_their_diagonal_doorway() {
        let wall = |x: f64, y: f64| {
            (y < 12.0 && (10.0..14.0).contains(&x)) || (y > 22.0 && (18.0..22.0).contains(&x))
        };
        let l = drawn(32, 36, wall, |x| 17.0 + (x - 16.0) * 2.5);
        let span = door_span(&l, None, (1, 2), &border(&l), &SLANT_LIMITS).unwrap();
        let len = line_length(&span);
        // Between the wall ends' corners, within a pixel and a half (the
        // median chord of a slanted opening runs a little long); a chord
        // along the walls would run the image's height, 36 pixels.
        let truth = 4f64.hypot(10.0);
        assert!((len - truth).abs() < 1.5, "{len} vs {truth}: {span:?}");
    }

    /// A jamb that ends in a thin tail (two pixels thick, under a thicker
    /// block; the wall pieces of a scanned lab map) facing a square jamb
    /// across a doorway 25 pixels wide, and the doorway line found there
    /// between the tail's tip and the other jamb's face, a little aslant.
    /// The wall by the tail leans a few degrees off that line, but a chord
    /// along it runs on over the tail to the block behind (40 pixels):
    /// the line stays as it is.
    #[test]
    fn a_thin_tail_on_a_jamb_keeps_the_doorway_at_its_tip() {
        let picture = [
            "#.##################..########",
            "####################..########.........................................##################.#",
            "##################....########........................................########################",
            "####################..########........................................########################",
            "###################...########........................................########################...........#",
            "####################...#######........................................########################...........#",
            "###################...##################..............................########################...........#",
            "####################..#######################.........................########################...........#",
            "###################..........################.........................########################...........#",
            "###################...................................................########################...........#",
            "###################...................................................########################...........#",
            "......................................................................########################...........#",
        ];
        // The wall pieces 30 pixels in from the picture's edges.
        let pixel = |x: i64, y: i64| {
            let row = usize::try_from(y - 30).ok().and_then(|y| picture.get(y));
            let cell = usize::try_from(x - 30)
                .ok()
                .and_then(|x| row?.as_bytes().get(x));
            if cell == Some(&b'#') {
                Pixel::Wall
            } else {
                Pixel::Free
            }
        };
        let limits = SpanLimits {
            max_width: 54.0,
            max_depth: 14.0,
            ..LIMITS
        };
        let line = [[100.0, 34.4], [75.0, 38.0]];
        assert_eq!(along_wall(&pixel, line, &limits), None);
    }
}
