//! The `oversketch` op on a document: which model the stroke redraws and its new version,
//! and the outline piece shown while the stroke is drawn.
//!
//! The committed op tries every model and keeps the best match ([`oversketch_op`]). While
//! the stroke is drawn, an [`OutlinePreview`] finds each model's silhouettes once (the
//! stroke's camera does not move; one model per step) and matches the stroke so far every
//! [`PREVIEW_EVERY`] samples, so the app can show which piece the stroke would replace:
//! silhouettes and matching only, no edit.

use glam::DVec2;

use super::{CommandError, Document, Model, OversketchInput, StrokeInput, curve_edit};
use crate::camera::Camera;
use crate::oversketch::{
    BendOptions, ManualHandle, Outlines, OversketchError, Oversketched, manual_handle_preview,
    oversketch_manual, oversketch_with,
};

/// New samples between two matches of the stroke so far: matching runs on whole
/// silhouettes, so not on every sample.
const PREVIEW_EVERY: usize = 8;

/// Over-sketches the model whose outline the stroke matches best (highest match score
/// among the models that accept it), returning its index and its new version. Where a
/// control curve draws the redrawn outline (automatic, exact, near the handle), the curve
/// moves and the surface settles through it ([`curve_edit::oversketch_curve`]); elsewhere
/// the mesh bends, and control curves, chains of its vertices, follow them.
///
/// Errors: [`CommandError::BadView`], [`CommandError::StrokeTooShort`],
/// [`CommandError::StrokeNotFinite`], a failed settle of a moved curve, or the most telling
/// refusal over all models (a failed edit, then a doubtful match, then no match).
pub(super) fn oversketch_op(
    document: &Document,
    input: &OversketchInput,
) -> Result<(usize, Model), CommandError> {
    let input_stroke = StrokeInput::of_oversketch(input);
    let viewport = input_stroke.viewport_size();
    let stroke = curve_edit::screen_stroke(&input_stroke, 2)?;
    let options = BendOptions {
        fit: input.fit.handle_fit(),
        roi: input.roi,
    };
    let mut best: Option<(usize, Candidate, f64)> = None;
    let mut refusal = OversketchError::NoMatch;
    let mut failed_curve: Option<CommandError> = None;
    for (index, model) in document.models.iter().enumerate() {
        let (mesh, camera) = (&model.mesh, &input.camera);
        let along_curve = (input.handle.is_none() && options == BendOptions::EXACT)
            .then(|| curve_edit::oversketch_curve(model, camera, viewport, &stroke))
            .flatten();
        let result = match (along_curve, &input.handle) {
            (Some(Ok((model, score))), _) => Ok((Candidate::Curve(model), score)),
            (Some(Err(error)), _) => {
                failed_curve = Some(error);
                continue;
            }
            (None, Some(handle)) => {
                oversketch_manual(mesh, camera, viewport, handle, &stroke, options)
                    .map(Candidate::scored)
            }
            (None, None) => {
                oversketch_with(mesh, camera, viewport, &stroke, options).map(Candidate::scored)
            }
        };
        match result {
            Ok((candidate, score)) => {
                if best.as_ref().is_none_or(|(_, _, b)| score > *b) {
                    best = Some((index, candidate, score));
                }
            }
            Err(error) => {
                if refusal_rank(&error) > refusal_rank(&refusal) {
                    refusal = error;
                }
            }
        }
    }
    let Some((index, candidate, _)) = best else {
        return Err(failed_curve.unwrap_or(refusal.into()));
    };
    match candidate {
        Candidate::Curve(model) => Ok((index, model)),
        Candidate::Mesh(result) => {
            let mut model = Model::clone(&document.models[index]);
            model
                .mesh
                .positions_mut()
                .copy_from_slice(&result.positions);
            Ok((index, model))
        }
    }
}

/// One model's over-sketch: its curve moved and the surface settled, or its mesh bent
/// (control curves, chains of its vertices, follow them).
enum Candidate {
    Curve(Model),
    Mesh(Oversketched),
}

