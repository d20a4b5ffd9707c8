//! What a document is made of, as plain data: models (a mesh, its control curves and, for
//! an imported one, how it looked), sketches and point clouds, gathered in a [`Document`].
//!
//! These types sit just above the ground floor, under everything that computes, stores or
//! edits them: the modeling techniques read and make them (the FiberMesh solver takes a
//! model's [`ControlCurve`]s, chains of mesh vertices; the skeleton technique edits a
//! [`CurveHandle`]), the `io` layer reads and writes them, and the `document` layer changes a
//! [`Document`] through undoable ops. Nothing here edits anything, and nothing here depends
//! on a technique.

mod appearance;
mod as_imported;
mod control_curve;
mod curve_handle;
mod document;
mod finish;
mod keyframe;
mod mirror_plane;
mod point_cloud;
mod sketch;
mod surface;

pub use appearance::{
    AlphaMode, Appearance, Image, Material, Texture, positions_hash, positions_hash_of,
};
pub use as_imported::AsImported;
pub use control_curve::{ControlCurve, CurveKind};
pub use curve_handle::{CurveHandle, HandleCurve, HandleKind, HandleTarget};
pub use document::{Document, Stats};
pub use finish::Finish;
pub use keyframe::Keyframe;
pub use mirror_plane::{MirrorPlane, Side};
pub use point_cloud::PointCloud;
pub use sketch::SketchCurve;
pub use surface::Model;
