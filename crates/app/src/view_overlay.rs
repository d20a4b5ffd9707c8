//! What the view shows over the scene: the tool in use's hint and overlay, what the edit in
//! progress shows (a move held back, an over-sketch's outline piece), the tools' marks and the
//! stroke being drawn, and the strokes that wait for the worker.

use sketchmesh_core::document::{Edit, Op};

use crate::overlay::{centered_galley, hint_ui, outline_ui, stroke_ui};
use crate::tools::{Mark, Scene, ToolSet};

/// Draws over the view: the tool in use's hint and what it shows, what the edit in
/// progress shows (a move held back, the outline piece an over-sketch would replace),
/// the marks and the stroke in progress, and the strokes waiting for the worker.
pub fn draw<'a>(
    ui: &egui::Ui,
    scene: &Scene<'_>,
    tools: &ToolSet,
    waiting: impl Iterator<Item = &'a Op>,
) {
    let viewport = scene.viewport;
    if let Some(hint) = tools.hint(scene.doc) {
        hint_ui(ui, viewport, hint);
    }
    tools.overlay(ui, scene);
    if let Some(kept) = scene.edit.and_then(Edit::limited_move) {
        let said = format!(
            "Held at {:.0}% of the move: more would fold the part through itself",
            100.0 * kept
        );
        hint_ui(ui, viewport, &said);
    }
    if let Some(o) = scene.edit.and_then(Edit::outline) {
        outline_ui(ui, viewport, &o.points, o.is_confident, false);
    }
    for mark in tools.marks(&scene.camera) {
        mark_ui(ui, viewport, &mark);
    }
    if let Some(raw) = tools.preview() {
        stroke_ui(ui, viewport, raw, egui::Color32::from_rgb(242, 199, 82));
    }
    tools.edit_overlay(ui, scene);
    // The strokes made while the worker computes an edit wait for it, shown dimmer.
    for op in waiting {
        let points = op.stroke_points();
        stroke_ui(ui, viewport, &points, egui::Color32::from_rgb(200, 170, 90));
    }
}

/// A lasso (a line) or a brush stroke (a translucent band as wide as the brush) of the
/// optimize tool: green for what moves, orange for features that hold.
fn mark_ui(ui: &egui::Ui, viewport: egui::Rect, mark: &Mark) {
    let color = match mark.features {
        false => egui::Color32::from_rgb(110, 220, 150),
        true => egui::Color32::from_rgb(240, 150, 60),
    };
    let Some(radius) = mark.radius else {
        return stroke_ui(ui, viewport, &mark.points, color);
    };
    let points: Vec<egui::Pos2> = (mark.points.iter())
        .map(|p| viewport.min + egui::vec2(p.pos.x as f32, p.pos.y as f32))
        .collect();
    let band = egui::Stroke::new(2.0 * radius as f32, color.gamma_multiply(0.35));
    match points.as_slice() {
        [only] => ui.painter().circle_filled(*only, radius as f32, band.color),
        _ => ui.painter().add(egui::Shape::line(points, band)),
    };
}

/// Where the pen would touch: a ring that shows on light and dark alike.
pub fn pen_ring(ui: &egui::Ui, at: egui::Pos2) {
    let painter = ui.painter();
    painter.circle_stroke(
        at,
        5.0,
        egui::Stroke::new(3.0, egui::Color32::from_black_alpha(140)),
    );
    painter.circle_stroke(at, 5.0, egui::Stroke::new(1.5, egui::Color32::WHITE));
}

/// What to do first, at the bottom of an empty view.
pub fn first_hint(ui: &egui::Ui, viewport: egui::Rect) {
    let text = "Draw a closed outline to make a shape. Two fingers or right-drag orbit.";
    let galley = centered_galley(ui, viewport, text, egui::Color32::from_white_alpha(110));
    let pos = viewport.center_bottom() - egui::vec2(0.0, 40.0 + galley.size().y);
    ui.painter().galley(pos, galley, egui::Color32::WHITE);
}
