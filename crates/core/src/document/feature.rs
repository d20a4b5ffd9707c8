//! The `sketch_feature` op ([`crate::feature`]) and its live preview while the user drags the
//! amount.
//!
//! The preview keeps the [`FeatureEdit`] built for the op's sketch, region and kind: a new
//! amount only weighs its solutions again (a pass over the region, nothing allocated), and
//! the committed result is that edit's shape at the final amount, bit for bit what
//! [`feature_op`] computes from the op alone, so replay gives the same document.

use glam::{DVec2, DVec3};

use super::next::{target, with_positions};
use super::{CommandError, Document, Model, SketchFeatureInput, model_under};
use crate::curve::process_stroke;
use crate::feature::{FeatureEdit, FeatureError, Sketch};

/// The index of the model under the sketch and the model with the feature made.
///
/// Errors: [`CommandError::BadView`], a stroke too short, or the feature's refusal.
pub(super) fn feature_op(
    doc: &Document,
    input: &SketchFeatureInput,
) -> Result<(usize, Model), CommandError> {
    let (index, edit) = new_feature(doc, input)?;
    let shaped = edit.shape(input.amount())?;
    Ok((index, with_positions(doc, index, &shaped.positions)))
}

/// The model under the sketch's first point and the feature edit of `input` on it.
fn new_feature(
    doc: &Document,
    input: &SketchFeatureInput,
) -> Result<(usize, FeatureEdit), CommandError> {
    let stroke = input.stroke_input();
    let viewport = stroke.checked_viewport()?;
    let points = process_stroke(&stroke.points())?;
    let index = model_under(doc, &stroke).ok_or(FeatureError::MissesMesh)?;
    let region = (input.region.as_ref())
        .map(|lasso| lasso.iter().map(|&p| DVec2::from(p)).collect::<Vec<_>>());
    if region
        .as_ref()
        .is_some_and(|lasso| lasso.iter().any(|p| !p.is_finite()))
    {
        return Err(FeatureError::RegionCrosses.into());
    }
    let sketch = Sketch {
        camera: input.camera,
        viewport,
        points: points.iter().map(|p| p.pos).collect(),
        region,
    };
    let mesh = &target(doc, index)?.mesh;
    Ok((index, FeatureEdit::new(mesh, &sketch, input.kind)?))
}

/// A live feature on one model: the edit behind it and what it shows.
#[derive(Debug)]
pub(super) struct FeaturePreview {
    built: Option<Built>,
    /// The amount the shown positions are shaped for, once shaped.
    shown_for: Option<f64>,
    shown: Vec<DVec3>,
    /// The amount used, when the one asked for was cut back.
    limited_to: Option<f64>,
}

/// A feature edit and what it was built for.
#[derive(Debug)]
struct Built {
    /// The op, its amount left out.
    key: SketchFeatureInput,
    model: usize,
    edit: FeatureEdit,
}

impl FeaturePreview {
    /// Shows the document as it is until the first step.
    pub(super) fn new() -> Self {
        FeaturePreview {
            built: None,
            shown_for: None,
            shown: Vec::new(),
            limited_to: None,
        }
    }

    /// Brings what is shown to `input`'s amount, building the edit first if the sketch,
    /// region or kind changed: `None` when it is there already, `Some(false)` after a step
    /// that got there.
    ///
    /// Errors: the feature's refusal (the edit then repeats it; the document is untouched).
    pub(super) fn step(
        &mut self,
        base: &Document,
        input: &SketchFeatureInput,
    ) -> Result<Option<bool>, CommandError> {
        let amount = input.amount();
        let (built, is_new) = edit_for(&mut self.built, base, input)?;
        if is_new {
            self.shown = built.edit.embedded().to_vec();
        } else if self.shown_for == Some(amount) {
            return Ok(None);
        }
        self.limited_to = built.edit.shape_into(amount, &mut self.shown)?;
        self.shown_for = Some(amount);
        Ok(Some(false))
    }

    /// The committed result of `input`, from the kept edit when it serves.
    ///
    /// Errors: the feature's refusal.
    pub(super) fn result(
        &mut self,
        base: &Document,
        input: &SketchFeatureInput,
    ) -> Result<(usize, Model), CommandError> {
        let (built, _) = edit_for(&mut self.built, base, input)?;
        let shaped = built.edit.shape(input.amount())?;
        Ok((
            built.model,
            with_positions(base, built.model, &shaped.positions),
        ))
    }

    /// The model shown and its positions, once the first step shaped it.
    pub(super) fn moved(&self) -> Option<(usize, &[DVec3])> {
        let built = self.built.as_ref()?;
        self.shown_for.map(|_| (built.model, &self.shown[..]))
    }

    /// The amount used, when the one asked for would have folded triangles over.
    pub(super) fn limited_to(&self) -> Option<f64> {
        self.limited_to
    }
}

/// The edit in `slot` if it was built for `input`'s sketch, region and kind, else a new one
/// put there; and whether it is new.
fn edit_for<'a>(
    slot: &'a mut Option<Built>,
    base: &Document,
    input: &SketchFeatureInput,
) -> Result<(&'a Built, bool), CommandError> {
    let key = SketchFeatureInput {
        amount: None,
        ..input.clone()
    };
    let (built, is_new) = match slot.take() {
        Some(built) if built.key == key => (built, false),
        _ => {
            let (model, edit) = new_feature(base, input)?;
            (Built { key, model, edit }, true)
        }
    };
    Ok((slot.insert(built), is_new))
}
