//! Sketchmesh core: all geometry and modeling, with no UI and no web.
//!
//! Everything here computes in `f64` (glam `DVec3`, faer `f64`); `f32` appears only at
//! the GPU and glTF boundaries. The app, the CLI and the tests drive it through
//! [`document::Editor`], which changes the [`document::Document`] only through
//! serializable, undoable operations.
//!
//! The modules form layers; each uses only those below it (ARCHITECTURE.md's table, which
//! `cargo xtask layers` checks):
//! 1. the ground floor: [`solve`], [`camera`], [`curve`] (screen strokes), [`mesh`] and
//!    [`unit`] (lengths in files), which use nothing of the crate, and [`geometry`] (which
//!    builds on `mesh` and `solve`);
//! 2. [`model`]: what a document holds, as plain data, on the ground floor's `mesh`;
//! 3. the modeling techniques, on the floors below: [`deform`], [`silhouette`],
//!    [`fibermesh`], [`optimize`], [`skeleton`], [`symmetry`], [`paint`] (vertex colours),
//!    [`print_check`] (what a printer would make of a model), [`feature`] (which solves
//!    with `deform`'s system), [`oversketch`] (which bends with `deform` along
//!    `silhouette`s and embeds a sketch as `feature` does), [`region_edit`] (with
//!    `feature`'s placement and `fibermesh`'s curve embedding), [`volumetric`] (with
//!    `deform` and `feature`) and [`animation`] (with `volumetric`'s similarities);
//! 4. [`io`]: glTF files in and out of the model (an export bakes an `animation`), STL
//!    and OBJ out;
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
pub mod paint;
pub mod print_check;
pub mod region_edit;
pub mod silhouette;
pub mod skeleton;
pub mod solve;
pub mod symmetry;
pub mod unit;
pub mod volumetric;
