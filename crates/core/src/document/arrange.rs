//! Arranging models (issue 16): moving, rotating and scaling one by an affine matrix,
//! deleting one, duplicating one, and placing an import beside what the document holds.
//!
//! A model's curves are chains of its vertices, so they follow any of these as they are. A
//! mirroring matrix (negative determinant) would turn the surface inside out, so its
//! triangles are reversed as well: the model stays outward-facing.

use std::sync::Arc;

use glam::{DMat3, DMat4, DVec3};

use super::next::{Outcome, target};
use super::skeleton::remove_model;
use super::{CommandError, Document, DuplicateInput, ModelInput, TransformInput};
use crate::io::Imported;
use crate::mesh::Mesh;
use crate::model::Model;

/// A matrix whose 3×3 part has a determinant below this (relative to its columns' lengths
/// cubed) flattens the model: refused as singular.
const MIN_RELATIVE_DETERMINANT: f64 = 1e-9;

/// The gap between an imported file and the models beside it, as a fraction of the larger
/// of the two.
const IMPORT_GAP: f64 = 0.1;

/// A duplicate without a direction (sessions from before it had one) lands this many of the
/// model's widths along +x from it.
const DUPLICATE_SHIFT: f64 = 1.2;

/// The gap between a duplicate and the models beside it, as a fraction of its largest
/// extent.
const DUPLICATE_GAP: f64 = 0.1;

/// Applies a `transform` op: model `input.model` with `input.matrix` applied.
///
/// Errors: [`CommandError::NoSuchModel`]; [`CommandError::BadTransform`] when the matrix is
/// not finite, not affine or singular.
pub(super) fn transform_op(
    doc: &Document,
    input: &TransformInput,
) -> Result<(usize, Model), CommandError> {
    let model = target(doc, input.model)?;
    let matrix = DMat4::from_cols_array(&input.matrix);
    let determinant = checked_determinant(&matrix)?;
    Ok((input.model, transformed(model, &matrix, determinant)?))
}

/// A transform's live preview while its handle is dragged: the model's vertices moved by
/// the op's latest matrix (the committed op computes the same positions).
#[derive(Debug)]
pub(super) struct TransformPreview {
    model: usize,
    positions: Vec<DVec3>,
    /// The matrix the positions show.
    shown: Option<[f64; 16]>,
}

impl TransformPreview {
    /// The preview of `input` on `base`, showing the model as it is.
    ///
    /// Errors: [`CommandError::NoSuchModel`].
    pub(super) fn start(base: &Document, input: &TransformInput) -> Result<Self, CommandError> {
        let model = target(base, input.model)?;
        Ok(TransformPreview {
            model: input.model,
            positions: model.mesh.positions().to_vec(),
            shown: None,
        })
    }

    /// Moves the vertices by the op's matrix if it changed: `Some(false)` when it did (the
    /// preview waits for the next), `None` when nothing changed.
    ///
    /// Errors: [`CommandError::BadTransform`] for a matrix the op would refuse.
    pub(super) fn step(
        &mut self,
        base: &Document,
        input: &TransformInput,
    ) -> Result<Option<bool>, CommandError> {
        if self.shown == Some(input.matrix) {
            return Ok(None);
        }
        let matrix = DMat4::from_cols_array(&input.matrix);
        checked_determinant(&matrix)?;
        let rest = target(base, self.model)?.mesh.positions();
        for (p, &r) in self.positions.iter_mut().zip(rest) {
            *p = matrix.transform_point3(r);
        }
        self.shown = Some(input.matrix);
        Ok(Some(false))
    }

    /// The model's index and where its vertices are drawn.
    pub(super) fn moved(&self) -> (usize, &[DVec3]) {
        (self.model, &self.positions)
    }
}

/// Applies a `delete` op.
///
/// Errors: [`CommandError::NoSuchModel`].
pub(super) fn delete_op(doc: &Document, input: &ModelInput) -> Result<Outcome, CommandError> {
    target(doc, input.model)?;
    let mut next = doc.clone();
    remove_model(&mut next, input.model);
    Ok(Outcome::Document(next))
}

