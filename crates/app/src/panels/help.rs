//! The help window: every tool in its group with its icon, key and gestures (read from the
//! tool registry), the gestures of the pointer in use first, the other shortcuts, and a link
//! to the user guide (`docs/guide.md`, which the web build
//! turns into `guide.html` beside the page).

use crate::panels::readout::{self, HelpScroll, corners};
use crate::panels::tool_button::icon_ui;
use crate::tools::{Group, Mode};

/// Where the web build puts the user guide, beside the page.
const GUIDE_URL: &str = "guide.html";

/// The help window's height at most, as a share of the screen's: the rest scrolls.
const MAX_HEIGHT_SHARE: f32 = 0.8;

/// The height of the window's title and the buttons above the scrolled list, in points
/// (with a finger's targets).
const HEADER: f32 = 110.0;

/// The space kept between the window and the screen's edges, so a phone shows it whole.
const SCREEN_MARGIN: f32 = 8.0;

/// Keyboard shortcuts other than the tools' own keys, as shown.
const SHORTCUTS: &[(&str, &str)] = &[
    (
        "Ctrl+O",
        "Import glTF or open a session (or drop files on the page)",
    ),
    ("Ctrl+S, Ctrl+E", "Export .glb"),
    ("Ctrl+Shift+S", "Save the session (.sketchmesh.json)"),
    ("Ctrl+Z", "Undo"),
    ("Ctrl+Shift+Z, Ctrl+Y", "Redo"),
    ("F", "Frame everything"),
    ("R, Home", "Reset the view"),
    (
        "K",
        "Over-sketch: pick the handle first (outline piece or surface curve)",
    ),
    (
        "A",
        "Over-sketch: bend the whole part (an ear, a finger) or only near the outline",
    ),
    ("[ and ]", "Optimize: less or more hold (the amount s)"),
    (
        "B",
        "Optimize: strokes lasso a part, paint what moves, or paint edges that hold",
    ),
    ("Enter", "Optimize: apply the preview"),
    ("Delete, Backspace", "Arrange: delete the selected model"),
    ("Esc", "Drop what is in progress (a preview, a drag)"),
    ("W", "Wireframe on/off"),
    ("G", "Grid on/off"),
    ("X", "Symmetry on/off"),
    ("H, F1", "This help"),
];

/// What a mouse does in the view, as shown.
const MOUSE: &[(&str, &str)] = &[
    ("Left drag", "Use the tool"),
    ("Right drag", "Orbit"),
    ("Middle drag", "Pan"),
    ("Wheel, trackpad pinch", "Zoom"),
];

/// What a pen does, as shown.
const PEN: &[(&str, &str)] = &[
    ("The pen", "Use the tool; fingers then only move the view"),
    (
        "Eraser end or barrel button",
        "Erase curves, whatever the tool",
    ),
    (
        "A palm resting near the pen",
        "Ignored: it neither draws nor moves the view",
    ),
];

/// What fingers do, as shown.
const FINGER: &[(&str, &str)] = &[
    ("One finger (no pen yet)", "Use the tool"),
    (
        "Two fingers (no pen yet)",
        "Drag to orbit, pinch to zoom and pan",
    ),
    ("One finger (after a pen)", "Orbit"),
    ("Two fingers (after a pen)", "Drag to pan, pinch to zoom"),
    ("Two-finger tap", "Undo"),
    ("Three-finger tap", "Redo"),
    ("Double tap on empty canvas", "Frame everything"),
    (
        "Hold on a model",
        "Its menu: frame, duplicate, delete, over-sketch",
    ),
    ("Hold on a tool", "Its name and what it is for"),
    (
        "Arrange: two fingers on the selected model",
        "Move, twist and pinch it",
    ),
];

/// What the Sketch tool makes of strokes on a shape, with any pointer.
const SKETCH: &[(&str, &str)] = &[
    (
        "A stroke across a shape",
        "Cut off the part past it; a tap right after makes a cross-section curve instead",
    ),
    (
        "A loop on a shape, then",
        "a tap: a closed curve; a stroke out from the loop and back: a limb with that \
         outline; a loop on the far side: a tunnel",
    ),
];

/// A kind of pointer, as the help orders the gestures: the one in use first.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Pointer {
    Finger,
    Pen,
    Mouse,
}

impl Pointer {
    /// The pointers, the one the screen is used with first: a pen once one is seen, a
    /// finger on a touch screen, else a mouse.
    fn in_order(pen_seen: bool, coarse: bool) -> [Pointer; 3] {
        use Pointer::{Finger, Mouse, Pen};
        match (pen_seen, coarse) {
            (true, _) => [Pen, Finger, Mouse],
            (false, true) => [Finger, Pen, Mouse],
            (false, false) => [Mouse, Pen, Finger],
        }
    }

