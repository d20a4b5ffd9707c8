//! Tools: small state machines that turn [`ToolEvent`]s into document operations.
//!
//! A tool never touches a mesh; it emits an [`Op`](sketchmesh_core::document::Op) for the
//! editor, so one gesture is one undo step and every edit replays from the session. A tool
//! whose op previews while it is drawn (pull, over-sketch) begins it as a gesture
//! ([`ToolOutput::Begin`]) and feeds it samples; the app runs it as it runs every edit.
//! Every tool implements [`Tool`] in a folder of its own; [`registry`] declares them and
//! lists them, one line each, and [`ToolSet`] holds one of each and routes events to the one
//! in use.

mod context;
pub mod draw;
pub mod icon;
pub mod registry;
#[cfg(test)]
mod test_support;
pub mod tool;

use egui::Key;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{Document, Edit, Op};

pub use crate::input::router::{Hands, ToolEvent};
pub use context::{ToolOutput, ViewCtx};
pub use icon::Icon;
pub use registry::Mode;
pub use tool::{Gestures, Group, Mark, Scene, Tool, ToolInfo};

/// Every tool, one per [`Mode`], and which one gets the events.
#[derive(Debug)]
pub struct ToolSet {
    mode: Mode,
    /// One tool per mode, in [`Mode::ALL`]'s order.
    tools: Vec<Box<dyn Tool>>,
}

impl Default for ToolSet {
    fn default() -> Self {
        ToolSet {
            mode: Mode::default(),
            tools: Mode::ALL.into_iter().map(Mode::tool).collect(),
        }
    }
}

impl ToolSet {
    /// The active mode.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// The tool in use.
    pub fn active(&self) -> &dyn Tool {
        self.tool(self.mode)
    }

    fn active_mut(&mut self) -> &mut dyn Tool {
        let index = self.mode as usize;
        self.tools[index].as_mut()
    }

    /// The tool of `mode`.
    pub fn tool(&self, mode: Mode) -> &dyn Tool {
        self.tools[mode as usize].as_ref()
    }

    /// Switches tools; a gesture in progress is dropped, a stroke waiting for a tap stays
    /// ink (returned for committing).
    pub fn set_mode(&mut self, mode: Mode) -> ToolOutput {
        if mode == self.mode {
            return ToolOutput::None;
        }
        let dropped = self.cancel();
        self.mode = mode;
        dropped
    }

    /// The tool in use's options; what the user did there (`None`: it has none).
    pub fn panel(&mut self, ui: &mut egui::Ui, doc: &Document) -> Option<ToolOutput> {
        self.active_mut().panel(ui, doc)
    }

    /// Draws what the tool in use shows over the view.
    pub fn overlay(&self, ui: &egui::Ui, scene: &Scene<'_>) {
        self.active().overlay(ui, scene);
    }

    /// Draws what the edit in progress shows, by the tool whose op it is.
    pub fn edit_overlay(&self, ui: &egui::Ui, scene: &Scene<'_>) {
        for tool in &self.tools {
            tool.edit_overlay(ui, scene);
        }
    }

    /// What the tools say once an edit of `op` has landed.
    pub fn report(&self, op: &Op, before: &Document, after: &Document) -> Option<String> {
        (self.tools.iter()).find_map(|tool| tool.report(op, before, after))
    }

    /// The edit in progress stepped: a tool waiting on what it finds takes it (the region
    /// tool's handles and profile panel).
    pub fn edit_stepped(&mut self, edit: &Edit) {
        for tool in &mut self.tools {
            tool.edit_stepped(edit);
        }
    }

    /// The edit a tool's gesture began was refused: the tools start over (the region tool
    /// keeps its reference curve when the curves were refused).
    pub fn gesture_refused(&mut self) {
        for tool in &mut self.tools {
            tool.gesture_refused();
        }
    }

    /// Tells the tools whether the animation is playing (see [`Tool::playing`]).
    pub fn playing(&mut self, is_playing: bool) {
        for tool in &mut self.tools {
            tool.playing(is_playing);
        }
    }

    /// Every key a tool takes: the tool in use's own, and those any tool takes from
    /// anywhere, with the mode of the tool that takes each.
    pub fn keys(&self) -> Vec<(Mode, Key)> {
        let own = (self.active().keys().iter()).map(|&key| (self.mode, key));
        let anywhere = (Mode::ALL.into_iter())
            .flat_map(|mode| (self.tool(mode).keys_anywhere().iter()).map(move |&key| (mode, key)));
        own.chain(anywhere).collect()
    }

    /// One of the tool in use's keys was pressed (see [`ToolSet::keys`]; a key taken from
    /// anywhere makes its tool the one in use first).
    pub fn on_key(&mut self, key: Key, doc: &Document) -> ToolOutput {
        self.active_mut().on_key(key, doc)
    }

    /// What the active tool asks the user to do next, if anything.
    pub fn hint(&self, doc: &Document) -> Option<&'static str> {
        self.active().hint(doc)
    }

    /// Drops any gesture in progress in every tool; see [`ToolSet::set_mode`].
    pub fn cancel(&mut self) -> ToolOutput {
        let dropped: Vec<ToolOutput> = (self.tools.iter_mut()).map(|tool| tool.cancel()).collect();
        (dropped.into_iter())
            .find(|output| *output != ToolOutput::None)
            .unwrap_or(ToolOutput::None)
    }

    /// Feeds one event to the active tool.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        self.active_mut().on_event(event, view, doc)
    }

    /// Feeds two fingers to the active tool.
    pub fn on_hands(&mut self, hands: &Hands, view: &ViewCtx, doc: &Document) -> ToolOutput {
        self.active_mut().on_hands(hands, view, doc)
    }

    /// The stroke in progress of the active tool, for live display.
    pub fn preview(&self) -> Option<&[StrokePoint]> {
        self.active().preview()
    }

    /// Called every frame with the frame's clock (s): what a waiting stroke becomes when its
    /// tap is late, and how long until the next such moment.
    pub fn poll(&mut self, now: f64) -> (ToolOutput, Option<f64>) {
        self.active_mut().poll(now)
    }

    /// The active tool's lasso and brush strokes, while the view is the one each was drawn
    /// in.
    pub fn marks(&self, camera: &Camera) -> Vec<Mark> {
        self.active().marks(camera)
    }
}
