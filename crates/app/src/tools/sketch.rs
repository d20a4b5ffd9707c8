//! The sketch tool (FiberMesh §3.2.1): what a stroke means is read from the stroke in core
//! ([`op_for_stroke`]); a closed curve on a shape and a cross-section wait for a confirming
//! tap, as in the thesis, and stay ink if something else comes instead.

use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{Document, Op, StrokeInput, ink_instead, needs_tap, op_for_stroke};

use super::context::{ToolOutput, ViewCtx};
use super::draw::{DrawTool, is_tap};
use crate::input::router::ToolEvent;

/// A stroke that waits for its confirming tap.
#[derive(Clone, Debug)]
struct Waiting {
    op: Op,
    points: Vec<StrokePoint>,
}

/// The sketch tool's state.
#[derive(Clone, Debug, Default)]
pub struct SketchTool {
    draw: DrawTool,
    waiting: Option<Waiting>,
}

impl SketchTool {
    /// Feeds one event; see the module docs for what a finished stroke commits.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let Some(input) = self.draw.capture(event, view) else {
            return ToolOutput::None;
        };
        let held = self.waiting.take().map(|w| w.op);
        if is_tap(&input) {
            return held.map_or(ToolOutput::None, ToolOutput::Commit);
        }
        let op = op_for_stroke(doc, input);
        let mut ops: Vec<Op> = held.map(ink_instead).into_iter().collect();
        if needs_tap(&op) {
            self.waiting = Some(Waiting {
                points: stroke_points(&op),
                op,
            });
        } else {
            ops.push(op);
        }
        match ops.len() {
            0 => ToolOutput::None,
            1 => ToolOutput::Commit(ops.remove(0)),
            _ => ToolOutput::CommitAll(ops),
        }
    }

    /// Drops a stroke in progress; a stroke waiting for a tap becomes ink.
    pub fn cancel(&mut self) -> ToolOutput {
        self.draw = DrawTool::Idle;
        self.waiting
            .take()
            .map_or(ToolOutput::None, |w| ToolOutput::Commit(ink_instead(w.op)))
    }

    /// The stroke being drawn.
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        self.draw.preview()
    }

    /// The stroke waiting for a tap, and what the tap will do.
    pub fn waiting(&self) -> Option<(&[StrokePoint], &'static str)> {
        let waiting = self.waiting.as_ref()?;
        let what = match &waiting.op {
            Op::AddCurve(input) if input.cross_section => "Tap to add a cross-section curve",
            _ => "Tap to add a closed curve",
        };
        Some((&waiting.points, what))
    }
}

/// The samples of an `add_curve` op, for showing it while it waits.
fn stroke_points(op: &Op) -> Vec<StrokePoint> {
    match op {
        Op::AddCurve(input) => StrokeInput::of_add_curve(input).points(),
        _ => Vec::new(),
    }
}
