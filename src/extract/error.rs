//! Errors raised by extraction.

/// Why a map could not be turned into an NRG.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ExtractError {
    /// A parameter is out of range.
    #[error("parameter `{name}` = {value} is invalid: lengths must be finite and >= 0")]
    BadParam {
        /// The parameter.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A fraction above 1.
    #[error("parameter `{name}` = {value} is invalid: it is a fraction, from 0 to 1")]
    NotAFraction {
        /// The parameter.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A least value above its greatest.
    #[error(
        "parameters `{low}` = {low_value} and `{high}` = {high_value} contradict each other: `{low}` must not exceed `{high}`"
    )]
    ParamsOutOfOrder {
        /// The least value's parameter.
        low: &'static str,
        /// Its value.
        low_value: f64,
        /// The greatest value's parameter.
        high: &'static str,
        /// Its value.
        high_value: f64,
    },
    /// A parameters file or value that cannot be read.
    #[error("invalid parameters: {message}")]
    ParamsText {
        /// What is wrong, with the parameter's name.
        message: String,
    },
    /// A parameter name that is none.
    #[error("no such parameter `{key}` (known: {known})")]
    UnknownParam {
        /// The name given.
        key: String,
        /// Every parameter's name.
        known: String,
    },
    /// Nothing free is left after noise removal.
    #[error(
        "no free space is left after removing noise narrower than {noise_m} m and components under {min_area_m2} m² (lower building.noise_radius_m or internals.min_free_area_m2)"
    )]
    NoSpace {
        /// The noise radius used.
        noise_m: f64,
        /// The minimum area used.
        min_area_m2: f64,
    },
    /// The map has more spaces than a 16-bit label image can hold.
    #[error(
        "the map produced {0} spaces; at most 65535 fit a label image (raise building.min_room_area_m2)"
    )]
    TooManySpaces(usize),
    /// The extracted graph broke a model invariant (a bug).
    #[error("extracted graph is not a valid nrg: {0}")]
    Model(#[from] crate::model::ModelError),
}
