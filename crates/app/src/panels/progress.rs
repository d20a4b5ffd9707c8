//! The progress line of work running off the frame (an import in the page's worker): a
//! spinner, what runs, and a touch-sized Cancel. It sits where the status line does, on its
//! own layer, so a tap on Cancel neither draws nor orbits.

/// Touch-sized Cancel.
const CANCEL: egui::Vec2 = egui::vec2(88.0, 44.0);

/// Shows `what` is running at the bottom of `viewport`; whether Cancel was pressed.
pub fn progress_ui(ctx: &egui::Context, viewport: egui::Rect, what: &str) -> bool {
    let mut cancelled = false;
    egui::Area::new(egui::Id::unique("work in progress"))
        .order(egui::Order::Foreground)
        .pivot(egui::Align2::CENTER_BOTTOM)
        .fixed_pos(viewport.center_bottom() - egui::vec2(0.0, 14.0))
        .show(ctx, |ui| {
            egui::Frame::popup(ui.style()).show(ui, |ui| {
                ui.horizontal(|ui| {
                    ui.add(egui::Spinner::new().size(20.0));
                    ui.label(what);
                    cancelled = ui
                        .add(egui::Button::new("Cancel").min_size(CANCEL))
                        .clicked();
                });
            });
        });
    cancelled
}
