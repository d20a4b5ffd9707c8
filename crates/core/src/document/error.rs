//! Why an op was refused: one error for every op, each message a sentence for the user.

use crate::curve::StrokeError;
use crate::feature::FeatureError;
use crate::fibermesh::CreateError;
use crate::fibermesh::add_curve::AddCurveError;
use crate::fibermesh::curve_pull::PullError;
use crate::fibermesh::cut::CutError;
use crate::fibermesh::extrude::ExtrudeError;
use crate::fibermesh::merge::MergeError;
use crate::fibermesh::tunnel::TunnelError;
use crate::io::GltfError;
use crate::mesh::remesh::RemeshError;
use crate::optimize::OptimizeError;
use crate::oversketch::OversketchError;
use crate::region_edit::RegionError;
use crate::skeleton::SkeletonError;
use crate::solve::SolveError;
use crate::symmetry::SymmetryError;
use crate::volumetric::VolumetricError;

/// Why an op was refused. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CommandError {
    /// The stroke has too few points or is too short.
    #[error("That stroke is too short to use; draw a longer line.")]
    StrokeTooShort,
    /// The stroke contains NaN or infinite numbers.
    #[error("That stroke has coordinates that are not numbers; draw it again.")]
    StrokeNotFinite,
    /// The camera or viewport sent with the op cannot project anything.
    #[error("The camera or viewport of that op is not usable (degenerate view or zero size).")]
    BadView,
    /// A stroke point's ray misses the drawing plane.
    #[error("That stroke could not be placed in the scene; look at the scene and draw again.")]
    StrokeOffPlane,
    /// A paint stroke that reached no model.
    #[error("The brush touched no model; paint over a model.")]
    NothingPainted,
    /// Undo with an empty undo history.
    #[error("Nothing to undo.")]
    NothingToUndo,
    /// Redo with an empty redo history.
    #[error("Nothing to redo.")]
    NothingToRedo,
    /// A closed stroke did not become a shape.
    #[error("{0}")]
    Create(#[from] CreateError),
    /// A `create` op asks for a resolution outside
    /// [`CREATE_VERTICES`](super::CREATE_VERTICES).
    #[error("A new shape takes 500 to 100,000 vertices, not {0}.")]
    CreateVertices(usize),
    /// An import op names a file whose contents were not loaded.
    #[error("The contents of {0} are not in the session; replay it next to that file.")]
    FileNotLoaded(String),
    /// An import op has no files.
    #[error("The import has no file.")]
    NoFile,
    /// A file could not be imported.
    #[error("{0}")]
    Import(#[from] GltfError),
    /// Work the page ran in its worker was refused there (the sentence is that refusal), or
    /// its result could not be read back.
    #[error("{0}")]
    Elsewhere(String),
    /// An op was handed to [`model_op`](super::model_op) that does not make one model
    /// (a programming error of the caller: see [`Op::makes_one_model`](super::Op::makes_one_model)).
    #[error("The {0} op cannot be computed from the models alone.")]
    NotOneModel(&'static str),
    /// An over-sketch was refused.
    #[error("{0}")]
    Oversketch(#[from] OversketchError),
    /// A curve tool started where no visible control curve is.
    #[error("No control curve there: start on a curve (the blue and red lines on a shape).")]
    NoCurveHere,
    /// A curve was drawn where no model with control curves is.
    #[error("Draw the curve on a shape made here; imported models are edited with over-sketch.")]
    NotOnModel,
    /// An erase would leave a shape with no curve to hold it.
    #[error("That would erase the last curve holding the shape; a shape needs at least one.")]
    LastCurve,
    /// A curve could not be pulled.
    #[error("{0}")]
    Pull(#[from] PullError),
    /// A curve could not be put on the surface.
    #[error("{0}")]
    AddCurve(#[from] AddCurveError),
    /// A transform's matrix is not finite, not affine, or flattens the model.
    #[error("That transform cannot be applied: it must be finite and must not flatten the model.")]
    BadTransform,
    /// Two loops did not make a tunnel.
    #[error("{0}")]
    Tunnel(#[from] TunnelError),
    /// A base loop and a silhouette did not grow a limb.
    #[error("{0}")]
    Extrude(#[from] ExtrudeError),
    /// Two models were not merged.
    #[error("{0}")]
    Merge(#[from] MergeError),
    /// A stroke did not cut a model.
    #[error("{0}")]
    Cut(#[from] CutError),
    /// The surface could not be remeshed after a curve edit.
    #[error("{0}")]
    Remesh(#[from] RemeshError),
    /// The surface could not be re-optimized through its curves.
    #[error(
        "The surface could not follow its curves after that change; undo it and try a smaller one."
    )]
    Surface(SolveError),
    /// An op names a model the document does not have.
    #[error("There is no model {0} in the document.")]
    NoSuchModel(usize),
    /// A feature sketch was refused.
    #[error("{0}")]
    Feature(#[from] FeatureError),
    /// A region edit was refused.
    #[error("{0}")]
    Region(#[from] RegionError),
    /// A curve handle or its edit was refused.
    #[error("{0}")]
    Skeleton(#[from] SkeletonError),
    /// An op names a curve handle the document does not have.
    #[error("There is no curve handle {0}.")]
    NoSuchHandle(u32),
    /// A handle edit that neither moves, twists nor scales.
    #[error("A handle edit needs a move, a twist or a scale.")]
    NothingToEdit,
    /// A link from a handle to itself.
    #[error("Link a handle to another one, not to itself.")]
    LinkToItself,
    /// A link between handles on different objects.
    #[error("Only handles on the same object can be linked.")]
    LinkAcrossObjects,
    /// A volumetric (or scripted surface) deformation was refused.
    #[error("{0}")]
    Volumetric(#[from] VolumetricError),
    /// A key frame time that is negative or not a number.
    #[error("A key frame's time must be a number of seconds, zero or more.")]
    BadKeyTime,
    /// A key frame with no model to key.
    #[error("There is nothing to key: the document has no model.")]
    NothingToKey,
    /// A pose asked of an animation that has no key frames.
    #[error("No model has key frames to take a pose from; key a pose first.")]
    NoKeyframes,
    /// No key frame at that time.
    #[error("There is no key frame at {0} s.")]
    NoKeyAt(f64),
    /// A mesh optimization was refused.
    #[error("The mesh could not be optimized: {0}.")]
    Optimize(#[from] OptimizeError),
    /// An op made with symmetry on changed a model that is neither symmetric about the
    /// plane nor one of a pair of mirror twins.
    #[error(
        "This model is not mirror-symmetric about the symmetry plane, so the edit cannot act on both sides: symmetrize it first (Arrange, Symmetrize) or turn Symmetry off."
    )]
    NotSymmetric,
    /// A model could not be made symmetric.
    #[error("{0}")]
    Symmetry(#[from] SymmetryError),
}

impl From<StrokeError> for CommandError {
    fn from(error: StrokeError) -> Self {
        match error {
            StrokeError::TooFewPoints { .. } | StrokeError::TooShort { .. } => {
                CommandError::StrokeTooShort
            }
            StrokeError::NonFinite { .. } => CommandError::StrokeNotFinite,
        }
    }
}
