//! What the curve ops share: reading the stroke, picking the model and the curve vertex
//! under it, and putting the changed model together.

use glam::DVec2;

use crate::document::{CommandError, Document, StrokeInput};
use crate::fibermesh::ControlCurve;
use crate::fibermesh::curve_tools::VisibleCurves;
use crate::geometry::Bvh;
use crate::mesh::{Mesh, VertexId};
use crate::model::Model;

/// How close (CSS px) a stroke must pass to a curve to act on it.
pub const CURVE_PICK_RADIUS_PX: f64 = 16.0;

/// The stroke's points in screen space, after checking the view and the numbers.
///
/// Errors: [`CommandError::BadView`], [`CommandError::StrokeNotFinite`],
/// [`CommandError::StrokeTooShort`] (fewer than `min_points` samples).
pub(crate) fn screen_stroke(
    input: &StrokeInput,
    min_points: usize,
) -> Result<Vec<DVec2>, CommandError> {
    input.checked_viewport()?;
    if input.stroke.iter().flatten().any(|x| !x.is_finite()) {
        return Err(CommandError::StrokeNotFinite);
    }
    if input.stroke.len() < min_points {
        return Err(CommandError::StrokeTooShort);
    }
    Ok(input.points().iter().map(|p| p.pos).collect())
}

/// Whether the curve ops may act on `model`: whether its shape is defined by curves.
pub(super) fn has_curves(model: &Model) -> bool {
    !model.curves.is_empty()
}

/// A curve vertex a pointer is over, found in screen space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct CurvePick {
    /// Index of the model in the document.
    pub(super) model: usize,
    /// The curve vertex.
    pub(super) vertex: VertexId,
}

/// The visible curve vertex nearest to `screen` within [`CURVE_PICK_RADIUS_PX`], over all
/// models with curves.
pub(super) fn pick_curve_vertex(
    doc: &Document,
    input: &StrokeInput,
    screen: DVec2,
) -> Result<CurvePick, CommandError> {
    let viewport = input.viewport_size();
    let mut best: Option<(f64, CurvePick)> = None;
    for (index, model) in doc.models.iter().enumerate() {
        if !has_curves(model) {
            continue;
        }
        let vertices = || model.curves.iter().flat_map(|c| &c.vertices);
        let visible = VisibleCurves::new(&model.mesh, vertices(), &input.camera, viewport);
        for &v in vertices() {
            let Some(distance) = visible.screen(v).map(|s| s.distance(screen)) else {
                continue;
            };
            if distance <= CURVE_PICK_RADIUS_PX && best.is_none_or(|(d, _)| distance < d) {
                let pick = CurvePick {
                    model: index,
                    vertex: v,
                };
                best = Some((distance, pick));
            }
        }
    }
    best.map(|(_, pick)| pick).ok_or(CommandError::NoCurveHere)
}

/// The length of a mesh's bounding-box diagonal.
pub(super) fn bounding_diagonal(mesh: &Mesh) -> f64 {
    mesh.bounding_box().map_or(1.0, |(lo, hi)| lo.distance(hi))
}

/// `model` with a new mesh and curves, keeping its name and appearance.
pub(super) fn replaced(model: &Model, mesh: Mesh, curves: Vec<ControlCurve>) -> Model {
    Model {
        curves,
        mesh,
        name: model.name.clone(),
        appearance: model.appearance.clone(),
    }
}

/// Inserts `new` between consecutive vertices `a` and `b` of `curve` (either order,
/// including the closing edge), where an embedding split that curve edge.
pub(super) fn insert_on_edge(curve: &mut ControlCurve, a: VertexId, b: VertexId, new: VertexId) {
    let n = curve.vertices.len();
    let n_edges = if curve.is_closed {
        n
    } else {
        n.saturating_sub(1)
    };
    let is_edge = |k: usize| {
        let (p, q) = (curve.vertices[k], curve.vertices[(k + 1) % n]);
        (p, q) == (a, b) || (p, q) == (b, a)
    };
    if let Some(k) = (0..n_edges).find(|&k| is_edge(k)) {
        curve.vertices.insert(k + 1, new);
    }
}

/// The model for which `accept` holds that most stroke samples hit, if any sample hits one.
pub(super) fn model_crossed(
    doc: &Document,
    input: &StrokeInput,
    stroke: &[DVec2],
    accept: impl Fn(&Model) -> bool,
) -> Option<usize> {
    let viewport = input.viewport_size();
    let rays: Vec<_> = stroke
        .iter()
        .map(|&s| input.camera.ray_in_world(s, viewport))
        .collect();
    doc.models
        .iter()
        .enumerate()
        .filter(|(_, model)| accept(model))
        .map(|(index, model)| {
            let bvh = Bvh::new(&model.mesh);
            let hits = rays
                .iter()
                .filter(|&&(origin, dir)| bvh.raycast(&model.mesh, origin, dir).is_some())
                .count();
            (hits, index)
        })
        .filter(|&(hits, _)| hits > 0)
        .max()
        .map(|(_, index)| index)
}
