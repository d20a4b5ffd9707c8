//! The deform tool (FiberMesh §3.2.2): grab a control curve and drag it. Pointer-down begins
//! a `pull` edit as a gesture, moves extend its drag path, and release ends it; the app steps
//! the edit every frame, so the core previews the drag (following the latest sample once
//! per frame, however many samples came) and then computes the committed op from the path.

mod icon;

use sketchmesh_core::document::{Document, Op, StrokeInput};

use crate::input::router::ToolEvent;
use crate::tools::context::{ToolOutput, ViewCtx};
use crate::tools::draw::point;
use crate::tools::hint::{Device, Hint, NO_CURVES, has_curves};
use crate::tools::tool::{Gestures, Group, Tool, ToolInfo};

/// The pull tool's name, icon, key and description.
static INFO: ToolInfo = ToolInfo {
    label: "Pull",
    icon: icon::draw,
    key: egui::Key::P,
    group: Group::Reshape,
    about: "Grab a control curve and drag it; the shape follows",
    gestures: Gestures {
        pen: "Press on a curve and drag it",
        finger: "Press on a curve and drag it",
        mouse: "Left-drag a curve",
    },
    when: Some("For a shape made here: drag one of its curves and the surface follows"),
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

    /// What to do: grab a curve; while dragging, let go to keep the shape.
    fn hint(&self, doc: &Document, device: Device) -> Hint {
        match (self.is_dragging, has_curves(doc)) {
            (true, _) => device.say("The shape follows the curve; let go to keep it"),
            (false, false) => device.say(NO_CURVES),
            (false, true) => device.say(
                "Drag a control curve (a blue or red line) {with}: the shape follows; {orbit}",
            ),
        }
    }

    /// Forgets the drag in progress (the app cancels its edit).
    fn cancel(&mut self) -> ToolOutput {
        self.is_dragging = false;
        ToolOutput::None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::Phase;
    use crate::tools::test_support::{line, pen, shape, stroke, view};

    #[test]
    fn a_drag_begins_a_pull_at_pointer_down_extends_it_and_ends_it_at_release() {
        let editor = shape();
        let mut tool = PullTool::default();
        let outputs = stroke(
            &mut tool,
            editor.document(),
            &line((250.0, 340.0), (200.0, 300.0), 5),
        );
        // Screen points less the view's corner (0, 40), at the pen's pressure.
        let ToolOutput::Begin(Op::Pull(input)) = &outputs[0] else {
            panic!("pointer-down begins a pull: {:?}", outputs[0]);
        };
        assert_eq!(input.stroke, vec![[250.0, 300.0, 0.5]]);
        assert_eq!(input.viewport, [800.0, 600.0]);
        assert_eq!(outputs[1], ToolOutput::Extend([240.0, 292.0, 0.5]));
        assert!(matches!(outputs[4], ToolOutput::Extend(_)));
        assert_eq!(outputs[5], ToolOutput::End([200.0, 260.0, 0.5]));
        // The drag is over: a stray move makes nothing.
        let moved = tool.on_event(
            &ToolEvent::Move(pen(Phase::Move, 10.0, 10.0)),
            &view(),
            editor.document(),
        );
        assert_eq!(moved, ToolOutput::None);
    }

    #[test]
    fn a_cancelled_drag_drops_the_pull_and_leaves_nothing_behind() {
        let editor = shape();
        let (doc, v) = (editor.document(), view());
        let mut tool = PullTool::default();
        tool.on_event(&ToolEvent::Begin(pen(Phase::Down, 250.0, 340.0)), &v, doc);
        assert_eq!(
            tool.on_event(&ToolEvent::Cancel, &v, doc),
            ToolOutput::Cancel
        );
        let up = tool.on_event(&ToolEvent::End(pen(Phase::Up, 200.0, 300.0)), &v, doc);
        assert_eq!(
            up,
            ToolOutput::None,
            "the release of a cancelled drag ends nothing"
        );
        // Cancelled from outside (a tool switch), the drag's moves extend nothing either.
        tool.on_event(&ToolEvent::Begin(pen(Phase::Down, 250.0, 340.0)), &v, doc);
        assert_eq!(Tool::cancel(&mut tool), ToolOutput::None);
        let moved = tool.on_event(&ToolEvent::Move(pen(Phase::Move, 240.0, 330.0)), &v, doc);
        assert_eq!(moved, ToolOutput::None);
    }
}