/// Applies a `duplicate` op: a copy of the model, added after the others, placed beside it
/// along `input.beside` ([`free_shift`]) or, in sessions from before that field,
/// [`DUPLICATE_SHIFT`] of its widths along +x.
///
/// Errors: [`CommandError::NoSuchModel`].
pub(super) fn duplicate_op(
    doc: &Document,
    input: &DuplicateInput,
) -> Result<Outcome, CommandError> {
    let model = target(doc, input.model)?;
    let bounds = model.mesh.bounding_box();
    let shift = match (input.beside, bounds) {
        (Some(beside), Some(own)) => {
            let toward = DVec3::from(beside).try_normalize().unwrap_or(DVec3::X);
            let boxes: Vec<_> = doc
                .models
                .iter()
                .filter_map(|m| m.mesh.bounding_box())
                .collect();
            let gap = DUPLICATE_GAP * (own.1 - own.0).max_element();
            toward * free_shift(own, toward, &boxes, gap)
        }
        _ => {
            let width = bounds.map_or(1.0, |(lo, hi)| (hi.x - lo.x).max(f64::EPSILON));
            DVec3::X * DUPLICATE_SHIFT * width
        }
    };
    let mut copy = model.clone();
    for p in copy.mesh.positions_mut() {
        *p += shift;
    }
    let mut next = doc.clone();
    next.models.push(Arc::new(copy));
    Ok(Outcome::Document(next))
}

/// How far the box `own` must move along the unit vector `toward` to overlap none of
/// `boxes` (each grown by `gap` on every side, `own` itself among them): the least distance
/// `t ≥ 0` outside every distance at which it overlaps one. Along a line, each box is
/// overlapped over one open interval of `t` (the intersection of one interval per axis), so
/// the answer is found by stepping past the intervals that hold `t`, each at most once.
fn free_shift(own: (DVec3, DVec3), toward: DVec3, boxes: &[(DVec3, DVec3)], gap: f64) -> f64 {
    let overlaps: Vec<(f64, f64)> = (boxes.iter())
        .filter_map(|&(lo, hi)| overlap_interval(own, toward, (lo - gap, hi + gap)))
        .collect();
    let mut t = 0.0;
    while let Some(&(_, end)) = overlaps.iter().find(|&&(start, end)| start < t && t < end) {
        t = end;
    }
    t
}

/// The open interval of distances `t` along `toward` at which the box `own` moved by
/// `t * toward` overlaps `other` (their interiors share a point), if any.
fn overlap_interval(
    own: (DVec3, DVec3),
    toward: DVec3,
    other: (DVec3, DVec3),
) -> Option<(f64, f64)> {
    let (mut start, mut end) = (f64::NEG_INFINITY, f64::INFINITY);
    for axis in 0..3 {
        let (lo, hi, step) = (own.0[axis], own.1[axis], toward[axis]);
        let (other_lo, other_hi) = (other.0[axis], other.1[axis]);
        if step.abs() < 1e-12 {
            if lo >= other_hi || hi <= other_lo {
                return None;
            }
            continue;
        }
        let (a, b) = ((other_lo - hi) / step, (other_hi - lo) / step);
        start = start.max(a.min(b));
        end = end.min(a.max(b));
    }
    (start < end).then_some((start, end))
}

/// The other model that `index`'s overlaps most (by the volume their bounding boxes share),
/// if any overlaps: the one the app offers to merge it with.
pub fn overlapping_model(doc: &Document, index: usize) -> Option<usize> {
    let boxes: Vec<Option<(DVec3, DVec3)>> =
        (doc.models.iter()).map(|m| m.mesh.bounding_box()).collect();
    let (lo, hi) = (*boxes.get(index)?)?;
    let shared = |(l, h): (DVec3, DVec3)| {
        let extent = h.min(hi) - l.max(lo);
        (extent.min_element() > 0.0).then_some(extent.x * extent.y * extent.z)
    };
    (boxes.iter().enumerate())
        .filter(|&(i, _)| i != index)
        .filter_map(|(i, b)| Some((shared((*b)?)?, i)))
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, i)| i)
}

