//! What an op makes of a document ([`Outcome`]), and the model an op targets: the pieces
//! that the ops' own files and the dispatch in `outcome.rs` share.

use super::{CommandError, Document, Model};
use crate::model::MirrorPlane;
use crate::symmetry::are_twins;

/// What an op does to the editor, ready to commit.
#[derive(Debug)]
pub(super) enum Outcome {
    /// The next document; the current one goes on the undo history.
    Document(Document),
    /// An import's next document, with what the user may want to know about it (repairs
    /// made, textures left behind).
    Imported {
        /// The next document, as for [`Outcome::Document`].
        next: Document,
        /// Sentences for the user.
        notes: Vec<String>,
    },
    /// Go back to the last undo snapshot.
    Undo,
    /// Go forward to the last redo snapshot.
    Redo,
}

/// Model `index` of `doc`.
///
/// Errors: [`CommandError::NoSuchModel`].
pub(super) fn target(doc: &Document, index: usize) -> Result<&Model, CommandError> {
    doc.models
        .get(index)
        .map(|model| &**model)
        .ok_or(CommandError::NoSuchModel(index))
}

/// Model `index` of `doc` with its vertices at `positions`; its triangles, curves (chains
/// of vertices, so they follow) and appearance stay.
pub(super) fn with_positions(doc: &Document, index: usize, positions: &[glam::DVec3]) -> Model {
    let mut next = Model::clone(&doc.models[index]);
    next.mesh.positions_mut().copy_from_slice(positions);
    next
}

/// The index of model `index`'s mirror twin in `doc`, if it has one.
pub(super) fn twin_of(doc: &Document, index: usize, plane: &MirrorPlane) -> Option<usize> {
    let model = doc.models.get(index)?;
    (0..doc.models.len())
        .find(|&j| j != index && are_twins(&model.mesh, &doc.models[j].mesh, plane))
}
