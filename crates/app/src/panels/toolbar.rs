//! The toolbar: import and export, undo and redo for tablets (no keyboard there), view
//! switches, status.

use sketchmesh_core::document::Editor;

use crate::render::ViewOptions;
use crate::tools::{Mode, ToolOutput, ToolSet};

pub use crate::command::Command as Action;

/// Minimum target, in points, with a mouse or pen.
const POINTER_TARGET: f32 = 36.0;

/// Minimum target, in points (CSS px), for a finger: what touch guidelines ask for.
const FINGER_TARGET: f32 = 44.0;

/// Below this width (points) the toolbar is two single-line rows, with the file and view
/// buttons in one menu and the tools that do not fit in another: wrapped, it took four rows,
/// a third of a phone's screen.
const NARROW: f32 = 700.0;

/// Below this width a screen whose main pointer is a finger (phones, tablets upright) gets
/// the touch layout. Wider touch screens (a tablet on its side) keep the desktop one, whose
/// wrapped rows fit there, with targets for a finger all the same.
const TOUCH_WIDE: f32 = 1000.0;

/// From this width (points) the wide toolbar's tools show their icons before their labels:
/// the row with them (and a finger's 44-point targets) still fits on one line. In the
/// compact layout, whose tools that do not fit go behind ⋯, they always do.
const ICONS_FROM: f32 = 1500.0;
/// Undo's and redo's buttons in the compact layout: arrows, which leave the row room for
/// more tools (the app's fonts must have them).
pub const UNDO_REDO_ICONS: (&str, &str) = ("↩", "↪");

/// Below this width (points) the compact toolbar's tools show their icons only: a phone's
/// row then holds three tools beside the menus and the arrows, where it held one with labels.
const ICONS_ONLY_BELOW: f32 = 600.0;

/// How the toolbar is laid out for a screen and its pointer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layout {
    /// Single-line rows, the file and view buttons behind one menu, the tools that do not fit
    /// behind another.
    pub compact: bool,
    /// The smallest width and height of a target, in points.
    pub target: f32,
    /// Docked at the bottom with the tools in the last row, in reach of a thumb.
    pub bottom: bool,
}

impl Layout {
    /// The layout for a screen of `size` points whose main pointer is coarse (a finger:
    /// the page's `(pointer: coarse)`) or not.
    pub fn for_screen(size: egui::Vec2, coarse_pointer: bool) -> Layout {
        let touch = coarse_pointer && size.x < TOUCH_WIDE;
        Layout {
            compact: touch || size.x < NARROW,
            target: if coarse_pointer {
                FINGER_TARGET
            } else {
                POINTER_TARGET
            },
            bottom: touch && size.y > size.x,
        }
    }

    /// The space above and below a button's text: egui sizes a text button to its text, so
    /// for a finger it pads a line of body text (about 17 points) out to the target.
    fn padding(self) -> f32 {
        if self.target > POINTER_TARGET {
            (self.target - 17.0) / 2.0
        } else {
            6.0
        }
    }
}

