//! Coordinate reference systems as files name them (a GeoJSON `crs`
//! member, a GML `srsName`), and the map frame a file given in one of them
//! is read into: the one place that decides how a placed file's positions
//! become map-frame metres.
//!
//! nrgdb places WGS84 (longitude, latitude in degrees) and WGS84 / UTM
//! (EPSG:326zz, 327zz, metres). Any other name is not ours to place; the
//! readers decide what that means for their format.

use super::{Georef, GeorefError, Point, UtmZone};

/// A CRS nrgdb can place positions in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NamedCrs {
    /// WGS84 longitude and latitude, degrees (CRS84, EPSG:4326).
    Wgs84,
    /// Metres in a WGS84 / UTM zone.
    Utm(UtmZone),
}

impl NamedCrs {
    /// The CRS a name gives, in the forms files use:
    /// `urn:ogc:def:crs:EPSG::32632`, `EPSG:32632`,
    /// `http://www.opengis.net/def/crs/EPSG/0/32632`, `…:OGC:1.3:CRS84`.
    /// None for any other CRS (a local one, another projection).
    ///
    /// ```
    /// use nrgdb::model::{NamedCrs, UtmZone};
    /// let utm = NamedCrs::parse("urn:ogc:def:crs:EPSG::32632");
    /// assert_eq!(utm, UtmZone::from_epsg(32632).map(NamedCrs::Utm));
    /// assert_eq!(NamedCrs::parse("EPSG:4326"), Some(NamedCrs::Wgs84));
    /// assert_eq!(NamedCrs::parse("urn:ulol:def:crs:local-m"), None);
    /// assert_eq!(NamedCrs::parse("EPSG:5186"), None);
    /// ```
    pub fn parse(name: &str) -> Option<NamedCrs> {
        let name = name.trim();
        if name.ends_with("CRS84") {
            return Some(NamedCrs::Wgs84);
        }
        if !name.to_ascii_uppercase().contains("EPSG") {
            return None;
        }
        let code: u32 = name.rsplit([':', '/']).next()?.parse().ok()?;
        if code == 4326 {
            return Some(NamedCrs::Wgs84);
        }
        UtmZone::from_epsg(code).map(NamedCrs::Utm)
    }

    /// `[longitude, latitude]` of a position given in this CRS.
    pub fn to_lon_lat(self, p: Point) -> [f64; 2] {
        match self {
            NamedCrs::Wgs84 => p,
            NamedCrs::Utm(zone) => zone.inverse(p),
        }
    }

    /// The map frame a file in this CRS is read into: the map's own
    /// georeference when it has one (`stored`: revisions keep one frame),
    /// else the one the file carries (`carried`: a file nrgdb wrote,
    /// already [`Georef::checked`]), else
    /// one made at `corner` (the file's lowest x and y, in this CRS):
    /// origin there, +y along the CRS's north (grid north for UTM),
    /// level `level`. An origin the georeference refuses (beyond ±85°
    /// latitude: positions that are not in this CRS) is an error.
    pub fn frame(
        self,
        stored: Option<&Georef>,
        carried: Option<Georef>,
        corner: Point,
        level: &str,
    ) -> Result<Georef, GeorefError> {
        if let Some(g) = stored {
            return Ok(g.clone());
        }
        if let Some(g) = carried {
            return Ok(g);
        }
        let [lon, lat] = self.to_lon_lat(corner);
        let north_up = Georef::new(lat, lon, 0.0, level)?;
        // The bearing of the CRS's north at the corner: a step north in
        // the CRS, seen in a frame whose +y is true north.
        let step = match self {
            NamedCrs::Wgs84 => [corner[0], corner[1] + 1e-5],
            NamedCrs::Utm(_) => [corner[0], corner[1] + 1.0],
        };
        let [dx, dy] = north_up.to_map(self.to_lon_lat(step));
        Georef::new(lat, lon, dx.atan2(dy).to_degrees(), level)
    }
}

/// The lowest x and the lowest y over `positions` (`[0, 0]` for none).
pub fn lowest_corner(positions: impl IntoIterator<Item = Point>) -> Point {
    let mut corner = [f64::INFINITY, f64::INFINITY];
    for p in positions {
        corner = [corner[0].min(p[0]), corner[1].min(p[1])];
    }
    if corner[0].is_finite() && corner[1].is_finite() {
        corner
    } else {
        [0.0, 0.0]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_utm_file_without_a_georeference_reads_as_metres_from_its_corner() {
        // Munich, zone 32: the map frame starts at the corner, +y along
        // grid north, lengths true metres (UTM scales them by about k0).
        let zone = UtmZone::from_epsg(32632).unwrap();
        let crs = NamedCrs::Utm(zone);
        let corner = [691_000.0, 5_334_000.0];
        let g = crs.frame(None, None, corner, "0").unwrap();
        let origin = g.to_map(crs.to_lon_lat(corner));
        assert!(
            origin[0].abs() < 1e-6 && origin[1].abs() < 1e-6,
            "{origin:?}"
        );
        let up = g.to_map(crs.to_lon_lat([corner[0], corner[1] + 50.0]));
        assert!(up[0].abs() < 0.002, "+y follows grid north: {up:?}");
        let right = g.to_map(crs.to_lon_lat([corner[0] + 40.0, corner[1]]));
        assert!(right[1].abs() < 0.002, "+x follows grid east: {right:?}");
        // The scale at 191 km east of the central meridian is about 1.00005.
        let k = 50.0 / up[1];
        assert!((k - 1.000_05).abs() < 2e-5, "scale {k}");
        // East of the central meridian grid north lies east of true north,
        // by the convergence Δλ·sin φ: 191 km east at 48.1° N is
        // Δλ ≈ 2.57°, so about 1.91°.
        assert!((g.heading_deg - 1.91).abs() < 0.02, "{}", g.heading_deg);
    }

    #[test]
    fn a_stored_georeference_wins_then_the_carried_one() {
        let crs = NamedCrs::Wgs84;
        let stored = Georef::new(48.0, 11.0, 30.0, "1").unwrap();
        let carried = Georef::new(47.0, 10.0, 0.0, "0").unwrap();
        let got = crs
            .frame(Some(&stored), Some(carried.clone()), [0.0, 0.0], "0")
            .unwrap();
        assert_eq!(got, stored);
        assert_eq!(
            crs.frame(None, Some(carried.clone()), [0.0, 0.0], "0")
                .unwrap(),
            carried
        );
    }

    #[test]
    fn positions_not_in_the_crs_are_refused() {
        // Degrees read as UTM metres land near the equator west of the
        // zone; a latitude beyond 85° is refused.
        let err = NamedCrs::Wgs84
            .frame(None, None, [10.0, 89.0], "0")
            .unwrap_err();
        assert!(err.to_string().starts_with("latitude is 89"), "{err}");
    }
}
