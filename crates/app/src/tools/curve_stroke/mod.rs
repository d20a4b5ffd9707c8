//! The erase, type-change and rub tools (FiberMesh §3.2.3–3.2.4): a stroke along control
//! curves, committed on release as one op; the surface re-optimizes then, as in the thesis.

mod icon;

use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{CurveTypeInput, Document, Op, curve_type_toggle};

use crate::input::router::ToolEvent;
use crate::tools::context::{ToolOutput, ViewCtx};
use crate::tools::draw::DrawTool;
use crate::tools::hint::{Device, Hint, NO_CURVES, has_curves};
use crate::tools::tool::{Gestures, Group, Tool, ToolInfo};

/// Which of the three tools a stroke along curves is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Removes the curves.
    Erase,
    /// Switches them between smooth and sharp.
    CurveType,
    /// Smooths them.
    Rub,
}

static ERASE: ToolInfo = ToolInfo {
    label: "Erase",
    icon: icon::erase,
    key: egui::Key::E,
    group: Group::Curves,
    about: "Drag along control curves to remove them",
    gestures: Gestures {
        pen: "Stroke along a curve (the pen's eraser end erases in any tool)",
        finger: "Drag along a curve",
        mouse: "Left-drag along a curve",
    },
    when: None,
};

static CURVE_TYPE: ToolInfo = ToolInfo {
    label: "Sharp",
    icon: icon::sharp,
    key: egui::Key::T,
    group: Group::Curves,
    about: "Drag along control curves to switch smooth (blue) and sharp (red)",
    gestures: Gestures {
        pen: "Stroke along a curve",
        finger: "Drag along a curve",
        mouse: "Left-drag along a curve",
    },
    when: None,
};

static RUB: ToolInfo = ToolInfo {
    label: "Rub",
    icon: icon::rub,
    key: egui::Key::U,
    group: Group::Curves,
    about: "Rub back and forth near a control curve to smooth it",
    gestures: Gestures {
        pen: "Scribble back and forth over a curve",
        finger: "Rub back and forth over a curve",
        mouse: "Left-drag back and forth over a curve",
    },
    when: None,
};

/// The state of one of the three stroke-along-curves tools: the stroke being drawn.
#[derive(Clone, Debug)]
pub struct CurveStrokeTool {
    kind: Kind,
    draw: DrawTool,
}

impl CurveStrokeTool {
    /// The `kind` tool, with no stroke drawn.
    pub fn new(kind: Kind) -> Self {
        CurveStrokeTool {
            kind,
            draw: DrawTool::Idle,
        }
    }
}

impl Tool for CurveStrokeTool {
    fn info(&self) -> &'static ToolInfo {
        match self.kind {
            Kind::Erase => &ERASE,
            Kind::CurveType => &CURVE_TYPE,
            Kind::Rub => &RUB,
        }
    }

    /// Feeds one event; a finished stroke becomes the kind's op. The type-change tool
    /// toggles: sharp if any curve under the stroke is smooth, else smooth.
    fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        let op = match self.kind {
            Kind::Erase => Op::Erase(input),
            Kind::Rub => Op::Rub(input),
            Kind::CurveType => {
                let Some(sharp) = curve_type_toggle(doc, &input) else {
                    return ToolOutput::Refused(
                        "No control curve under that stroke: drag along a blue or red curve."
                            .to_owned(),
                    );
                };
                Op::SetCurveType(CurveTypeInput {
                    viewport: input.viewport,
                    camera: input.camera,
                    stroke: input.stroke,
                    sharp,
                })
            }
        };
        ToolOutput::Commit(op)
    }

    /// Drops the stroke in progress.
    fn cancel(&mut self) -> ToolOutput {
        self.draw = DrawTool::Idle;
        ToolOutput::None
    }

    /// What a stroke along curves does with this tool, and when it happens.
    fn hint(&self, doc: &Document, device: Device) -> Hint {
        if !has_curves(doc) {
            return device.say(NO_CURVES);
        }
        let drawing = self.draw.preview().is_some();
        device.say(match (self.kind, drawing) {
            (Kind::Erase, false) => {
                "Drag {with} along a control curve (a blue or red line) to remove it; {orbit}"
            }
            (Kind::CurveType, false) => {
                "Drag {with} along a control curve to switch it: blue is smooth, red is sharp"
            }
            (Kind::Rub, false) => "Rub back and forth {with} along a control curve to smooth it",
            (Kind::Erase, true) => "Let go to remove the curves under the stroke",
            (Kind::CurveType, true) => "Let go to switch the curves under the stroke",
            (Kind::Rub, true) => "Keep rubbing, then let go: the curve smooths",
        })
    }

    /// The stroke being drawn.
    fn preview(&self) -> Option<&[StrokePoint]> {
        self.draw.preview()
    }
}

