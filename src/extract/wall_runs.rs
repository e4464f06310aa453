//! Straight runs of wall face along a map's two dominant directions, in
//! pixels: the wall lines of the clutter rule (`clutter.rs`) and the walls
//! a doorway must sit in (`wall_support.rs`).

use std::collections::HashMap;

/// A run along a line: its first and last position along the direction,
/// whole pixels, inclusive.
pub(crate) type Run = (i64, i64);

/// For each of the two dominant directions, the runs of wall face on each
/// line across it (offset in whole pixels along `across`).
#[derive(Debug, Clone)]
pub(crate) struct WallRuns {
    /// Unit vectors across each direction (the offsets are taken on).
    across: [(f64, f64); 2],
    /// Each line's runs, keyed by offset.
    runs: [HashMap<i64, Vec<Run>>; 2],
}

impl WallRuns {
    /// The runs of at least `min_run` pixels, bridging breaks of up to
    /// `gap` whole pixels, through `face` (pixels `[x, y]` of wall face)
    /// along `deg` (degrees, image coordinates) and a quarter turn from it.
    pub(crate) fn new(face: &[[u32; 2]], deg: f64, min_run: f64, gap: i64) -> WallRuns {
        let (s, c) = deg.to_radians().sin_cos();
        let across = [(c, s), (-s, c)];
        let runs = across.map(|a| {
            let along = along(a);
            // Each face pixel counts for its own line and the two beside it,
            // so a face a pixel off straight still makes one run.
            // Sorted as one number each, the line's offset in the high
            // half: the order of the pairs (offset, position along).
            const BIAS: i64 = 1 << 31;
            let mut keys: Vec<u64> = face
                .iter()
                .flat_map(|&p| {
                    let p = [f64::from(p[0]), f64::from(p[1])];
                    let off = project(p, a).round() as i64;
                    let t = project(p, along).round() as i64;
                    (-1..=1).map(move |k| ((off + k + BIAS) as u64) << 32 | (t + BIAS) as u64)
                })
                .collect();
            keys.sort_unstable();
            keys.dedup();
            let at = |k: u64| ((k >> 32) as i64 - BIAS, (k & 0xffff_ffff) as i64 - BIAS);
            let mut lines: HashMap<i64, Vec<Run>> = HashMap::new();
            for line in keys.chunk_by(|a, b| a >> 32 == b >> 32) {
                let off = at(line[0]).0;
                let mut start = at(line[0]).1;
                let mut keep = |start: i64, last: i64| {
                    if (last - start + 1) as f64 >= min_run {
                        lines.entry(off).or_default().push((start, last));
                    }
                };
                for w in line.windows(2) {
                    let (t0, t1) = (at(w[0]).1, at(w[1]).1);
                    if t1 - t0 > gap + 1 {
                        keep(start, t0);
                        start = t1;
                    }
                }
                keep(start, at(line[line.len() - 1]).1);
            }
            lines
        });
        WallRuns { across, runs }
    }

    /// The unit vector across direction `k` (0 or 1).
    pub(crate) fn across(&self, k: usize) -> (f64, f64) {
        self.across[k]
    }

    /// The offsets of the lines along direction `k` with a run.
    pub(crate) fn lines(&self, k: usize) -> impl Iterator<Item = i64> + '_ {
        self.runs[k].keys().copied()
    }

    /// The runs along direction `k` on the lines within `tolerance` whole
    /// pixels of offset `off`.
    pub(crate) fn near(
        &self,
        k: usize,
        off: f64,
        tolerance: i64,
    ) -> impl Iterator<Item = Run> + '_ {
        let off = off.round() as i64;
        (off - tolerance..=off + tolerance)
            .filter_map(move |o| self.runs[k].get(&o))
            .flatten()
            .copied()
    }
}

/// The unit vector along the direction `across` is taken across.
pub(crate) fn along(across: (f64, f64)) -> (f64, f64) {
    (-across.1, across.0)
}

/// Point `p`'s coordinate along `axis`.
pub(crate) fn project(p: [f64; 2], axis: (f64, f64)) -> f64 {
    p[0] * axis.0 + p[1] * axis.1
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_bridge_small_breaks_and_drop_short_pieces() {
        // Row 5: x 0..=29 with a 1-px break at 10, then x 40..=44.
        let face: Vec<[u32; 2]> = (0..30)
            .filter(|&x| x != 10)
            .chain(40..45)
            .map(|x| [x, 5])
            .collect();
        let runs = WallRuns::new(&face, 0.0, 10.0, 1);
        // Lines across direction 1 ((0, 1) at 0 degrees) are rows.
        let len = |r: &WallRuns, row: f64| -> Vec<i64> {
            let mut l: Vec<i64> = r.near(1, row, 0).map(|(a, b)| b - a + 1).collect();
            l.sort_unstable();
            l
        };
        assert_eq!(len(&runs, 5.0), vec![30], "the 5-px piece is too short");
        assert_eq!(len(&runs, 6.0), vec![30], "a line beside counts");
        assert!(len(&runs, 8.0).is_empty());
        let unbridged = WallRuns::new(&face, 0.0, 10.0, 0);
        assert_eq!(
            len(&unbridged, 5.0),
            vec![10, 19],
            "the break splits the run"
        );
    }
}
