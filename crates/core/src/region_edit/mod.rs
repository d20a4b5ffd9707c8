//! Bujans' region editor (`../shared/seeds/003_…`, §4, §5 and §8): a reference curve
//! sketched on any model and a closed boundary drawn around it mark a region; a transform
//! moves the region with a fall-off, fully at the reference curve and not at all at the
//! boundary, each vertex by its weight's fraction `w ⊙ T` of the transform (Alexa's
//! operators, [`crate::geometry::Fractions`]). No solve: a drag frame is one pass over the
//! region.
//!
//! One idea per file:
//! 1. [`embed`]: both curves become vertices of a copy of the mesh (FiberMesh's curve
//!    embedding), so the reference curve moves exactly as drawn and the edit ends on the
//!    drawn boundary. Placement is then the feature sketch's ([`crate::feature`]): the
//!    boundary is its lasso, so the region is the front of the model inside the boundary
//!    (the boundary's own chain outside it), grown over edges from under the reference
//!    curve; the reference path is its embedded chain (or, where it could not be embedded,
//!    the cheapest edge path under it).
//! 2. [`falloff`]: how close each vertex is to the reference curve, `s = d_b / (d_r + d_b)`
//!    with `d_r` and `d_b` its distances along edges (Dijkstra over edge lengths, within the
//!    region) to the reference curve and to the first vertices outside the boundary; `s` is
//!    1 on the curve and falls to 0 at the boundary whatever the region's shape, which the
//!    thesis leaves open (a distance normalised per vertex, not by one global maximum, so a
//!    boundary drawn nearer the curve on one side still reaches 0 there). The weight is the
//!    user's [`Levels`] read at `s`: N weights at evenly spaced `s`, linear between them
//!    (the thesis' gray levels, 5 by default).
//! 3. [`RegionEdit`]: the region and its weights, found once per pair of curves; applying a
//!    transform writes the region's vertices only, so everything outside stays bit for bit.
//! 4. [`disc`]: the region flattened to the unit disc (Tutte's embedding), where the
//!    fall-off panel draws its levels.
//! 5. [`profile`]: the cross-section across the reference curve, and a re-sketched one
//!    swept along the curve (§6).
//! 6. [`handles`]: handles along the reference curve with transforms of their own, blended
//!    along it (§7); a [`Motion`] is one transform or such a blend, each checked by
//!    [`transform`] (finite, affine, short of half a turn).

mod disc;
mod edit;
mod embed;
mod error;
mod falloff;
mod handles;
mod profile;
mod transform;

use glam::DVec2;

use crate::camera::Camera;

pub use disc::Flattening;
pub use edit::{Finding, RegionEdit};
pub use error::RegionError;
pub use falloff::{Area, Levels};
pub use handles::{Handle, HandleFrame, HandleRail, Motion, blend_at};
pub use profile::{Profile, ProfileChange};
pub use transform::checked_transform;

/// The two curves of a region edit as drawn, in screen CSS px (y down).
#[derive(Clone, Debug, PartialEq)]
pub struct RegionSketch {
    /// The camera the curves were drawn with.
    pub camera: Camera,
    /// The viewport's size in CSS px.
    pub viewport: DVec2,
    /// The reference curve on the surface, in order: the part that moves fully.
    pub reference: Vec<DVec2>,
    /// The closed boundary around it (first point not repeated): what lies outside stays.
    pub boundary: Vec<DVec2>,
}
