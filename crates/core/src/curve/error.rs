//! Why a stroke is refused.

/// Strokes shorter than this (in CSS px of arc length) are refused
/// ([`StrokeError::TooShort`]).
pub const MIN_STROKE_LENGTH_PX: f64 = 4.0;

/// Why a stroke was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum StrokeError {
    /// Fewer than two points.
    #[error("The stroke has {count} point(s); at least 2 are needed.")]
    TooFewPoints {
        /// How many points the stroke had.
        count: usize,
    },
    /// A coordinate or pressure is NaN or infinite.
    #[error("Point {index} of the stroke is not a finite number.")]
    NonFinite {
        /// Index of the first bad point.
        index: usize,
    },
    /// The stroke is shorter than [`MIN_STROKE_LENGTH_PX`].
    #[error("The stroke is {length_px:.1} px long; at least {MIN_STROKE_LENGTH_PX} px are needed.")]
    TooShort {
        /// Arc length of the stroke in CSS px.
        length_px: f64,
    },
}
