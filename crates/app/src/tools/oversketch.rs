//! The over-sketch tool: redraw part of an outline and the model follows (SilSketch, SEED).
//!
//! It captures a stroke exactly as the draw tool does (it wraps one) and commits an
//! `oversketch` op instead. While the stroke is drawn it asks core which silhouette piece it
//! would replace, so the app can highlight it: green when the match is confident, orange
//! when core would refuse it.

use glam::DVec2;
use sketchmesh_core::document::{Document, Op, OversketchFit, OversketchInput};
use sketchmesh_core::oversketch::preview_handle;

use super::draw::DrawTool;
use super::{ToolEvent, ToolOutput, ViewCtx};

/// Samples between two previews: matching runs on whole silhouettes, so not on every sample.
const PREVIEW_EVERY: usize = 8;

/// The silhouette piece a stroke would replace, in viewport-relative points.
#[derive(Clone, Debug, PartialEq)]
pub struct HandlePreview {
    /// The piece, in order.
    pub points: Vec<DVec2>,
    /// Whether the match is confident enough to be applied.
    pub confident: bool,
}

/// The over-sketch tool's state: the stroke being drawn, the current match, and how closely
/// the outline is to follow (the user's setting).
#[derive(Clone, Debug, Default)]
pub struct OversketchTool {
    stroke: DrawTool,
    handle: Option<HandlePreview>,
    samples_since_preview: usize,
    fit: OversketchFit,
}

impl OversketchTool {
    /// Feeds one event; a finished stroke becomes an `oversketch` op.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        let finished = self.stroke.capture(event, view);
        match event {
            ToolEvent::Move(_) => {
                self.samples_since_preview += 1;
                if self.samples_since_preview >= PREVIEW_EVERY {
                    self.samples_since_preview = 0;
                    self.handle = self.preview_now(view, doc);
                }
            }
            ToolEvent::End(_) | ToolEvent::Cancel => {
                self.handle = None;
                self.samples_since_preview = 0;
            }
            ToolEvent::Begin(_) => {}
        }
        finished.map_or(ToolOutput::None, |input| {
            ToolOutput::Commit(Op::Oversketch(OversketchInput {
                viewport: input.viewport,
                camera: input.camera,
                stroke: input.stroke,
                fit: self.fit,
                handle: None,
            }))
        })
    }

    /// Drops the stroke in progress; the fit setting stays.
    pub fn cancel(&mut self) {
        *self = Self {
            fit: self.fit,
            ..Self::default()
        };
    }

    /// How closely over-sketched outlines follow their strokes, for the toolbar to change.
    pub fn fit_mut(&mut self) -> &mut OversketchFit {
        &mut self.fit
    }

    /// The stroke in progress, as the draw tool shows it.
    pub fn preview(&self) -> Option<&[sketchmesh_core::curve::StrokePoint]> {
        self.stroke.preview()
    }

    /// The silhouette piece the stroke would replace, if any.
    pub fn handle(&self) -> Option<&HandlePreview> {
        self.handle.as_ref()
    }

    /// Matches the stroke so far against the first model whose silhouettes it fits.
    fn preview_now(&self, view: &ViewCtx, doc: &Document) -> Option<HandlePreview> {
        let points: Vec<DVec2> = self.stroke.preview()?.iter().map(|p| p.pos).collect();
        let size = view.viewport.size();
        let viewport = DVec2::new(size.x.into(), size.y.into());
        doc.models.iter().find_map(|model| {
            preview_handle(&model.mesh, &view.camera, viewport, &points)
                .map(|(points, confident)| HandlePreview { points, confident })
        })
    }
}

#[cfg(test)]
mod tests {
    use egui::{Rect, pos2};
    use sketchmesh_core::camera::Camera;

    use super::*;
    use crate::input::{Phase, PointerKind, PointerSample};

    fn pen(phase: Phase, x: f32) -> PointerSample {
        PointerSample {
            id: 1,
            phase,
            pos_in_screen: pos2(x, 100.0),
            pressure: 0.5,
            kind: PointerKind::Pen,
            buttons: 1,
            time: 0.0,
        }
    }

    /// Draws a short stroke and returns what the tool commits.
    fn draw(tool: &mut OversketchTool) -> ToolOutput {
        let view = ViewCtx {
            camera: Camera::default(),
            viewport: Rect::from_min_max(pos2(0.0, 40.0), pos2(800.0, 640.0)),
        };
        let doc = Document::default();
        tool.on_event(&ToolEvent::Begin(pen(Phase::Down, 10.0)), &view, &doc);
        tool.on_event(&ToolEvent::Move(pen(Phase::Move, 60.0)), &view, &doc);
        tool.on_event(&ToolEvent::End(pen(Phase::Up, 110.0)), &view, &doc)
    }

    #[test]
    fn the_fit_setting_goes_into_the_op_and_outlives_a_cancel() {
        let mut tool = OversketchTool::default();
        let ToolOutput::Commit(Op::Oversketch(exact)) = draw(&mut tool) else {
            panic!("no oversketch op");
        };
        assert_eq!(exact.fit, OversketchFit::Exact);
        assert_eq!(exact.stroke.len(), 3);
        *tool.fit_mut() = OversketchFit::Soft;
        tool.cancel();
        let ToolOutput::Commit(Op::Oversketch(soft)) = draw(&mut tool) else {
            panic!("no oversketch op");
        };
        assert_eq!(soft.fit, OversketchFit::Soft);
        assert_eq!(soft.stroke, exact.stroke);
    }
}
