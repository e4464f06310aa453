//! WGS84 / UTM: the projected CRS in which GIS tools (QGIS, GDAL) place a
//! georeferenced building in metres without hand work (EPSG:326zz north of
//! the equator, 327zz south). Transverse Mercator by Krüger's series to
//! the fourth order in the third flattening (C. F. F. Karney,
//! "Transverse Mercator with an accuracy of a few nanometers", J. Geodesy
//! 2011, eqs. 7–11 and 35–36): well under a millimetre within a zone.
//! Zones are the regular 6° ones (the Norway and Svalbard exceptions are
//! not applied: the zone is named in the output, so any reader agrees).

use serde::{Deserialize, Serialize};

/// WGS84 semi-major axis (m).
const A: f64 = 6_378_137.0;
/// WGS84 flattening.
const F: f64 = 1.0 / 298.257_223_563;
/// UTM scale on the central meridian.
const K0: f64 = 0.9996;
/// False easting (m).
const E0: f64 = 500_000.0;
/// False northing in the southern hemisphere (m).
const N0_SOUTH: f64 = 10_000_000.0;

/// A UTM zone: its number (1–60) and hemisphere.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct UtmZone {
    /// The zone number, 1 to 60.
    pub zone: u8,
    /// North of the equator (EPSG:326zz) or south (EPSG:327zz).
    pub north: bool,
}

/// The series' constants: the third flattening's powers, the rectifying
/// radius and the forward (α) and inverse (β) coefficients.
struct Series {
    a_r: f64,
    alpha: [f64; 4],
    beta: [f64; 4],
    e: f64,
}

fn series() -> Series {
    let n = F / (2.0 - F);
    let (n2, n3, n4) = (n * n, n * n * n, n * n * n * n);
    Series {
        a_r: A / (1.0 + n) * (1.0 + n2 / 4.0 + n4 / 64.0),
        alpha: [
            n / 2.0 - 2.0 * n2 / 3.0 + 5.0 * n3 / 16.0 + 41.0 * n4 / 180.0,
            13.0 * n2 / 48.0 - 3.0 * n3 / 5.0 + 557.0 * n4 / 1440.0,
            61.0 * n3 / 240.0 - 103.0 * n4 / 140.0,
            49561.0 * n4 / 161_280.0,
        ],
        beta: [
            n / 2.0 - 2.0 * n2 / 3.0 + 37.0 * n3 / 96.0 - n4 / 360.0,
            n2 / 48.0 + n3 / 15.0 - 437.0 * n4 / 1440.0,
            17.0 * n3 / 480.0 - 37.0 * n4 / 840.0,
            4397.0 * n4 / 161_280.0,
        ],
        e: (F * (2.0 - F)).sqrt(),
    }
}

impl UtmZone {
    /// The zone holding `[longitude, latitude]` (degrees).
    pub fn of(lon_lat: [f64; 2]) -> UtmZone {
        let lon = (lon_lat[0] + 180.0).rem_euclid(360.0);
        UtmZone {
            zone: ((lon / 6.0).floor() as u8).min(59) + 1,
            north: lon_lat[1] >= 0.0,
        }
    }

    /// The EPSG code: 32600 + zone north, 32700 + zone south.
    pub fn epsg(self) -> u32 {
        (if self.north { 32_600 } else { 32_700 }) + u32::from(self.zone)
    }

    /// The zone of an EPSG code (32601–32660, 32701–32760), if it is one.
    pub fn from_epsg(code: u32) -> Option<UtmZone> {
        let (north, zone) = match code {
            32_601..=32_660 => (true, code - 32_600),
            32_701..=32_760 => (false, code - 32_700),
            _ => return None,
        };
        Some(UtmZone {
            zone: zone as u8,
            north,
        })
    }

    /// The OGC URN of the CRS, as GDAL reads it from a GeoJSON `crs`.
    pub fn urn(self) -> String {
        format!("urn:ogc:def:crs:EPSG::{}", self.epsg())
    }

    fn central_meridian(self) -> f64 {
        f64::from(self.zone) * 6.0 - 183.0
    }

