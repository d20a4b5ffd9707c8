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
pub mod hint;
pub mod icon;
pub mod registry;
#[cfg(test)]
pub(crate) mod test_support;
pub mod tool;

use egui::Key;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::curve::StrokePoint;
use sketchmesh_core::document::{Document, Edit, Op};

pub use crate::input::router::{Hands, ToolEvent};
pub use context::{ToolOutput, ViewCtx};
pub use hint::{Device, Hint};
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

    /// What the edit in progress says in place of the hint, by the tool whose op it is.
    pub fn edit_line(&self, edit: &Edit) -> Option<String> {
        (self.tools.iter()).find_map(|tool| tool.edit_line(edit))
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

    /// What the active tool asks the user to do next, in `device`'s words; while there is
    /// nothing it can work on, which tool makes shapes.
    pub fn hint(&self, doc: &Document, device: Device) -> Hint {
        match self.waits_for_a_shape(doc) {
            true => self.needs_a_shape(device),
            false => self.active().hint(doc, device),
        }
    }

    /// Whether the tool in use needs a shape and the document has nothing to work on.
    fn waits_for_a_shape(&self, doc: &Document) -> bool {
        let nothing = doc.models.is_empty() && doc.point_clouds.is_empty();
        nothing && !self.active().makes_shapes()
    }

    /// The tool in use needs a shape: which tool makes one, and how.
    fn needs_a_shape(&self, device: Device) -> Hint {
        let maker = (Mode::ALL.into_iter())
            .find(|&mode| self.tool(mode).makes_shapes())
            .unwrap_or_default();
        let key = match device.has_keys() {
            true => format!(" ({})", maker.key().name()),
            false => String::new(),
        };
        let maker = format!("{}{key}", maker.label());
        hint::needs_a_shape(self.active().info().label, device, &maker)
    }

    /// Drops any gesture in progress in every tool; see [`ToolSet::set_mode`].
    pub fn cancel(&mut self) -> ToolOutput {
        let dropped: Vec<ToolOutput> = (self.tools.iter_mut()).map(|tool| tool.cancel()).collect();
        (dropped.into_iter())
            .find(|output| *output != ToolOutput::None)
            .unwrap_or(ToolOutput::None)
    }

    /// Feeds one event to the active tool. A stroke drawn while the tool in use waits for a
    /// shape is refused at its end with the hint's words, which name the tool that makes
    /// shapes. It does not make the shape itself: tldraw, Procreate and Nomad never switch
    /// tools behind the user's back, and a Pull that sometimes sketches would make the
    /// toolbar's choice mean nothing; redrawing an outline in Sketch costs a second.
    pub fn on_event(&mut self, event: &ToolEvent, view: &ViewCtx, doc: &Document) -> ToolOutput {
        if !self.waits_for_a_shape(doc) {
            return self.active_mut().on_event(event, view, doc);
        }
        match event {
            ToolEvent::End(sample) => {
                let hint = self.needs_a_shape(Device::of(Some(sample.kind), false));
                ToolOutput::Refused(format!("{hint}."))
            }
            _ => ToolOutput::None,
        }
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

#[cfg(test)]
mod tests {
    use sketchmesh_core::document::Editor;

    use super::*;
    use crate::tools::test_support::{line, shape, stroke, stroke_events, view};

    /// Every tool says what to do on an empty document, differently for each device; those
    /// that cannot work on nothing name the tool that makes shapes.
    #[test]
    fn every_tool_says_what_to_do_on_an_empty_document_in_each_devices_words() {
        let empty = Editor::new();
        let mut tools = ToolSet::default();
        for mode in Mode::ALL {
            let _ = tools.set_mode(mode);
            let said: Vec<Hint> = [Device::Pen, Device::Finger, Device::Mouse]
                .map(|device| tools.hint(empty.document(), device))
                .into();
            for (hint, words) in
                said.iter()
                    .zip(["with the pen", "with one finger", "with the mouse"])
            {
                assert!(hint.contains(words), "{mode:?}: {hint}");
                assert!(hint.contains("closed outline"), "{mode:?}: {hint}");
                assert!(!hint.contains('{'), "{mode:?} left a placeholder: {hint}");
            }
            if mode != Mode::Sketch {
                assert!(said[0].contains("Sketch"), "{mode:?}: {}", said[0]);
            }
        }
    }

    /// With a shape, every tool in its first stage asks for something of its own, with no
    /// placeholder left; the curve tools name the curves.
    #[test]
    fn every_tool_has_a_hint_of_its_own_on_a_shape() {
        let editor = shape();
        let mut tools = ToolSet::default();
        let mut seen = Vec::new();
        for mode in Mode::ALL {
            let _ = tools.set_mode(mode);
            let hint = tools.hint(editor.document(), Device::Mouse).into_owned();
            assert!(!hint.is_empty() && !hint.contains('{'), "{mode:?}: {hint}");
            assert!(
                !hint.contains("none yet"),
                "{mode:?} sees the shape: {hint}"
            );
            assert!(
                !seen.contains(&hint),
                "{mode:?} repeats another tool's hint: {hint}"
            );
            seen.push(hint);
        }
    }

    /// A closed outline drawn in Pull on an empty document makes nothing and is refused
    /// with a sentence naming the tool that makes shapes.
    #[test]
    fn an_outline_in_pull_on_nothing_is_refused_naming_sketch() {
        let empty = Editor::new();
        let mut tools = ToolSet::default();
        let _ = tools.set_mode(Mode::Pull);
        let mut loop_ = line((300.0, 300.0), (400.0, 300.0), 5);
        loop_.extend(line((400.0, 300.0), (350.0, 380.0), 5));
        loop_.extend(line((350.0, 380.0), (300.0, 300.0), 5));
        let v = view();
        let outputs: Vec<ToolOutput> = (stroke_events(&loop_).iter())
            .map(|event| tools.on_event(event, &v, empty.document()))
            .collect();
        let Some(ToolOutput::Refused(said)) = outputs.last() else {
            panic!("the outline is refused: {outputs:?}");
        };
        assert!(said.contains("Sketch") && said.ends_with('.'), "{said}");
        assert!(
            outputs[..outputs.len() - 1]
                .iter()
                .all(|o| *o == ToolOutput::None)
        );
        // The shape is not made: the sketch tool would make it.
        let mut sketch = Mode::Sketch.tool();
        let made = stroke(sketch.as_mut(), empty.document(), &loop_);
        assert!(
            matches!(made.last(), Some(ToolOutput::Commit(_))),
            "{made:?}"
        );
    }
}