/// Moves what a file brought in beside the document's contents (along +x, a gap of
/// [`IMPORT_GAP`] between them, standing on the same floor and centred in depth), so that
/// it does not land inside them. Into an empty document it stays where the file put it.
pub(super) fn place_beside(doc: &Document, imported: &mut Imported) {
    let here = bounds(
        doc.models.iter().map(|m| m.mesh.positions()).chain(
            doc.point_clouds
                .iter()
                .map(|c| c.positions.as_slice())
                .chain(doc.sketches.iter().map(|s| s.points.as_slice())),
        ),
    );
    let coming = bounds(
        imported
            .models
            .iter()
            .map(|m| m.mesh.positions())
            .chain(imported.point_clouds.iter().map(|c| c.positions.as_slice()))
            .chain(imported.sketches.iter().map(|s| s.points.as_slice())),
    );
    let (Some((lo, hi)), Some((new_lo, new_hi))) = (here, coming) else {
        return;
    };
    let gap = IMPORT_GAP * (hi - lo).max_element().max((new_hi - new_lo).max_element());
    let offset = DVec3::new(
        hi.x + gap - new_lo.x,
        lo.y - new_lo.y,
        0.5 * (lo.z + hi.z) - 0.5 * (new_lo.z + new_hi.z),
    );
    let moved = imported
        .models
        .iter_mut()
        .flat_map(|m| m.mesh.positions_mut().iter_mut())
        .chain(
            imported
                .point_clouds
                .iter_mut()
                .flat_map(|c| c.positions.iter_mut()),
        )
        .chain(
            imported
                .sketches
                .iter_mut()
                .flat_map(|s| s.points.iter_mut()),
        );
    for p in moved {
        *p += offset;
    }
}

/// The bounding box of all the points, if there are any.
fn bounds<'a>(sets: impl Iterator<Item = &'a [DVec3]>) -> Option<(DVec3, DVec3)> {
    sets.flatten().fold(None, |bounds, &p| match bounds {
        None => Some((p, p)),
        Some((lo, hi)) => Some((lo.min(p), hi.max(p))),
    })
}

/// The determinant of the matrix's linear part, once the matrix is known to be a finite,
/// invertible affine map.
fn checked_determinant(matrix: &DMat4) -> Result<f64, CommandError> {
    let bottom = matrix.row(3);
    let affine = bottom == glam::DVec4::W;
    let linear = DMat3::from_mat4(*matrix);
    let determinant = linear.determinant();
    let scale = [linear.x_axis, linear.y_axis, linear.z_axis]
        .map(DVec3::length)
        .into_iter()
        .fold(0.0, f64::max);
    let invertible = determinant.abs() > MIN_RELATIVE_DETERMINANT * scale.powi(3);
    if matrix.is_finite() && affine && invertible {
        Ok(determinant)
    } else {
        Err(CommandError::BadTransform)
    }
}

/// `model` with `matrix` applied to its vertices, its triangles reversed when the matrix
/// mirrors (`determinant < 0`).
fn transformed(model: &Model, matrix: &DMat4, determinant: f64) -> Result<Model, CommandError> {
    let mut next = model.clone();
    for p in next.mesh.positions_mut() {
        *p = matrix.transform_point3(*p);
    }
    if determinant < 0.0 {
        next.mesh = reversed(&next.mesh)?;
    }
    Ok(next)
}

/// The mesh with every triangle's orientation reversed; vertex ids stay.
fn reversed(mesh: &Mesh) -> Result<Mesh, CommandError> {
    let mut soup = mesh.to_soup();
    for t in &mut soup.triangles {
        t.swap(1, 2);
    }
    Mesh::from_soup(&soup).map_err(|_| CommandError::BadTransform)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube(lo: [f64; 3], hi: [f64; 3]) -> (DVec3, DVec3) {
        (DVec3::from(lo), DVec3::from(hi))
    }

    #[test]
    fn a_free_shift_steps_past_the_boxes_in_the_way_and_only_those() {
        let own = cube([0.0; 3], [1.0; 3]);
        // Alone, it moves its width and the gap.
        assert!((free_shift(own, DVec3::X, &[own], 0.1) - 1.1).abs() < 1e-12);
        // A box right beside it is stepped past: its far side plus the gap.
        let next = cube([1.5, 0.0, 0.0], [2.5, 1.0, 1.0]);
        assert!((free_shift(own, DVec3::X, &[own, next], 0.1) - 2.6).abs() < 1e-12);
        // One listed first but farther, then the near one that pushes into it: both.
        let far = cube([2.8, 0.0, 0.0], [4.0, 1.0, 1.0]);
        assert!((free_shift(own, DVec3::X, &[far, own, next], 0.1) - 4.1).abs() < 1e-12);
        // A box above the path is not in the way.
        let above = cube([1.5, 3.0, 0.0], [2.5, 4.0, 1.0]);
        assert!((free_shift(own, DVec3::X, &[own, above], 0.1) - 1.1).abs() < 1e-12);
        // Diagonally: the box clears the original's on the first axis it leaves.
        let toward = DVec3::new(1.0, 0.0, 1.0).normalize();
        let t = free_shift(own, toward, &[own], 0.0);
        assert!((t - 2f64.sqrt()).abs() < 1e-12, "{t}");
    }
}
