//! The `optimize` op: Laplacian mesh optimization of one model ([`crate::optimize`]).

use super::{CommandError, Document, Model, OptimizeInput};
use crate::optimize::optimize;

/// The index of the model and the model with its vertices optimized; its triangles, curves
/// (chains of vertices, so they follow) and appearance stay.
///
/// Errors: [`CommandError::NoSuchModel`], or the optimization's refusal.
pub(super) fn optimize_op(
    doc: &Document,
    input: &OptimizeInput,
) -> Result<(usize, Model), CommandError> {
    let model = doc
        .models
        .get(input.model)
        .ok_or(CommandError::NoSuchModel(input.model))?;
    let positions = optimize(&model.mesh, &input.settings)?;
    let mut next = Model::clone(model);
    next.mesh.positions_mut().copy_from_slice(&positions);
    Ok((input.model, next))
}
