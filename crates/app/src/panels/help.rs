//! The help window: every shortcut and gesture in one place.

/// Keyboard shortcuts, as shown.
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
    ("S", "Sketch: shapes, curves on shapes, ink"),
    ("P", "Pull: drag a control curve"),
    ("E", "Erase control curves"),
    ("T", "Switch control curves sharp/smooth"),
    ("U", "Rub: smooth a control curve"),
    ("O", "Over-sketch: a stroke near an outline redraws it"),
    (
        "K",
        "Over-sketch: pick the handle first (outline piece or surface curve)",
    ),
    (
        "A",
        "Over-sketch: bend the whole part (an ear, a finger) or only near the outline",
    ),
    (
        "M",
        "Optimize: tap a model (or lasso part of one) to preview better triangles or smoothing",
    ),
    ("[ and ]", "Optimize: less or more hold (the amount s)"),
    (
        "B",
        "Optimize: strokes lasso a part, paint what moves, or paint edges that hold",
    ),
    ("Enter", "Optimize: apply the preview"),
    (
        "D",
        "Feature: sketch on a model, then drag for a ridge, bump or suggestive contours",
    ),
    (
        "L",
        "Region: a curve on a model, a loop around it, then drag: the region follows, fading out",
    ),
    (
        "V",
        "Move: tap a model, drag it to move, its ring to turn, its square to scale",
    ),
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

/// Shows the help window while `open` is set.
pub fn help_ui(ctx: &egui::Context, open: &mut bool, backend: &str, pen_seen: bool) {
    egui::Window::new("Help")
        .open(open)
        .collapsible(false)
        .resizable(false)
        .default_width(420.0)
        .show(ctx, |ui| {
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
                ui.label(*what);
                ui.end_row();
            }
        });
}
