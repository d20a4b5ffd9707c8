//! Ops made with symmetry on, and the `symmetrize` op.
//!
//! An op made with symmetry on (`"mirror": [nx, ny, nz, d]` in the session) is computed as
//! it would be without, and then every model it changed is made symmetric again
//! ([`mirrored_outcome`]):
//! - a model with a mirror twin: the twin becomes the changed model's mirror image;
//! - a symmetric model: the side the op changed (much more than the other) stays and the
//!   other becomes its mirror image; an op that changed both alike meets halfway; an op that
//!   changed its triangles is symmetrized, keeping the side it changed;
//! - a new model across the plane is symmetrized, one beside it gets its mirror twin;
//! - a deleted model takes its twin along, a duplicate is the model's mirror twin.
//!
//! So one stroke makes both arms and one pull moves both sides, in one undo step, for every
//! op alike, and the pairing is exact after each op (see [`crate::symmetry`]).

use std::sync::Arc;

use super::next::{Outcome, target, twin_of};
use super::paint::{carry_colors, fill_op, material_op, paint_op};
use super::skeleton::remove_model;
use glam::DVec2;

use super::{CommandError, CreateInput, Document, Op, SymmetrizeInput};
use crate::mesh::VertexId;
use crate::model::{MirrorPlane, Model, Side};
use crate::symmetry::{
    Keep, Place, changed_side, mirror_positions, mirrored_curves, mirrored_model, partners,
    side_of_model, symmetric_outline, symmetrized,
};

/// Applies a `symmetrize` op: the model made symmetric about the plane, keeping one side.
///
/// Errors: [`CommandError::NoSuchModel`]; the plane misses the model, or the halves do not
/// join ([`crate::symmetry::SymmetryError`]).
pub(super) fn symmetrize_op(
    doc: &Document,
    input: &SymmetrizeInput,
) -> Result<(usize, Model), CommandError> {
    let model = target(doc, input.model)?;
    Ok((input.model, symmetrized(model, &input.plane, input.keep)?))
}

/// A creation drawn across the plane in a view that lies in it, its outline made even
/// ([`symmetric_outline`]): what is computed in its place (the session keeps the op as
/// drawn). `None` for any other op, or when the outline cannot be evened.
pub(super) fn even_outline(op: &Op, plane: &MirrorPlane) -> Option<Op> {
    let Op::Create(input) = op else {
        return None;
    };
    let viewport = DVec2::from(input.viewport);
    let stroke = symmetric_outline(&input.stroke, &input.camera, viewport, plane)?;
    Some(Op::Create(CreateInput {
        stroke,
        ..input.clone()
    }))
}

/// `doc` with the mirror image of its model `index` added after its models, when that model
/// lies wholly on one side of `plane` (as a creation's result adds its twin); `None` when
/// there is no such model or it crosses the plane.
pub(super) fn with_twin_shown(
    doc: &Document,
    index: usize,
    plane: &MirrorPlane,
) -> Option<Document> {
    let model = doc.models.get(index)?;
    side_of_model(&model.mesh, plane)?;
    let mut shown = doc.clone();
    shown.models.push(Arc::new(mirrored_model(model, plane)));
    Some(shown)
}

/// `outcome` of `op` on `base`, made symmetric about `plane` (see the module docs).
///
/// Errors: [`CommandError::NotSymmetric`] when the op changed a model that is neither
/// symmetric nor a twin; a symmetrize's refusal.
pub(super) fn mirrored_outcome(
    base: &Document,
    op: &Op,
    plane: MirrorPlane,
    outcome: Outcome,
) -> Result<Outcome, CommandError> {
    let Outcome::Document(mut next) = outcome else {
        return Ok(outcome);
    };
    // The colour ops change no position for the general rule to go by: computed again with
    // the plane, they colour the mirror image too.
    let recoloured = match op {
        Op::Paint(input) => Some(paint_op(base, input, Some(&plane))?),
        Op::Fill(input) => Some(fill_op(base, input, Some(&plane))?),
        Op::Material(input) => Some(material_op(base, input, Some(&plane))?),
        _ => None,
    };
    if let Some(recoloured) = recoloured {
        next = recoloured;
    }
    next.symmetry = Some(plane);
    match op {
        Op::Paint(_) | Op::Fill(_) | Op::Material(_) => {}
        Op::Delete(input) => {
            if let Some(twin) = twin_of(base, input.model, &plane) {
                remove_model(&mut next, if twin > input.model { twin - 1 } else { twin });
            }
        }
        Op::Duplicate(input) => {
            let copy = mirrored_model(target(base, input.model)?, &plane);
            if let Some(last) = next.models.last_mut() {
                *last = Arc::new(copy);
            }
        }
        Op::Merge(input) => merged(base, &mut next, input.kept_and_gone(), &plane)?,
        _ => {
            let n = base.models.len().min(next.models.len());
            let mut settled = vec![false; next.models.len()];
            for i in 0..n {
                if !settled[i] && !Arc::ptr_eq(&base.models[i], &next.models[i]) {
                    let is_move = matches!(op, Op::Transform(_));
                    let twin = follow(base, &mut next, i, &plane, is_move)?;
                    settled[i] = true;
                    if let Some(j) = twin {
                        settled[j] = true;
                    }
                }
            }
            for i in base.models.len()..next.models.len() {
                made_symmetric(&mut next, i, &plane)?;
            }
        }
    }
    Ok(Outcome::Document(next))
}

