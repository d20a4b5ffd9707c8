//! Merging two models ([`crate::fibermesh::merge`]): both parts' curves carried over, each
//! seam a new smooth curve, and the band along the seams remeshed and re-optimized toward
//! the typical curvature around it, so that the parts blend. Models without curves
//! (imported) are joined and their band remeshed, but get no curves (see `cut.rs` for why).

use super::settle::{Aim, Change, remesh_and_fair_within, remesh_only};
use super::shared::{bounding_diagonal, carried_over, has_curves};
use crate::document::next::target;
use crate::document::{CommandError, Document, MergeInput};
use crate::fibermesh::merge::{MergeError, merge};
use crate::mesh::VertexId;
use crate::model::Model;
use crate::model::{ControlCurve, CurveKind};

/// How far from the seams (as a fraction of the merged model's size) the surface is
/// remeshed and re-optimized.
const MERGE_REGION: f64 = 0.08;

/// Applies a `merge` op: returns the index the merged model takes (the lower) and the
/// merged model (the first's name and appearance); the other model goes when it lands
/// ([`MergeInput::kept_and_gone`]).
///
/// Errors: [`CommandError::NoSuchModel`]; [`CommandError::Merge`] for one model named twice
/// or models that do not merge; remesher and solver failures.
pub fn merge_op(doc: &Document, input: &MergeInput) -> Result<(usize, Model), CommandError> {
    let (kept, gone) = input.kept_and_gone();
    target(doc, kept)?;
    target(doc, gone)?;
    if kept == gone {
        return Err(MergeError::SameModel.into());
    }
    let (first, second) = (&doc.models[kept], &doc.models[gone]);
    let merged = merge(&first.mesh, &second.mesh)?;
    let mesh = merged.mesh;
    let mut curves = Vec::new();
    for (part, model) in merged.parts.iter().zip([first, second]) {
        curves.extend(carried_over(
            &model.curves,
            &part.split_edges,
            &part.remap,
            &mesh,
        ));
    }
    let seam_vertices: Vec<VertexId> = (mesh.vertices())
        .filter(|v| merged.is_seam[v.index()])
        .collect();
    let change = Change {
        around: &seam_vertices,
        radius: MERGE_REGION * bounding_diagonal(&mesh),
    };
    let band = change.region(&mesh);
    let (mesh, curves) = if has_curves(first) || has_curves(second) {
        curves.extend(merged.seams.into_iter().map(|seam| ControlCurve {
            vertices: seam,
            is_closed: true,
            kind: CurveKind::Smooth,
        }));
        remesh_and_fair_within(&mesh, &curves, &band, Aim::Typical)?
    } else {
        (remesh_only(&mesh, &curves, &band)?.0, Vec::new())
    };
    let model = Model {
        mesh,
        curves,
        name: first.name.clone(),
        appearance: first.appearance.clone(),
        as_imported: first.as_imported.clone(),
        // The merged surface has new vertices: no old pose fits it.
        keyframes: Vec::new(),
        // Its colours are carried over from both models once it is made
        // (`paint::carried_colors`, for every op that makes a model).
        colors: None,
        finish: first.finish,
    };
    Ok((kept, model))
}