/// Shows the toolbar: two rows, the tools (the menus, undo and redo, the tools and, wide,
/// the view buttons) and the mode's options (on the bottom the options come first, so that
/// the tools are nearest the thumb); on a wide screen they wrap and the file buttons sit in a
/// File menu, in the compact layout the file and view buttons sit in one menu (☰) and the
/// tools that do not fit in another (⋯).
pub fn toolbar_ui(
    ui: &mut egui::Ui,
    layout: Layout,
    editor: &Editor,
    options: &mut ViewOptions,
    tools: &mut ToolSet,
    show_help: &mut bool,
) -> Option<Action> {
    let interact = &mut ui.spacing_mut().interact_size;
    *interact = egui::vec2(interact.x.max(layout.target), layout.target);
    ui.spacing_mut().button_padding = egui::vec2(10.0, layout.padding());
    // Bottom first: the tools row ends up nearest the thumb.
    let options_first = layout
        .bottom
        .then(|| options_row(ui, layout, editor, tools));
    let mut action = None;
    let mut picked_mode = None;
    let mode = tools.mode();
    let target = egui::vec2(layout.target, layout.target);
    let full_width = ui.available_width();
    let shows = ToolText::for_row(layout, full_width);
    row(ui, layout.compact, "tools", |ui| {
        // Narrower padding in this row keeps its twelve tools and the view buttons on one
        // line at 1280 points, with a finger's 44-point File button too.
        ui.spacing_mut().button_padding.x = 7.0;
        if layout.compact {
            let menu = egui::Button::new("☰").min_size(target);
            egui::containers::menu::MenuButton::from_button(menu).ui(ui, |ui| {
                file_buttons(ui, layout, editor, &mut action);
                ui.separator();
                view_buttons(ui, layout, options, show_help, &mut action);
            });
        } else {
            // No title: the page's is enough, and the row needs the room for the buttons.
            let menu = egui::Button::new("File").min_size(target);
            egui::containers::menu::MenuButton::from_button(menu)
                .ui(ui, |ui| file_buttons(ui, layout, editor, &mut action));
            ui.separator();
        }
        let (undo, redo) = if layout.compact {
            UNDO_REDO_ICONS
        } else {
            ("Undo", "Redo")
        };
        button(
            ui,
            layout,
            editor.can_undo(),
            undo,
            "Undo (Ctrl+Z, or tap with two fingers)",
            Action::Undo,
            &mut action,
        );
        button(
            ui,
            layout,
            editor.can_redo(),
            redo,
            "Redo (Ctrl+Shift+Z or Ctrl+Y, or tap with three fingers)",
            Action::Redo,
            &mut action,
        );
        if !layout.compact {
            ui.separator();
        }
        // Compact, the tools that fit beside a More menu (the one in use among them), the
        // rest in it; wide, all of them.
        let (shown, more) = if layout.compact {
            let room = full_width - ui.min_rect().width() - ui.spacing().item_spacing.x;
            tools_in_room(ui, mode, shows, room, layout.target)
        } else {
            (Mode::ALL.to_vec(), Vec::new())
        };
        for m in shown {
            let button = egui::Button::selectable(m == mode, shows.text(m));
            let hint = format!("{}: {} ({})", m.label(), m.hint(), m.key().name());
            if ui
                .add(button.min_size(target))
                .on_hover_text(hint)
                .clicked()
            {
                picked_mode = Some(m);
            }
        }
        if !more.is_empty() {
            let button = egui::Button::new("⋯").min_size(target);
            egui::containers::menu::MenuButton::from_button(button).ui(ui, |ui| {
                for m in more {
                    let button = egui::Button::new(ToolText::Both.text(m)).min_size(target);
                    if ui.add(button).clicked() {
                        picked_mode = Some(m);
                    }
                }
            });
        }
        if !layout.compact {
            ui.separator();
            view_buttons(ui, layout, options, show_help, &mut action);
        }
    });
    let options_last = (!layout.bottom).then(|| options_row(ui, layout, editor, tools));
    (action.or(picked_mode.map(Action::Mode)))
        .or(options_first.flatten())
        .or(options_last.flatten())
}

/// What a tool's button shows.
#[derive(Clone, Copy, Debug, PartialEq)]
enum ToolText {
    /// Its icon and label.
    Both,
    /// Its icon (a phone's row; the label is in its tooltip and in the More menu).
    Icon,
    /// Its label (a desktop row without room for the icons).
    Label,
}

impl ToolText {
    /// What the tools row of `layout`, `width` points wide, shows.
    fn for_row(layout: Layout, width: f32) -> ToolText {
        if layout.compact && width < ICONS_ONLY_BELOW {
            ToolText::Icon
        } else if layout.compact || width >= ICONS_FROM {
            ToolText::Both
        } else {
            ToolText::Label
        }
    }

    fn text(self, mode: Mode) -> String {
        match self {
            ToolText::Both => format!("{} {}", mode.icon(), mode.label()),
            ToolText::Icon => mode.icon().to_owned(),
            ToolText::Label => mode.label().to_owned(),
        }
    }
}

