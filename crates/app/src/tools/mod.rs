//! Tools: small state machines that turn [`ToolEvent`]s into document operations.
//!
//! A tool never touches a mesh; it emits an [`Op`] for the editor, so one gesture is one
//! undo step and every edit replays from the session.

pub mod draw;
pub mod oversketch;

use egui::Rect;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::Op;

pub use crate::input::router::ToolEvent;

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
}