/// Makes model `i` of `next`, changed from `base`'s, symmetric again: its twin follows it,
/// or its own other side does. A moved symmetric model is left as moved. Returns the twin's
/// index when it had one.
///
/// Errors: [`CommandError::NotSymmetric`] for a model neither symmetric nor a twin.
fn follow(
    base: &Document,
    next: &mut Document,
    i: usize,
    plane: &MirrorPlane,
    is_move: bool,
) -> Result<Option<usize>, CommandError> {
    let (before, changed) = (&base.models[i], Arc::clone(&next.models[i]));
    if let Some(j) = twin_of(base, i, plane) {
        next.models[j] = Arc::new(mirrored_model(&changed, plane));
        return Ok(Some(j));
    }
    let Some(pairs) = partners(&before.mesh, plane) else {
        return Err(CommandError::NotSymmetric);
    };
    if is_move {
        return Ok(None);
    }
    let keep = changed_side(&before.mesh, &changed.mesh, plane);
    let made = if changed.mesh.triangles() == before.mesh.triangles() {
        with_mirrored_side(before, &changed, &pairs, plane, keep)
    } else {
        let side = match keep {
            Keep::Side(side) => side,
            Keep::Average => Side::Positive,
        };
        let mut made = symmetrized(&changed, plane, side)?;
        carry_colors(&[&changed], &mut made);
        made
    };
    next.models[i] = Arc::new(made);
    Ok(None)
}

/// `changed`, a symmetric model `before` an op that kept its triangles, made symmetric
/// again under the same pairing: positions as `keep` says, and its curves, if the op
/// changed them, those of the kept side with their mirror images.
fn with_mirrored_side(
    before: &Model,
    changed: &Model,
    pairs: &[VertexId],
    plane: &MirrorPlane,
    keep: Keep,
) -> Model {
    let mut made = changed.clone();
    let sides_from = before.mesh.positions();
    mirror_positions(sides_from, made.mesh.positions_mut(), pairs, plane, keep);
    if changed.curves != before.curves {
        let side = match keep {
            Keep::Side(side) => side,
            Keep::Average => Side::Positive,
        };
        let place = |v: VertexId| {
            let s = side.sign() * plane.signed_distance(sides_from[v.index()]);
            match pairs[v.index()] == v {
                true => Place::OnPlane,
                false if s >= 0.0 => Place::Kept,
                false => Place::Gone,
            }
        };
        made.curves = mirrored_curves(&changed.curves, place, |v| pairs[v.index()]);
    }
    made
}

/// Makes new model `i` of `next` symmetric: across the plane, symmetrized keeping its
/// larger side; beside it, with a mirror twin added.
///
/// Errors: a symmetrize's refusal.
fn made_symmetric(next: &mut Document, i: usize, plane: &MirrorPlane) -> Result<(), CommandError> {
    let model = Arc::clone(&next.models[i]);
    match side_of_model(&model.mesh, plane) {
        Some(_) => next.models.push(Arc::new(mirrored_model(&model, plane))),
        None => {
            let positive = (model.mesh.positions().iter())
                .filter(|&&p| plane.signed_distance(p) > 0.0)
                .count();
            let side = match 2 * positive >= model.mesh.n_vertices() {
                true => Side::Positive,
                false => Side::Negative,
            };
            next.models[i] = Arc::new(symmetrized(&model, plane, side)?);
        }
    }
    Ok(())
}

/// Makes a merge symmetric: the merged model (at `kept`, `gone` removed) made symmetric
/// (mirror twin or symmetrized, keeping the side the merged-in part came from), and the twins
/// of the two models it was made of, now part of it or of its twin, handled with it.
///
/// Errors: [`CommandError::NotSymmetric`]; a symmetrize's refusal.
fn merged(
    base: &Document,
    next: &mut Document,
    (kept, gone): (usize, usize),
    plane: &MirrorPlane,
) -> Result<(), CommandError> {
    let in_next = |index: usize| if index > gone { index - 1 } else { index };
    let (kept_twin, gone_twin) = (twin_of(base, kept, plane), twin_of(base, gone, plane));
    let merged = Arc::clone(&next.models[kept]);
    let mut removed = Vec::new();
    match side_of_model(&merged.mesh, plane) {
        Some(_) => {
            let (Some(kept_twin), Some(gone_twin)) = (kept_twin, gone_twin) else {
                return Err(CommandError::NotSymmetric);
            };
            next.models[in_next(kept_twin)] = Arc::new(mirrored_model(&merged, plane));
            if gone_twin != kept_twin {
                removed.push(in_next(gone_twin));
            }
        }
        None => {
            let side_of = |index: usize| side_of_model(&base.models[index].mesh, plane);
            let side = side_of(gone).or(side_of(kept)).unwrap_or(Side::Positive);
            next.models[kept] = Arc::new(symmetrized(&merged, plane, side)?);
            removed.extend(
                [kept_twin, gone_twin]
                    .into_iter()
                    .flatten()
                    .filter(|&t| t != kept && t != gone)
                    .map(in_next),
            );
        }
    }
    removed.sort_unstable();
    removed.dedup();
    for index in removed.into_iter().rev() {
        remove_model(next, index);
    }
    Ok(())
}