/// The tools whose buttons (showing `shows`, at least `target` wide) fit in `room` points,
/// in their order, beside a More button when not all do, with `mode` among them (in the
/// last place that fits, should it come later); and the rest, for the More menu.
fn tools_in_room(
    ui: &egui::Ui,
    mode: Mode,
    shows: ToolText,
    room: f32,
    target: f32,
) -> (Vec<Mode>, Vec<Mode>) {
    let spacing = ui.spacing().item_spacing.x;
    let font = egui::TextStyle::Button.resolve(ui.style());
    let width = |m: Mode| {
        let text = ui
            .painter()
            .layout_no_wrap(shows.text(m), font.clone(), egui::Color32::WHITE);
        (text.size().x + 2.0 * ui.spacing().button_padding.x).max(target) + spacing
    };
    let widths: Vec<f32> = Mode::ALL.into_iter().map(width).collect();
    if widths.iter().sum::<f32>() <= room {
        return (Mode::ALL.to_vec(), Vec::new());
    }
    let mut shown: Vec<Mode> = Vec::new();
    let mut used = target + spacing; // The More button.
    for (m, w) in Mode::ALL.into_iter().zip(&widths) {
        if used + w > room {
            break;
        }
        shown.push(m);
        used += w;
    }
    if !shown.contains(&mode) {
        // The tool in use takes the place of the last ones that make room for it.
        let w = |m: Mode| widths[Mode::ALL.iter().position(|&n| n == m).unwrap_or(0)];
        while !shown.is_empty() && used + w(mode) > room {
            used -= shown.pop().map_or(0.0, w);
        }
        shown.push(mode);
    }
    let more = Mode::ALL
        .into_iter()
        .filter(|m| !shown.contains(m))
        .collect();
    (shown, more)
}

/// The second row, always there so that the viewport keeps its size whatever the mode: the
/// mode's options and, on a wide screen, the document's size. (Messages show over the view.)
fn options_row(
    ui: &mut egui::Ui,
    layout: Layout,
    editor: &Editor,
    tools: &mut ToolSet,
) -> Option<Action> {
    let mut action = None;
    row(ui, layout.compact, "options", |ui| {
        if let Some(output) = tools.panel(ui, editor.document()) {
            if output != ToolOutput::None {
                action = Some(Action::Tool(Box::new(output)));
            }
            ui.separator();
        }
        let stats = editor.document().stats();
        let size = [
            (stats.models, "model"),
            (stats.vertices, "vertex"),
            (stats.triangles, "triangle"),
            (stats.curves, "curve"),
        ]
        .map(|(n, noun)| counted(n, noun))
        .join(" · ");
        if layout.compact {
            ui.label(counted(stats.vertices, "vertex"))
                .on_hover_text(size);
        } else {
            // Shorter, or left out, where the mode's options leave too little room: wrapped,
            // it would add a row as the options change, and the view below would jump.
            let short = counted(stats.vertices, "vertex");
            let room = ui.available_size_before_wrap().x;
            let width = |text: &str| {
                egui::WidgetText::from(text)
                    .into_galley(
                        ui,
                        Some(egui::TextWrapMode::Extend),
                        f32::INFINITY,
                        egui::TextStyle::Body,
                    )
                    .size()
                    .x
            };
            if width(&size) <= room {
                ui.label(size);
            } else if width(&short) <= room {
                ui.label(short).on_hover_text(size);
            }
        }
    });
    action
}

/// `n` and `noun`, plural unless `n` is one: "1 model", "2,500 vertices".
fn counted(n: usize, noun: &str) -> String {
    let digits = n.to_string();
    let grouped: Vec<&str> = (0..digits.len())
        .rev()
        .step_by(3)
        .map(|end| &digits[end.saturating_sub(2)..=end])
        .collect();
    let number = grouped.into_iter().rev().collect::<Vec<_>>().join(",");
    match (n, noun) {
        (1, _) => format!("{number} {noun}"),
        (_, "vertex") => format!("{number} vertices"),
        _ => format!("{number} {noun}s"),
    }
}

