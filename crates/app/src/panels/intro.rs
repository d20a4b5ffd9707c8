//! The first visit's introduction: three short cards over the view (make a shape, change
//! it, export it), each saying what to do with the device in hand and moving on once the
//! user has done it. Skip ends it at any time; Help's "Show the introduction" starts it
//! again. Whether it was seen is the shell's to keep (the page's store).

use sketchmesh_core::document::Editor;

use crate::tools::{Device, Mode};

/// A step of the introduction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// Draw a shape: done once the document has a model.
    Make,
    /// Change it: done once an edit followed.
    Change,
    /// Export it: done once an export was downloaded.
    Export,
}

impl Step {
    /// Its number, 1 to 3, as the card and the page API give it.
    pub fn number(self) -> u8 {
        match self {
            Step::Make => 1,
            Step::Change => 2,
            Step::Export => 3,
        }
    }

    /// The card's title and what to do, in `device`'s words.
    fn card(self, device: Device) -> (&'static str, String) {
        let tool = |mode: Mode| mode.label();
        let what = match self {
            Step::Make => format!(
                "Pick {} and draw a closed outline {{with}}, like a fat letter O: it puffs up \
                 into a shape.",
                tool(Mode::Sketch)
            ),
            Step::Change => format!(
                "Pick {} and drag a blue line on the shape {{with}}: the shape follows. To see \
                 it from the side, {{orbit}}.",
                tool(Mode::Pull)
            ),
            Step::Export => String::from(
                "Open the File menu and choose Export: you get a .glb file for Blender, Godot \
                 or a web page.",
            ),
        };
        let title = match self {
            Step::Make => "Make a shape",
            Step::Change => "Change it",
            Step::Export => "Export it",
        };
        (title, device.say(what).into_owned())
    }
}

/// The introduction's state: the step shown, and where the step began (the ops and exports
/// then, so a step is done by what the user does after it showed).
#[derive(Debug, Default)]
pub struct Intro {
    step: Option<Step>,
    ops_then: usize,
    exports_then: u32,
    /// Whether it has just ended (done or skipped), for the shell to remember.
    ended: bool,
    /// Where the Skip button was drawn last, for the page API's tests.
    skip_at: Option<egui::Pos2>,
}

impl Intro {
    /// The introduction at the page's start: shown unless it was `seen` before.
    pub fn new(seen: bool) -> Self {
        Intro {
            step: (!seen).then_some(Step::Make),
            ..Intro::default()
        }
    }

    /// Starts it again from the first step (Help's "Show the introduction").
    pub fn reopen(&mut self) {
        self.step = Some(Step::Make);
    }

    /// The step shown, if any.
    pub fn step(&self) -> Option<Step> {
        self.step
    }

    /// Where its Skip button is, while a card shows.
    pub fn skip_at(&self) -> Option<egui::Pos2> {
        self.step.and(self.skip_at)
    }

    /// Whether it ended since the last call (the shell then keeps that it was seen).
    pub fn take_ended(&mut self) -> bool {
        std::mem::take(&mut self.ended)
    }

    /// Moves on when the user has done the step: a shape exists, an edit followed, an
    /// export was downloaded (`exports` counts them since the page opened).
    pub fn follow(&mut self, editor: &Editor, exports: u32) {
        let ops = editor.ops().len();
        let next = match self.step {
            Some(Step::Make) if !editor.document().models.is_empty() => Some(Step::Change),
            Some(Step::Change) if ops > self.ops_then => Some(Step::Export),
            Some(Step::Export) if exports > self.exports_then => None,
            _ => return,
        };
        self.step = next;
        self.ended = next.is_none();
        (self.ops_then, self.exports_then) = (ops, exports);
    }

    /// Ends it now (Skip).
    fn skip(&mut self) {
        self.step = None;
        self.ended = true;
    }

    /// The card of the step shown, in the view below `top` (the hint line's bottom),
    /// centred and as wide as a phone allows, with Skip.
    pub fn ui(&mut self, ctx: &egui::Context, viewport: egui::Rect, top: f32, device: Device) {
        let Some(step) = self.step else {
            return;
        };
        let (title, what) = step.card(device);
        let width = (viewport.width() - 24.0).min(380.0);
        let at = egui::pos2(viewport.center().x - 0.5 * width, top + 10.0);
        let mut skip = false;
        egui::Area::new(egui::Id::unique("introduction"))
            .fixed_pos(at)
            .order(egui::Order::Foreground)
            .show(ctx, |ui| {
                egui::Frame::popup(ui.style())
                    .inner_margin(12.0)
                    .show(ui, |ui| {
                        ui.set_width(width - 24.0);
                        ui.horizontal(|ui| {
                            let step_of = format!("{} of 3 · {title}", step.number());
                            ui.label(egui::RichText::new(step_of).strong().size(16.0));
                            ui.with_layout(
                                egui::Layout::right_to_left(egui::Align::Center),
                                |ui| {
                                    let button = egui::Button::new("Skip")
                                        .min_size(crate::ui_size::target_size(ui));
                                    let response = ui.add(button).on_hover_text(
                                        "Hide the introduction; Help shows it again",
                                    );
                                    skip = response.clicked();
                                    self.skip_at = Some(response.rect.center());
                                },
                            );
                        });
                        ui.label(egui::RichText::new(what).size(15.0));
                    });
            });
        if skip {
            self.skip();
        }
    }
}

#[cfg(test)]
mod tests {
    use sketchmesh_core::document::{Op, TransformInput};

    use super::*;
    use crate::tools::test_support::shape;

    #[test]
    fn it_moves_on_as_the_user_makes_changes_and_exports() {
        let mut intro = Intro::new(false);
        let mut editor = Editor::new();
        intro.follow(&editor, 0);
        assert_eq!(intro.step(), Some(Step::Make));
        let made = shape();
        intro.follow(&made, 0);
        assert_eq!(intro.step(), Some(Step::Change));
        intro.follow(&made, 0);
        assert_eq!(intro.step(), Some(Step::Change), "nothing changed yet");
        editor = made;
        let lift = TransformInput {
            model: 0,
            matrix: glam::DMat4::from_translation(glam::DVec3::Y).to_cols_array(),
        };
        editor.apply(Op::Transform(lift)).expect("a move applies");
        intro.follow(&editor, 0);
        assert_eq!(intro.step(), Some(Step::Export));
        assert!(!intro.take_ended());
        intro.follow(&editor, 1);
        assert_eq!(intro.step(), None);
        assert!(intro.take_ended(), "the shell keeps that it was seen");
        assert!(!intro.take_ended());
        intro.reopen();
        intro.follow(&editor, 1);
        assert_eq!(intro.step(), Some(Step::Change), "a shape exists already");
    }

    #[test]
    fn a_seen_introduction_does_not_show_and_each_card_speaks_to_its_device() {
        assert_eq!(Intro::new(true).step(), None);
        let (_, pen) = Step::Make.card(Device::Pen);
        let (_, mouse) = Step::Make.card(Device::Mouse);
        assert!(pen.contains("with the pen"), "{pen}");
        assert!(mouse.contains("with the mouse"), "{mouse}");
        let (_, finger) = Step::Change.card(Device::Finger);
        assert!(finger.contains("two fingers"), "{finger}");
    }
}
