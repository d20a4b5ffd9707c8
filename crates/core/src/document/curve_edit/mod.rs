//! FiberMesh curve editing on a document's models (Nealen's thesis §3.2.1–3.2.4): pull,
//! add, erase, type change and rub, each one undoable op.
//!
//! The algorithms live in [`crate::fibermesh`] and [`crate::mesh::remesh`]; this module
//! picks the model and the curves an op acts on, and settles the surface afterwards. Every
//! op recomputes its result from the op alone (the stroke, viewport and camera), so
//! `sketchmesh replay` reproduces it exactly; the app's live previews (see [`PullPreview`])
//! only show where the committed result will land.
//!
//! After an op the surface is re-optimized with a fresh factorization: the thesis remeshes
//! "after every sketch operation and on mouse release after a pull", so adding a curve and
//! pulling also remesh (curves stay edge chains). Erase, type change and rub keep the
//! topology: they change constraints only, and remeshing would move vertices the user did
//! not touch.

mod add;
mod constraints;
mod pull;
mod settle;

use glam::DVec2;

pub use add::add_curve_op;
pub use constraints::{curve_type_toggle, erase_op, rub_op, set_curve_type_op};
pub(super) use pull::PullPreview;
pub use pull::pull_op;

use super::{CommandError, ControlCurve, Document, Model, StrokeInput};
use crate::fibermesh::curve_tools::VisibleCurves;
use crate::fibermesh::{self, CurveKind};
use crate::mesh::{Mesh, VertexId};

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
    let viewport = input.viewport_size();
    let viewport_ok = viewport.is_finite() && viewport.x > 0.0 && viewport.y > 0.0;
    if !viewport_ok || !input.camera.is_valid() {
        return Err(CommandError::BadView);
    }
    if input.stroke.iter().flatten().any(|x| !x.is_finite()) {
        return Err(CommandError::StrokeNotFinite);
    }
    if input.stroke.len() < min_points {
        return Err(CommandError::StrokeTooShort);
    }
    Ok(input.points().iter().map(|p| p.pos).collect())
}

/// The curves of `model` that are embedded in its mesh, as the FiberMesh solver takes them.
fn solver_curves(model: &Model) -> Vec<fibermesh::ControlCurve> {
    model
        .curves
        .iter()
        .filter(|c| c.vertices.len() >= 2)
        .map(|c| fibermesh::ControlCurve {
            vertices: c.vertices.clone(),
            is_closed: c.closed,
            kind: if c.sharp {
                CurveKind::Sharp
            } else {
                CurveKind::Smooth
            },
        })
        .collect()
}

/// The document's curves for solver curves on `mesh`: points where their vertices are.
fn document_curves(mesh: &Mesh, curves: &[fibermesh::ControlCurve]) -> Vec<ControlCurve> {
    curves
        .iter()
        .map(|c| ControlCurve {
            points: c.vertices.iter().map(|&v| mesh.position(v)).collect(),
            vertices: c.vertices.clone(),
            closed: c.is_closed,
            sharp: c.kind == CurveKind::Sharp,
        })
        .collect()
}

/// The model the curve ops may act on: those whose shape is defined by embedded curves.
fn has_curves(model: &Model) -> bool {
    model.curves.iter().any(|c| c.vertices.len() >= 2)
}

/// A curve vertex a pointer is over, found in screen space.
#[derive(Clone, Copy, Debug, PartialEq)]
struct CurvePick {
    /// Index of the model in the document.
    model: usize,
    /// The curve vertex.
    vertex: VertexId,
}

/// The visible curve vertex nearest to `screen` within [`CURVE_PICK_RADIUS_PX`], over all
/// models with curves.
fn pick_curve_vertex(
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
fn bounding_diagonal(mesh: &Mesh) -> f64 {
    mesh.bounding_box().map_or(1.0, |(lo, hi)| lo.distance(hi))
}

/// The model at `index` with a new mesh and curves, keeping its name and appearance.
fn replaced(model: &Model, mesh: Mesh, curves: &[fibermesh::ControlCurve]) -> Model {
    Model {
        curves: document_curves(&mesh, curves),
        mesh,
        name: model.name.clone(),
        appearance: model.appearance.clone(),
    }
}
