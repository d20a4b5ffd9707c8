//! The progress line of work running off the frame (an import in the page's worker, a
//! replayed session): a spinner, what runs, and a touch-sized Cancel. It sits where the
//! status line does, on its own layer, so a tap on Cancel neither draws nor orbits; on a
//! narrow phone its text wraps rather than push Cancel off the screen.

/// Touch-sized Cancel.
const CANCEL: egui::Vec2 = egui::vec2(88.0, 44.0);

/// Shows `what` is running at the bottom of `viewport`; whether Cancel was pressed.
pub fn progress_ui(ctx: &egui::Context, viewport: egui::Rect, what: &str) -> bool {
    let mut cancelled = false;
    let width = (viewport.width() - 24.0).max(CANCEL.x + 60.0);
    egui::Area::new(egui::Id::unique("work in progress"))
        .order(egui::Order::Foreground)
        .pivot(egui::Align2::CENTER_BOTTOM)
        .fixed_pos(viewport.center_bottom() - egui::vec2(0.0, 14.0))
        .constrain(true)
        .show(ctx, |ui| {
            egui::Frame::popup(ui.style()).show(ui, |ui| {
                ui.set_max_width(width);
                ui.horizontal(|ui| {
                    ui.add(egui::Spinner::new().size(20.0));
                    let room = ui.available_width() - CANCEL.x - ui.spacing().item_spacing.x;
                    ui.allocate_ui(egui::vec2(room.max(40.0), CANCEL.y), |ui| {
                        ui.add(egui::Label::new(what).wrap());
                    });
                    cancelled = ui
                        .add(egui::Button::new("Cancel").min_size(CANCEL))
                        .clicked();
                });
            });
        });
    cancelled
}
