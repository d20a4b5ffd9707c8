//! What an op makes of a document when computed in one go: the next document, or an undo
//! or redo of the history.

use std::sync::Arc;

use super::arrange::{delete_op, duplicate_op, place_beside, transform_op};
use super::create::create_op;
use super::feature::feature_op;
use super::keyframes::{delete_keyframe_op, keyframe_op, pose_at_op};
use super::next::Outcome;
use super::optimize::optimize_op;
use super::oversketch::oversketch_op;
use super::paint::{carry_colors, fill_op, material_op, paint_op, with_colors_carried};
use super::region_edit::region_edit_op;
use super::skeleton::{
    curve_handle_op, delete_handle_op, handle_edit_op, link_handles_op, remove_model,
};
use super::symmetry::symmetrize_op;
use super::volumetric::{curve_deform_op, deform_op};
use super::{CommandError, Document, ImportInput, Model, Op, SketchCurve, StrokeInput, curve_edit};
use crate::curve::process_stroke;
use crate::io::{ImportFile, ImportLimits, Imported, import_gltf};

/// Computes `op` on `base` in one go. A `create` runs its steps to the end here
/// ([`create_op`]); the edits that spread an op over steps ([`super::Edit`]) end with the
/// same result.
///
/// Errors: the op's refusal, see [`CommandError`].
pub(super) fn outcome(base: &Document, op: &Op) -> Result<Outcome, CommandError> {
    let replaced = |model| with_model(base, model);
    Ok(match op {
        Op::Stroke(input) => {
            let mut next = base.clone();
            next.sketches.push(Arc::new(place_stroke(input)?));
            Outcome::Document(next)
        }
        Op::Import(input) => with_imported(base, input, import_files(input)?),
        Op::Transform(input) => replaced(transform_op(base, input)?),
        Op::Delete(input) => delete_op(base, input)?,
        Op::Duplicate(input) => duplicate_op(base, input)?,
        Op::CurveHandle(input) => Outcome::Document(curve_handle_op(base, input)?),
        Op::HandleEdit(input) => Outcome::Document(handle_edit_op(base, input)?),
        Op::LinkHandles(input) => Outcome::Document(link_handles_op(base, input)?),
        Op::DeleteHandle(input) => Outcome::Document(delete_handle_op(base, input.handle)?),
        Op::Keyframe(input) => Outcome::Document(keyframe_op(base, input)?),
        Op::DeleteKeyframe(input) => Outcome::Document(delete_keyframe_op(base, input)?),
        Op::PoseAt(input) => Outcome::Document(pose_at_op(base, input)?),
        Op::Paint(input) => Outcome::Document(paint_op(base, input, None)?),
        Op::Fill(input) => Outcome::Document(fill_op(base, input, None)?),
        Op::Material(input) => Outcome::Document(material_op(base, input, None)?),
        Op::SymmetryPlane(input) => {
            let mut next = base.clone();
            next.symmetry = Some(input.plane);
            Outcome::Document(next)
        }
        Op::Undo => Outcome::Undo,
        Op::Redo => Outcome::Redo,
        // The ops that make one model from the models alone (`Op::makes_one_model`).
        _ => made_by(base, op, model_op(base, op)?),
    })
}

/// What an op that [makes one model](Op::makes_one_model) makes of `doc`: the model's
/// index and its next version (a new model's index is `doc.models.len()`). It reads the models only, so the page computes it in its
/// worker on a copy of them, and [`super::Edit::supply_model`] lands the result as if it
/// had been computed here.
///
/// Errors: the op's refusal; [`CommandError::NotOneModel`] for any other op.
pub fn model_op(doc: &Document, op: &Op) -> Result<(usize, Model), CommandError> {
    let made = match op {
        Op::Create(input) => create_op(doc, input),
        Op::Oversketch(input) => oversketch_op(doc, input),
        Op::Pull(input) => curve_edit::pull_op(doc, input),
        Op::AddCurve(input) => curve_edit::add_curve_op(doc, input),
        Op::Cut(input) => curve_edit::cut_op(doc, input),
        Op::Tunnel(input) => curve_edit::tunnel_op(doc, input),
        Op::Extrude(input) => curve_edit::extrude_op(doc, input),
        Op::Erase(input) => curve_edit::erase_op(doc, input),
        Op::SetCurveType(input) => curve_edit::set_curve_type_op(doc, input),
        Op::Rub(input) => curve_edit::rub_op(doc, input),
        Op::CurveDeform(input) => curve_deform_op(doc, input),
        Op::Optimize(input) => optimize_op(doc, input),
        Op::SketchFeature(input) => feature_op(doc, input),
        Op::RegionEdit(input) => region_edit_op(doc, input),
        Op::Deform(input) => deform_op(doc, input),
        Op::Merge(input) => curve_edit::merge_op(doc, input),
        Op::Symmetrize(input) => symmetrize_op(doc, input),
        other => Err(CommandError::NotOneModel(other.name())),
    }?;
    Ok(with_colors_carried(doc, op, made))
}

