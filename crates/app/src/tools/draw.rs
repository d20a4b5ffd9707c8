//! The draw tool: one stroke in, one operation out.
//!
//! Two states, as tldraw's draw tool: `Idle` and `Drawing`. What the finished stroke means
//! (a new shape or ink) is decided in core by [`op_for_stroke`]. The stroke is kept in
//! viewport-relative screen points together with the camera it was drawn with, because
//! that is what a session stores and what replays identically anywhere.

use glam::DVec2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{Document, StrokeInput, op_for_stroke};

use super::context::{ToolOutput, ViewCtx};
use crate::input::router::ToolEvent;

/// The draw tool's state.
#[derive(Clone, Debug, Default)]
pub enum DrawTool {
    /// Waiting for a pointer to go down.
    #[default]
    Idle,
    /// A stroke is in progress.
    Drawing {
        /// Samples so far, relative to the viewport's top-left corner.
        points: Vec<StrokePoint>,
        /// The camera at the start of the stroke.
        camera: Camera,
        /// The viewport size in points.
        viewport: DVec2,
    },
}

impl DrawTool {
    /// Feeds one event; a finished stroke becomes a [`ToolOutput::Commit`] of what it means
    /// in the sketch tool ([`op_for_stroke`]).
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        match self.capture(event, view) {
            Some(input) => ToolOutput::Commit(op_for_stroke(doc, input)),
            None => ToolOutput::None,
        }
    }

    /// Feeds one event; returns the stroke when it is finished. Tools that give a stroke
    /// another meaning (over-sketch, erase, …) start from this.
    pub fn capture(&mut self, event: &ToolEvent, view: &ViewCtx) -> Option<StrokeInput> {
        match event {
            ToolEvent::Begin(s) => {
                if matches!(self, Self::Idle) {
                    let size = view.viewport.size();
                    *self = Self::Drawing {
                        points: vec![point(s, view)],
                        camera: view.camera,
                        viewport: DVec2::new(size.x.into(), size.y.into()),
                    };
                }
                None
            }
            ToolEvent::Move(s) => {
                if let Self::Drawing { points, .. } = self {
                    push_distinct(points, point(s, view));
                }
                None
            }
            ToolEvent::End(s) => {
                let Self::Drawing {
                    mut points,
                    camera,
                    viewport,
                } = std::mem::take(self)
                else {
                    return None;
                };
                push_distinct(&mut points, point(s, view));
                Some(StrokeInput {
                    viewport: viewport.to_array(),
                    camera,
                    stroke: points
                        .iter()
                        .map(|p| [p.pos.x, p.pos.y, p.pressure])
                        .collect(),
                })
            }
            ToolEvent::Cancel => {
                *self = Self::Idle;
                None
            }
        }
    }

    /// The stroke being drawn, in viewport-relative points, for live display.
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        match self {
            Self::Drawing { points, .. } => Some(points),
            Self::Idle => None,
        }
    }
}

/// Appends `p` unless it repeats the last point (pointer events often do).
fn push_distinct(points: &mut Vec<StrokePoint>, p: StrokePoint) {
    if points.last().is_none_or(|last| last.pos != p.pos) {
        points.push(p);
    }
}

/// A pointer sample in viewport-relative points, with its pressure.
pub fn point(s: &crate::input::PointerSample, view: &ViewCtx) -> StrokePoint {
    let local = s.pos_in_screen - view.viewport.min;
    StrokePoint {
        pos: DVec2::new(local.x.into(), local.y.into()),
        pressure: s.pressure.into(),
    }
}

/// A gesture whose samples all lie within this many points of its first one is a tap.
const TAP_RADIUS: f64 = 10.0;

/// Whether a finished gesture stayed within [`TAP_RADIUS`] of where it began.
pub(super) fn is_tap(input: &StrokeInput) -> bool {
    let Some(&[x0, y0, _]) = input.stroke.first() else {
        return false;
    };
    let start = DVec2::new(x0, y0);
    input
        .stroke
        .iter()
        .all(|&[x, y, _]| DVec2::new(x, y).distance(start) <= TAP_RADIUS)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::input::{Phase, PointerKind, PointerSample};
    use egui::{Rect, pos2};
    use sketchmesh_core::document::Op;

    fn pen(phase: Phase, x: f32, y: f32, pressure: f32) -> PointerSample {
        PointerSample {
            id: 1,
            phase,
            pos_in_screen: pos2(x, y),
            pressure,
            kind: PointerKind::Pen,
            buttons: 1,
            contact: 0.0,
            time: 0.0,
        }
    }

    fn view() -> ViewCtx {
        ViewCtx {
            camera: Camera::default(),
            viewport: Rect::from_min_max(pos2(0.0, 40.0), pos2(800.0, 640.0)),
        }
    }

    #[test]
    fn stroke_commits_viewport_relative_points_with_pressure() {
        let mut tool = DrawTool::default();
        let v = view();
        let doc = Document::default();
        assert_eq!(
            tool.on_event(
                &ToolEvent::Begin(pen(Phase::Down, 10.0, 50.0, 0.2)),
                &v,
                &doc
            ),
            ToolOutput::None
        );
        tool.on_event(
            &ToolEvent::Move(pen(Phase::Move, 20.0, 60.0, 0.6)),
            &v,
            &doc,
        );
        assert_eq!(tool.preview().map(<[_]>::len), Some(2));
        let out = tool.on_event(&ToolEvent::End(pen(Phase::Up, 30.0, 70.0, 0.9)), &v, &doc);
        let ToolOutput::Commit(Op::Stroke(input)) = out else {
            panic!("expected a stroke, got {out:?}");
        };
        assert_eq!(input.viewport, [800.0, 600.0]);
        assert_eq!(input.stroke[0], [10.0, 10.0, 0.2f32 as f64]);
        assert_eq!(input.stroke.len(), 3);
        assert!(matches!(tool, DrawTool::Idle));
    }

    #[test]
    fn cancel_leaves_no_trace() {
        let mut tool = DrawTool::default();
        let v = view();
        let doc = Document::default();
        tool.on_event(
            &ToolEvent::Begin(pen(Phase::Down, 10.0, 50.0, 0.5)),
            &v,
            &doc,
        );
        assert_eq!(
            tool.on_event(&ToolEvent::Cancel, &v, &doc),
            ToolOutput::None
        );
        assert!(tool.preview().is_none());
        // A stray end after a cancel commits nothing.
        assert_eq!(
            tool.on_event(&ToolEvent::End(pen(Phase::Up, 1.0, 1.0, 0.5)), &v, &doc),
            ToolOutput::None
        );
    }
}
