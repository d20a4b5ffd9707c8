//! Curves drawn on the screen: raw pointer strokes, planar polylines, even resampling and
//! smoothing.
//!
//! A stroke arrives as [`StrokePoint`]s in screen space (CSS px, y down) with pen pressure.
//! [`process_stroke`] validates it, [`resample`](polyline::resample)s it to an even spacing
//! and [`smooth`]s it lightly; later techniques (FiberMesh creation, pulling curves) work on
//! the result. [`polyline`] holds the planar helpers every technique shares: arclength,
//! resampling, nearest points, simplification, polygon area and containment, crossings.
//! [`bspline`] shapes a curve by a few control points.

pub mod bspline;
mod error;
mod point;
pub mod polyline;
mod smooth;
mod stroke;

pub use error::{MIN_STROKE_LENGTH_PX, StrokeError};
pub use point::StrokePoint;
pub use smooth::{smooth, smooth_closed};
pub use stroke::{
    SAMPLE_SPACING_PX, SMOOTHING_ITERATIONS, is_closed_loop, process_stroke, validate_stroke,
};
