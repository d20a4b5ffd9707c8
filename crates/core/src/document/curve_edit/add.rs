//! Adding a control curve (thesis §3.2.1, Fig. 3.4): the stroke becomes an edge chain on the
//! model it was drawn on, the mesh is remeshed around it, and the surface settles.

use super::settle::{Change, remesh_and_settle};
use super::shared::{
    bounding_diagonal, has_curves, model_crossed, replaced, screen_stroke, with_splits,
};
use crate::document::{AddCurveInput, CommandError, Document, StrokeInput};
use crate::fibermesh::add_curve::{CurveShape, add_curve};
use crate::model::Model;
use crate::model::{ControlCurve, CurveKind};

/// How far from a new curve (as a fraction of the model's size) the surface settles after
/// the remesh: the curve lies on the surface, so only the new vertices need to find it.
const ADD_REGION: f64 = 0.1;

/// Applies an `add_curve` op: returns the index of the model that got the curve and its
/// new version. The new curve is smooth, as the thesis' newly painted curves are.
///
/// The model is the one the stroke crosses in most samples (a cross-section stroke starts
/// and ends off the model, so its ends cannot decide).
///
/// Errors: the stroke's; [`CommandError::NotOnModel`] when no model with curves is under the
/// stroke; [`CommandError::AddCurve`] when the curve cannot be placed; remesher and solver
/// failures.
pub fn add_curve_op(doc: &Document, input: &AddCurveInput) -> Result<(usize, Model), CommandError> {
    let stroke_input = StrokeInput::of_add_curve(input);
    let stroke = screen_stroke(&stroke_input, 2)?;
    let index =
        model_crossed(doc, &stroke_input, &stroke, has_curves).ok_or(CommandError::NotOnModel)?;
    let model = &doc.models[index];
    let shape = match (input.closed, input.cross_section) {
        (_, true) => CurveShape::CrossSection,
        (true, false) => CurveShape::Closed,
        (false, false) => CurveShape::Open,
    };
    let embedded = add_curve(
        &model.mesh,
        &input.camera,
        stroke_input.viewport_size(),
        &stroke,
        shape,
    )?;
    let mut curves = with_splits(&model.curves, &embedded.split_edges);
    curves.push(ControlCurve {
        vertices: embedded.chain.clone(),
        is_closed: embedded.closed,
        kind: CurveKind::Smooth,
    });
    let change = Change {
        around: &embedded.chain,
        radius: ADD_REGION * bounding_diagonal(&model.mesh),
    };
    let (mesh, curves) = remesh_and_settle(&embedded.mesh, &curves, change)?;
    Ok((index, replaced(model, mesh, curves)))
}
