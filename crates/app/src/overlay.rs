//! Drawing over the 3D view, shared by the app and the tools: a hint line, a stroke as it
//! will be stored, a piece of outline, a fall-off level's gray, and the card at the bottom
//! for work that runs.

use sketchmesh_core::curve::{StrokePoint, process_stroke};

use crate::render::geometry::pressure_width;

/// A piece of outline on screen: green when confident, orange otherwise; the ends marked
/// when they can be dragged.
pub fn outline_ui(
    ui: &egui::Ui,
    viewport: egui::Rect,
    points: &[glam::DVec2],
    confident: bool,
    croppable: bool,
) {
    let color = if confident {
        egui::Color32::from_rgb(90, 220, 120)
    } else {
        egui::Color32::from_rgb(240, 150, 60)
    };
    let points: Vec<egui::Pos2> = points
        .iter()
        .map(|p| viewport.min + egui::vec2(p.x as f32, p.y as f32))
        .collect();
    if croppable {
        for end in [points.first(), points.last()].into_iter().flatten() {
            ui.painter().circle_filled(*end, 7.0, color);
        }
    }
    ui.painter()
        .add(egui::Shape::line(points, egui::Stroke::new(4.0, color)));
}

/// What to do next, at the top of the view, wrapped to its width (a phone's is narrow), on
/// a dark band so it reads over a light model; where it ends (screen y).
pub fn hint_ui(ui: &egui::Ui, viewport: egui::Rect, text: &str) -> f32 {
    let color = egui::Color32::from_white_alpha(220);
    let galley = centered_galley(ui, viewport, text, color);
    let at = viewport.center_top() + egui::vec2(0.0, 14.0);
    let rect = galley.rect.translate(at.to_vec2());
    let band = rect.expand2(egui::vec2(10.0, 5.0));
    ui.painter()
        .rect_filled(band, 6.0, egui::Color32::from_black_alpha(120));
    ui.painter().galley(at, galley, color);
    band.max.y
}

/// `text` laid out centred and wrapped to the view's width, to be drawn at the view's
/// horizontal middle.
pub fn centered_galley(
    ui: &egui::Ui,
    viewport: egui::Rect,
    text: &str,
    color: egui::Color32,
) -> std::sync::Arc<egui::Galley> {
    let width = (viewport.width() - 40.0).max(80.0);
    let mut job = egui::text::LayoutJob::simple(
        text.to_owned(),
        egui::FontId::proportional(16.0),
        color,
        width,
    );
    job.halign = egui::Align::Center;
    ui.painter().layout_job(job)
}

/// Draws a stroke, smoothed as it will be stored, with pressure widths.
pub fn stroke_ui(ui: &egui::Ui, viewport: egui::Rect, raw: &[StrokePoint], color: egui::Color32) {
    let points = process_stroke(raw).unwrap_or_else(|_| raw.to_vec());
    let to_screen = |p: &StrokePoint| viewport.min + egui::vec2(p.pos.x as f32, p.pos.y as f32);
    for pair in points.windows(2) {
        let width = pressure_width((pair[0].pressure + pair[1].pressure) * 0.5) as f32;
        ui.painter()
            .line_segment([to_screen(&pair[0]), to_screen(&pair[1])], (width, color));
        ui.painter()
            .circle_filled(to_screen(&pair[1]), width * 0.5, color);
    }
}

/// The gray a fall-off level is drawn in on the model (`scene.wgsl`'s `falloff_gray`,
/// gamma-encoded), so the panel and the model agree.
pub fn falloff_gray(level: f64) -> u8 {
    let linear = 0.04 + (1.0 - 0.04) * level.clamp(0.0, 1.0);
    (linear.powf(1.0 / 2.2) * 255.0).round() as u8
}

/// A card at the bottom of `viewport`, at most `width` wide, over the scene: where what
/// runs (work in progress, an example's making) shows its state and its buttons.
pub fn bottom_card(
    ctx: &egui::Context,
    id: &str,
    viewport: egui::Rect,
    width: f32,
    body: impl FnOnce(&mut egui::Ui),
) {
    egui::Area::new(egui::Id::unique(id))
        .order(egui::Order::Foreground)
        .pivot(egui::Align2::CENTER_BOTTOM)
        .fixed_pos(viewport.center_bottom() - egui::vec2(0.0, 14.0))
        .constrain(true)
        .show(ctx, |ui| {
            egui::Frame::popup(ui.style()).show(ui, |ui| {
                ui.set_max_width(width);
                body(ui);
            });
        });
}
