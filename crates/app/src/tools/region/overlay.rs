//! What the region tool draws over the view: its handles and its profile panel.

use super::{AxisMark, Part, ProfileView};
use crate::tools::tool::Scene;

/// The region tool's handles: per handle three axes (red along the curve, green along
/// the surface normal, blue across), each drawn in its thirds: a bar near the handle
/// (move), a square in the middle (scale), a ring at the end (turn); the part being
/// dragged brighter.
pub fn handles_ui(ui: &egui::Ui, scene: &Scene<'_>, axes: &[AxisMark]) {
    let at = |p: glam::DVec2| scene.at(p);
    let painter = ui.painter();
    for mark in axes {
        let [r, g, b] = [[230, 80, 70], [90, 200, 90], [80, 140, 240]][mark.axis];
        let colour = |part| match mark.dragged == Some(part) {
            true => egui::Color32::from_rgb(255, 240, 160),
            false => egui::Color32::from_rgb(r, g, b),
        };
        let (from, to) = (at(mark.from), at(mark.to));
        let third = |k: f32| from + (to - from) * (k / 3.0);
        let shadow = egui::Stroke::new(6.0, egui::Color32::from_black_alpha(140));
        painter.line_segment([from, to], shadow);
        painter.line_segment(
            [from, third(1.0)],
            egui::Stroke::new(4.0, colour(Part::Translate)),
        );
        painter.line_segment(
            [third(1.0), to],
            egui::Stroke::new(2.0, egui::Color32::from_rgb(r, g, b)),
        );
        let square = egui::Rect::from_center_size(third(1.5), egui::vec2(11.0, 11.0));
        painter.rect_filled(square, 2.0, colour(Part::Scale));
        painter.circle_stroke(to, 7.0, egui::Stroke::new(3.0, colour(Part::Rotate)));
    }
    for mark in axes.iter().filter(|m| m.axis == 0) {
        painter.circle_filled(at(mark.from), 6.0, egui::Color32::WHITE);
        painter.circle_stroke(
            at(mark.from),
            6.0,
            egui::Stroke::new(1.5, egui::Color32::BLACK),
        );
    }
}

/// The region tool's profile panel in the view's lower right corner: the cross-section
/// across the curve coloured from blue (one side of the curve) to orange (the other), the
/// same colours along it on the model, the arrow out of the surface where the curve
/// crosses, and the stroke drawn over it in white.
pub fn profile_ui(ui: &egui::Ui, scene: &Scene<'_>, view: &ProfileView) {
    let (size, at) = (scene.size(), |p: glam::DVec2| scene.at(p));
    let painter = ui.painter();
    let panel = egui::Rect::from_min_size(
        at(view.corner),
        egui::vec2(view.side as f32, view.side as f32),
    );
    painter.rect_filled(panel, 8.0, egui::Color32::from_black_alpha(200));
    painter.text(
        panel.left_top() + egui::vec2(8.0, 6.0),
        egui::Align2::LEFT_TOP,
        "Profile: draw over it",
        egui::FontId::proportional(12.0),
        egui::Color32::from_gray(210),
    );
    if let Some(why) = &view.refusal {
        let galley = painter.layout(
            why.clone(),
            egui::FontId::proportional(12.0),
            egui::Color32::from_gray(220),
            panel.width() - 16.0,
        );
        painter.galley(
            panel.left_top() + egui::vec2(8.0, 26.0),
            galley,
            egui::Color32::WHITE,
        );
        return;
    }
    let gradient = |k: usize, n: usize| {
        let t = k as f32 / (n.max(2) - 1) as f32;
        let mix = |a: f32, b: f32| (a + (b - a) * t) as u8;
        egui::Color32::from_rgb(mix(70.0, 250.0), mix(150.0, 150.0), mix(255.0, 40.0))
    };
    let camera = scene.camera;
    let on_screen: Vec<Option<egui::Pos2>> = (view.section_in_world.iter())
        .map(|&p| camera.screen_from_world(p, size).map(|s| at(s.truncate())))
        .collect();
    let n = view.section.len();
    for k in 1..n {
        let colour = gradient(k, n);
        let stroke = egui::Stroke::new(2.5, colour);
        painter.line_segment([at(view.section[k - 1]), at(view.section[k])], stroke);
        if let (Some(a), Some(b)) = (on_screen[k - 1], on_screen[k]) {
            painter.line_segment([a, b], egui::Stroke::new(3.0, colour));
        }
    }
    let (from, to) = view.curve;
    painter.arrow(
        at(from),
        at(to) - at(from),
        egui::Stroke::new(2.0, egui::Color32::from_rgb(255, 230, 120)),
    );
    if let Some(stroke) = &view.stroke {
        let points: Vec<egui::Pos2> = stroke.iter().map(|&p| at(p)).collect();
        painter.add(egui::Shape::line(
            points,
            egui::Stroke::new(2.0, egui::Color32::WHITE),
        ));
    }
}
