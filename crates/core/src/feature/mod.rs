//! Sketching features onto any mesh (Nealen's dissertation ch. 4, §4.2 and §4.4): the user
//! draws on the surface, optionally inside a lasso, and drags to raise a sharp ridge or cut a
//! ravine along the sketch, raise a smooth bump or valley over the region, flatten it, or
//! rotate its Laplacians to make suggestive contours.
//!
//! The pipeline, one idea per file:
//! 1. [`place`](placement): the sketch on screen becomes the vertices that may move (the
//!    lasso's inside, or a band [`BAND_PX`] wide on either side of the sketch, over the front
//!    of the model only) and the cheapest edge path under it (§4.4.1 step 2: an edge costs
//!    its ends' screen distances to the sketch).
//! 2. [`embedding`]: each path vertex goes onto the sketch, on its own tangent plane, and
//!    the path's surroundings relax with uniform Laplacians equal to the cotangent ones
//!    (Eq. 4.5) while the path's vertices keep positional and averaging constraints (Eq. 4.6).
//! 3. [`targets`]: how each kind changes the Laplacian coordinates of the region (§4.4.2,
//!    §4.4.3), written as a few fixed vectors times coefficients of the amount.
//! 4. [`FeatureEdit`]: the Laplacian system of the region (the deform module's, with its
//!    anchor rings) is factored once and solved once per vector; a drag then only weighs the
//!    solutions, and an amount that would fold triangles over is cut back.
//!
//! Why a band of 40 px: the Laplacian change along a path spreads like a tent to the edge of
//! the region that may move, so the band's width is the width of the ridge's foot. 40 px on
//! either side keeps a feature about as wide as the stroke of a finger looks, local enough to
//! sketch several side by side, and still several triangles wide on a model that fills the
//! screen; a lasso sets any other width.

mod edit;
mod embedding;
mod error;
mod placement;
mod targets;

use glam::DVec2;
use serde::{Deserialize, Serialize};

use crate::camera::Camera;

pub use edit::{Embedded, FeatureEdit, Shaped, embed_sketch, pick_path};
pub use error::FeatureError;
pub use placement::BAND_PX;
pub(crate) use placement::{Placed, place};

/// What a feature sketch does to the surface.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FeatureKind {
    /// A sharp ridge (amount above 1) or ravine (below 0) along the sketch; between 0 and 1
    /// it softens what is there.
    #[default]
    Ridge,
    /// A smooth bump or valley over the region: all its Laplacians scaled.
    Bump,
    /// The region made flat: its Laplacians set to zero.
    Flatten,
    /// Suggestive contours: the region's Laplacians turned by an angle (degrees) about the
    /// axes of their radial planes.
    Suggestive,
}

impl FeatureKind {
    /// Every kind, in the order the tool offers them.
    pub const ALL: [FeatureKind; 4] = [
        FeatureKind::Ridge,
        FeatureKind::Bump,
        FeatureKind::Flatten,
        FeatureKind::Suggestive,
    ];

    /// The amount that leaves the surface as the embedded sketch left it: a factor of 1, or
    /// a turn of 0 degrees.
    pub fn neutral_amount(self) -> f64 {
        match self {
            FeatureKind::Ridge | FeatureKind::Bump | FeatureKind::Flatten => 1.0,
            FeatureKind::Suggestive => 0.0,
        }
    }
}

/// A feature sketch as drawn: the view, the sketch on the surface and the optional region,
/// in screen CSS px (y down).
#[derive(Clone, Debug, PartialEq)]
pub struct Sketch {
    /// The camera the sketch was drawn with.
    pub camera: Camera,
    /// The viewport's size in CSS px.
    pub viewport: DVec2,
    /// The sketch on the surface, in order.
    pub points: Vec<DVec2>,
    /// The closed lasso around the region that may move (first point not repeated).
    pub region: Option<Vec<DVec2>>,
}
