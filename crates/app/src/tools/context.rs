//! What a tool is given (the view it acts in) and what it gives back.

use egui::Rect;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::Op;

/// What a tool needs to know about the view it acts in.
#[derive(Clone, Copy, Debug)]
pub struct ViewCtx {
    /// The camera the user sees through.
    pub camera: Camera,
    /// The 3D viewport's rectangle in screen points; stroke coordinates are relative to it.
    pub viewport: Rect,
}

/// The result of feeding an event to a tool.
#[derive(Clone, Debug, PartialEq)]
pub enum ToolOutput {
    /// Nothing for the document (the tool may have updated its preview).
    None,
    /// Apply this operation as one undoable step.
    Commit(Op),
    /// Apply this operation as one undoable step exactly as made, even with the Symmetry
    /// switch on: a mirror flip, which is no edit to mirror about the plane it flips across.
    CommitAsMade(Op),
    /// Apply these operations in order, one undoable step each.
    CommitAll(Vec<Op>),
    /// Begin this op as a gesture: its stroke (the pointer-down sample so far) is still
    /// being drawn, and the edit previews it.
    Begin(Op),
    /// The gesture's stroke reached this sample `[x, y, pressure]`.
    Extend([f64; 3]),
    /// The gesture ended with this sample: apply its op as one undoable step.
    End([f64; 3]),
    /// The gesture's op has new settings (a panel changed): preview them instead.
    Revise(Op),
    /// The gesture ended without a sample (a panel's Apply): apply its op as one undoable
    /// step.
    Finish,
    /// The gesture ended with these last settings (a drag's release): preview them, then
    /// apply the op as one undoable step.
    FinishWith(Op),
    /// Drop the gesture: nothing changes.
    Cancel,
    /// The gesture did nothing; tell the user why.
    Refused(String),
    /// Turn the view to look at `point` along `normal` (a plane to draw on, face on).
    Face {
        /// The point to look at.
        point: glam::DVec3,
        /// The direction to look along (either way round).
        normal: glam::DVec3,
    },
    /// Play the key-framed animation (`true`), or stop it (`false`).
    Play(bool),
    /// Load a backdrop image to trace over (`true`), or remove it (`false`).
    Backdrop(bool),
}
