//! The clear part of a doorway line, in pixels: where an obstacle stands
//! in a doorway, the doorway is as wide as the longest stretch of its line
//! that no obstacle blocks, the width a person or a robot can pass.
//!
//! The furniture filter lets the spaces take in obstacles standing free
//! (a chair, a bin, a door leaf seen end-on, a scan of a passer-by), so
//! the doorway chords, which read the regions as free, run through them
//! from jamb to jamb. The opening is where the chords say; its width is
//! what is left of the line between the obstacles (occupied cells no
//! bigger than a speck are crossed, see
//! [`outside_pixels`](super::chord_pixels::outside_pixels); the obstacles
//! are [`obstacle_in_regions`](super::chord_pixels::obstacle_in_regions)).

/// Sampling step along the line, pixels.
const STEP: f64 = 0.25;

/// The longest stretch of `line` (pixel coordinates) that no pixel
/// `blocked` says is an obstacle touches, sampled every quarter pixel:
/// `line` itself when nothing blocks it; the first of equally long
/// stretches; `line` when every sample is blocked.
pub(super) fn clear_part(
    blocked: &impl Fn(i64, i64) -> bool,
    line: [[f64; 2]; 2],
) -> [[f64; 2]; 2] {
    let d = [line[1][0] - line[0][0], line[1][1] - line[0][1]];
    let length = d[0].hypot(d[1]);
    if !length.is_finite() || length <= 0.0 {
        return line;
    }
    let at = |s: f64| {
        [
            line[0][0] + d[0] * s / length,
            line[0][1] + d[1] * s / length,
        ]
    };
    let samples = (length / STEP).ceil() as usize;
    // Clear stretches as (from, to) along the line; a blocked sample ends
    // a stretch halfway back to the last clear one.
    let mut best: Option<(f64, f64)> = None;
    let mut start: Option<f64> = None;
    for k in 0..=samples {
        let s = (k as f64 * STEP).min(length);
        let p = at(s);
        let free = !blocked(p[0].floor() as i64, p[1].floor() as i64);
        match (free, start) {
            (true, None) => start = Some(if k == 0 { 0.0 } else { s - STEP / 2.0 }),
            (false, Some(from)) => {
                let to = s - STEP / 2.0;
                if best.is_none_or(|(a, b)| to - from > b - a + 1e-9) {
                    best = Some((from, to));
                }
                start = None;
            }
            _ => {}
        }
    }
    if let Some(from) = start
        && best.is_none_or(|(a, b)| length - from > b - a + 1e-9)
    {
        best = Some((from, length));
    }
    match best {
        Some((a, b)) => [at(a), at(b)],
        None => line,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn length(l: [[f64; 2]; 2]) -> f64 {
        (l[1][0] - l[0][0]).hypot(l[1][1] - l[0][1])
    }

    #[test]
    fn a_line_nothing_blocks_is_kept() {
        let line = [[2.0, 5.5], [22.0, 5.5]];
        assert_eq!(clear_part(&|_, _| false, line), line);
    }

    #[test]
    fn an_obstacle_in_a_doorway_leaves_the_longer_side() {
        // A 20 px doorway along row 5 with an obstacle in pixels 8..=10:
        // 6 px clear on the left (2..8), 11 on the right (11..22).
        let line = [[2.0, 5.5], [22.0, 5.5]];
        let part = clear_part(&|x, y| y == 5 && (8..=10).contains(&x), line);
        assert!((length(part) - 11.0).abs() <= 0.25, "{part:?}");
        assert!((part[0][0] - 11.0).abs() <= 0.25 && (part[1][0] - 22.0).abs() < 1e-9);
        // Mirrored: the obstacle nearer the far end.
        let part = clear_part(&|x, y| y == 5 && (14..=16).contains(&x), line);
        assert!((length(part) - 12.0).abs() <= 0.25, "{part:?}");
        assert!((part[0][0] - 2.0).abs() < 1e-9 && (part[1][0] - 14.0).abs() <= 0.25);
    }

    #[test]
    fn a_slanted_line_is_measured_along_itself() {
        // 3-4-5 line of length 25 px; an obstacle covering its first
        // fifth (x < 5 + 2): the clear part is about four fifths.
        let line = [[2.0, 2.0], [17.0, 22.0]];
        let part = clear_part(&|x, _| x < 5, line);
        let expected = 25.0 * (17.0 - 5.0) / 15.0;
        assert!((length(part) - expected).abs() <= 0.5, "{part:?}");
    }
}
