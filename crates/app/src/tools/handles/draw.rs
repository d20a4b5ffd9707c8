//! The curve handles drawn over the view (the handles tool): each handle's curve and its
//! control points as dots big enough to grab with a finger; a surface handle orange, a
//! skeleton cyan, the selected dot yellow, linked dots ringed. While a handle is dragged, it
//! is drawn at the pose being previewed.

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{Document, HandleEditInput};
use sketchmesh_core::skeleton::{HandleCurve, HandleKind};

/// Curve samples drawn per span between control points.
const SAMPLES_PER_SPAN: usize = 16;

/// Draws every handle of `doc` (see the module docs).
pub fn curve_handles_ui(
    ui: &egui::Ui,
    viewport: egui::Rect,
    doc: &Document,
    camera: &Camera,
    dragged: Option<(&HandleEditInput, f64)>,
    selected: Option<(u32, usize)>,
) {
    let size = DVec2::new(viewport.width().into(), viewport.height().into());
    let at = |p: DVec3| {
        camera
            .screen_from_world(p, size)
            .map(|s| viewport.min + egui::vec2(s.x as f32, s.y as f32))
    };
    let painter = ui.painter();
    for handle in &doc.handles {
        let curve = match dragged.filter(|d| d.0.handle == handle.id) {
            Some((edit, kept)) => posed(&handle.curve, edit, kept),
            None => handle.curve.clone(),
        };
        let colour = match handle.kind {
            HandleKind::Surface => egui::Color32::from_rgb(250, 150, 50),
            HandleKind::Skeleton => egui::Color32::from_rgb(60, 200, 230),
        };
        let spline = curve.spline();
        let n = SAMPLES_PER_SPAN * (curve.points.len() - 1);
        let line: Vec<egui::Pos2> = (0..=n)
            .filter_map(|i| at(spline.eval(i as f64 / n as f64).0))
            .collect();
        painter.add(egui::Shape::line(
            line.clone(),
            egui::Stroke::new(5.0, egui::Color32::from_black_alpha(120)),
        ));
        painter.add(egui::Shape::line(line, egui::Stroke::new(2.5, colour)));
        for (k, &p) in curve.points.iter().enumerate() {
            let Some(dot) = at(p) else { continue };
            let fill = if selected == Some((handle.id, k)) {
                egui::Color32::from_rgb(255, 235, 120)
            } else {
                egui::Color32::WHITE
            };
            painter.circle_filled(dot, 8.0, fill);
            painter.circle_stroke(dot, 8.0, egui::Stroke::new(2.0, colour));
            if handle.links.iter().any(|l| l.0 == k) {
                painter.circle_stroke(dot, 12.0, egui::Stroke::new(2.0, egui::Color32::WHITE));
            }
        }
    }
}

/// A handle's curve at the pose a drag previews, its move held at `kept` of the way (as the
/// op will make it, links aside).
fn posed(curve: &HandleCurve, edit: &HandleEditInput, kept: f64) -> HandleCurve {
    let mut change = edit.change();
    change.translate = change.translate.map(|t| t * kept);
    curve.edited(&change).unwrap_or_else(|_| curve.clone())
}
