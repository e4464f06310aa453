//! Where a map lies on the Earth: the WGS84 position of its frame's origin,
//! the compass bearing of its +y axis and the building level, and the
//! transform between map-frame metres and WGS84 degrees.
//!
//! The map frame is treated as a plane tangent to the WGS84 ellipsoid at
//! the origin: east and north offsets become latitude and longitude with
//! the ellipsoid's radii of curvature there. For a building (a few hundred
//! metres) this is exact to well under a centimetre: the tangent plane
//! departs from the ellipsoid by d²/2R, 3 mm at 200 m.

use serde::{Deserialize, Serialize};

use super::Point;

/// WGS84 semi-major axis, metres.
const WGS84_A: f64 = 6_378_137.0;
/// WGS84 first eccentricity squared.
const WGS84_E2: f64 = 6.694_379_990_14e-3;

/// The JSON key a file carries its georeference under (GeoJSON's member,
/// IndoorGML's root description), so it reads back into its frame.
pub const GEOREF_KEY: &str = "nrgdb:georef";

/// A map's georeference.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Georef {
    /// Latitude of the map frame's origin, degrees (WGS84).
    pub lat: f64,
    /// Longitude of the map frame's origin, degrees (WGS84).
    pub lon: f64,
    /// Compass bearing of the map's +y axis ("up" in its picture),
    /// degrees clockwise from north: 0 puts +y north and +x east.
    pub heading_deg: f64,
    /// The building level the map shows (OpenStreetMap's `level`).
    #[serde(default)]
    pub level: String,
}

/// Why a georeference is not usable.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GeorefError {
    /// A value out of its range.
    #[error("{field} is {value}: {why}")]
    OutOfRange {
        /// Which value.
        field: &'static str,
        /// It.
        value: f64,
        /// The range.
        why: &'static str,
    },
    /// The level names nothing usable.
    #[error("level {0:?}: give a short name such as 0, 1, -1 or M (at most 16 characters, no ';')")]
    Level(String),
}

impl Georef {
    /// A checked georeference: latitude within ±85° (the tangent plane
    /// breaks down at the poles), longitude within ±180°, a finite heading
    /// (kept in [0, 360)), a short level name.
    ///
    /// ```
    /// use nrgdb::model::Georef;
    /// assert!(Georef::new(52.5, 13.4, 90.0, "0").is_ok());
    /// let err = Georef::new(95.0, 13.4, 0.0, "0").unwrap_err().to_string();
    /// assert!(err.starts_with("latitude is 95"), "{err}");
    /// ```
    pub fn new(lat: f64, lon: f64, heading_deg: f64, level: &str) -> Result<Georef, GeorefError> {
        let range = |field, value: f64, ok: bool, why| {
            if ok && value.is_finite() {
                Ok(())
            } else {
                Err(GeorefError::OutOfRange { field, value, why })
            }
        };
        range(
            "latitude",
            lat,
            lat.abs() <= 85.0,
            "must be between -85 and 85 degrees",
        )?;
        range(
            "longitude",
            lon,
            lon.abs() <= 180.0,
            "must be between -180 and 180 degrees",
        )?;
        range("heading", heading_deg, true, "must be a number of degrees")?;
        if level.is_empty() || level.chars().count() > 16 || level.contains(';') {
            return Err(GeorefError::Level(level.into()));
        }
        Ok(Georef {
            lat,
            lon,
            heading_deg: heading_deg.rem_euclid(360.0),
            level: level.into(),
        })
    }

    /// Metres per degree of latitude and of longitude at the origin.
    fn metres_per_degree(&self) -> (f64, f64) {
        let phi = self.lat.to_radians();
        let w = 1.0 - WGS84_E2 * phi.sin().powi(2);
        // Meridian and prime-vertical radii of curvature.
        let m = WGS84_A * (1.0 - WGS84_E2) / w.powf(1.5);
        let n = WGS84_A / w.sqrt();
        let per_rad = std::f64::consts::PI / 180.0;
        (m * per_rad, n * phi.cos() * per_rad)
    }

    /// This georeference checked as [`Georef::new`] checks (one read from
    /// a file).
    pub fn checked(self) -> Result<Georef, GeorefError> {
        Georef::new(self.lat, self.lon, self.heading_deg, &self.level)
    }

