//! Sketchmesh core: all geometry and modeling, with no UI and no web.
//!
//! Everything here computes in `f64` (glam `DVec3`, faer `f64`); `f32` appears only at
//! the GPU and glTF boundaries. The app, the CLI and the tests drive it through
//! [`document::Editor`], which changes the [`document::Document`] only through
//! serializable, undoable operations.
//!
//! The modules form layers; each uses only those below it:
//! 1. the ground floor: [`camera`], [`curve`] (screen strokes), [`mesh`], [`solve`] and
//!    [`geometry`] (which builds on `mesh` and `solve`);
//! 2. the modeling techniques: [`fibermesh`], [`deform`], [`silhouette`], [`oversketch`]
//!    (which bends with `deform` along `silhouette`s), [`feature`] (which solves with
//!    `deform`'s system) and [`optimize`];
//! 3. [`model`]: what a document holds, as plain data;
//! 4. [`io`]: glTF files in and out of the model;
//! 5. [`document`]: editing it, with ops, undo history and sessions.

pub mod animation;
pub mod camera;
pub mod curve;
pub mod deform;
pub mod document;
pub mod feature;
pub mod fibermesh;
pub mod geometry;
pub mod io;
pub mod mesh;
pub mod model;
pub mod optimize;
pub mod oversketch;
pub mod region_edit;
pub mod silhouette;
pub mod skeleton;
pub mod solve;
pub mod volumetric;
