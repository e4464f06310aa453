//! The frame a model file is written in: map-frame metres, WGS84
//! longitude and latitude, or metres in the WGS84 / UTM zone of the map's
//! georeference. Decided here once, for `nrgdb export` and the server's
//! export endpoints:
//!
//! | format | default, georeferenced map | allowed |
//! |---|---|---|
//! | GeoJSON | WGS84 (RFC 7946) | local, wgs84, utm |
//! | IndoorGML | UTM, zone as `srsName` | local, utm |
//! | model JSON, IndoorJSON2 | local | local |
//!
//! A map without a georeference is written in map-frame metres; asking for
//! WGS84 or UTM then is an error that says how to set one.

use super::ModelFormat;
use crate::indoorgml::{self, IndoorGmlVersion};
use crate::model::Georef;
use crate::route::WalkedModel;

/// A frame a model file can be written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Frame {
    /// Map-frame metres (x right, y up from the map's origin).
    Local,
    /// WGS84 longitude and latitude in degrees (RFC 7946 GeoJSON).
    Wgs84,
    /// Metres in the WGS84 / UTM zone of the georeference's origin, the
    /// zone named in the file.
    Utm,
}

impl Frame {
    /// The frame a parameter value names: `local`, `wgs84` or `utm`.
    pub fn parse(name: &str) -> Option<Frame> {
        match name {
            "local" => Some(Frame::Local),
            "wgs84" => Some(Frame::Wgs84),
            "utm" => Some(Frame::Utm),
            _ => None,
        }
    }

    /// The name [`Frame::parse`] reads.
    pub fn name(self) -> &'static str {
        match self {
            Frame::Local => "local",
            Frame::Wgs84 => "wgs84",
            Frame::Utm => "utm",
        }
    }
}

/// Why a model cannot be written in the frame asked for.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum FrameError {
    /// WGS84 or UTM asked for a map without a georeference.
    #[error(
        "the map has no georeference, so no {frame} output: set one with `nrgdb georef MAP --origin LAT,LON --heading DEG`"
    )]
    NoGeoref {
        /// The frame asked for.
        frame: &'static str,
    },
    /// A frame the format is not written in.
    #[error("{format} is written in {allowed}, not {frame}")]
    NotForFormat {
        /// The format.
        format: &'static str,
        /// The frame asked for.
        frame: &'static str,
        /// The frames it is written in.
        allowed: &'static str,
    },
}

/// The frame a model in `format` is written in: `asked`, or the format's
/// default when None (see the module docs), checked against what the
/// format allows and whether the map is `georeferenced`.
///
/// ```
/// use nrgdb::format::{Frame, ModelFormat, frame_for};
/// assert_eq!(frame_for(ModelFormat::GeoJson, None, true), Ok(Frame::Wgs84));
/// assert_eq!(frame_for(ModelFormat::IndoorGml, None, true), Ok(Frame::Utm));
/// assert_eq!(frame_for(ModelFormat::IndoorGml, None, false), Ok(Frame::Local));
/// assert!(frame_for(ModelFormat::IndoorGml, Some(Frame::Wgs84), true).is_err());
/// assert!(frame_for(ModelFormat::GeoJson, Some(Frame::Utm), false).is_err());
/// ```
pub fn frame_for(
    format: ModelFormat,
    asked: Option<Frame>,
    georeferenced: bool,
) -> Result<Frame, FrameError> {
    let (name, default, allowed): (&str, Frame, &[Frame]) = match format {
        ModelFormat::GeoJson => (
            "GeoJSON",
            Frame::Wgs84,
            &[Frame::Local, Frame::Wgs84, Frame::Utm],
        ),
        ModelFormat::IndoorGml => ("IndoorGML", Frame::Utm, &[Frame::Local, Frame::Utm]),
        ModelFormat::Json => ("model JSON", Frame::Local, &[Frame::Local]),
        ModelFormat::IndoorJson => ("IndoorJSON2", Frame::Local, &[Frame::Local]),
    };
    let Some(frame) = asked else {
        return Ok(if georeferenced { default } else { Frame::Local });
    };
    if !allowed.contains(&frame) {
        return Err(FrameError::NotForFormat {
            format: name,
            frame: frame.name(),
            allowed: match allowed.len() {
                1 => "map-frame metres (local) only",
                2 => "local or utm",
                _ => "local, wgs84 or utm",
            },
        });
    }
    if frame != Frame::Local && !georeferenced {
        return Err(FrameError::NoGeoref {
            frame: frame.name(),
        });
    }
    Ok(frame)
}

/// A walked model as the text of `format` in `frame` (placed by
/// `georef`; map-frame metres when `frame` is local or there is none).
pub fn render_in(
    walked: &WalkedModel,
    format: ModelFormat,
    version: IndoorGmlVersion,
    frame: Frame,
    georef: Option<&Georef>,
) -> String {
    let Some(g) = georef.filter(|_| frame != Frame::Local) else {
        return super::render_as(walked, format, version);
    };
    match (format, frame) {
        (ModelFormat::GeoJson, Frame::Wgs84) => super::render_geojson_wgs84(walked, g),
        (ModelFormat::GeoJson, _) => super::render_geojson_utm(walked, g),
        (ModelFormat::IndoorGml, _) => {
            let mut doc = indoorgml::from_nrg_with_paths(&walked.nrg, &walked.paths);
            indoorgml::placed::into_utm(&mut doc, g);
            indoorgml::write_string_as(&doc, version)
        }
        _ => super::render_as(walked, format, version),
    }
}
