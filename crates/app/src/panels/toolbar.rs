//! The toolbar: import and export, undo and redo for tablets (no keyboard there), view
//! switches, status.

use sketchmesh_core::document::Editor;

use crate::panels::tool_button::{self, NAMED_HEIGHT, Shows, icon_button, tool_button};
use crate::render::ViewOptions;
use crate::tools::icon::Pen;
use crate::tools::{Icon, Mode, ToolOutput, ToolSet};

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

/// The signs the compact layout's menus show as text: ☰ (files and view), ⋯ (more tools).
const SIGNS: [&str; 2] = ["☰", "⋯"];

/// Below this width (points) the compact toolbar's tools show their icons only: a phone's
/// row then holds four tools beside the menus and the arrows.
const ICONS_ONLY_BELOW: f32 = 600.0;

/// The gap between two groups of tools, in points, with a faint line in it.
const GROUP_GAP: f32 = 9.0;

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

/// Shows the toolbar: two rows, the tools (the menus, undo and redo, the tools in their
/// groups and, wide, Help) and the mode's options (on the bottom the options come
/// first, so that the tools are nearest the thumb). Each row has one height whatever the
/// tool: the options row is one line that scrolls sideways should it not fit. Wide, the file
/// and view buttons sit in a File and a View menu; in the compact layout the file and view buttons sit in one
/// menu (☰) and the tools that do not fit in another (⋯).
pub fn toolbar_ui(
    ui: &mut egui::Ui,
    layout: Layout,
    editor: &Editor,
    symmetry: bool,
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
    let full_width = ui.available_width();
    let shows = tool_shows(layout, full_width);
    let height = match shows {
        Shows::Icon => layout.target,
        _ => NAMED_HEIGHT.max(layout.target),
    };
    let target = egui::vec2(layout.target, height);
    tools_row(ui, layout.compact, height, |ui| {
        // Every button of the row as tall as the tools'.
        ui.spacing_mut().interact_size.y = height;
        ui.spacing_mut().button_padding.x = 7.0;
        if layout.compact {
            let menu = egui::Button::new(SIGNS[0]).min_size(target);
            egui::containers::menu::MenuButton::from_button(menu).ui(ui, |ui| {
                file_buttons(ui, layout, editor, &mut action);
                ui.separator();
                view_buttons(ui, layout, options, &mut action);
                // A phone's row has no room for it beside the tools.
                symmetry_switch(ui, symmetry, Shows::Beside, layout.target, &mut action);
                help_toggle(ui, layout, show_help);
            });
        } else {
            // No title: the page's is enough, and the row needs the room for the tools.
            let menu = egui::Button::new("File").min_size(target);
            egui::containers::menu::MenuButton::from_button(menu)
                .ui(ui, |ui| file_buttons(ui, layout, editor, &mut action));
            let menu = egui::Button::new("View").min_size(target);
            egui::containers::menu::MenuButton::from_button(menu)
                .ui(ui, |ui| view_buttons(ui, layout, options, &mut action));
        }
        let undo = (editor.can_undo(), undo_icon as Icon, "Undo");
        let redo = (editor.can_redo(), redo_icon as Icon, "Redo");
        for ((enabled, icon, label), hint, a) in [
            (undo, "Undo (Ctrl+Z, or tap with two fingers)", Action::Undo),
            (
                redo,
                "Redo (Ctrl+Shift+Z or Ctrl+Y, or tap with three fingers)",
                Action::Redo,
            ),
        ] {
            let size = egui::vec2(layout.target, height);
            let response = ui
                .add_enabled_ui(enabled, |ui| {
                    icon_button(ui, icon, label, false, Shows::Icon, size)
                })
                .inner;
            if response.on_hover_text(hint).clicked() {
                action = Some(a);
            }
        }
        if !layout.compact {
            symmetry_switch(ui, symmetry, shows, height, &mut action);
            group_gap(ui, height);
        }
        // Compact, the tools that fit beside a More menu (the one in use among them), the
        // rest in it; wide, all of them.
        let (shown, more) = if layout.compact {
            let room = full_width - ui.min_rect().width() - ui.spacing().item_spacing.x;
            tools_in_room(ui, mode, shows, room, layout.target)
        } else {
            (Mode::ALL.to_vec(), Vec::new())
        };
        // A phone's row of icons has no room for the gaps between groups (the More menu
        // shows them).
        let mut group = None;
        for m in shown {
            if shows != Shows::Icon && group.is_some_and(|g| g != m.group()) {
                group_gap(ui, height);
            }
            group = Some(m.group());
            let size = egui::vec2(tool_button::width(ui, m, shows, layout.target), height);
            if tool_button(ui, m, m == mode, shows, size).clicked() {
                picked_mode = Some(m);
            }
        }
        if !more.is_empty() {
            let button = egui::Button::new(SIGNS[1]).min_size(target);
            egui::containers::menu::MenuButton::from_button(button).ui(ui, |ui| {
                more_menu_ui(ui, &more, mode, layout.target, &mut picked_mode);
            });
        }
        if !layout.compact {
            group_gap(ui, height);
            help_toggle(ui, layout, show_help);
        }
    });
    let options_last = (!layout.bottom).then(|| options_row(ui, layout, editor, tools));
    (action.or(picked_mode.map(Action::Mode)))
        .or(options_first.flatten())
        .or(options_last.flatten())
}

/// What the tools' buttons show in the tools row of `layout`, `width` points wide: names
/// under the icons, but a phone's row has room for icons only.
fn tool_shows(layout: Layout, width: f32) -> Shows {
    if layout.compact && width < ICONS_ONLY_BELOW {
        Shows::Icon
    } else {
        Shows::Below
    }
}

