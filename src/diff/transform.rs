//! Rigid 2D transforms (rotation + translation) in metres, and moving a
//! whole model by one.

use serde::{Deserialize, Serialize};

use crate::model::{ModelError, Nrg, Point};

/// `p' = R(rotation) · p + (tx, ty)`, in metres and radians (CCW).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct RigidTransform {
    /// Rotation about the map origin, radians, counter-clockwise.
    pub rotation_rad: f64,
    /// Translation along x after rotating, metres.
    pub tx_m: f64,
    /// Translation along y after rotating, metres.
    pub ty_m: f64,
}

impl Default for RigidTransform {
    fn default() -> Self {
        RigidTransform::IDENTITY
    }
}

impl RigidTransform {
    /// No motion.
    pub const IDENTITY: RigidTransform = RigidTransform {
        rotation_rad: 0.0,
        tx_m: 0.0,
        ty_m: 0.0,
    };

    /// A transform from a rotation in degrees and a translation in metres.
    pub fn from_degrees(rotation_deg: f64, tx_m: f64, ty_m: f64) -> RigidTransform {
        RigidTransform {
            rotation_rad: rotation_deg.to_radians(),
            tx_m,
            ty_m,
        }
    }

    /// The rotation in degrees, in (-180, 180].
    pub fn rotation_deg(&self) -> f64 {
        let d = self.rotation_rad.to_degrees().rem_euclid(360.0);
        if d > 180.0 { d - 360.0 } else { d }
    }

    /// Moves one point.
    ///
    /// ```
    /// use nrgdb::diff::RigidTransform;
    /// let t = RigidTransform::from_degrees(90.0, 1.0, 0.0);
    /// let p = t.apply([1.0, 0.0]);
    /// assert!((p[0] - 1.0).abs() < 1e-12 && (p[1] - 1.0).abs() < 1e-12);
    /// ```
    pub fn apply(&self, p: Point) -> Point {
        let (s, c) = self.rotation_rad.sin_cos();
        [
            c * p[0] - s * p[1] + self.tx_m,
            s * p[0] + c * p[1] + self.ty_m,
        ]
    }

    /// The transform undoing this one.
    pub fn inverse(&self) -> RigidTransform {
        let (s, c) = self.rotation_rad.sin_cos();
        RigidTransform {
            rotation_rad: -self.rotation_rad,
            tx_m: -(c * self.tx_m + s * self.ty_m),
            ty_m: -(-s * self.tx_m + c * self.ty_m),
        }
    }

    /// `self` after `first`: `p ↦ self(first(p))`.
    pub fn after(&self, first: &RigidTransform) -> RigidTransform {
        let t = self.apply([first.tx_m, first.ty_m]);
        RigidTransform {
            rotation_rad: self.rotation_rad + first.rotation_rad,
            tx_m: t[0],
            ty_m: t[1],
        }
    }

    /// Whether this is the identity.
    pub fn is_identity(&self) -> bool {
        *self == RigidTransform::IDENTITY
    }

    /// The model moved by this transform: polygons, holes, anchors and
    /// doorway lines (areas and widths are kept, up to rounding;
    /// connection lengths are kept).
    pub fn apply_to_nrg(&self, nrg: &Nrg) -> Result<Nrg, ModelError> {
        if self.is_identity() {
            return Ok(nrg.clone());
        }
        let (mut spaces, connections) = nrg.clone().into_parts();
        for s in &mut spaces {
            s.anchor = self.apply(s.anchor);
            for p in s.polygon.iter_mut().chain(s.holes.iter_mut().flatten()) {
                *p = self.apply(*p);
            }
            if let Some(line) = &mut s.doorway {
                *line = line.map(|p| self.apply(p));
            }
        }
        Nrg::new(spaces, connections)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_and_composition() {
        let t = RigidTransform::from_degrees(33.0, 2.5, -1.0);
        let p = [3.0, 4.0];
        let q = t.inverse().apply(t.apply(p));
        assert!((q[0] - p[0]).abs() < 1e-12 && (q[1] - p[1]).abs() < 1e-12);
        let u = RigidTransform::from_degrees(-50.0, 0.5, 7.0);
        let (a, b) = (u.after(&t).apply(p), u.apply(t.apply(p)));
        assert!((a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12);
        assert!((RigidTransform::from_degrees(270.0, 0.0, 0.0).rotation_deg() + 90.0).abs() < 1e-9);
    }

    #[test]
    fn moving_a_model_keeps_areas() {
        let nrg = crate::fixtures::corridor_building(3);
        let moved = RigidTransform::from_degrees(30.0, 5.0, 5.0)
            .apply_to_nrg(&nrg)
            .unwrap();
        for (a, b) in nrg.spaces().iter().zip(moved.spaces()) {
            assert!((a.area_m2 - b.area_m2).abs() < 1e-9);
        }
    }
}
