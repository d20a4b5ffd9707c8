//! The progress line of work running off the frame (an import in the page's worker, a
//! replayed session): a spinner, what runs, and a touch-sized Cancel. It sits where the
//! status line does, on its own layer, so a tap on Cancel neither draws nor orbits; on a
//! narrow phone its text wraps rather than push Cancel off the screen.
//!
//! Its ring turns in two ticks a second rather than at every frame (egui's spinner): every
//! repaint draws the whole scene again, and while the worker takes one core, a page
//! repainting often competes with it for the other (a tablet would also spend its battery on
//! an animation). On this project's 2-core machine, with the software rasterizer and a
//! 40k-vertex shape on screen, the page's repaints kept its main thread busy for 11 of the
//! 11 s a pull's result took in the worker; with fewer, for 5–7 of 8–12 s.

/// Touch-sized Cancel.
const CANCEL: egui::Vec2 = egui::vec2(88.0, 44.0);

/// Shows `what` is running at the bottom of `viewport`; whether Cancel was pressed.
pub fn progress_ui(ctx: &egui::Context, viewport: egui::Rect, what: &str) -> bool {
    let mut cancelled = false;
    let width = (viewport.width() - 24.0).max(CANCEL.x + 60.0);
    crate::overlay::bottom_card(ctx, "work in progress", viewport, width, |ui| {
        ui.horizontal(|ui| {
            ticking_ring(ui);
            let room = ui.available_width() - CANCEL.x - ui.spacing().item_spacing.x;
            ui.allocate_ui(egui::vec2(room.max(40.0), CANCEL.y), |ui| {
                ui.add(egui::Label::new(what).wrap());
            });
            cancelled = ui
                .add(egui::Button::new("Cancel").min_size(CANCEL))
                .clicked();
        });
    });
    cancelled
}

/// A ring with a gap that moves an eighth of a turn every [`TICK`] seconds.
fn ticking_ring(ui: &mut egui::Ui) {
    let (rect, _) = ui.allocate_exact_size(egui::Vec2::splat(20.0), egui::Sense::hover());
    let time = ui.input(|i| i.time);
    let tick = (time / TICK).floor();
    let start = tick * std::f64::consts::TAU / 8.0;
    let points: Vec<egui::Pos2> = (0..=24)
        .map(|k| {
            let angle = (start + f64::from(k) / 24.0 * 0.75 * std::f64::consts::TAU) as f32;
            rect.center() + 8.0 * egui::vec2(angle.cos(), angle.sin())
        })
        .collect();
    let stroke = egui::Stroke::new(2.5, ui.visuals().strong_text_color());
    ui.painter().add(egui::Shape::line(points, stroke));
    let next = (tick + 1.0) * TICK - time;
    ui.ctx()
        .request_repaint_after(std::time::Duration::from_secs_f64(next.max(0.01)));
}

/// Seconds between two ticks of the ring.
const TICK: f64 = 0.5;
