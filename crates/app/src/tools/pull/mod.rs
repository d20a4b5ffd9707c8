//! The deform tool (FiberMesh §3.2.2): grab a control curve and drag it. Pointer-down begins
//! a `pull` edit as a gesture, moves extend its drag path, and release ends it; the app steps
//! the edit every frame, so the core previews the drag (following the latest sample once
//! per frame, however many samples came) and then computes the committed op from the path.

use sketchmesh_core::document::{Document, Op, StrokeInput};

use super::context::{ToolOutput, ViewCtx};
use super::draw::point;
use super::tool::{Tool, ToolInfo};
use crate::input::router::ToolEvent;

/// The pull tool's name, icon, key and description.
static INFO: ToolInfo = ToolInfo {
    label: "Pull",
    icon: "✋",
    key: egui::Key::P,
    about: "Grab a control curve and drag it; the shape follows",
};

/// The pull tool's state: whether a drag is in progress.
#[derive(Debug, Default)]
pub struct PullTool {
    is_dragging: bool,
}

impl PullTool {
    /// Feeds one event: down grabs the curve point under the pointer, moves drag it, up
    /// commits.
    fn drag(&mut self, event: &ToolEvent, view: &ViewCtx) -> ToolOutput {
        let sample = |s| {
            let p = point(s, view);
            [p.pos.x, p.pos.y, p.pressure]
        };
        match event {
            ToolEvent::Begin(s) => {
                self.is_dragging = true;
                let size = view.viewport.size();
                ToolOutput::Begin(Op::Pull(StrokeInput {
                    viewport: [size.x.into(), size.y.into()],
                    camera: view.camera,
                    stroke: vec![sample(s)],
                }))
            }
            ToolEvent::Move(s) if self.is_dragging => ToolOutput::Extend(sample(s)),
            ToolEvent::End(s) if self.is_dragging => {
                self.is_dragging = false;
                ToolOutput::End(sample(s))
            }
            ToolEvent::Cancel if self.is_dragging => {
                self.is_dragging = false;
                ToolOutput::Cancel
            }
            _ => ToolOutput::None,
        }
    }
}

impl Tool for PullTool {
    fn info(&self) -> &'static ToolInfo {
        &INFO
    }

    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, _doc: &Document) -> ToolOutput {
        self.drag(event, view)
    }

    /// Forgets the drag in progress (the app cancels its edit).
    fn cancel(&mut self) -> ToolOutput {
        self.is_dragging = false;
        ToolOutput::None
    }
}