    /// East and north offsets (metres) of a map-frame point from the origin.
    pub fn east_north(&self, p: Point) -> [f64; 2] {
        let (s, c) = self.heading_deg.to_radians().sin_cos();
        [p[0] * c + p[1] * s, -p[0] * s + p[1] * c]
    }

    /// The map-frame point at east and north offsets from the origin.
    pub fn from_east_north(&self, en: [f64; 2]) -> Point {
        let (s, c) = self.heading_deg.to_radians().sin_cos();
        [en[0] * c - en[1] * s, en[0] * s + en[1] * c]
    }

    /// `[longitude, latitude]` in degrees of a map-frame point (GeoJSON's
    /// order).
    ///
    /// ```
    /// use nrgdb::model::Georef;
    /// // The map's +y points east: 111 m along it is about 0.0016° east at 45° N.
    /// let g = Georef::new(45.0, 7.0, 90.0, "0").unwrap();
    /// let [lon, lat] = g.to_lon_lat([0.0, 111.0]);
    /// assert!((lat - 45.0).abs() < 1e-9 && (lon - 7.0014).abs() < 1e-4);
    /// assert!((g.to_map([lon, lat])[1] - 111.0).abs() < 1e-9);
    /// ```
    pub fn to_lon_lat(&self, p: Point) -> [f64; 2] {
        let [e, n] = self.east_north(p);
        let (m_lat, m_lon) = self.metres_per_degree();
        [self.lon + e / m_lon, self.lat + n / m_lat]
    }

    /// The map-frame point of `[longitude, latitude]`.
    pub fn to_map(&self, lon_lat: [f64; 2]) -> Point {
        let (m_lat, m_lon) = self.metres_per_degree();
        let en = [
            (lon_lat[0] - self.lon) * m_lon,
            (lon_lat[1] - self.lat) * m_lat,
        ];
        self.from_east_north(en)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degrees_per_metre_match_the_ellipsoid() {
        // One degree of latitude is 110 574 m at the equator and 111 694 m
        // at the pole; of longitude 111 320 m at the equator and 78 847 m
        // at 45° (standard WGS84 tables).
        let at = |lat: f64| Georef::new(lat, 0.0, 0.0, "0").unwrap().metres_per_degree();
        assert!((at(0.0).0 - 110_574.0).abs() < 1.0);
        assert!((at(0.0).1 - 111_320.0).abs() < 1.0);
        assert!((at(45.0).1 - 78_847.0).abs() < 1.0);
        assert!((at(45.0).0 - 111_132.0).abs() < 1.0);
    }

    #[test]
    fn heading_turns_the_map_clockwise() {
        let g = Georef::new(0.0, 0.0, 90.0, "0").unwrap();
        // +y points east, +x points south.
        let [e, n] = g.east_north([0.0, 1.0]);
        assert!((e - 1.0).abs() < 1e-12 && n.abs() < 1e-12);
        let [e, n] = g.east_north([1.0, 0.0]);
        assert!(e.abs() < 1e-12 && (n + 1.0).abs() < 1e-12);
        for p in [[3.0, -4.0], [120.5, 77.25]] {
            let back = g.to_map(g.to_lon_lat(p));
            assert!((back[0] - p[0]).abs() < 1e-9 && (back[1] - p[1]).abs() < 1e-9);
        }
    }

    #[test]
    fn bad_values_are_named() {
        for (lat, lon, h, level, says) in [
            (95.0, 0.0, 0.0, "0", "latitude is 95"),
            (0.0, 181.0, 0.0, "0", "longitude is 181"),
            (0.0, 0.0, f64::NAN, "0", "heading is NaN"),
            (0.0, 0.0, 0.0, "", "level \"\""),
            (0.0, 0.0, 0.0, "1;2", "level \"1;2\""),
        ] {
            let err = Georef::new(lat, lon, h, level).unwrap_err().to_string();
            assert!(err.starts_with(says), "{err}");
        }
        assert_eq!(
            Georef::new(0.0, 0.0, -90.0, "0").unwrap().heading_deg,
            270.0
        );
    }
}
