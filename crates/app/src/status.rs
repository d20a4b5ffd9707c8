//! The status line: the latest sentence for the user, shown at the bottom of the view for a
//! few seconds. What it reports looks different by its [`Tone`]: a success, work under way,
//! a refusal (what to do instead) or a plain note each have their colour and marker.

/// How long a status message stays up, in seconds.
const STATUS_SECONDS: f64 = 6.0;

/// What kind of news a status sentence is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Tone {
    /// Something the user asked for was done (an export, an import, an optimization).
    Success,
    /// Something is under way or waits (a file opening, an edit being computed).
    Progress,
    /// Something was not done, and the sentence says what to do instead.
    Refusal,
    /// Anything else worth knowing.
    #[default]
    Info,
}

impl Tone {
    /// Its colour: green, blue, orange, light grey.
    pub fn color(self) -> egui::Color32 {
        match self {
            Tone::Success => egui::Color32::from_rgb(110, 220, 140),
            Tone::Progress => egui::Color32::from_rgb(130, 185, 255),
            Tone::Refusal => egui::Color32::from_rgb(255, 160, 60),
            Tone::Info => egui::Color32::from_gray(225),
        }
    }

    /// Its marker, before the sentence (glyphs of egui's icon font).
    fn marker(self) -> &'static str {
        match self {
            Tone::Success => "✔",
            Tone::Progress => "⟳",
            Tone::Refusal => "⚠",
            Tone::Info => "ℹ",
        }
    }
}

/// The latest sentence for the user, its tone, and until when it shows (the frame clock,
/// seconds).
#[derive(Debug, Default)]
pub struct Status(Option<(String, Tone, f64)>);

impl Status {
    /// Says `message` in `tone` from `now` on, in place of what was said.
    pub fn say(&mut self, tone: Tone, message: String, now: f64) {
        self.0 = Some((message, tone, now + STATUS_SECONDS));
    }

    /// Says that something was done.
    pub fn done(&mut self, message: String, now: f64) {
        self.say(Tone::Success, message, now);
    }

    /// Says that something is under way or waits.
    pub fn working(&mut self, message: String, now: f64) {
        self.say(Tone::Progress, message, now);
    }

    /// Says that something was not done, and what to do instead.
    pub fn refuse(&mut self, message: String, now: f64) {
        self.say(Tone::Refusal, message, now);
    }

    /// Says nothing.
    pub fn clear(&mut self) {
        self.0 = None;
    }

    /// What is said, if anything.
    pub fn message(&self) -> Option<&str> {
        self.0.as_ref().map(|(message, ..)| message.as_str())
    }

    /// What is said and its tone, if anything.
    pub fn said(&self) -> Option<(&str, Tone)> {
        (self.0.as_ref()).map(|(message, tone, _)| (message.as_str(), *tone))
    }

    /// Says nothing once what was said has shown long enough at `now`.
    pub fn expire(&mut self, now: f64) {
        if self.0.as_ref().is_some_and(|(.., until)| *until < now) {
            self.0 = None;
        }
    }
}

/// The latest message, at the bottom of the view on a dark band, wrapped to its width, in
/// its tone's colour after its marker, with a bar of that colour down the band's left edge:
/// the view never moves or shrinks for a message, however long.
pub fn status_ui(ui: &egui::Ui, viewport: egui::Rect, text: &str, tone: Tone) {
    let color = tone.color();
    let font = egui::FontId::proportional(15.0);
    let width = (viewport.width() - 40.0).max(80.0);
    let said = format!("{}  {text}", tone.marker());
    let galley = ui.painter().layout(said, font, color, width);
    let size = galley.size();
    let pos = viewport.center_bottom() - egui::vec2(0.5 * size.x, size.y + 18.0);
    let band = egui::Rect::from_min_size(pos, size).expand2(egui::vec2(12.0, 8.0));
    ui.painter()
        .rect_filled(band, 6.0, egui::Color32::from_rgb(20, 21, 25));
    let bar = egui::Rect::from_min_max(band.min, egui::pos2(band.min.x + 4.0, band.max.y));
    ui.painter().rect_filled(bar, 2.0, color);
    ui.painter().galley(pos, galley, color);
}
