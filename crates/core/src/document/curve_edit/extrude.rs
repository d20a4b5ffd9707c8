//! Extrusions (thesis §3.2.1, Fig. 3.3): the limb ([`crate::fibermesh::extrude`]), the
//! curves carried over, the base loop as a sharp curve and the silhouette as a smooth one,
//! and the limb with a band around its base remeshed and re-optimized, so that the sweep
//! becomes the fair surface through its curves and joins the shape smoothly.

use super::settle::{Aim, Change, remesh_and_fair_within};
use super::shared::{
    bounding_diagonal, carried_over, has_curves, model_crossed, replaced, screen_stroke, viewed,
};
use crate::document::{CommandError, Document, StrokePairInput};
use crate::fibermesh::extrude::extrude;
use crate::model::Model;
use crate::model::{ControlCurve, CurveKind};

/// How far from the base loop (as a fraction of the model's size) the shape around the limb
/// is re-optimized and remeshed with it.
const EXTRUDE_REGION: f64 = 0.08;

/// Applies an `extrude` op: returns the index of the model grown and its new version.
///
/// Errors: the strokes'; [`CommandError::NotOnModel`] when the base loop is on no model with
/// curves; [`CommandError::Extrude`] when the extrusion is refused; remesher and solver
/// failures.
pub fn extrude_op(doc: &Document, input: &StrokePairInput) -> Result<(usize, Model), CommandError> {
    let [base, silhouette] = &input.strokes;
    let (a, b) = (screen_stroke(base, 3)?, screen_stroke(silhouette, 2)?);
    let index = model_crossed(doc, base, &a, has_curves).ok_or(CommandError::NotOnModel)?;
    let model = &doc.models[index];
    let grown = extrude(&model.mesh, viewed(base, &a), viewed(silhouette, &b))?;
    let mut curves = carried_over(&model.curves, &grown.split_edges, &grown.remap, &grown.mesh);
    curves.push(ControlCurve {
        vertices: grown.base.clone(),
        is_closed: true,
        kind: CurveKind::Sharp,
    });
    curves.push(ControlCurve {
        vertices: grown.silhouette,
        is_closed: false,
        kind: CurveKind::Smooth,
    });
    let mesh = grown.mesh;
    let change = Change {
        around: &grown.base,
        radius: EXTRUDE_REGION * bounding_diagonal(&mesh),
    };
    let mut region = change.region(&mesh);
    for (inside, &limb) in region.iter_mut().zip(&grown.is_limb) {
        *inside |= limb;
    }
    let (mesh, curves) = remesh_and_fair_within(&mesh, &curves, &region, Aim::Measured)?;
    Ok((index, replaced(model, mesh, curves)))
}