/// The More menu's tools, each with its icon and name, a line between groups.
fn more_menu_ui(
    ui: &mut egui::Ui,
    more: &[Mode],
    mode: Mode,
    target: f32,
    picked: &mut Option<Mode>,
) {
    let width = (more.iter())
        .map(|&m| tool_button::width(ui, m, Shows::Beside, target))
        .fold(target, f32::max);
    for (k, &m) in more.iter().enumerate() {
        if k > 0 && more[k - 1].group() != m.group() {
            ui.separator();
        }
        let size = egui::vec2(width, target);
        if tool_button(ui, m, m == mode, Shows::Beside, size).clicked() {
            *picked = Some(m);
        }
    }
}

/// The space between two groups of tools, a faint line in its middle.
fn group_gap(ui: &mut egui::Ui, height: f32) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(GROUP_GAP, height), egui::Sense::hover());
    let stroke = ui.visuals().widgets.noninteractive.bg_stroke;
    let x = rect.center().x;
    let (top, bottom) = (rect.top() + height * 0.2, rect.bottom() - height * 0.2);
    ui.painter().vline(x, top..=bottom, stroke);
}

/// Undo's icon: an arrow turning back to the left.
fn undo_icon(pen: &Pen<'_>) {
    pen.arc((12.5, 15.0), (7.5, 7.0), 0.0, -3.0, false);
    pen.arrow_head((5.2, 11.0), (5.0, 18.5));
}

/// Redo's icon: undo's, mirrored.
fn redo_icon(pen: &Pen<'_>) {
    let half_turn = std::f32::consts::PI;
    pen.arc((11.5, 15.0), (7.5, 7.0), half_turn, half_turn + 3.0, false);
    pen.arrow_head((18.8, 11.0), (19.0, 18.5));
}

/// The Symmetry switch's name.
const SYMMETRY: &str = "Symmetry";

/// The Symmetry switch, `height` points tall, showing `shows`, lit while `on`: pressed, it
/// sets `action`.
fn symmetry_switch(
    ui: &mut egui::Ui,
    on: bool,
    shows: Shows,
    height: f32,
    action: &mut Option<Action>,
) {
    let width = tool_button::width_of(ui, SYMMETRY, shows, height);
    let size = egui::vec2(width, height);
    let response = icon_button(ui, symmetry_icon, SYMMETRY, on, shows, size);
    let hint = match on {
        true => {
            "Symmetry is on: what you draw or change on one side is mirrored across the \
             plane shown (X)"
        }
        false => {
            "Symmetry is off: turn it on to mirror what you draw or change across the plane (X)"
        }
    };
    if response.on_hover_text(hint).clicked() {
        *action = Some(Action::ToggleSymmetry);
    }
}

/// The Symmetry switch's icon: a shape and its mirror image either side of a dashed plane.
fn symmetry_icon(pen: &Pen<'_>) {
    for (from, to) in [(2.0, 6.0), (9.0, 13.0), (16.0, 20.0)] {
        pen.dim_line(&[(12.0, from), (12.0, to)]);
    }
    pen.curve([(9.0, 4.0), (2.0, 5.0), (2.0, 19.0), (9.0, 20.0)], false);
    pen.curve(
        [(15.0, 4.0), (22.0, 5.0), (22.0, 19.0), (15.0, 20.0)],
        false,
    );
}

/// The tools whose buttons (showing `shows`, at least `target` wide, a gap between groups)
/// fit in `room` points, in their order, beside a More button when not all do, with `mode`
/// among them (in the last place that fits, should it come later); and the rest, for the
/// More menu.
fn tools_in_room(
    ui: &egui::Ui,
    mode: Mode,
    shows: Shows,
    room: f32,
    target: f32,
) -> (Vec<Mode>, Vec<Mode>) {
    let spacing = ui.spacing().item_spacing.x;
    let width = |k: usize| {
        let m = Mode::ALL[k];
        let gap = shows != Shows::Icon && k > 0 && Mode::ALL[k - 1].group() != m.group();
        tool_button::width(ui, m, shows, target) + spacing + f32::from(gap) * (GROUP_GAP + spacing)
    };
    let widths: Vec<f32> = (0..Mode::ALL.len()).map(width).collect();
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
        let w = |m: Mode| widths[m as usize];
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
    options_line(ui, layout.target, |ui| {
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

/// The tools row: wide, wrapped onto more lines where the screen is narrow (the same for
/// every tool); in the `compact` layout one line that scrolls sideways should it not fit.
fn tools_row(ui: &mut egui::Ui, compact: bool, height: f32, add: impl FnOnce(&mut egui::Ui)) {
    if compact {
        egui::ScrollArea::horizontal()
            .id_salt("tools")
            .max_height(height)
            .show(ui, |ui| {
                ui.horizontal(add);
            });
    } else {
        ui.horizontal_wrapped(add);
    }
}

/// The options row: one line `height` points tall whatever the tool, which scrolls sideways
/// (a finger or a mouse drags it, a wheel turns it) should the tool's options not fit, so
/// that the view below never moves as the tools change.
fn options_line(ui: &mut egui::Ui, height: f32, add: impl FnOnce(&mut egui::Ui)) {
    egui::ScrollArea::horizontal()
        .id_salt("options")
        .max_height(height)
        .show(ui, |ui| {
            ui.horizontal(|ui| {
                ui.set_height(height);
                add(ui);
            });
        });
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
}

/// Help's button, which opens and closes it.
fn help_toggle(ui: &mut egui::Ui, layout: Layout, show_help: &mut bool) {
    toggle(
        ui,
        layout,
        show_help,
        "Help",
        "Every tool, gesture and shortcut (H)",
    );
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
