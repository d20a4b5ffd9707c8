//! Large deformations that keep volume: Zhou et al.'s volumetric graph Laplacian (SIGGRAPH
//! 2005; `shared/digests/001-vgl-digest.md`).
//!
//! A surface Laplacian editor keeps the surface's detail but not its volume: bent by half a
//! turn, a limb's cross-sections flatten and its inner side folds. The paper adds the
//! volume to the energy without a tetrahedral mesh: a graph of points inside the model (an
//! inner shell and a BCC lattice) and just outside it (an outer shell), whose Laplacian
//! coordinates are kept too. The inner points resist collapse, the outer ones local
//! self-intersection.
//!
//! - `shell`, `lattice`, `graph`: the graph (§3.2), built once per model revision;
//! - `weights`: its Laplacian weights, one small QP per point (§3.3);
//! - `similarity`, `spread`: rotations and scales at the handles, propagated by geodesic
//!   strength fields and inverse-distance weights (§3.3), so the system stays linear;
//! - `edit`: the energy (Eq. 3, its volume term kept edge by edge: see there why),
//!   factored once per handle set, back-substituted per frame;
//! - `sphere_handles`: scripted deformations (the `deform` op), volumetric or, for
//!   comparison, with the surface editor;
//! - `coarse_curve`: a planar curve edited by its coarse B-spline, its detail kept (§4.1);
//! - `control_curve`: the paper's interaction: a curve picked on the surface, redrawn in
//!   its editing plane, drives the deformation through WIRE transforms (§3.3, §4.1).

mod coarse_curve;
mod control_curve;
mod edit;
mod error;
mod graph;
mod lattice;
mod shell;
mod similarity;
mod sphere_handles;
mod spread;
mod weights;

pub use control_curve::{
    COARSE_CONTROLS, CoarsePlaneCurve, CurveEdit, Plane, curve_targets, editing_plane, pick_curve,
    wire_transforms,
};
pub use edit::{Constraints, GraphTerm, VolumetricEdit, VolumetricParams};
pub use error::VolumetricError;
pub use graph::{MAX_VERTICES, VolumetricGraph};
pub use similarity::Similarity;
pub use sphere_handles::{Method, Sphere, SphereHandle, deform_with_spheres};
pub use spread::{Falloff, spread};
