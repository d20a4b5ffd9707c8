//! The status line: the latest sentence for the user, shown at the bottom of the view for a
//! few seconds.

/// How long a status message stays up, in seconds.
const STATUS_SECONDS: f64 = 6.0;

/// The latest sentence for the user, and until when it shows (the frame clock, seconds).
#[derive(Debug, Default)]
pub struct Status(Option<(String, f64)>);

impl Status {
    /// Says `message` from `now` on, in place of what was said.
    pub fn say(&mut self, message: String, now: f64) {
        self.0 = Some((message, now + STATUS_SECONDS));
    }

    /// Says nothing.
    pub fn clear(&mut self) {
        self.0 = None;
    }

    /// What is said, if anything.
    pub fn message(&self) -> Option<&str> {
        self.0.as_ref().map(|(message, _)| message.as_str())
    }

    /// Says nothing once what was said has shown long enough at `now`.
    pub fn expire(&mut self, now: f64) {
        if self.0.as_ref().is_some_and(|(_, until)| *until < now) {
            self.0 = None;
        }
    }
}

/// The latest message, at the bottom of the view on a dark band, wrapped to its width: the
/// view never moves or shrinks for a message, however long.
pub fn status_ui(ui: &egui::Ui, viewport: egui::Rect, text: &str) {
    let color = ui.visuals().warn_fg_color;
    let font = egui::FontId::proportional(15.0);
    let width = (viewport.width() - 40.0).max(80.0);
    let galley = ui.painter().layout(text.to_owned(), font, color, width);
    let size = galley.size();
    let pos = viewport.center_bottom() - egui::vec2(0.5 * size.x, size.y + 18.0);
    let band = egui::Rect::from_min_size(pos, size).expand(8.0);
    ui.painter()
        .rect_filled(band, 6.0, egui::Color32::from_rgb(20, 21, 25));
    ui.painter().galley(pos, galley, color);
}
