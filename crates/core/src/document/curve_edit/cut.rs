//! Cutting a model (thesis §3.2.1, §3.3.3): the stroke's cut ([`crate::fibermesh::cut`]),
//! the curves that survive it, the caps' rims as new sharp curves, and a remesh and settle
//! around the rims.
//!
//! A model without curves (imported) is cut too, and its band around the rims remeshed, but
//! it gets no curves: those would make the curve tools re-optimize its surface, which would
//! smooth away a scan's detail; its rims stay creases because the remesh keeps them as
//! edge chains.

use super::settle::{Change, remesh_and_settle_within, remesh_only};
use super::shared::{
    bounding_diagonal, carried_over, has_curves, model_crossed, replaced, screen_stroke,
};
use crate::document::{CommandError, Document, StrokeInput};
use crate::fibermesh::cut::{CutError, cut};
use crate::model::Model;
use crate::model::{ControlCurve, CurveKind};

/// How far from the rims (as a fraction of the model's size) the surface is remeshed and
/// settled: the band of slivers the cut's splits left on both sides of each rim.
const CUT_REGION: f64 = 0.1;

/// Applies a `cut` op: returns the index of the model cut and its new version.
///
/// The model is the one the stroke crosses in most samples. Its curves keep the
/// parts on the kept side; each cap's rim becomes a sharp curve, as in the thesis.
///
/// Errors: the stroke's; [`CommandError::Cut`] when it crosses no model or the cut is
/// refused; remesher and solver failures.
pub fn cut_op(doc: &Document, input: &StrokeInput) -> Result<(usize, Model), CommandError> {
    let stroke = screen_stroke(input, 2)?;
    let index = model_crossed(doc, input, &stroke, |_| true).ok_or(CutError::DoesNotCross)?;
    let model = &doc.models[index];
    let cut = cut(&model.mesh, &input.camera, input.viewport_size(), &stroke)?;
    let mut curves = carried_over(&model.curves, &cut.split_edges, &cut.remap, &cut.mesh);
    curves.extend(cut.rims.iter().map(|rim| ControlCurve {
        vertices: rim.clone(),
        is_closed: true,
        kind: CurveKind::Sharp,
    }));
    let around = cut.rims.concat();
    let change = Change {
        around: &around,
        radius: CUT_REGION * bounding_diagonal(&cut.mesh),
    };
    // The caps are meshed well already and stay flat: only the band of slivers on the
    // kept surface along the rims is remeshed (and settled, on a shape curves define).
    let mut band = change.region(&cut.mesh);
    for (inside, &cap) in band.iter_mut().zip(&cut.is_cap) {
        *inside &= !cap;
    }
    let (mesh, curves) = if has_curves(model) {
        remesh_and_settle_within(&cut.mesh, &curves, &band)?
    } else {
        (remesh_only(&cut.mesh, &curves, &band)?.0, Vec::new())
    };
    Ok((index, replaced(model, mesh, curves)))
}
