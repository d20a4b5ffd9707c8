//! Why a volumetric deformation could not be done.

use crate::deform::DeformError;
use crate::feature::FeatureError;
use crate::solve::SolveError;

/// Why a volumetric graph could not be built or a deformation solved; each says it in a
/// sentence for the user.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum VolumetricError {
    /// The mesh has a hole or no faces: it encloses no volume.
    #[error(
        "The volumetric deformation needs a closed surface, and this model has holes or is not one piece of surface."
    )]
    NotClosed,
    /// More vertices than [`MAX_VERTICES`](super::MAX_VERTICES).
    #[error(
        "The volumetric deformation handles models of up to 60,000 vertices; this one has {vertices}. Simplify it first (the Optimize tool evens triangles, not counts), or bend it with the Bend tool."
    )]
    TooLarge {
        /// The model's vertex count.
        vertices: usize,
    },
    /// The faces point inward.
    #[error(
        "The volumetric deformation needs a model whose faces point outward; this one is inside out."
    )]
    InsideOut,
    /// A sphere with a non-finite centre or a radius that is not positive.
    #[error("The {what} sphere {index} needs a finite centre and a positive radius.")]
    BadSphere {
        /// "handle" or "fixed".
        what: &'static str,
        /// Its index.
        index: usize,
    },
    /// A handle's matrix is not finite, not affine, singular or mirroring.
    #[error(
        "Handle {index}'s matrix must be a finite affine transform that neither flattens nor mirrors."
    )]
    BadMatrix {
        /// The handle's index.
        index: usize,
    },
    /// A handle's sphere holds no vertex.
    #[error("Handle {index}'s sphere holds no vertex of the model.")]
    EmptyHandle {
        /// The handle's index.
        index: usize,
    },
    /// A vertex lies in a handle's sphere and a fixed sphere.
    #[error("Handle {index}'s sphere overlaps a fixed sphere: a vertex cannot both move and stay.")]
    FixedOverlapsHandle {
        /// The handle's index.
        index: usize,
    },
    /// A vertex lies in two handles' spheres.
    #[error("Handle {index}'s sphere overlaps an earlier handle's: a vertex cannot follow both.")]
    HandlesOverlap {
        /// The later handle's index.
        index: usize,
    },
    /// A control curve stroke that could not be placed on the surface.
    #[error("{0}")]
    Curve(#[from] FeatureError),
    /// A control curve given by its vertices names one the model lacks, or two in a row that
    /// no edge joins; or it is given both ways, or neither.
    #[error(
        "A control curve must be given once, as a stroke along the surface or as a chain of the model's vertices joined by edges."
    )]
    BadPath,
    /// A coarse edit's knots are not increasing inside (0, 1), or it names a control point
    /// its spline lacks.
    #[error(
        "The curve's spline needs increasing knots strictly between 0 and 1, and a control point it has ({controls} with these knots)."
    )]
    BadSpline {
        /// How many control points the knots give.
        controls: usize,
    },
    /// A control curve of fewer than two vertices.
    #[error("The control curve is too short: draw it along the surface over a few triangles.")]
    CurveTooShort,
    /// The new curve was drawn on a plane seen edge-on.
    #[error("The editing plane is seen edge-on; turn the view or the plane, then draw again.")]
    EdgeOnPlane,
    /// α or β̃ is not a positive number.
    #[error("The volumetric deformation's weights must be positive numbers.")]
    BadParams,
    /// The surface editor (the comparison method) refused.
    #[error(transparent)]
    Deform(#[from] DeformError),
    /// The system could not be solved.
    #[error(transparent)]
    Solve(#[from] SolveError),
}
