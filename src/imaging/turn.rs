//! Turning a mask by an arbitrary angle (nearest neighbour) into an image
//! large enough to hold all of it, and mapping points back.

use super::Mask;

/// A turn of an image by an angle about its centre, into a larger image.
#[derive(Debug, Clone, Copy)]
pub struct Turn {
    cos: f64,
    sin: f64,
    /// Centre of the source image.
    from: [f64; 2],
    /// Centre of the turned image.
    to: [f64; 2],
}

impl Turn {
    /// The source position of a point of the turned image.
    pub fn back(&self, p: [f64; 2]) -> [f64; 2] {
        let (dx, dy) = (p[0] - self.to[0], p[1] - self.to[1]);
        [
            self.from[0] + dx * self.cos - dy * self.sin,
            self.from[1] + dx * self.sin + dy * self.cos,
        ]
    }
}

/// Turns `mask` by −`deg` degrees (image coordinates, y down), so that a
/// direction at `deg` in the source runs along the x axis of the result.
/// Pixels of the result outside the source are background.
///
/// ```
/// use nrgdb::imaging::{Mask, turn_mask};
/// let m = Mask::from_fn(4, 2, |_, _| image::Luma([255]));
/// let (t, _) = turn_mask(&m, 90.0);
/// assert_eq!(t.dimensions(), (2, 4));
/// assert_eq!(t.pixels().filter(|p| p.0[0] != 0).count(), 8);
/// ```
pub fn turn_mask(mask: &Mask, deg: f64) -> (Mask, Turn) {
    let (w, h) = (f64::from(mask.width()), f64::from(mask.height()));
    let (sin, cos) = deg.to_radians().sin_cos();
    // Size of the turned bounding box.
    let tw = (w * cos.abs() + h * sin.abs()).round().max(1.0);
    let th = (w * sin.abs() + h * cos.abs()).round().max(1.0);
    let turn = Turn {
        cos,
        sin,
        from: [w / 2.0, h / 2.0],
        to: [tw / 2.0, th / 2.0],
    };
    let src = mask.as_raw();
    let sw = mask.width() as usize;
    // `back` per pixel, its products taken once per column and per row
    // (the same operations in the same order, so the same result).
    let (tw, th) = (tw as usize, th as usize);
    let cols: Vec<(f64, f64)> = (0..tw)
        .map(|x| {
            let dx = x as f64 + 0.5 - turn.to[0];
            (dx * cos, dx * sin)
        })
        .collect();
    let mut data = vec![0u8; tw * th];
    for (y, row) in data.chunks_exact_mut(tw).enumerate() {
        let dy = y as f64 + 0.5 - turn.to[1];
        let (dy_sin, dy_cos) = (dy * sin, dy * cos);
        for (o, &(dx_cos, dx_sin)) in row.iter_mut().zip(&cols) {
            let sx = turn.from[0] + dx_cos - dy_sin;
            let sy = turn.from[1] + dx_sin + dy_cos;
            if sx >= 0.0 && sy >= 0.0 && sx < w && sy < h {
                *o = src[sy as usize * sw + sx as usize];
            }
        }
    }
    let out = Mask::from_raw(tw as u32, th as u32, data)
        .unwrap_or_else(|| Mask::new(tw as u32, th as u32));
    (out, turn)
}

/// The pixels of a 4-connected line from `a` to `b` (pixel coordinates,
/// pixel centres at +0.5), clipped to a `w` × `h` image, as row-major
/// indices. Being 4-connected, it blocks a 4-connected flood.
///
/// ```
/// use nrgdb::imaging::line_pixels;
/// assert_eq!(line_pixels([0.5, 0.5], [2.5, 2.5], 3, 3), vec![0, 1, 4, 5, 8]);
/// ```
pub fn line_pixels(a: [f64; 2], b: [f64; 2], w: u32, h: u32) -> Vec<u32> {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let steps = (dx.abs().max(dy.abs()) * 4.0).ceil().max(1.0) as usize;
    let mut out: Vec<u32> = Vec::new();
    let mut last: Option<(i64, i64)> = None;
    let push = |x: i64, y: i64, out: &mut Vec<u32>| {
        if x >= 0 && y >= 0 && x < i64::from(w) && y < i64::from(h) {
            let i = (y * i64::from(w) + x) as u32;
            if out.last() != Some(&i) {
                out.push(i);
            }
        }
    };
    for k in 0..=steps {
        let t = k as f64 / steps as f64;
        let (x, y) = (
            (a[0] + dx * t).floor() as i64,
            (a[1] + dy * t).floor() as i64,
        );
        if let Some((lx, ly)) = last {
            if (lx, ly) == (x, y) {
                continue;
            }
            if lx != x && ly != y {
                // A diagonal step: fill the corner so the line stays 4-connected.
                push(x, ly, &mut out);
            }
        }
        push(x, y, &mut out);
        last = Some((x, y));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn turning_back_and_forth_keeps_a_square() {
        let m = Mask::from_fn(40, 30, |x, y| {
            image::Luma([if (10..20).contains(&x) && (5..25).contains(&y) {
                255
            } else {
                0
            }])
        });
        let (t, turn) = turn_mask(&m, 30.0);
        let area = t.pixels().filter(|p| p.0[0] != 0).count();
        assert!((180..=220).contains(&area), "area {area}");
        // Every foreground pixel of the turned image maps back into the square.
        for (x, y, p) in t.enumerate_pixels() {
            if p.0[0] != 0 {
                let [sx, sy] = turn.back([f64::from(x) + 0.5, f64::from(y) + 0.5]);
                assert!((9.0..21.0).contains(&sx) && (4.0..26.0).contains(&sy));
            }
        }
    }

    #[test]
    fn lines_are_four_connected() {
        let px = line_pixels([0.5, 0.5], [9.5, 3.5], 10, 10);
        for pair in px.windows(2) {
            let (a, b) = (pair[0] as i64, pair[1] as i64);
            let (ax, ay, bx, by) = (a % 10, a / 10, b % 10, b / 10);
            assert_eq!((ax - bx).abs() + (ay - by).abs(), 1, "{px:?}");
        }
        assert_eq!((px[0], *px.last().unwrap()), (0, 39));
    }
}
