//! Exact ray/segment casting against a floor plan's walls, accelerated by a
//! uniform bucket grid walked with the Amanatides-Woo traversal.

use crate::model::Point;

use super::floor_plan::Segment;

/// Distance along the ray `origin + t (cos a, sin a)`, `t >= 0`, to
/// `segment`, or `None` when they do not meet.
///
/// ```
/// use nrgdb::sim::ray_segment;
/// let t = ray_segment([0.0, 0.0], [1.0, 0.0], [[2.0, -1.0], [2.0, 1.0]]);
/// assert_eq!(t, Some(2.0));
/// ```
pub fn ray_segment(origin: Point, dir: Point, segment: Segment) -> Option<f64> {
    let [a, b] = segment;
    let e = [b[0] - a[0], b[1] - a[1]];
    let den = dir[0] * e[1] - dir[1] * e[0];
    if den.abs() < 1e-15 {
        return None;
    }
    let w = [a[0] - origin[0], a[1] - origin[1]];
    let t = (w[0] * e[1] - w[1] * e[0]) / den;
    let u = (w[0] * dir[1] - w[1] * dir[0]) / den;
    (t >= 0.0 && (-1e-12..=1.0 + 1e-12).contains(&u)).then_some(t)
}

/// Walls bucketed into square cells, for fast nearest-hit queries.
#[derive(Debug, Clone)]
pub struct WallIndex {
    segments: Vec<Segment>,
    min: Point,
    cell_m: f64,
    nx: usize,
    ny: usize,
    buckets: Vec<Vec<u32>>,
}

impl WallIndex {
    /// Indexes `segments` with buckets of `cell_m` metres (1 m is good for
    /// buildings).
    pub fn new(segments: Vec<Segment>, cell_m: f64) -> WallIndex {
        let cell_m = if cell_m > 0.0 { cell_m } else { 1.0 };
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in segments.iter().flatten() {
            lo = [lo[0].min(p[0]), lo[1].min(p[1])];
            hi = [hi[0].max(p[0]), hi[1].max(p[1])];
        }
        if segments.is_empty() {
            lo = [0.0; 2];
            hi = [0.0; 2];
        }
        let nx = (((hi[0] - lo[0]) / cell_m).floor() as usize + 1).min(1 << 14);
        let ny = (((hi[1] - lo[1]) / cell_m).floor() as usize + 1).min(1 << 14);
        let mut buckets = vec![Vec::new(); nx * ny];
        for (i, s) in segments.iter().enumerate() {
            let cx = |x: f64| (((x - lo[0]) / cell_m).floor().max(0.0) as usize).min(nx - 1);
            let cy = |y: f64| (((y - lo[1]) / cell_m).floor().max(0.0) as usize).min(ny - 1);
            let (x0, x1) = (cx(s[0][0].min(s[1][0])), cx(s[0][0].max(s[1][0])));
            let (y0, y1) = (cy(s[0][1].min(s[1][1])), cy(s[0][1].max(s[1][1])));
            for y in y0..=y1 {
                for x in x0..=x1 {
                    buckets[y * nx + x].push(i as u32);
                }
            }
        }
        WallIndex {
            segments,
            min: lo,
            cell_m,
            nx,
            ny,
            buckets,
        }
    }

    /// The walls indexed.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// Distance to the nearest wall along the ray from `origin` at `angle`
    /// (radians), if one is hit within `max_range` metres.
    pub fn cast(&self, origin: Point, angle: f64, max_range: f64) -> Option<f64> {
        let dir = [angle.cos(), angle.sin()];
        let gx = (origin[0] - self.min[0]) / self.cell_m;
        let gy = (origin[1] - self.min[1]) / self.cell_m;
        if !(gx >= 0.0 && gy >= 0.0 && gx < self.nx as f64 && gy < self.ny as f64) {
            return self.cast_all(origin, dir, max_range);
        }
        let (mut ix, mut iy) = (gx as usize, gy as usize);
        let step = |d: f64| if d > 0.0 { 1i64 } else { -1 };
        let (sx, sy) = (step(dir[0]), step(dir[1]));
        let next = |g: f64, i: usize, d: f64| {
            if d.abs() < 1e-15 {
                f64::INFINITY
            } else if d > 0.0 {
                ((i + 1) as f64 - g) * self.cell_m / d
            } else {
                (i as f64 - g) * self.cell_m / d
            }
        };
        let mut tx = next(gx, ix, dir[0]);
        let mut ty = next(gy, iy, dir[1]);
        let dtx = if dir[0] == 0.0 {
            f64::INFINITY
        } else {
            self.cell_m / dir[0].abs()
        };
        let dty = if dir[1] == 0.0 {
            f64::INFINITY
        } else {
            self.cell_m / dir[1].abs()
        };
        let mut best = f64::INFINITY;
        loop {
            for &s in &self.buckets[iy * self.nx + ix] {
                if let Some(t) = ray_segment(origin, dir, self.segments[s as usize]) {
                    best = best.min(t);
                }
            }
            let exit = tx.min(ty);
            if best <= exit || exit > max_range {
                break;
            }
            if tx < ty {
                tx += dtx;
                let n = ix as i64 + sx;
                if n < 0 || n >= self.nx as i64 {
                    break;
                }
                ix = n as usize;
            } else {
                ty += dty;
                let n = iy as i64 + sy;
                if n < 0 || n >= self.ny as i64 {
                    break;
                }
                iy = n as usize;
            }
        }
        (best <= max_range).then_some(best)
    }

    fn cast_all(&self, origin: Point, dir: Point, max_range: f64) -> Option<f64> {
        self.segments
            .iter()
            .filter_map(|s| ray_segment(origin, dir, *s))
            .fold(None, |b: Option<f64>, t| Some(b.map_or(t, |b| b.min(t))))
            .filter(|&t| t <= max_range)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::SplitMix64;

    #[test]
    fn ray_misses_parallel_and_behind_and_past_the_end() {
        let s = [[2.0, -1.0], [2.0, 1.0]];
        assert_eq!(ray_segment([0.0, 0.0], [0.0, 1.0], s), None);
        assert_eq!(ray_segment([0.0, 0.0], [-1.0, 0.0], s), None);
        assert_eq!(ray_segment([0.0, 2.0], [1.0, 0.0], s), None);
        let d = [0.6, 0.8];
        let t = ray_segment([0.0, 0.0], d, [[-5.0, 4.0], [5.0, 4.0]]).unwrap();
        assert!((t - 5.0).abs() < 1e-12);
    }

    #[test]
    fn index_agrees_with_brute_force() {
        let mut g = SplitMix64::new(5);
        let segs: Vec<Segment> = (0..200)
            .map(|_| {
                let a = [g.range(0.0, 30.0), g.range(0.0, 20.0)];
                [a, [a[0] + g.range(-3.0, 3.0), a[1] + g.range(-3.0, 3.0)]]
            })
            .collect();
        let idx = WallIndex::new(segs, 1.0);
        for _ in 0..2000 {
            let o = [g.range(-2.0, 32.0), g.range(-2.0, 22.0)];
            let a = g.range(-4.0, 4.0);
            let d = [a.cos(), a.sin()];
            assert_eq!(idx.cast(o, a, 12.0), idx.cast_all(o, d, 12.0), "{o:?} {a}");
        }
    }
}