    /// Easting and northing (m) of `[longitude, latitude]` (degrees).
    pub fn forward(self, lon_lat: [f64; 2]) -> [f64; 2] {
        let s = series();
        let phi = lon_lat[1].to_radians();
        let lam = (lon_lat[0] - self.central_meridian()).to_radians();
        let sin_phi = phi.sin();
        let t = (sin_phi.atanh() - s.e * (s.e * sin_phi).atanh()).sinh();
        let xi_p = t.atan2(lam.cos());
        let eta_p = (lam.sin() / (1.0 + t * t).sqrt()).atanh();
        let (mut xi, mut eta) = (xi_p, eta_p);
        for (j, a) in s.alpha.iter().enumerate() {
            let k = 2.0 * (j + 1) as f64;
            xi += a * (k * xi_p).sin() * (k * eta_p).cosh();
            eta += a * (k * xi_p).cos() * (k * eta_p).sinh();
        }
        let north0 = if self.north { 0.0 } else { N0_SOUTH };
        [E0 + K0 * s.a_r * eta, north0 + K0 * s.a_r * xi]
    }

    /// `[longitude, latitude]` (degrees) of an easting and northing (m).
    pub fn inverse(self, en: [f64; 2]) -> [f64; 2] {
        let s = series();
        let north0 = if self.north { 0.0 } else { N0_SOUTH };
        let xi = (en[1] - north0) / (K0 * s.a_r);
        let eta = (en[0] - E0) / (K0 * s.a_r);
        let (mut xi_p, mut eta_p) = (xi, eta);
        for (j, b) in s.beta.iter().enumerate() {
            let k = 2.0 * (j + 1) as f64;
            xi_p -= b * (k * xi).sin() * (k * eta).cosh();
            eta_p -= b * (k * xi).cos() * (k * eta).sinh();
        }
        // The conformal latitude's tangent, then the geographic one by
        // Newton's method (Karney eqs. 19–21).
        let tau_p = xi_p.sin() / (eta_p.sinh().hypot(xi_p.cos()));
        let e2 = s.e * s.e;
        let mut tau = tau_p;
        for _ in 0..6 {
            let sigma = (s.e * (s.e * tau / (1.0 + tau * tau).sqrt()).atanh()).sinh();
            let tau_i = tau * (1.0 + sigma * sigma).sqrt() - sigma * (1.0 + tau * tau).sqrt();
            tau += (tau_p - tau_i) / (1.0 + tau_i * tau_i).sqrt() * (1.0 + (1.0 - e2) * tau * tau)
                / ((1.0 - e2) * (1.0 + tau * tau).sqrt());
        }
        let lam = eta_p.sinh().atan2(xi_p.cos());
        [
            self.central_meridian() + lam.to_degrees(),
            tau.atan().to_degrees(),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zones_and_codes() {
        assert_eq!(UtmZone::of([11.575, 48.137]).epsg(), 32632);
        assert_eq!(UtmZone::of([151.2, -33.9]).epsg(), 32756);
        assert_eq!(UtmZone::of([-180.0, 0.0]).zone, 1);
        assert_eq!(UtmZone::of([180.0, 0.0]).zone, 1);
        assert_eq!(UtmZone::of([179.99, 0.0]).zone, 60);
        assert_eq!(UtmZone::from_epsg(32632), Some(UtmZone::of([11.0, 48.0])));
        assert_eq!(UtmZone::from_epsg(4326), None);
    }

    #[test]
    fn on_the_central_meridian_at_the_equator() {
        // Easting 500 000 m, northing 0 by definition.
        let z = UtmZone::of([9.0, 0.0]);
        let [e, n] = z.forward([9.0, 0.0]);
        assert!((e - 500_000.0).abs() < 1e-6 && n.abs() < 1e-6, "{e} {n}");
        // The meridian arc to 45° N is 4 984 944.378 m (WGS84), times k0.
        let [_, n] = z.forward([9.0, 45.0]);
        assert!((n - 0.9996 * 4_984_944.378).abs() < 0.01, "{n}");
    }

    #[test]
    fn inverse_undoes_forward_to_a_tenth_of_a_millimetre() {
        for (lon, lat) in [(11.575, 48.137), (151.2, -33.9), (-3.7, 40.4), (2.9, 0.01)] {
            let z = UtmZone::of([lon, lat]);
            let en = z.forward([lon, lat]);
            let [lo, la] = z.inverse(en);
            let back = z.forward([lo, la]);
            assert!((back[0] - en[0]).abs() < 1e-4 && (back[1] - en[1]).abs() < 1e-4);
            assert!(
                (lo - lon).abs() < 1e-9 && (la - lat).abs() < 1e-9,
                "{lo} {la}"
            );
        }
    }
}
