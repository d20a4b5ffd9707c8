//! The `optimize` op: Laplacian mesh optimization of one model ([`crate::optimize`]), and
//! its live preview while the user tunes the settings.
//!
//! The preview keeps an [`Optimizer`]: a new scale (the slider) is approached by conjugate
//! gradients preconditioned with the kept factorization, one iteration per step, so the view
//! follows the slider without a frame spent refactoring; other settings build a new one.
//! When the gesture ends, the kept optimizer computes the exact result (a numeric
//! refactorization at the final scale, if it changed): bit for bit what [`optimize_op`]
//! computes (see [`Optimizer`]), so replay gives the same document.

use glam::DVec3;

use super::next::{target, with_positions};
use super::{BrushInput, CommandError, Document, Model, OptimizeInput, StrokeInput};
use crate::mesh::Mesh;
use crate::optimize::region::{brushed_vertices, lasso_vertices};
use crate::optimize::{OptimizeError, Optimizer, Selection};

/// The index of the model and the model with its vertices optimized; its triangles, curves
/// (chains of vertices, so they follow) and appearance stay.
///
/// Errors: [`CommandError::NoSuchModel`], [`CommandError::BadView`] for a lasso's view,
/// or the optimization's refusal.
pub(super) fn optimize_op(
    doc: &Document,
    input: &OptimizeInput,
) -> Result<(usize, Model), CommandError> {
    let positions = new_optimizer(doc, input)?.solve(input.settings.scale)?;
    Ok((input.model, with_positions(doc, input.model, &positions)))
}

/// The optimizer for `input`: its model, settings and the vertices its lasso and brush
/// strokes mark.
fn new_optimizer(doc: &Document, input: &OptimizeInput) -> Result<Optimizer, CommandError> {
    let mesh = &target(doc, input.model)?.mesh;
    let lassoed = (input.region.as_ref())
        .map(|lasso| lassoed_vertices(mesh, lasso))
        .transpose()?;
    let selection = Selection {
        movable: union(
            lassoed
                .into_iter()
                .chain(painted_vertices(mesh, &input.painted)?),
        ),
        features: union(painted_vertices(mesh, &input.painted_features)?),
        sliding: None,
    };
    Ok(Optimizer::new(mesh, &input.settings, &selection)?)
}

/// The vertices of `mesh` inside `lasso`.
///
/// Errors: [`CommandError::BadView`] for its view, [`OptimizeError::EmptyRegion`] for
/// fewer than three finite samples.
fn lassoed_vertices(mesh: &Mesh, lasso: &StrokeInput) -> Result<Vec<bool>, CommandError> {
    let viewport = lasso.checked_viewport()?;
    let points: Vec<_> = lasso.points().iter().map(|p| p.pos).collect();
    if points.len() < 3 || points.iter().any(|p| !p.is_finite()) {
        return Err(OptimizeError::EmptyRegion.into());
    }
    Ok(lasso_vertices(mesh, &lasso.camera, viewport, &points))
}

/// The vertices of `mesh` each of `strokes` covers.
///
/// Errors: [`CommandError::BadView`] for a stroke's view, [`OptimizeError::EmptyRegion`]
/// for a stroke without samples or with a radius that is not positive and finite.
fn painted_vertices(mesh: &Mesh, strokes: &[BrushInput]) -> Result<Vec<Vec<bool>>, CommandError> {
    strokes
        .iter()
        .map(|brush| {
            let viewport = brush.stroke.checked_viewport()?;
            let points = brush.stroke.points();
            let usable = brush.radius.is_finite() && brush.radius > 0.0;
            if !usable || points.is_empty() || points.iter().any(|p| !p.pos.is_finite()) {
                return Err(OptimizeError::EmptyRegion.into());
            }
            let camera = &brush.stroke.camera;
            Ok(brushed_vertices(
                mesh,
                camera,
                viewport,
                &points,
                brush.radius,
            ))
        })
        .collect()
}

/// The vertices any of `masks` marks; `None` without masks.
fn union(masks: impl IntoIterator<Item = Vec<bool>>) -> Option<Vec<bool>> {
    (masks.into_iter()).reduce(|a, b| a.iter().zip(&b).map(|(&x, &y)| x || y).collect())
}

/// A live optimization of one model: what it shows and the optimizer behind it.
#[derive(Debug)]
pub(super) struct OptimizePreview {
    /// The settings the shown positions are solved for, once solved (exactly, or to the
    /// refinement's tolerance).
    solved: Option<OptimizeInput>,
    /// The op the optimizer was built for (its model and region; the settings but the
    /// scale are the optimizer's own).
    built: Option<OptimizeInput>,
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
            built: None,
            optimizer: None,
            shown: target(base, input.model)?.mesh.positions().to_vec(),
        })
    }

    /// Brings what is shown closer to `input`'s result: `None` when it is there already,
    /// `Some(true)` after a step that is not there yet (an iteration toward a new scale),
    /// `Some(false)` after the step that got there.
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
        let is_there = match optimizer_for(&mut self.optimizer, &mut self.built, base, input)? {
            (optimizer, true) => optimizer.refine(input.settings.scale, &mut self.shown)?,
            (optimizer, false) => {
                self.shown = optimizer.solve(input.settings.scale)?;
                true
            }
        };
        if is_there {
            self.solved = Some(input.clone());
        }
        Ok(Some(!is_there))
    }

    /// The committed result of `input`: exact, from the kept optimizer when it serves.
    ///
    /// Errors: [`CommandError::NoSuchModel`], or the optimization's refusal.
    pub(super) fn result(
        &mut self,
        base: &Document,
        input: &OptimizeInput,
    ) -> Result<(usize, Model), CommandError> {
        let (optimizer, _) = optimizer_for(&mut self.optimizer, &mut self.built, base, input)?;
        let positions = optimizer.solve(input.settings.scale)?;
        Ok((input.model, with_positions(base, input.model, &positions)))
    }

    /// The model shown and its positions.
    pub(super) fn moved(&self, input: &OptimizeInput) -> (usize, &[DVec3]) {
        (input.model, &self.shown)
    }
}

/// The optimizer in `slot` if it was built for the model and region of `input` and serves
/// its settings (and whether it was kept), else a new one for `input`, recorded in `slot`
/// and `built`.
fn optimizer_for<'a>(
    slot: &'a mut Option<Optimizer>,
    built: &mut Option<OptimizeInput>,
    base: &Document,
    input: &OptimizeInput,
) -> Result<(&'a mut Optimizer, bool), CommandError> {
    let same_target = built.as_ref().is_some_and(|b| {
        b.model == input.model
            && b.region == input.region
            && b.painted == input.painted
            && b.painted_features == input.painted_features
    });
    let keep = same_target && slot.as_ref().is_some_and(|o| o.serves(&input.settings));
    Ok(match (slot, keep) {
        (Some(kept), true) => (kept, true),
        (slot, _) => {
            let optimizer = slot.insert(new_optimizer(base, input)?);
            *built = Some(input.clone());
            (optimizer, false)
        }
    })
}
