//! Building levels (floors): the level a space is on, by name ("0", "M",
//! "-1") and elevation in metres. A model without levels is one unnamed
//! floor at elevation 0, as every single map is.

use serde::{Deserialize, Serialize};

/// Longest level name, in characters.
pub const MAX_LEVEL_NAME_CHARS: usize = 16;

/// Largest elevation magnitude, metres (taller than any building, deeper
/// than any mine shaft a robot maps).
pub const MAX_ELEVATION_M: f64 = 10_000.0;

/// A level of a building: its name and the elevation of its floor.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Level {
    /// Short name: "0", "1", "-1", "M" (OpenStreetMap's `level` values).
    pub name: String,
    /// Elevation of the floor in metres (z in the building frame).
    pub elevation_m: f64,
}

/// Why a level is not usable.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LevelError {
    /// An empty or too long name, or one with a control character.
    #[error(
        "level name {0:?}: give a short name such as 0, 1, -1 or M (1 to {MAX_LEVEL_NAME_CHARS} characters, no control characters)"
    )]
    Name(String),
    /// An elevation that is not finite or out of range.
    #[error(
        "level {name}: elevation {elevation_m} m is not a finite number within ±{MAX_ELEVATION_M} m"
    )]
    Elevation {
        /// The level.
        name: String,
        /// Its elevation.
        elevation_m: f64,
    },
}

impl Level {
    /// A checked level.
    ///
    /// ```
    /// use nrgdb::model::Level;
    /// assert_eq!(Level::new("1", 3.5).unwrap().elevation_m, 3.5);
    /// assert!(Level::new("", 0.0).is_err());
    /// assert!(Level::new("2", f64::NAN).is_err());
    /// ```
    pub fn new(name: &str, elevation_m: f64) -> Result<Level, LevelError> {
        let level = Level {
            name: name.to_string(),
            elevation_m,
        };
        level.check()?;
        Ok(level)
    }

    /// Checks the name and elevation (see [`Level::new`]).
    pub fn check(&self) -> Result<(), LevelError> {
        let chars = self.name.chars().count();
        if chars == 0 || chars > MAX_LEVEL_NAME_CHARS || self.name.chars().any(char::is_control) {
            return Err(LevelError::Name(self.name.clone()));
        }
        if !self.elevation_m.is_finite() || self.elevation_m.abs() > MAX_ELEVATION_M {
            return Err(LevelError::Elevation {
                name: self.name.clone(),
                elevation_m: self.elevation_m,
            });
        }
        Ok(())
    }
}

/// The level name of an optional level ("" for the one floor of a model
/// without levels), for keys and messages.
pub fn level_name(level: Option<&Level>) -> &str {
    level.map_or("", |l| l.name.as_str())
}
