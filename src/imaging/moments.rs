//! Second moments of a set of pixels ([`Moments`]): which way they run
//! and how long against how thick they are. One
//! definition for the extraction's shape tests (furniture pieces, the wall
//! by a doorway's jambs).

/// Running sums over pixel centres: n, Σx, Σy, Σx², Σy², Σxy.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Moments([f64; 6]);

/// The principal axes of a set of pixel centres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Principal {
    /// The major axis's angle, radians, in the coordinates the pixels were
    /// given in (image coordinates: x right, y down), in (-π/2, π/2].
    pub angle: f64,
    /// The variance of the centres along the major axis.
    pub major: f64,
    /// The variance of the centres across it (the minor axis).
    pub minor: f64,
}

impl Moments {
    /// Adds the pixel whose centre is `p`.
    pub(crate) fn add(&mut self, p: [f64; 2]) {
        let s = &mut self.0;
        s[0] += 1.0;
        s[1] += p[0];
        s[2] += p[1];
        s[3] += p[0] * p[0];
        s[4] += p[1] * p[1];
        s[5] += p[0] * p[1];
    }

    /// Adds the pixels `x0..x1` of row `y` (centres at those whole
    /// coordinates), in constant time.
    pub(crate) fn add_row(&mut self, y: u32, x0: u32, x1: u32) {
        let (a, b) = (f64::from(x0), f64::from(x1.max(x0)));
        let n = b - a;
        let sx = (a + b - 1.0) * n / 2.0;
        // Σ x² for x in 0..m.
        let sq = |m: f64| (m - 1.0) * m * (2.0 * m - 1.0) / 6.0;
        let y = f64::from(y);
        let s = &mut self.0;
        s[0] += n;
        s[1] += sx;
        s[2] += y * n;
        s[3] += sq(b) - sq(a);
        s[4] += y * y * n;
        s[5] += y * sx;
    }

    /// How many pixels were added.
    pub(crate) fn count(&self) -> f64 {
        self.0[0]
    }

    /// The principal axes; None for no pixels.
    pub(crate) fn principal(&self) -> Option<Principal> {
        let s = &self.0;
        if s[0] <= 0.0 {
            return None;
        }
        let n = s[0];
        let (mx, my) = (s[1] / n, s[2] / n);
        let cxx = s[3] / n - mx * mx;
        let cyy = s[4] / n - my * my;
        let cxy = s[5] / n - mx * my;
        let half = (cxx + cyy) / 2.0;
        let d = (((cxx - cyy) / 2.0).powi(2) + cxy * cxy).sqrt();
        Some(Principal {
            angle: 0.5 * (2.0 * cxy).atan2(cxx - cyy),
            major: half + d,
            minor: (half - d).max(0.0),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_added_whole_is_its_pixels_added_one_by_one() {
        let mut whole = Moments::default();
        whole.add_row(3, 2, 9);
        let mut each = Moments::default();
        for x in 2..9 {
            each.add([f64::from(x), 3.0]);
        }
        for (a, b) in whole.0.iter().zip(&each.0) {
            assert!((a - b).abs() < 1e-9, "{whole:?} vs {each:?}");
        }
    }

    #[test]
    fn a_slanted_bar_runs_along_its_slant() {
        // A bar 40 pixels long and 3 thick at 30° (image coordinates).
        let (s, c) = 30f64.to_radians().sin_cos();
        let mut m = Moments::default();
        for i in 0..40 {
            for j in -1..=1 {
                let (a, b) = (f64::from(i), f64::from(j));
                m.add([10.0 + a * c - b * s, 5.0 + a * s + b * c]);
            }
        }
        let p = m.principal().unwrap();
        assert!((p.angle.to_degrees() - 30.0).abs() < 1e-6, "{p:?}");
        // Along: 0..40 spread as (40² - 1) / 12; across: -1, 0, 1 as 2/3.
        assert!((p.major - (1600.0 - 1.0) / 12.0).abs() < 1e-6, "{p:?}");
        assert!((p.minor - 2.0 / 3.0).abs() < 1e-6, "{p:?}");
    }

    #[test]
    fn no_pixels_have_no_axes() {
        assert_eq!(Moments::default().principal(), None);
        let mut m = Moments::default();
        m.add_row(1, 5, 5);
        assert_eq!(m.count(), 0.0);
    }
}
