//! The document (models and sketches) and the only way to change it: [`Op`]s applied by an
//! [`Editor`], which keeps undo history and a replayable [`Session`] log. Every op is applied
//! as an [`Edit`]: begun, stepped (in one go, or across the app's frames) and finished; see
//! `edit.rs` for the protocol.
//!
//! Every op builds the new state first and swaps it in only on success, so a refused op leaves
//! the document, the history and the log untouched. Models and sketches sit behind `Arc`, so an
//! undo snapshot is a copy of a few pointers and restores the exact previous state.
//!
//! The data itself ([`Document`], [`Model`], [`ControlCurve`], ...) is defined in
//! [`crate::model`], below both this module and [`crate::io`], and re-exported here as part
//! of the editor's interface. This is the top layer: it uses the techniques (FiberMesh,
//! over-sketch) and `io` (the `import` op), and nothing below uses it.

mod arrange;
mod create;
mod curve_edit;
mod edit;
mod editor;
mod error;
mod feature;
mod gizmo;
mod history;
mod intent;
mod keyframes;
mod next;
mod op;
mod optimize;
mod outcome;
mod oversketch;
mod paint;
mod region_edit;
mod replay;
mod session;
mod session_error;
mod skeleton;
mod symmetry;
mod volumetric;

pub use crate::model::{
    AlphaMode, Appearance, AsImported, ControlCurve, CurveHandle, CurveKind, Document,
    HandleTarget, Image, Keyframe, Material, Model, PointCloud, SketchCurve, Stats, Texture,
    positions_hash,
};
pub use arrange::overlapping_model;
pub use create::{CREATE_VERTICES, STEPPED_MAX_VERTICES};
pub use curve_edit::{CURVE_PICK_RADIUS_PX, curve_type_toggle};
pub use edit::{Edit, Progress};
pub use editor::Editor;
pub use error::CommandError;
pub use gizmo::{Gizmo, GizmoHandle, HANDLE_REACH_PX};
pub use intent::{
    CLOSE_TOLERANCE_PX, cut_instead, extrude_from, ink_instead, is_cross_section, model_in_lasso,
    model_under, needs_tap, op_for_stroke, starts_on_model, surface_at, tunnel_from,
};
pub use keyframes::KeyframeInput;
pub use op::{
    AddCurveInput, AreaInput, BrushInput, CreateInput, CurveHandleInput, CurveTypeInput,
    DeleteHandleInput, DuplicateInput, FileInput, FillInput, HandleEditInput, HandleInput,
    ImportInput, LinkHandlesInput, MaterialInput, MergeInput, MirroredOp, ModelInput, Op,
    OptimizeInput, OversketchFit, OversketchInput, PaintInput, PlaneInput, ProfileInput,
    RegionEditInput, SketchFeatureInput, StrokeInput, StrokePairInput, SymmetrizeInput,
    TransformInput,
};
pub use outcome::{import_files, model_op};
pub use oversketch::OutlinePiece;
pub use region_edit::{RegionDrag, dragged_region};
pub use replay::Replay;
pub use session::{SESSION_FORMAT, SESSION_VERSION, Session, SessionPiece};
pub use session_error::SessionError;
pub use volumetric::{CoarseInput, CurveDeformInput, DeformHandleInput, DeformInput, DeformMethod};