    fn name(self) -> &'static str {
        match self {
            Pointer::Finger => "Finger",
            Pointer::Pen => "Pen",
            Pointer::Mouse => "Mouse",
        }
    }

    /// What this pointer does with `mode`'s tool.
    fn with(self, mode: Mode) -> &'static str {
        let gestures = &mode.info().gestures;
        match self {
            Pointer::Finger => gestures.finger,
            Pointer::Pen => gestures.pen,
            Pointer::Mouse => gestures.mouse,
        }
    }

    /// What this pointer does anywhere.
    fn rows(self) -> &'static [(&'static str, &'static str)] {
        match self {
            Pointer::Finger => FINGER,
            Pointer::Pen => PEN,
            Pointer::Mouse => MOUSE,
        }
    }
}

/// The size of a tool's icon in the help, in points.
const ICON: f32 = 24.0;

/// Shows the help window while `open` is set: the pointer in use first, a pen once one is
/// seen (`pen_seen`), else a finger where the screen's main pointer is `coarse`. Returns
/// whether the user asked to see the introduction again.
pub fn help_ui(
    ctx: &egui::Context,
    open: &mut bool,
    backend: &str,
    pen_seen: bool,
    coarse: bool,
) -> bool {
    let mut intro = false;
    let shown = egui::Window::new("Help")
        .open(open)
        .collapsible(false)
        .resizable(false)
        .default_width(440.0)
        .max_width(ctx.content_rect().width() - 2.0 * SCREEN_MARGIN)
        .max_height(ctx.content_rect().height() * MAX_HEIGHT_SHARE)
        .show(ctx, |ui| {
            // One row, so the list below keeps the height `HEADER` leaves it.
            ui.horizontal(|ui| {
                if ui
                    .button("User guide")
                    .on_hover_text("Every tool with a pen, a finger and a mouse, in a new tab")
                    .clicked()
                {
                    ui.ctx().open_url(egui::OpenUrl::new_tab(GUIDE_URL));
                }
                intro = ui.button("Show the introduction").clicked();
            });
            ui.add_space(8.0);
            let order = Pointer::in_order(pen_seen, coarse);
            // As tall as the window may be: egui would keep a scrolled list short.
            let list = ctx.content_rect().height() * MAX_HEIGHT_SHARE - HEADER;
            egui::ScrollArea::vertical()
                .max_height(list)
                .min_scrolled_height(list)
                .show(ui, |ui| contents_ui(ui, backend, pen_seen, order))
        });
    let scroll = shown
        .and_then(|window| window.inner)
        .map(|scrolled| HelpScroll {
            rect: corners(scrolled.inner_rect),
            offset: scrolled.state.clamped_offset().y,
            max_offset: (scrolled.content_size.y - scrolled.inner_rect.height()).max(0.0),
        });
    readout::update(ctx, |r| r.help = scroll);
    intro
}

/// The tools in their groups, the gestures of each pointer, the keys, and the state of the
/// pen and graphics.
fn contents_ui(ui: &mut egui::Ui, backend: &str, pen_seen: bool, order: [Pointer; 3]) {
    for group in Group::ALL {
        ui.strong(group.label());
        for mode in Mode::ALL.into_iter().filter(|m| m.group() == group) {
            tool_ui(ui, mode, order);
        }
        ui.add_space(6.0);
    }
    for pointer in order {
        table_ui(ui, pointer.name(), pointer.name(), pointer.rows());
        ui.add_space(8.0);
    }
    table_ui(ui, "sketch", "Sketch on a shape", SKETCH);
    ui.add_space(8.0);
    table_ui(ui, "shortcuts", "Keyboard", SHORTCUTS);
    ui.add_space(8.0);
    let palm = if pen_seen {
        "on (a pen was seen)"
    } else {
        "off until a pen is seen"
    };
    ui.label(format!("Palm rejection: {palm}. Graphics: {backend}."));
}

/// One tool: its icon, name and key, what it does, when to choose it (a tool that deforms),
/// and how each pointer uses it.
fn tool_ui(ui: &mut egui::Ui, mode: Mode, order: [Pointer; 3]) {
    ui.horizontal(|ui| {
        icon_ui(ui, mode, ICON);
        ui.strong(mode.label());
        ui.weak(format!("key {}", mode.key().name()));
    });
    ui.indent(mode.label(), |ui| {
        ui.add(egui::Label::new(mode.hint()).wrap());
        if let Some(when) = mode.info().when {
            ui.add(egui::Label::new(egui::RichText::new(when).italics()).wrap());
        }
        for pointer in order {
            let line = format!("{}: {}", pointer.name(), pointer.with(mode));
            ui.add(egui::Label::new(egui::RichText::new(line).weak()).wrap());
        }
    });
}
fn table_ui(ui: &mut egui::Ui, id: &str, title: &str, rows: &[(&str, &str)]) {
    ui.strong(title);
    egui::Grid::new(id)
        .num_columns(2)
        .striped(true)
        .show(ui, |ui| {
            for (keys, what) in rows {
                ui.monospace(*keys);
                // Wrapped to the window, which a phone's screen holds.
                ui.add(egui::Label::new(*what).wrap());
                ui.end_row();
            }
        });
}
