//! The deform tool (FiberMesh §3.2.2): grab a control curve and drag it. While the pointer
//! is down a core [`PullSession`] previews the result every frame; release commits the
//! `pull` op, which the editor recomputes from the drag path.
//!
//! Pointer samples come several per frame (coalesced events); the preview follows only the
//! latest one, once per frame ([`PullTool::tick`]), so its cost does not grow with the
//! pointer's sample rate.

use sketchmesh_core::document::{Document, PullSession, StrokeInput};

use super::context::{ToolOutput, ViewCtx};
use super::draw::point;
use crate::input::router::ToolEvent;

/// The pull tool's state: the session of the drag in progress.
#[derive(Debug, Default)]
pub struct PullTool {
    session: Option<PullSession>,
    /// The latest sample not yet followed.
    latest: Option<[f64; 3]>,
}

impl PullTool {
    /// Feeds one event: down grabs the curve point under the pointer, moves drag it, up
    /// commits.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        match event {
            ToolEvent::Begin(s) => {
                let p = point(s, view);
                let size = view.viewport.size();
                let input = StrokeInput {
                    viewport: [size.x.into(), size.y.into()],
                    camera: view.camera,
                    stroke: vec![[p.pos.x, p.pos.y, p.pressure]],
                };
                match PullSession::start(doc, input) {
                    Ok(session) => {
                        self.session = Some(session);
                        ToolOutput::None
                    }
                    Err(e) => ToolOutput::Refused(e.to_string()),
                }
            }
            ToolEvent::Move(s) => {
                let p = point(s, view);
                self.latest = Some([p.pos.x, p.pos.y, p.pressure]);
                ToolOutput::None
            }
            ToolEvent::End(s) => {
                let p = point(s, view);
                self.latest = Some([p.pos.x, p.pos.y, p.pressure]);
                let moved = self.tick();
                match self.session.take() {
                    Some(session) => ToolOutput::Commit(session.finish()),
                    None => moved,
                }
            }
            ToolEvent::Cancel => {
                self.cancel();
                ToolOutput::None
            }
        }
    }

    /// Drops the drag in progress: the model stays as it was.
    pub fn cancel(&mut self) {
        self.session = None;
        self.latest = None;
    }

    /// The drag in progress.
    pub fn session(&self) -> Option<&PullSession> {
        self.session.as_ref()
    }

    /// Follows the latest pointer sample, if it moved since the last frame.
    pub fn tick(&mut self) -> ToolOutput {
        let (Some(session), Some(sample)) = (self.session.as_mut(), self.latest.take()) else {
            return ToolOutput::None;
        };
        match session.drag(sample) {
            Ok(()) => ToolOutput::None,
            Err(e) => {
                self.session = None;
                ToolOutput::Refused(e.to_string())
            }
        }
    }
}
