//! The erase, type-change and rub tools (FiberMesh §3.2.3–3.2.4): a stroke along control
//! curves, committed on release as one op; the surface re-optimizes then, as in the thesis.

use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{CurveTypeInput, Document, Op, curve_type_toggle};

use super::context::{ToolOutput, ViewCtx};
use super::draw::DrawTool;
use super::tool::{Tool, ToolInfo};
use crate::input::router::ToolEvent;

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
    icon: "✖",
    key: egui::Key::E,
    about: "Drag along control curves to remove them",
};

static CURVE_TYPE: ToolInfo = ToolInfo {
    label: "Sharp",
    icon: "♦",
    key: egui::Key::T,
    about: "Drag along control curves to switch smooth (blue) and sharp (red)",
};

static RUB: ToolInfo = ToolInfo {
    label: "Rub",
    icon: "〰",
    key: egui::Key::U,
    about: "Rub back and forth near a control curve to smooth it",
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

    /// The stroke being drawn.
    fn preview(&self) -> Option<&[StrokePoint]> {
        self.draw.preview()
    }
}
