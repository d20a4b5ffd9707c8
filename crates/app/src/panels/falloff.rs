//! The fall-off panel (Bujans §5): while a region edit is open, its region laid flat in the
//! unit disc (the core's Tutte embedding, `RegionEdit::disc`) in a corner of the view, each
//! part in the gray of its level, as the model shows it: white moves fully, black stays.
//! The mesh for the painter is built once per region and levels, not every frame.

use std::sync::Arc;

use egui::{Color32, Pos2, Rect, Stroke, pos2, vec2};
use glam::DVec2;
use sketchmesh_core::camera::Camera;
use sketchmesh_core::document::Edit;
use sketchmesh_core::mesh::Mesh;

pub use crate::overlay::falloff_gray;

/// The panel's side as a share of the view's shorter side, and its bounds in points.
const SIDE_SHARE: f32 = 0.3;
const SIDE_RANGE: (f32, f32) = (120.0, 220.0);
/// Room between the panel and the view's edges, in points.
const MARGIN: f32 = 12.0;

/// The painted disc, kept while the region, its levels and the panel's place stay.
#[derive(Default)]
pub struct FalloffPanel {
    key: Option<(u64, Vec<u32>, Rect)>,
    mesh: Option<Arc<egui::Mesh>>,
}

impl FalloffPanel {
    /// Draws the panel for `edit` (the `edit_key`-th edit begun) in `viewport`'s lower left
    /// corner, if it is a region edit whose region is found.
    pub fn ui(
        &mut self,
        ui: &egui::Ui,
        viewport: Rect,
        camera: &Camera,
        edit: &Edit,
        edit_key: u64,
    ) {
        let (Some((model, vertices, weights)), Some(disc), Some(levels)) = (
            edit.region_falloff(),
            edit.region_disc(),
            edit.region_levels(),
        ) else {
            return;
        };
        let rect = panel_rect(viewport);
        let side = rect.width();
        let painter = ui.painter();
        painter.rect_filled(rect.expand(6.0), 8.0, Color32::from_black_alpha(200));
        let caption = "Fall-off, flattened";
        painter.text(
            rect.left_top() + vec2(2.0, -2.0),
            egui::Align2::LEFT_BOTTOM,
            caption,
            egui::FontId::proportional(12.0),
            Color32::from_gray(210),
        );
        let disc = match disc {
            Ok(disc) => disc,
            Err(why) => {
                let text = why.to_string();
                let galley = painter.layout(
                    text,
                    egui::FontId::proportional(12.0),
                    Color32::from_gray(220),
                    side,
                );
                painter.galley(rect.left_top() + vec2(0.0, 8.0), galley, Color32::WHITE);
                return;
            }
        };
        let mesh = &edit.document().models[model].mesh;
        let steps = levels.max(2) as f64 - 1.0;
        let quantised: Vec<u32> = weights.iter().map(|w| (w * steps).round() as u32).collect();
        let key = (edit_key, quantised, rect);
        if self.key.as_ref() != Some(&key) {
            let size = DVec2::new(viewport.width().into(), viewport.height().into());
            let seen: Vec<Option<DVec2>> = vertices
                .iter()
                .map(|&v| {
                    camera
                        .screen_from_world(mesh.position(v), size)
                        .map(|p| p.truncate())
                })
                .collect();
            let turned = as_seen(disc, &seen);
            self.mesh = Some(Arc::new(disc_mesh(
                mesh, vertices, &turned, &key.1, steps, rect,
            )));
            self.key = Some(key);
        }
        if let Some(painted) = &self.mesh {
            painter.add(egui::Shape::Mesh(Arc::clone(painted)));
        }
        painter.circle_stroke(
            rect.center(),
            side / 2.0,
            Stroke::new(1.0, Color32::from_gray(120)),
        );
    }
}

/// The disc turned (and mirrored, if that fits better) to lie as the region is seen: the
/// rotation that best carries the disc onto the vertices' places on screen (y down), by
/// least squares (2D Procrustes with complex numbers).
fn as_seen(disc: &[DVec2], seen: &[Option<DVec2>]) -> Vec<DVec2> {
    let pairs: Vec<(DVec2, DVec2)> = disc
        .iter()
        .zip(seen)
        .filter_map(|(&d, s)| s.map(|s| (d, DVec2::new(s.x, -s.y))))
        .collect();
    let n = pairs.len().max(1) as f64;
    let centre = pairs.iter().map(|(_, s)| *s).sum::<DVec2>() / n;
    // Σ conj(d) s for a rotation, Σ d s for a mirror then a rotation.
    let (mut turn, mut mirror) = (DVec2::ZERO, DVec2::ZERO);
    for &(d, s) in &pairs {
        let s = s - centre;
        turn += DVec2::new(d.x * s.x + d.y * s.y, d.x * s.y - d.y * s.x);
        mirror += DVec2::new(d.x * s.x - d.y * s.y, d.x * s.y + d.y * s.x);
    }
    let mirrored = mirror.length() > turn.length();
    let rotation = if mirrored { mirror } else { turn }.normalize_or(DVec2::X);
    disc.iter()
        .map(|&d| {
            let d = if mirrored { DVec2::new(d.x, -d.y) } else { d };
            rotation.rotate(d)
        })
        .collect()
}

/// Where the panel's disc sits in `viewport`: its lower left corner.
pub fn panel_rect(viewport: Rect) -> Rect {
    let side =
        (viewport.width().min(viewport.height()) * SIDE_SHARE).clamp(SIDE_RANGE.0, SIDE_RANGE.1);
    Rect::from_min_size(
        pos2(viewport.left() + MARGIN, viewport.bottom() - MARGIN - side),
        vec2(side, side),
    )
}

/// The region's triangles in the disc, each vertex in its level's gray.
fn disc_mesh(
    mesh: &Mesh,
    vertices: &[sketchmesh_core::mesh::VertexId],
    disc: &[DVec2],
    levels: &[u32],
    steps: f64,
    rect: Rect,
) -> egui::Mesh {
    let mut local = vec![u32::MAX; mesh.n_vertices()];
    for (i, v) in vertices.iter().enumerate() {
        local[v.index()] = i as u32;
    }
    let at = |p: DVec2| -> Pos2 {
        // y up in the disc, down on screen.
        rect.center() + vec2(p.x as f32, -p.y as f32) * (rect.width() / 2.0)
    };
    let mut painted = egui::Mesh::default();
    for ((&p, &level), _) in disc.iter().zip(levels).zip(vertices) {
        let gray = falloff_gray(f64::from(level) / steps);
        painted.colored_vertex(at(p), Color32::from_gray(gray));
    }
    for f in mesh.faces() {
        let corners = mesh.face_vertices(f).map(|v| local[v.index()]);
        if corners.iter().all(|&i| i != u32::MAX) {
            painted.add_triangle(corners[0], corners[1], corners[2]);
        }
    }
    painted
}
