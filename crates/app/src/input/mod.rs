//! Pointer input, normalized across mouse, pen and touch.
//!
//! eframe's web backend forwards neither `pointerType` nor pen pressure, so on the web
//! [`web_pointer`] listens to `PointerEvent`s on the canvas itself; natively [`egui_pointer`]
//! turns egui's events into the same [`PointerSample`]s. [`router`] then decides, per
//! pointer, whether a sample feeds the active tool or the camera (palm rejection included).

#[cfg(not(target_arch = "wasm32"))]
pub mod egui_pointer;
pub mod gestures;
pub mod router;
pub mod taps;
#[cfg(target_arch = "wasm32")]
pub mod web_pointer;

use egui::Pos2;

/// What produced a pointer sample.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointerKind {
    /// A mouse or trackpad.
    Mouse,
    /// A pen or stylus; the only source of real pressure.
    Pen,
    /// A finger on a touch screen.
    Touch,
}

/// Where a sample sits in its pointer's life.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// The pointer touched or a button went down.
    Down,
    /// The pointer moved while down (or hovering, for mouse and pen).
    Move,
    /// The pointer lifted or the button went up.
    Up,
    /// The system took the pointer away (for example a browser gesture).
    Cancel,
}

/// Mouse buttons as in the DOM's `PointerEvent.buttons` bit mask.
pub mod buttons {
    /// Left button, pen tip or touch contact.
    pub const PRIMARY: u16 = 1;
    /// Right button or pen barrel button.
    pub const SECONDARY: u16 = 2;
    /// Middle button (wheel press).
    pub const MIDDLE: u16 = 4;
    /// A pen's eraser end.
    pub const ERASER: u16 = 32;
}

/// One normalized pointer sample, in egui points (CSS pixels at zoom 1), y down.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointerSample {
    /// Identifies the pointer across its samples (the DOM `pointerId`).
    pub id: i64,
    /// Down, move, up or cancel.
    pub phase: Phase,
    /// Position in screen points.
    pub pos_in_screen: Pos2,
    /// Pressure in 0..=1; 0.5 for devices without pressure, as tldraw does.
    pub pressure: f32,
    /// Mouse, pen or touch.
    pub kind: PointerKind,
    /// Buttons held, as a [`buttons`] mask.
    pub buttons: u16,
    /// A touch's contact size in points: the larger of its width and height (0 when the
    /// device does not say, and for mice and pens). Palms are large.
    pub contact: f32,
    /// Time stamp in seconds.
    pub time: f64,
}

impl PointerSample {
    /// Whether this is a pen's eraser end, or a pen with its barrel button held: both erase.
    pub fn is_eraser(&self) -> bool {
        self.kind == PointerKind::Pen && self.buttons & (buttons::ERASER | buttons::SECONDARY) != 0
    }

    /// Pressure used for drawing: devices that report none (or a constant 0/1) get 0.5.
    pub fn drawing_pressure(kind: PointerKind, reported: f32) -> f32 {
        match kind {
            PointerKind::Pen if reported > 0.0 => reported.clamp(0.0, 1.0),
            _ => 0.5,
        }
    }
}

/// Now on the clock pointer samples are stamped with (seconds): the page's event time
/// (`performance.now()`), or egui's input time natively.
pub fn sample_clock(ctx: &egui::Context) -> f64 {
    #[cfg(target_arch = "wasm32")]
    {
        let _ = ctx;
        crate::clock::now_ms() / 1000.0
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        ctx.input(|i| i.time)
    }
}