impl Candidate {
    /// A bent mesh and its match score.
    fn scored(result: Oversketched) -> (Candidate, f64) {
        let score = result.score;
        (Candidate::Mesh(result), score)
    }
}

/// How much a refusal tells the user: a failed edit, then a doubtful match, then none.
fn refusal_rank(error: &OversketchError) -> u8 {
    match error {
        OversketchError::NoMatch => 0,
        OversketchError::LowConfidence | OversketchError::HandleLost | OversketchError::NoPart => 1,
        OversketchError::Deform(_) => 2,
    }
}

/// The silhouette piece an over-sketch stroke would redraw, on screen (CSS px of the op's
/// viewport), as shown while the stroke is drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct OutlinePiece {
    /// The piece, in the stroke's direction.
    pub points: Vec<DVec2>,
    /// Whether the match is confident enough for the op to be applied (it is refused
    /// otherwise); a picked handle always is.
    pub is_confident: bool,
}

/// The piece an over-sketch stroke being drawn would redraw; see the module docs.
#[derive(Debug)]
pub(super) struct OutlinePreview {
    camera: Camera,
    viewport: DVec2,
    /// A picked handle (manual mode): shown as it resolves, never matched.
    handle: Option<ManualHandle>,
    /// Whether the picked handle was looked for.
    is_resolved: bool,
    /// The silhouettes of the first models, one more each step until all have theirs.
    outlines: Vec<Outlines>,
    /// How many samples the stroke had at the last match.
    matched: usize,
    shown: Option<OutlinePiece>,
}

impl OutlinePreview {
    /// The preview of `input`, nothing found yet.
    pub(super) fn new(input: &OversketchInput) -> Self {
        OutlinePreview {
            camera: input.camera,
            viewport: DVec2::from(input.viewport),
            handle: input.handle.clone(),
            is_resolved: false,
            outlines: Vec::new(),
            matched: 0,
            shown: None,
        }
    }

    /// One chunk of work for the stroke so far (`document` is the one the edit began on):
    /// a picked handle found on the models (once), or the silhouettes of one more model, or
    /// a match of the stroke once every model has its silhouettes and [`PREVIEW_EVERY`]
    /// samples came since the last match. Returns `None` when there was nothing to do, else
    /// whether more work is ready.
    pub(super) fn step(&mut self, document: &Document, stroke: &[[f64; 3]]) -> Option<bool> {
        let (camera, viewport) = (&self.camera, self.viewport);
        if let Some(handle) = &self.handle {
            if std::mem::replace(&mut self.is_resolved, true) {
                return None;
            }
            self.shown = document.models.iter().find_map(|model| {
                let points = manual_handle_preview(&model.mesh, camera, viewport, handle)?;
                Some(OutlinePiece {
                    points,
                    is_confident: true,
                })
            });
            return Some(false);
        }
        if let Some(model) = document.models.get(self.outlines.len()) {
            self.outlines
                .push(Outlines::new(&model.mesh, camera, viewport));
            let is_more = self.outlines.len() < document.models.len() || self.is_due(stroke);
            return Some(is_more);
        }
        if !self.is_due(stroke) {
            return None;
        }
        let points: Vec<DVec2> = stroke.iter().map(|&[x, y, _]| DVec2::new(x, y)).collect();
        self.shown = self.outlines.iter().find_map(|outlines| {
            let (points, is_confident) = outlines.preview(&points)?;
            Some(OutlinePiece {
                points,
                is_confident,
            })
        });
        self.matched = stroke.len();
        Some(false)
    }

    /// Whether the stroke is to be matched again.
    fn is_due(&self, stroke: &[[f64; 3]]) -> bool {
        stroke.len() >= self.matched + PREVIEW_EVERY
    }

    /// The piece found at the last match, or the picked handle.
    pub(super) fn shown(&self) -> Option<&OutlinePiece> {
        self.shown.as_ref()
    }
}
