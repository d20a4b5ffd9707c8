//! The hint line's words: every tool says what to do next in every stage, in the words of
//! the device in hand. A hint is written once with a few placeholders ([`Device::say`]), so a
//! pen user reads "with the pen", a phone user "with one finger" and a mouse user "click"
//! and "right-drag", without each tool matching on the device.

use std::borrow::Cow;

use crate::input::PointerKind;

/// A hint: a static sentence, or one made for the device.
pub type Hint = Cow<'static, str>;

/// What the user works with, as hints name it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Device {
    /// A pen or stylus (fingers then only move the view).
    Pen,
    /// A finger on a touch screen.
    Finger,
    /// A mouse or trackpad.
    #[default]
    Mouse,
}

impl Device {
    /// The device of the last pointer seen (see `InputRouter::device`); before any, a finger
    /// when the page's main pointer is coarse, else the mouse.
    pub fn of(kind: Option<PointerKind>, coarse_pointer: bool) -> Device {
        match kind {
            Some(PointerKind::Pen) => Device::Pen,
            Some(PointerKind::Touch) => Device::Finger,
            Some(PointerKind::Mouse) => Device::Mouse,
            None if coarse_pointer => Device::Finger,
            None => Device::Mouse,
        }
    }

    /// Whether it has keys at hand to name (a mouse comes with a keyboard).
    pub fn has_keys(self) -> bool {
        self == Device::Mouse
    }

    /// `text` in this device's words. Placeholders: `{tap}`/`{Tap}` (tap or click),
    /// `{with}` ("with the pen", "with one finger", "with the mouse"), `{orbit}` (how to
    /// turn the view), `{pinch}` (how to zoom), `{enter}` (" (Enter)" where there is a
    /// keyboard). A text without placeholders is kept as it is.
    pub fn say(self, text: impl Into<Hint>) -> Hint {
        let text = text.into();
        if !text.contains('{') {
            return text;
        }
        let mut said = text.into_owned();
        for (placeholder, word) in self.words() {
            said = said.replace(placeholder, word);
        }
        Cow::Owned(said)
    }

    fn words(self) -> [(&'static str, &'static str); 6] {
        let (tap, tap_cap, with, orbit, pinch, enter) = match self {
            Device::Pen => (
                "tap",
                "Tap",
                "with the pen",
                "drag one finger to turn the view",
                "pinch to zoom",
                "",
            ),
            Device::Finger => (
                "tap",
                "Tap",
                "with one finger",
                "drag two fingers to turn the view",
                "pinch to zoom",
                "",
            ),
            Device::Mouse => (
                "click",
                "Click",
                "with the mouse",
                "right-drag to turn the view",
                "scroll to zoom",
                " (Enter)",
            ),
        };
        [
            ("{tap}", tap),
            ("{Tap}", tap_cap),
            ("{with}", with),
            ("{orbit}", orbit),
            ("{pinch}", pinch),
            ("{enter}", enter),
        ]
    }
}

/// What a tool that needs a shape says while there is none: which tool makes one, and how.
/// A stroke drawn then is refused with the same words (see `ToolSet::on_event`).
pub fn needs_a_shape(label: &str, device: Device, maker: &str) -> Hint {
    device.say(format!(
        "{label} works on a shape, and there is none yet: pick {maker} and draw a closed \
         outline {{with}} to make one"
    ))
}

/// Whether some model has control curves, which the curve tools (Pull, Erase, Sharp, Rub)
/// work on; an imported model has none until one is drawn on it.
pub fn has_curves(doc: &sketchmesh_core::document::Document) -> bool {
    doc.models.iter().any(|model| !model.curves.is_empty())
}

/// What a curve tool says while no model has control curves.
pub const NO_CURVES: &str =
    "No control curves yet: draw one on a shape with Sketch, then come back to this tool";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_device_reads_its_own_words() {
        let text = "{Tap} it, draw {with}, {orbit}; Apply{enter}";
        assert_eq!(
            Device::Pen.say(text),
            "Tap it, draw with the pen, drag one finger to turn the view; Apply"
        );
        assert_eq!(
            Device::Finger.say(text),
            "Tap it, draw with one finger, drag two fingers to turn the view; Apply"
        );
        assert_eq!(
            Device::Mouse.say(text),
            "Click it, draw with the mouse, right-drag to turn the view; Apply (Enter)"
        );
        assert!(matches!(Device::Pen.say("Plain"), Cow::Borrowed("Plain")));
    }

    #[test]
    fn the_device_follows_the_last_pointer_and_else_the_screen() {
        assert_eq!(Device::of(None, true), Device::Finger);
        assert_eq!(Device::of(None, false), Device::Mouse);
        assert_eq!(Device::of(Some(PointerKind::Pen), false), Device::Pen);
        assert_eq!(Device::of(Some(PointerKind::Touch), false), Device::Finger);
    }
}
