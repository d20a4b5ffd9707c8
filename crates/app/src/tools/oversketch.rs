//! The over-sketch tool: redraw part of an outline and the model follows (SilSketch, SEED).
//!
//! It captures a stroke exactly as the draw tool does (it wraps one) and commits an
//! `oversketch` op instead. While the stroke is drawn it asks core which silhouette piece it
//! would replace, so the app can highlight it: green when the match is confident, orange
//! when core would refuse it.

use glam::DVec2;
use sketchmesh_core::document::{Document, Op};
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

/// The over-sketch tool's state: the stroke being drawn and the current match.
#[derive(Clone, Debug, Default)]
pub struct OversketchTool {
    stroke: DrawTool,
    handle: Option<HandlePreview>,
    samples_since_preview: usize,
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
            ToolOutput::Commit(Op::Oversketch(input))
        })
    }

    /// Drops the stroke in progress.
    pub fn cancel(&mut self) {
        *self = Self::default();
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