/// `model`, the next version of `before` computed elsewhere, sharing `before`'s looks, its
/// soup as imported and its key frames again where they are the same: the copies that went
/// to the page's worker and back are dropped, and the page's textures, kept per image, are
/// not decoded and uploaded again.
pub(super) fn sharing_looks(before: &Model, mut model: Model) -> Model {
    if model.appearance == before.appearance {
        model.appearance.clone_from(&before.appearance);
    }
    if model.as_imported == before.as_imported {
        model.as_imported.clone_from(&before.as_imported);
    }
    if model.keyframes == before.keyframes {
        model.keyframes.clone_from(&before.keyframes);
    }
    model
}

/// `base` once `op` made model `index` ([`model_op`]): it replaces the one there, or is
/// added when `index` is past the models; a merge's second model goes.
pub(super) fn made_by(base: &Document, op: &Op, made: (usize, Model)) -> Outcome {
    let mut outcome = with_model(base, made);
    match (op, &mut outcome) {
        (Op::Merge(input), Outcome::Document(next)) => remove_model(next, input.kept_and_gone().1),
        (Op::Symmetrize(input), Outcome::Document(next)) => next.symmetry = Some(input.plane),
        _ => {}
    }
    outcome
}

/// `base` with model `index` replaced, or added when `index` is past its models.
pub(super) fn with_model(base: &Document, (index, mut model): (usize, Model)) -> Outcome {
    if let Some(before) = base.models.get(index) {
        carry_colors(&[before], &mut model);
    }
    let mut next = base.clone();
    match next.models.get_mut(index) {
        Some(slot) => *slot = Arc::new(model),
        None => next.models.push(Arc::new(model)),
    }
    Outcome::Document(next)
}

/// Processes the stroke in screen space and projects each point onto the plane through the
/// camera target facing the camera.
fn place_stroke(input: &StrokeInput) -> Result<SketchCurve, CommandError> {
    let viewport = input.checked_viewport()?;
    let processed = process_stroke(&input.points())?;
    let mut sketch = SketchCurve {
        points: Vec::with_capacity(processed.len()),
        pressures: Vec::with_capacity(processed.len()),
    };
    for point in &processed {
        let Some(point_in_world) = input.camera.point_on_target_plane(point.pos, viewport) else {
            return Err(CommandError::StrokeOffPlane);
        };
        sketch.points.push(point_in_world);
        sketch.pressures.push(point.pressure);
    }
    Ok(sketch)
}

/// `base` with what the files of `input` brought ([`import_files`]) added: placed beside
/// its contents when the op asks.
pub(super) fn with_imported(
    base: &Document,
    input: &ImportInput,
    mut imported: Imported,
) -> Outcome {
    if input.beside {
        place_beside(base, &mut imported);
    }
    let mut next = base.clone();
    if let Some(plane) = imported.symmetry {
        next.symmetry.get_or_insert(plane);
    }
    next.models
        .extend(imported.models.into_iter().map(Arc::new));
    next.sketches
        .extend(imported.sketches.into_iter().map(Arc::new));
    next.point_clouds
        .extend(imported.point_clouds.into_iter().map(Arc::new));
    Outcome::Imported {
        next,
        notes: imported.notes,
    }
}

/// Reads the files of an import op with the default limits: the long part of an import,
/// and a pure one (files in, models out), so the page may run it in a worker and hand the
/// result to [`super::Edit::supply_import`].
///
/// Errors: [`CommandError::FileNotLoaded`], [`CommandError::NoFile`], or the file's problem.
pub fn import_files(input: &ImportInput) -> Result<Imported, CommandError> {
    let files = input
        .files
        .iter()
        .map(|file| match &file.data {
            Some(data) => Ok(ImportFile {
                name: &file.name,
                bytes: data.as_slice(),
            }),
            None => Err(CommandError::FileNotLoaded(file.name.clone())),
        })
        .collect::<Result<Vec<_>, _>>()?;
    let (main, others) = files.split_first().ok_or(CommandError::NoFile)?;
    Ok(import_gltf(main, others, &ImportLimits::default())?)
}
