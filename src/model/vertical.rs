//! What moving between levels costs, as an equivalent walked length in
//! metres (the unit of every connection's `length_m`), so that routes
//! weigh a flight of stairs or a lift ride against walking.
//!
//! - **Stairs**: a flight at about 30° runs 2 m along its slope per metre
//!   of rise, walked at about half the speed of level floor: 4 m of
//!   walking per metre of rise.
//! - **Lift**: waiting for the car (30 s) plus 5 s a level, at a walking
//!   speed of 1.4 m/s: 42 m plus 7 m a level.

/// Equivalent walked metres per metre of rise on stairs.
pub const STAIRS_M_PER_RISE_M: f64 = 4.0;

/// Walking speed the lift's times are converted with, m/s.
pub const WALKING_SPEED_M_S: f64 = 1.4;

/// Waiting for a lift car, seconds.
pub const ELEVATOR_WAIT_S: f64 = 30.0;

/// A lift's ride per level passed, seconds.
pub const ELEVATOR_PER_LEVEL_S: f64 = 5.0;

/// The cost of climbing (or walking down) stairs between floors
/// `rise_m` apart.
///
/// ```
/// assert_eq!(nrgdb::model::stairs_length_m(3.5), 14.0);
/// ```
pub fn stairs_length_m(rise_m: f64) -> f64 {
    rise_m.abs() * STAIRS_M_PER_RISE_M
}

/// The cost of a lift ride across `levels` levels (1 for the next floor).
///
/// ```
/// assert!((nrgdb::model::elevator_length_m(2) - 56.0).abs() < 1e-9);
/// ```
pub fn elevator_length_m(levels: usize) -> f64 {
    (ELEVATOR_WAIT_S + ELEVATOR_PER_LEVEL_S * levels as f64) * WALKING_SPEED_M_S
}
