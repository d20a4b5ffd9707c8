//! Tunnels (thesis §3.2.1, Fig. 3.3): the two loops' hole ([`crate::fibermesh::tunnel`]),
//! the curves carried over, both loops as new smooth curves, and the band around the tube
//! remeshed and settled.

use super::settle::{Change, remesh_and_settle};
use super::shared::{
    bounding_diagonal, carried_over, has_curves, model_crossed, replaced, screen_stroke, viewed,
};
use crate::document::{CommandError, Document, StrokePairInput};
use crate::fibermesh::tunnel::{TunnelError, tunnel};
use crate::mesh::VertexId;
use crate::model::Model;
use crate::model::{ControlCurve, CurveKind};

/// How far from the tube and the loops (as a fraction of the model's size) the surface is
/// re-optimized and remeshed.
const TUNNEL_REGION: f64 = 0.05;

/// Applies a `tunnel` op: returns the index of the model drilled and its new version.
///
/// Errors: the strokes'; [`CommandError::NotOnModel`] when the first loop is on no model with
/// curves; [`CommandError::Tunnel`] when the loops are refused (the second on another model
/// among them); remesher and solver failures.
pub fn tunnel_op(doc: &Document, input: &StrokePairInput) -> Result<(usize, Model), CommandError> {
    let [first, second] = &input.strokes;
    let (a, b) = (screen_stroke(first, 3)?, screen_stroke(second, 3)?);
    let index = model_crossed(doc, first, &a, has_curves).ok_or(CommandError::NotOnModel)?;
    if model_crossed(doc, second, &b, has_curves) != Some(index) {
        return Err(TunnelError::NotFacing.into());
    }
    let model = &doc.models[index];
    let drilled = tunnel(&model.mesh, viewed(first, &a), viewed(second, &b))?;
    let mut curves = carried_over(
        &model.curves,
        &drilled.split_edges,
        &drilled.remap,
        &drilled.mesh,
    );
    curves.extend(drilled.loops.iter().map(|chain| ControlCurve {
        vertices: chain.clone(),
        is_closed: true,
        kind: CurveKind::Smooth,
    }));
    let mesh = drilled.mesh;
    let around: Vec<VertexId> = (mesh.vertices())
        .filter(|v| drilled.is_tube[v.index()])
        .chain(drilled.loops.iter().flatten().copied())
        .collect();
    let change = Change {
        around: &around,
        radius: TUNNEL_REGION * bounding_diagonal(&mesh),
    };
    let (mesh, curves) = remesh_and_settle(&mesh, &curves, change)?;
    Ok((index, replaced(model, mesh, curves)))
}
