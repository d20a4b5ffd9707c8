//! Planar polylines and polygons: the one home of the 2D helpers that strokes, outlines,
//! silhouettes and over-sketch matching share.
//!
//! A polyline is a slice of points joined in order; a polygon (a closed polyline) joins the
//! last point back to the first without repeating it. Everything is in `f64` and in one
//! plane, whatever its units (screen px, or drawing-plane units).
//!
//! - [`length`], [`cumulative_lengths`] (the arclength table) and lookups by arclength or
//!   by fractional point index ([`point_at`], [`index_at`], [`point_at_index`]);
//! - [`resample`]: even arclength resampling, of positions or of points that carry data
//!   along (a stroke's pressure, through [`PolylinePoint`]);
//! - [`closest_point`], [`distance_to_polyline`], [`distance_to_segment`];
//! - [`thin`] (drop points near the last kept one), [`douglas_peucker`] and [`simplify`] (D. Douglas and T. Peucker, The Canadian
//!   Cartographer 10(2), 1973);
//! - [`oversketch_merge`], [`oversketch_merge_closed`]: a stroke drawn over part of a
//!   polyline or a loop merged into it (Baudel's merge, as Bujans uses it);
//! - [`signed_area`], [`perimeter`], [`centroid`], [`contains`] (even-odd rule);
//! - [`segment_crossing`] and [`self_crossings`], bucketed in a uniform grid so that a
//!   polyline of `m` segments is checked in about `O(m)`.
//!
//! Limits: at an arclength shared by repeated points, [`index_at`] gives the last of them;
//! crossings count touching (collinear overlap, an end on the other segment) as crossing,
//! and the tests are plain floating point, not robust predicates, so a nearly degenerate
//! pair of segments may go either way.

mod arclength;
mod crossing;
mod merge;
mod nearest;
mod polygon;
mod resample;
mod segment_grid;
mod segment_pair;
mod simplify;

pub use arclength::{
    cumulative_lengths, index_at, length, point_at, point_at_index, relative_arclengths, segment_at,
};
pub use crossing::self_crossings;
pub use merge::{BAUDEL_K, oversketch_merge, oversketch_merge_closed};
pub use nearest::{Closest, closest_point, distance_to_polyline, distance_to_segment};
pub use polygon::{centroid, contains, perimeter, signed_area};
pub use resample::{PolylinePoint, resample, resample_closed};
pub(crate) use segment_grid::SegmentGrid;
pub use segment_pair::segment_crossing;
pub use simplify::{douglas_peucker, simplify, thin};
