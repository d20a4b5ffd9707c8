//! Sketchmesh core: all geometry and modeling, with no UI and no web.
//!
//! Everything here computes in `f64` (glam `DVec3`, faer `f64`); `f32` appears only at
//! the GPU and glTF boundaries. The app, the CLI and the tests drive it through
//! [`document::Editor`], which changes the [`document::Document`] only through
//! serializable, undoable operations.

pub mod camera;
pub mod curve;
pub mod deform;
pub mod document;
pub mod fibermesh;
pub mod geometry;
pub mod io;
pub mod mesh;
pub mod oversketch;
pub mod silhouette;
pub mod solve;
