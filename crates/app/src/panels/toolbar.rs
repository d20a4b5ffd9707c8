//! The toolbar: import and export, undo and redo for tablets (no keyboard there), view
//! switches, status.

use sketchmesh_core::document::{Editor, OversketchFit};
use sketchmesh_core::oversketch::{OutlineKind, OversketchRoi};

use crate::render::ViewOptions;
use crate::tools::{Mode, OversketchSettings, ToolOutput, ToolSet};

/// A toolbar button the user pressed.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    /// Undo the last operation.
    Undo,
    /// Redo the last undone operation.
    Redo,
    /// Frame everything.
    FrameAll,
    /// Back to the default view.
    ResetView,
    /// Pick glTF files to import.
    Import,
    /// Download the document as .glb.
    Export,
    /// Download the session as .sketchmesh.json.
    SaveSession,
    /// Switch to a tool.
    Mode(Mode),
    /// The active tool's panel asked for this.
    Tool(Box<ToolOutput>),
}

/// Minimum touch target, in points, so buttons are easy to hit with a finger.
const TOUCH_TARGET: f32 = 36.0;

/// Shows the toolbar; wraps onto more rows on narrow screens.
pub fn toolbar_ui(
    ui: &mut egui::Ui,
    editor: &Editor,
    options: &mut ViewOptions,
    tools: &mut ToolSet,
    show_help: &mut bool,
) -> Option<Action> {
    let mut action = None;
    let mut picked_mode = None;
    let mode = tools.mode();
    ui.spacing_mut().interact_size.y = TOUCH_TARGET;
    ui.spacing_mut().button_padding = egui::vec2(10.0, 6.0);
    ui.horizontal_wrapped(|ui| {
        // No title: the page's is enough, and the row needs the room for the buttons.
        let mut button = |ui: &mut egui::Ui, enabled: bool, label: &str, hint: &str, a: Action| {
            let response = ui.add_enabled(
                enabled,
                egui::Button::new(label).min_size(egui::vec2(TOUCH_TARGET, TOUCH_TARGET)),
            );
            if response.on_hover_text(hint).clicked() {
                action = Some(a);
            }
        };
        button(
            ui,
            true,
            "Import",
            "Import a .glb or .gltf file, or open a saved session (.sketchmesh.json) (Ctrl+O); \
             or drop one on the page",
            Action::Import,
        );
        button(
            ui,
            !editor.document().is_empty(),
            "Export",
            "Download everything as .glb (Ctrl+S)",
            Action::Export,
        );
        button(
            ui,
            editor.can_undo() || editor.can_redo(),
            "Save",
            "Save the session, every step of it, to replay or to open elsewhere \
             (.sketchmesh.json, Ctrl+Shift+S)",
            Action::SaveSession,
        );
        ui.separator();
        button(ui, editor.can_undo(), "Undo", "Undo (Ctrl+Z)", Action::Undo);
        button(
            ui,
            editor.can_redo(),
            "Redo",
            "Redo (Ctrl+Shift+Z or Ctrl+Y)",
            Action::Redo,
        );
        ui.separator();
        for m in Mode::ALL {
            let button = egui::Button::selectable(m == mode, m.label())
                .min_size(egui::vec2(TOUCH_TARGET, TOUCH_TARGET));
            let hint = format!("{} ({})", m.hint(), m.key().name());
            if ui.add(button).on_hover_text(hint).clicked() {
                picked_mode = Some(m);
            }
        }
        ui.separator();
        button(ui, true, "Frame", "Frame everything (F)", Action::FrameAll);
        button(
            ui,
            true,
            "Reset",
            "Back to the front view (R)",
            Action::ResetView,
        );
        ui.toggle_value(&mut options.wireframe, "Edges")
            .on_hover_text("Show mesh edges (W)");
        ui.toggle_value(&mut options.grid, "Grid")
            .on_hover_text("Show the ground grid (G)");
        ui.toggle_value(show_help, "Help")
            .on_hover_text("Shortcuts and gestures (H)");
    });
    // The second row, always there so that the viewport keeps its size whatever the mode:
    // the mode's options and the document's size. (Messages show over the view.)
    ui.horizontal_wrapped(|ui| {
        match mode {
            Mode::Oversketch => {
                oversketch_options_ui(ui, tools.oversketch_settings_mut());
                ui.separator();
            }
            Mode::Feature => {
                let output = tools.feature_ui(ui);
                if output != ToolOutput::None {
                    action = Some(Action::Tool(Box::new(output)));
                }
                ui.separator();
            }
            Mode::Optimize => {
                let output = tools.optimize_ui(ui);
                if output != ToolOutput::None {
                    action = Some(Action::Tool(Box::new(output)));
                }
                ui.separator();
            }
            _ => {}
        }
        let stats = editor.document().stats();
        ui.label(format!(
            "{} models · {} vertices · {} triangles · {} curves",
            stats.models, stats.vertices, stats.triangles, stats.curves
        ));
    });
    action.or(picked_mode.map(Action::Mode))
}

/// The over-sketch mode's switches: manual handle picking, the fit and the region.
fn oversketch_options_ui(ui: &mut egui::Ui, settings: &mut OversketchSettings) {
    let hint = "On: pick what moves first (draw along an outline, or across the model), then \
                draw its new shape. Off: the stroke finds the outline (K)";
    ui.toggle_value(&mut settings.manual, "Pick handle")
        .on_hover_text(hint);
    let hint = "On: the outline lands on the stroke. Off: it follows the stroke as far as the \
                surface detail allows, so a rough stroke bends the shape less";
    let fit = [OversketchFit::Exact, OversketchFit::Soft];
    toggle_between(ui, &mut settings.fit, fit, "Exact fit", hint);
    let hint = "On: the part the outline belongs to bends as a whole (an ear, a finger, told \
                apart by thickness) and the rest stays. Off: only the surface near the outline \
                moves, farther for a longer pull (A)";
    let roi = [OversketchRoi::Part, OversketchRoi::NearHandle];
    toggle_between(ui, &mut settings.roi, roi, "Whole part", hint);
    if settings.manual {
        let hint = "On: pick the outline as drawn, along mesh edges: a sharp crest seen \
                    edge-on, such as a ridge. Off: the smooth silhouette between them";
        let outline = [OutlineKind::Edge, OutlineKind::Smooth];
        toggle_between(ui, &mut settings.outline, outline, "Edge outline", hint);
    }
}

/// A toggle button for a setting with two values, `[on, off]`.
fn toggle_between<T: Copy + PartialEq>(
    ui: &mut egui::Ui,
    value: &mut T,
    [on, off]: [T; 2],
    label: &str,
    hint: &str,
) {
    let mut is_on = *value == on;
    if ui
        .toggle_value(&mut is_on, label)
        .on_hover_text(hint)
        .changed()
    {
        *value = if is_on { on } else { off };
    }
}
