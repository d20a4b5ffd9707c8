//! Ops that change constraints along a stroke (thesis §3.2.3–3.2.4): erase, type change
//! and rub. The topology stays; the surface settles once, as on the thesis' mouse release.

use glam::DVec2;

use super::settle::{Change, settle};
use super::shared::{CURVE_PICK_RADIUS_PX, bounding_diagonal, has_curves, replaced, screen_stroke};
use crate::document::{CommandError, CurveTypeInput, Document, StrokeInput};
use crate::fibermesh::curve_tools::{StrokeHits, erase, hit_curves, rub, set_kind};
use crate::mesh::{Mesh, VertexId};
use crate::model::Model;
use crate::model::{ControlCurve, CurveKind};

/// How far from an erased curve (as a fraction of the model's bounding-box diagonal) the
/// surface re-optimizes and forgets the curvature the curve forced: as far as a pull by a
/// sixth of the model's size moves it (at 0.3 a third of such a pull's bump stayed).
const ERASE_REGION: f64 = 0.45;

/// The same for a curve changed between smooth and sharp, or rubbed (a rub does not
/// forget). Wider regions, whose magnitudes are all interpolated, kept a crease once made.
const RETYPE_REGION: f64 = 0.2;

/// Applies an `erase` op: the curve parts under the stroke go, and the surface settles
/// through the rest. Returns the model's index and new version.
///
/// Errors: the stroke's; [`CommandError::NoCurveHere`] when the stroke passes over no
/// visible curve; [`CommandError::LastCurve`] when nothing would be left to hold the shape.
pub fn erase_op(doc: &Document, input: &StrokeInput) -> Result<(usize, Model), CommandError> {
    let (index, curves, hits) = stroke_over_curves(doc, input)?;
    let model = &doc.models[index];
    let kept = erase(&curves, &hits);
    if kept.is_empty() {
        return Err(CommandError::LastCurve);
    }
    let around = hits.vertices_hit(&curves);
    let mut mesh = model.mesh.clone();
    let change = changed_near(&model.mesh, &around, ERASE_REGION);
    settle(&mut mesh, &kept, model.mesh.positions(), change, true)?;
    Ok((index, replaced(model, mesh, kept)))
}

/// Applies a `set_curve_type` op: the curve parts under the stroke become sharp or smooth.
///
/// Errors: as [`erase_op`], without the last-curve case.
pub fn set_curve_type_op(
    doc: &Document,
    input: &CurveTypeInput,
) -> Result<(usize, Model), CommandError> {
    let (index, curves, hits) = stroke_over_curves(doc, &StrokeInput::of_curve_type(input))?;
    let model = &doc.models[index];
    let kind = if input.sharp {
        CurveKind::Sharp
    } else {
        CurveKind::Smooth
    };
    let retyped = set_kind(&curves, &hits, kind);
    let around = hits.vertices_hit(&curves);
    let mut mesh = model.mesh.clone();
    let change = changed_near(&model.mesh, &around, RETYPE_REGION);
    settle(&mut mesh, &retyped, model.mesh.positions(), change, true)?;
    Ok((index, replaced(model, mesh, retyped)))
}

/// Applies a `rub` op: the curves near the stroke get smoother, more so the more
/// back-and-forth passes the stroke makes, and the surface follows.
///
/// Errors: as [`erase_op`], without the last-curve case.
pub fn rub_op(doc: &Document, input: &StrokeInput) -> Result<(usize, Model), CommandError> {
    let (index, curves, hits) = stroke_over_curves(doc, input)?;
    let model = &doc.models[index];
    let stroke = screen_stroke(input, 2)?;
    let rubbed = rub(
        &model.mesh,
        &curves,
        &input.camera,
        input.viewport_size(),
        &stroke,
        CURVE_PICK_RADIUS_PX,
    );
    let mut mesh = model.mesh.clone();
    mesh.positions_mut().copy_from_slice(&rubbed);
    let around = hits.vertices_hit(&curves);
    let change = changed_near(&model.mesh, &around, RETYPE_REGION);
    settle(&mut mesh, &curves, model.mesh.positions(), change, false)?;
    Ok((index, replaced(model, mesh, curves)))
}

/// The surface within `fraction` of `mesh`'s size from the curve vertices `around`.
fn changed_near<'a>(mesh: &Mesh, around: &'a [VertexId], fraction: f64) -> Change<'a> {
    Change {
        around,
        radius: fraction * bounding_diagonal(mesh),
    }
}

/// What the type-change tool toggles to for a stroke: sharp if any curve under it is
/// smooth, smooth if all are sharp; `None` when the stroke is over no curve.
pub fn curve_type_toggle(doc: &Document, input: &StrokeInput) -> Option<bool> {
    let (_, curves, hits) = stroke_over_curves(doc, input).ok()?;
    Some(
        hits.curve_indices()
            .any(|k| curves[k].kind == CurveKind::Smooth),
    )
}

/// The first model (in document order) whose visible curves the stroke passes over, its
/// curves and the hits.
fn stroke_over_curves(
    doc: &Document,
    input: &StrokeInput,
) -> Result<(usize, Vec<ControlCurve>, StrokeHits), CommandError> {
    let stroke: Vec<DVec2> = screen_stroke(input, 2)?;
    for (index, model) in doc.models.iter().enumerate() {
        if !has_curves(model) {
            continue;
        }
        let hits = hit_curves(
            &model.mesh,
            &model.curves,
            &input.camera,
            input.viewport_size(),
            &stroke,
            CURVE_PICK_RADIUS_PX,
        );
        if !hits.is_empty() {
            return Ok((index, model.curves.clone(), hits));
        }
    }
    Err(CommandError::NoCurveHere)
}
