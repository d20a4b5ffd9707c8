//! The erase, type-change and rub tools (FiberMesh §3.2.3–3.2.4): a stroke along control
//! curves, committed on release as one op; the surface re-optimizes then, as in the thesis.

use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{CurveTypeInput, Document, Op, curve_type_toggle};

use super::context::{ToolOutput, ViewCtx};
use super::draw::DrawTool;
use super::mode::Mode;
use crate::input::router::ToolEvent;

/// The state of the three stroke-along-curves tools: the stroke being drawn.
#[derive(Clone, Debug, Default)]
pub struct CurveStrokeTool {
    draw: DrawTool,
}

impl CurveStrokeTool {
    /// Feeds one event; a finished stroke becomes the `mode`'s op. The type-change tool
    /// toggles: sharp if any curve under the stroke is smooth, else smooth.
    pub fn on_event(
        &mut self,
        mode: Mode,
        event: &ToolEvent,
        view: &ViewCtx,
        doc: &Document,
    ) -> ToolOutput {
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        let op = match mode {
            Mode::Erase => Op::Erase(input),
            Mode::Rub => Op::Rub(input),
            _ => {
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
    pub fn cancel(&mut self) {
        self.draw = DrawTool::Idle;
    }

    /// The stroke being drawn.
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        self.draw.preview()
    }
}
