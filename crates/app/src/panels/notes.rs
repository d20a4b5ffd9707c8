//! The notes panel: what the last op wanted the user to know (an import's repairs, the
//! textures it left behind; `Editor::notes`), shown until dismissed.

/// What the panel shows and which document revision it was taken from.
#[derive(Debug, Default)]
pub struct Notes {
    /// The sentences shown, until dismissed.
    pub shown: Option<Vec<String>>,
    /// The revision whose notes were last looked at.
    seen: Option<(u64, u64)>,
}

impl Notes {
    /// Shows the notes of the op that brought the document to `revision` (documents opened,
    /// editor replacements, then edits), once. A document opened or restored says nothing:
    /// its notes were said when its op was made.
    pub fn follow(&mut self, revision: (u64, u64), notes: &[String]) {
        let before = self.seen.replace(revision);
        let edited =
            before.is_some_and(|(opened, edits)| opened == revision.0 && edits != revision.1);
        if edited && !notes.is_empty() {
            self.shown = Some(notes.to_vec());
        }
    }
}

impl Notes {
    /// Escape dismisses the panel while it shows (taking the key: it drops no gesture
    /// then). Runs before the app's shortcuts.
    pub fn take_escape(&mut self, ctx: &egui::Context) {
        let escape =
            |i: &mut egui::InputState| i.consume_key(egui::Modifiers::NONE, egui::Key::Escape);
        if self.shown.is_some() && ctx.input_mut(escape) {
            self.shown = None;
        }
    }
}

/// Shows the panel while there are notes; OK dismisses it (Escape too: [`Notes::take_escape`]).
pub fn notes_ui(ctx: &egui::Context, notes: &mut Notes) {
    let Some(sentences) = &notes.shown else {
        return;
    };
    let mut dismissed = false;
    egui::Window::new("Notes on the import")
        .collapsible(false)
        .resizable(false)
        .default_width(420.0)
        .anchor(egui::Align2::CENTER_TOP, egui::vec2(0.0, 110.0))
        .show(ctx, |ui| {
            for sentence in sentences {
                ui.label(sentence);
            }
            ui.add_space(6.0);
            let ok = egui::Button::new("OK").min_size(egui::vec2(64.0, 36.0));
            dismissed |= ui.add(ok).clicked();
        });
    if dismissed {
        notes.shown = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn notes_show_once_per_revision_and_stay_dismissed() {
        let said = vec![String::from(
            "Image 0 is image/webp, which Sketchmesh does not carry.",
        )];
        let mut notes = Notes::default();
        notes.follow((0, 0), &[]);
        notes.follow((0, 1), &said);
        assert_eq!(notes.shown.as_deref(), Some(said.as_slice()));
        notes.shown = None;
        notes.follow((0, 1), &said);
        assert_eq!(notes.shown, None, "dismissed notes stay dismissed");
        notes.follow((0, 2), &[]);
        assert_eq!(notes.shown, None, "an op without notes shows nothing");
        notes.follow((1, 7), &said);
        assert_eq!(
            notes.shown, None,
            "a restored document's last notes are not said again"
        );
    }
}