/// One toolbar row: wrapped onto more lines, or in the `compact` layout one line that
/// scrolls sideways (a finger drags it) should it not fit: a tool's options on a phone.
fn row(ui: &mut egui::Ui, compact: bool, id: &str, add: impl FnOnce(&mut egui::Ui)) {
    if compact {
        egui::ScrollArea::horizontal().id_salt(id).show(ui, |ui| {
            ui.horizontal(add);
        });
    } else {
        ui.horizontal_wrapped(add);
    }
}

/// A button at least a target square that sets `action` to `a` when pressed.
fn button(
    ui: &mut egui::Ui,
    layout: Layout,
    enabled: bool,
    label: &str,
    hint: &str,
    a: Action,
    action: &mut Option<Action>,
) {
    let response = ui.add_enabled(
        enabled,
        egui::Button::new(label).min_size(egui::vec2(layout.target, layout.target)),
    );
    if response.on_hover_text(hint).clicked() {
        *action = Some(a);
    }
}

/// New, Documents, Import, Export and Save.
fn file_buttons(ui: &mut egui::Ui, layout: Layout, editor: &Editor, action: &mut Option<Action>) {
    // The documents live in the page's storage: the desktop build has none.
    let has_store = cfg!(target_arch = "wasm32");
    button(
        ui,
        layout,
        has_store,
        "New",
        "Keep this document under Documents and start an empty one",
        Action::NewDocument,
        action,
    );
    button(
        ui,
        layout,
        has_store,
        "Documents…",
        "The documents kept in this browser: open, rename or delete them",
        Action::Documents,
        action,
    );
    ui.separator();
    button(
        ui,
        layout,
        true,
        "Import…",
        "Import a .glb or .gltf file, or open a saved session (.sketchmesh.json) (Ctrl+O); \
         or drop one on the page",
        Action::Import,
        action,
    );
    button(
        ui,
        layout,
        !editor.document().is_empty(),
        "Export",
        "Download everything as .glb (Ctrl+S)",
        Action::Export,
        action,
    );
    button(
        ui,
        layout,
        editor.can_undo() || editor.can_redo(),
        "Save session",
        "Save the session, every step of it, to replay or to open elsewhere \
         (.sketchmesh.json, Ctrl+Shift+S)",
        Action::SaveSession,
        action,
    );
}

/// Frame, Reset and the view switches.
fn view_buttons(
    ui: &mut egui::Ui,
    layout: Layout,
    options: &mut ViewOptions,
    show_help: &mut bool,
    action: &mut Option<Action>,
) {
    button(
        ui,
        layout,
        true,
        "Frame",
        "Frame everything (F)",
        Action::FrameAll,
        action,
    );
    button(
        ui,
        layout,
        true,
        "Reset",
        "Back to the front view (R)",
        Action::ResetView,
        action,
    );
    toggle(
        ui,
        layout,
        &mut options.wireframe,
        "Edges",
        "Show mesh edges (W)",
    );
    toggle(
        ui,
        layout,
        &mut options.grid,
        "Grid",
        "Show the ground grid (G)",
    );
    toggle(
        ui,
        layout,
        &mut options.clay,
        "Clay",
        "Draw imported models as clay, without their colours",
    );
    toggle(ui, layout, show_help, "Help", "Shortcuts and gestures (H)");
}

/// A toggle button at least a target square (in the compact layout's menu too).
fn toggle(ui: &mut egui::Ui, layout: Layout, value: &mut bool, label: &str, hint: &str) {
    let button =
        egui::Button::selectable(*value, label).min_size(egui::vec2(layout.target, layout.target));
    if ui.add(button).on_hover_text(hint).clicked() {
        *value = !*value;
    }
}

#[cfg(test)]
mod tests {
    use super::counted;

    #[test]
    fn counts_read_as_words() {
        assert_eq!(counted(1, "model"), "1 model");
        assert_eq!(counted(0, "curve"), "0 curves");
        assert_eq!(counted(39_340, "vertex"), "39,340 vertices");
        assert_eq!(counted(1_002_528, "triangle"), "1,002,528 triangles");
        assert_eq!(counted(100, "vertex"), "100 vertices");
    }
}
