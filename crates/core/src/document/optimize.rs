//! The `optimize` op: Laplacian mesh optimization of one model ([`crate::optimize`]), and
//! its live preview while the user tunes the settings.
//!
//! The preview keeps an [`Optimizer`]: a new scale (the slider) refactors numerically on
//! the kept analysis and back-substitutes; other settings build a new one. When the gesture
//! ends at settings the preview has solved, its positions are the committed result: they
//! are bit for bit what [`optimize_op`] computes (see [`Optimizer`]), so the commit costs
//! nothing and replay gives the same document.

use glam::DVec3;

use super::{CommandError, Document, Model, OptimizeInput};
use crate::optimize::{Optimizer, optimize};

/// The index of the model and the model with its vertices optimized; its triangles, curves
/// (chains of vertices, so they follow) and appearance stay.
///
/// Errors: [`CommandError::NoSuchModel`], or the optimization's refusal.
pub(super) fn optimize_op(
    doc: &Document,
    input: &OptimizeInput,
) -> Result<(usize, Model), CommandError> {
    let positions = optimize(&target(doc, input.model)?.mesh, &input.settings)?;
    Ok((input.model, with_positions(doc, input.model, &positions)))
}

/// A live optimization of one model: what it shows and the optimizer behind it.
#[derive(Debug)]
pub(super) struct OptimizePreview {
    /// The settings the shown positions were solved with, once solved.
    solved: Option<OptimizeInput>,
    optimizer: Option<Optimizer>,
    /// The model's positions as optimized (its own until the first step).
    shown: Vec<DVec3>,
}

impl OptimizePreview {
    /// Shows the model as it is until the first step.
    ///
    /// Errors: [`CommandError::NoSuchModel`].
    pub(super) fn start(base: &Document, input: &OptimizeInput) -> Result<Self, CommandError> {
        Ok(OptimizePreview {
            solved: None,
            optimizer: None,
            shown: target(base, input.model)?.mesh.positions().to_vec(),
        })
    }

    /// Solves for `input` unless it is what is shown: `None` when nothing changed,
    /// `Some(false)` when the preview was brought up to date (one step, however far the
    /// settings moved).
    ///
    /// Errors: [`CommandError::NoSuchModel`], or the optimization's refusal (the edit then
    /// repeats it; the document is untouched).
    pub(super) fn step(
        &mut self,
        base: &Document,
        input: &OptimizeInput,
    ) -> Result<Option<bool>, CommandError> {
        if self.solved.as_ref() == Some(input) {
            return Ok(None);
        }
        let mesh = &target(base, input.model)?.mesh;
        let same_model = self.solved.as_ref().is_some_and(|s| s.model == input.model);
        let optimizer = match &mut self.optimizer {
            Some(optimizer) if same_model && optimizer.serves(&input.settings) => optimizer,
            kept => kept.insert(Optimizer::new(mesh, &input.settings)?),
        };
        self.shown = optimizer.solve(input.settings.scale)?;
        self.solved = Some(input.clone());
        Ok(Some(false))
    }

    /// The model shown and its positions.
    pub(super) fn moved(&self, input: &OptimizeInput) -> (usize, &[DVec3]) {
        (input.model, &self.shown)
    }

    /// The committed result when the preview has solved exactly `input`.
    pub(super) fn result(&self, base: &Document, input: &OptimizeInput) -> Option<(usize, Model)> {
        (self.solved.as_ref() == Some(input))
            .then(|| (input.model, with_positions(base, input.model, &self.shown)))
    }
}

fn target(doc: &Document, index: usize) -> Result<&Model, CommandError> {
    doc.models
        .get(index)
        .map(|model| &**model)
        .ok_or(CommandError::NoSuchModel(index))
}

/// Model `index` of `doc` with its vertices at `positions`.
fn with_positions(doc: &Document, index: usize, positions: &[DVec3]) -> Model {
    let mut next = Model::clone(&doc.models[index]);
    next.mesh.positions_mut().copy_from_slice(positions);
    next
}
