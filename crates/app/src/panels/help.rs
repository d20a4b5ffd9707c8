//! The help window: every tool with its key (read from the tool registry), the other
//! shortcuts and gestures, and a link to the user guide (`docs/guide.md`, which the web build
//! turns into `guide.html` beside the page).

use crate::tools::Mode;

/// Where the web build puts the user guide, beside the page.
const GUIDE_URL: &str = "guide.html";

/// The help window's height at most, as a share of the screen's: the rest scrolls.
const MAX_HEIGHT_SHARE: f32 = 0.8;

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
    ("Delete, Backspace", "Move: delete the selected model"),
    ("Esc", "Drop what is in progress (a preview, a drag)"),
    ("W", "Wireframe on/off"),
    ("G", "Grid on/off"),
    ("H, F1", "This help"),
];

/// Mouse and touch gestures, as shown.
const GESTURES: &[(&str, &str)] = &[
    ("Left drag, pen", "Draw"),
    ("Right drag", "Orbit"),
    ("Middle drag", "Pan"),
    ("Wheel, trackpad pinch", "Zoom"),
    ("One finger (no pen yet)", "Draw"),
    (
        "Two fingers (no pen yet)",
        "Drag to orbit, pinch to zoom and pan",
    ),
    (
        "One finger (after a pen)",
        "Orbit; fingers never draw once a pen is seen",
    ),
    ("Two fingers (after a pen)", "Drag to pan, pinch to zoom"),
    ("Two-finger tap", "Undo"),
    ("Three-finger tap", "Redo"),
    ("Double tap on empty canvas", "Frame everything"),
    (
        "Sketch: a stroke across a shape",
        "Cut off the part past it; a tap right after makes a cross-section curve instead",
    ),
    (
        "Sketch: a loop on a shape, then",
        "a tap: a closed curve; a stroke out from the loop and back: a limb with that outline; a loop on the far side: a tunnel",
    ),
    (
        "Move: two fingers on the selected model",
        "Move, twist and pinch it; Merge joins it with the model it overlaps",
    ),
    (
        "Pen eraser end or barrel button",
        "Erase curves, whatever the tool",
    ),
    (
        "A palm resting near the pen",
        "Ignored: it neither draws nor moves the view",
    ),
];

/// Shows the help window while `open` is set; whether the user asked to see the
/// introduction again.
pub fn help_ui(ctx: &egui::Context, open: &mut bool, backend: &str, pen_seen: bool) -> bool {
    let mut intro = false;
    egui::Window::new("Help")
        .open(open)
        .collapsible(false)
        .resizable(false)
        .default_width(420.0)
        .max_width(ctx.content_rect().width() - 2.0 * SCREEN_MARGIN)
        .max_height(ctx.content_rect().height() * MAX_HEIGHT_SHARE)
        .show(ctx, |ui| {
            if ui
                .button("Open the user guide")
                .on_hover_text("Every tool with a pen, a finger and a mouse, in a new tab")
                .clicked()
            {
                ui.ctx().open_url(egui::OpenUrl::new_tab(GUIDE_URL));
            }
            intro = ui.button("Show the introduction").clicked();
            ui.add_space(8.0);
            egui::ScrollArea::vertical().show(ui, |ui| contents_ui(ui, backend, pen_seen));
        });
    intro
}

/// The tables and the state of the pen and graphics.
fn contents_ui(ui: &mut egui::Ui, backend: &str, pen_seen: bool) {
    let tools: Vec<(&str, String)> = Mode::ALL
        .into_iter()
        .map(|mode| {
            (
                mode.key().name(),
                format!("{}: {}", mode.label(), mode.hint()),
            )
        })
        .collect();
    let rows: Vec<(&str, &str)> = (tools.iter())
        .map(|(key, what)| (*key, what.as_str()))
        .collect();
    table_ui(ui, "tools", "Tools", &rows);
    ui.add_space(8.0);
    table_ui(ui, "shortcuts", "Keyboard", SHORTCUTS);
    ui.add_space(8.0);
    table_ui(ui, "gestures", "Mouse, pen and touch", GESTURES);
    ui.add_space(8.0);
    let palm = if pen_seen {
        "on (a pen was seen)"
    } else {
        "off until a pen is seen"
    };
    ui.label(format!("Palm rejection: {palm}. Graphics: {backend}."));
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
