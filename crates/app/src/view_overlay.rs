//! What the view shows over the scene: the line saying what to do next, the symmetry plane
//! while the Symmetry switch is on, the tool in use's overlay, what the edit in progress
//! shows (an over-sketch's outline piece), the tools' marks and the stroke being drawn, and
//! the strokes that wait for the worker.

use glam::{DVec2, DVec3};
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::{Edit, Op};
use sketchmesh_core::model::MirrorPlane;

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

/// How much of the models' bounds the symmetry plane's outline reaches beyond them, as a
/// fraction of their size: the outline then frames the models rather than touching them.
const PLANE_MARGIN: f64 = 0.08;

/// The symmetry plane, while the Symmetry switch is on: a faint outline where it cuts the
/// box around the models (`bounds`, as drawn), so the user sees where the mirror is; with no
/// models, where it cuts a box about the point the view turns around, filling most of the
/// view. Nothing when the plane misses the box.
pub fn symmetry_plane_ui(
    ui: &egui::Ui,
    scene: &Scene<'_>,
    plane: &MirrorPlane,
    bounds: Option<(DVec3, DVec3)>,
) {
    let camera = &scene.camera;
    let (lo, hi) = match bounds {
        Some((lo, hi)) => {
            let margin = DVec3::splat(PLANE_MARGIN * (hi - lo).length());
            (lo - margin, hi + margin)
        }
        None => {
            let half = 0.6 * camera.distance() * (0.5 * camera.fov_y_deg.to_radians()).tan();
            (
                camera.target - DVec3::splat(half),
                camera.target + DVec3::splat(half),
            )
        }
    };
    let corners = plane_in_box(plane, lo, hi);
    let size = scene.size();
    let on_screen: Option<Vec<egui::Pos2>> = (corners.iter())
        .map(|&p| Some(scene.at(screen_point(camera, p, size)?)))
        .collect();
    let Some(mut points) = on_screen.filter(|points| points.len() >= 3) else {
        return;
    };
    points.push(points[0]);
    let faint = egui::Color32::from_rgba_unmultiplied(150, 200, 255, 90);
    let dashes = egui::Shape::dashed_line(&points, egui::Stroke::new(1.5, faint), 10.0, 6.0);
    ui.painter().extend(dashes);
}

/// A world point on the screen (points from the viewport's corner), if it is in front of
/// the eye.
fn screen_point(camera: &Camera, p: DVec3, viewport: DVec2) -> Option<DVec2> {
    camera.screen_from_world(p, viewport).map(|s| s.truncate())
}

/// Where `plane` cuts the box `lo`..`hi`: the points where it crosses the box's edges, in
/// order around the cut (empty when it misses the box).
fn plane_in_box(plane: &MirrorPlane, lo: DVec3, hi: DVec3) -> Vec<DVec3> {
    let corner = |k: usize| {
        DVec3::new(
            if k & 1 == 0 { lo.x } else { hi.x },
            if k & 2 == 0 { lo.y } else { hi.y },
            if k & 4 == 0 { lo.z } else { hi.z },
        )
    };
    // The 12 edges: corner pairs that differ in one bit.
    let edges = (0..8usize)
        .flat_map(|a| [1usize, 2, 4].map(|bit| (a, a | bit)))
        .filter(|(a, b)| a != b);
    let mut cut: Vec<DVec3> = Vec::new();
    for (a, b) in edges {
        let (pa, pb) = (corner(a), corner(b));
        let (da, db) = (plane.signed_distance(pa), plane.signed_distance(pb));
        if (da < 0.0) != (db < 0.0) {
            cut.push(pa + (pb - pa) * (da / (da - db)));
        }
    }
    let Some(centre) = (!cut.is_empty()).then(|| cut.iter().sum::<DVec3>() / cut.len() as f64)
    else {
        return cut;
    };
    let u = plane.normal().any_orthonormal_vector();
    let v = plane.normal().cross(u);
    let angle = |p: &DVec3| (*p - centre).dot(v).atan2((*p - centre).dot(u));
    cut.sort_by(|p, q| angle(p).total_cmp(&angle(q)));
    cut
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_plane_cuts_a_box_in_a_polygon_in_order() {
        let plane = MirrorPlane::default();
        let cut = plane_in_box(
            &plane,
            DVec3::new(-1.0, -2.0, -3.0),
            DVec3::new(1.0, 2.0, 3.0),
        );
        assert_eq!(cut.len(), 4, "{cut:?}");
        assert!(
            cut.iter()
                .all(|p| p.x.abs() < 1e-12 && p.y.abs() == 2.0 && p.z.abs() == 3.0)
        );
        // In order around the cut: neighbours share a side of the rectangle.
        for k in 0..4 {
            let (p, q) = (cut[k], cut[(k + 1) % 4]);
            assert!(p.y == q.y || p.z == q.z, "{p} then {q}");
        }
        let tilted = MirrorPlane::new(DVec3::ONE, 0.0).unwrap();
        assert_eq!(
            plane_in_box(&tilted, -DVec3::ONE, DVec3::ONE).len(),
            6,
            "a hexagon"
        );
        let missed = MirrorPlane::new(DVec3::X, 5.0).unwrap();
        assert!(plane_in_box(&missed, -DVec3::ONE, DVec3::ONE).is_empty());
    }
}
