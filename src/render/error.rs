//! Errors raised while rendering.

/// Why a picture could not be drawn.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RenderError {
    /// Neither the model nor the map gives anything to draw.
    #[error(
        "nothing to draw: the model has no spaces and no map was given (pass a map or a non-empty model)"
    )]
    NothingToDraw,
    /// The picture would be larger than the limit.
    #[error(
        "the picture would be {width}×{height} px, more than {limit} px a side \
         (lower px_per_m, e.g. `--scale {suggest:.1}`)"
    )]
    TooLarge {
        /// Width in pixels.
        width: u64,
        /// Height in pixels.
        height: u64,
        /// Largest side allowed.
        limit: u64,
        /// A scale that would fit, in pixels per metre.
        suggest: f64,
    },
    /// The scale is not a positive finite number.
    #[error("scale must be a positive number of pixels per metre, got {0} (try 20)")]
    BadScale(f64),
    /// A coordinate of the model is not finite.
    #[error("space {0} has a coordinate that is not a finite number (check the model file)")]
    NotFinite(crate::model::SpaceId),
    /// The picture's memory could not be had.
    #[error("cannot allocate a {width}×{height} px picture (lower the scale)")]
    Allocate {
        /// Width in pixels.
        width: u32,
        /// Height in pixels.
        height: u32,
    },
    /// PNG encoding failed.
    #[error("cannot encode the PNG: {0}")]
    Encode(String),
}
