//! A tool's button: its drawn icon, its name under it (or beside it) where the row has
//! room, and a tooltip with its name, key, what it does and when to choose it, shown on hover
//! and on a long press, so a finger and a pen, which do not hover, see it too.

use crate::tools::{Icon, Mode, icon};

/// The icon's size in a tool's button, in points.
pub const ICON: f32 = 22.0;

/// The size of the name under an icon, in points.
const NAME_SIZE: f32 = 12.0;

/// The height of a button with its name under its icon, in points: a finger's target, and
/// room for a 22-point icon over a line of small text.
pub const NAMED_HEIGHT: f32 = 46.0;

/// How long a press is held before the tooltip shows (s): a hold, and shorter than egui's
/// longest click (0.8 s), so that letting go after reading it does not pick the tool.
const LONG_PRESS_S: f64 = 0.45;

/// Space around the icon and the name inside a button, in points.
const PADDING: f32 = 6.0;

/// What a tool's button shows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shows {
    /// Its icon with its name under it.
    Below,
    /// Its icon alone (a phone's row; the name is in its tooltip and in the More menu).
    Icon,
    /// Its icon with its name beside it (a menu's row).
    Beside,
}

/// The width of `mode`'s button showing `shows`, at least `target`.
pub fn width(ui: &egui::Ui, mode: Mode, shows: Shows, target: f32) -> f32 {
    width_of(ui, mode.label(), shows, target)
}

/// The width of a button named `label` showing `shows`, at least `target`.
pub fn width_of(ui: &egui::Ui, label: &str, shows: Shows, target: f32) -> f32 {
    let name = name_width(ui, label, shows);
    let wide = match shows {
        Shows::Below => name + 2.0 * PADDING,
        Shows::Icon => ICON + 2.0 * PADDING,
        Shows::Beside => ICON + name + 3.0 * PADDING,
    };
    wide.max(target)
}

/// The name's font: a menu's text beside the icon, smaller under it.
fn name_font(ui: &egui::Ui, shows: Shows) -> egui::FontId {
    match shows {
        Shows::Beside => egui::TextStyle::Button.resolve(ui.style()),
        _ => egui::FontId::proportional(NAME_SIZE),
    }
}

fn name_width(ui: &egui::Ui, label: &str, shows: Shows) -> f32 {
    let name =
        (ui.painter()).layout_no_wrap(label.to_owned(), name_font(ui, shows), egui::Color32::WHITE);
    name.size().x
}

/// A tool's button, `size` points, selected or not; shows its tooltip on hover and on a
/// long press.
pub fn tool_button(
    ui: &mut egui::Ui,
    mode: Mode,
    selected: bool,
    shows: Shows,
    size: egui::Vec2,
) -> egui::Response {
    let response = icon_button(ui, mode.icon(), mode.label(), selected, shows, size);
    let held = held_for(ui, &response);
    if held >= LONG_PRESS_S {
        response.show_tooltip_ui(|ui| tooltip_ui(ui, mode));
    } else if held > 0.0 {
        let wait = std::time::Duration::from_secs_f64(LONG_PRESS_S - held);
        ui.ctx().request_repaint_after(wait);
    }
    response.on_hover_ui(|ui| tooltip_ui(ui, mode))
}

/// A button `size` points showing a drawn icon and `label` as `shows` says: framed while
/// selected, hovered or pressed, bare otherwise, as a tool palette's.
pub fn icon_button(
    ui: &mut egui::Ui,
    icon: Icon,
    label: &str,
    selected: bool,
    shows: Shows,
    size: egui::Vec2,
) -> egui::Response {
    let (rect, response) = ui.allocate_exact_size(size, egui::Sense::click());
    response.widget_info(|| {
        egui::WidgetInfo::selected(egui::Role::Button, ui.is_enabled(), selected, label)
    });
    if !ui.is_rect_visible(rect) {
        return response;
    }
    let visuals = ui.style().interact_selectable(&response, selected);
    if selected || response.hovered() || response.is_pointer_button_down_on() {
        ui.painter().rect(
            rect,
            visuals.corner_radius,
            visuals.weak_bg_fill,
            visuals.bg_stroke,
            egui::StrokeKind::Inside,
        );
    }
    let ink = visuals.text_color();
    let name = (ui.painter()).layout_no_wrap(label.to_owned(), name_font(ui, shows), ink);
    let icon_at = match shows {
        Shows::Below => egui::pos2(rect.center().x, rect.top() + PADDING + ICON / 2.0),
        Shows::Icon => rect.center(),
        Shows::Beside => egui::pos2(rect.left() + PADDING + ICON / 2.0, rect.center().y),
    };
    let icon_rect = egui::Rect::from_center_size(icon_at, egui::Vec2::splat(ICON));
    icon::paint(ui.painter(), icon_rect, ink, icon);
    let name_at = match shows {
        Shows::Below => Some(egui::pos2(
            rect.center().x - name.size().x / 2.0,
            rect.bottom() - PADDING / 2.0 - name.size().y,
        )),
        Shows::Icon => None,
        Shows::Beside => Some(egui::pos2(
            icon_rect.right() + PADDING,
            rect.center().y - name.size().y / 2.0,
        )),
    };
    if let Some(at) = name_at {
        ui.painter().galley(at, name, ink);
    }
    response
}

/// How long the pointer has been held down on `response`'s widget (s; 0 if it is not).
fn held_for(ui: &egui::Ui, response: &egui::Response) -> f64 {
    if !response.is_pointer_button_down_on() {
        return 0.0;
    }
    ui.input(|i| {
        let dragging = i.pointer.is_decidedly_dragging();
        match (i.pointer.press_start_time(), dragging) {
            (Some(start), false) => (i.time - start).max(f64::MIN_POSITIVE),
            _ => 0.0,
        }
    })
}

/// A tool's name and key, what it does and, for a tool that deforms, when to choose it.
pub fn tooltip_ui(ui: &mut egui::Ui, mode: Mode) {
    ui.set_max_width(280.0);
    ui.strong(format!("{} ({})", mode.label(), mode.key().name()));
    ui.label(mode.hint());
    if let Some(when) = mode.info().when {
        ui.label(egui::RichText::new(when).italics());
    }
}

/// A tool's icon, `size` points square, in the text colour, as the help shows it.
pub fn icon_ui(ui: &mut egui::Ui, mode: Mode, size: f32) -> egui::Response {
    let (rect, response) = ui.allocate_exact_size(egui::Vec2::splat(size), egui::Sense::hover());
    let ink = ui.visuals().strong_text_color();
    icon::paint(ui.painter(), rect, ink, mode.icon());
    response
}