#[cfg(test)]
mod tests {
    use sketchmesh_core::document::Editor;

    use super::*;
    use crate::input::Phase;
    use crate::tools::test_support::{line, pen, shape, stroke, view};

    /// The stroke's points as a tool gives them: less the view's corner (0, 40).
    fn in_view(points: &[(f32, f32)]) -> Vec<[f64; 3]> {
        (points.iter())
            .map(|&(x, y)| [f64::from(x), f64::from(y) - 40.0, 0.5])
            .collect()
    }

    #[test]
    fn erase_and_rub_commit_the_stroke_drawn_on_release() {
        let editor = shape();
        let points = line((300.0, 200.0), (500.0, 220.0), 8);
        for (kind, name) in [(Kind::Erase, "erase"), (Kind::Rub, "rub")] {
            let mut tool = CurveStrokeTool::new(kind);
            let outputs = stroke(&mut tool, editor.document(), &points);
            assert!(outputs[..8].iter().all(|o| *o == ToolOutput::None));
            let ToolOutput::Commit(op) = &outputs[8] else {
                panic!("{name}: the release commits: {:?}", outputs[8]);
            };
            assert_eq!(op.name(), name);
            let input = match op {
                Op::Erase(input) | Op::Rub(input) => input,
                other => panic!("{name}: {other:?}"),
            };
            assert_eq!(input.stroke, in_view(&points));
        }
    }

    #[test]
    fn the_type_tool_makes_a_smooth_curve_sharp_and_refuses_a_stroke_off_every_curve() {
        let editor = shape();
        // Along the shape's outline, a circle of 150 px around (400, 340).
        let along: Vec<(f32, f32)> = (0..=12)
            .map(|k| {
                let a = -0.6 + 1.2 * k as f32 / 12.0;
                (400.0 + 150.0 * a.cos(), 340.0 + 150.0 * a.sin())
            })
            .collect();
        let mut tool = CurveStrokeTool::new(Kind::CurveType);
        let released = stroke(&mut tool, editor.document(), &along).pop();
        let Some(ToolOutput::Commit(Op::SetCurveType(input))) = released else {
            panic!("a stroke along the outline sets its type: {released:?}");
        };
        assert!(input.sharp, "the outline was smooth: it becomes sharp");
        assert_eq!(input.stroke, in_view(&along));
        let empty = Editor::new();
        let released = stroke(&mut tool, empty.document(), &along).pop();
        assert!(
            matches!(released, Some(ToolOutput::Refused(_))),
            "no curve under the stroke: {released:?}"
        );
    }

    #[test]
    fn a_cancelled_stroke_commits_nothing() {
        let editor = shape();
        let (doc, v) = (editor.document(), view());
        let mut tool = CurveStrokeTool::new(Kind::Erase);
        tool.on_event(&ToolEvent::Begin(pen(Phase::Down, 300.0, 200.0)), &v, doc);
        tool.on_event(&ToolEvent::Move(pen(Phase::Move, 400.0, 200.0)), &v, doc);
        assert_eq!(tool.preview().map(<[_]>::len), Some(2));
        assert_eq!(Tool::cancel(&mut tool), ToolOutput::None);
        assert!(tool.preview().is_none());
        let up = tool.on_event(&ToolEvent::End(pen(Phase::Up, 500.0, 200.0)), &v, doc);
        assert_eq!(up, ToolOutput::None);
    }
}
