//! What the view shows over the scene: the line saying what to do next, the tool in use's
//! overlay, what the edit in progress shows (an over-sketch's outline piece), the tools' marks
//! and the stroke being drawn, and the strokes that wait for the worker.

use sketchmesh_core::document::{Edit, Op};

use crate::overlay::{hint_ui, outline_ui, stroke_ui};
use crate::tools::{Device, Hint, Mark, Scene, ToolSet};

/// The line at the top of the view: what the edit in progress says (a move held back, a
/// feature's amount), else what the tool in use asks next, in `device`'s words.
pub fn line(scene: &Scene<'_>, tools: &ToolSet, device: Device) -> Hint {
    if scene.edit.and_then(Edit::limited_move).is_some() {
        return Hint::Borrowed(
            "Moved only part of the way: further would fold the part through itself; let go \
             to keep it, or drag back",
        );
    }
    match scene.edit.and_then(|edit| tools.edit_line(edit)) {
        Some(said) => Hint::Owned(said),
        None => tools.hint(scene.doc, device),
    }
}

/// Draws over the view: the `line` saying what to do next, what the tool in use shows, what
/// the edit in progress shows (the outline piece an over-sketch would replace), the marks
/// and the stroke in progress, and the strokes waiting for the worker. Returns where the
/// line ends (screen y), for what shows below it.
pub fn draw<'a>(
    ui: &egui::Ui,
    scene: &Scene<'_>,
    tools: &ToolSet,
    line: &str,
    waiting: impl Iterator<Item = &'a Op>,
) -> f32 {
    let viewport = scene.viewport;
    let below = hint_ui(ui, viewport, line);
    tools.overlay(ui, scene);
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
    below
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
