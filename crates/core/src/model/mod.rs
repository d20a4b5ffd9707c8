//! What a document is made of, as plain data: models (a mesh, its control curves and, for
//! an imported one, how it looked), sketches and point clouds, gathered in a [`Document`].
//!
//! These types sit between the modeling techniques and everything that stores or edits
//! their results: the `io` layer above reads and writes them, and the `document` layer above
//! that changes a [`Document`] through undoable ops. Nothing here edits anything, so both
//! can build on it without `io` knowing about editing. A model's curves are the FiberMesh
//! solver's own [`ControlCurve`]s (chains of mesh vertices), re-exported here as part of the
//! model; likewise a curve handle is the skeleton technique's own [`CurveHandle`].

mod appearance;
mod as_imported;
mod document;
mod keyframe;
mod point_cloud;
mod sketch;
mod surface;

pub use appearance::{
    AlphaMode, Appearance, Image, Material, Texture, positions_hash, positions_hash_of,
};
pub use as_imported::AsImported;
pub use document::{Document, Stats};
pub use keyframe::Keyframe;
pub use point_cloud::PointCloud;
pub use sketch::SketchCurve;
pub use surface::Model;

pub use crate::fibermesh::{ControlCurve, CurveKind};
pub use crate::skeleton::{CurveHandle, HandleTarget};
