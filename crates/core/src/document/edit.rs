//! Edits in progress: the one protocol by which an op changes a document, whether it is
//! applied at once (replay, the CLI, tests) or spread over frames (the app).
//!
//! ```text
//! let mut edit = editor.begin(op)?;           // cheap: checks, and a first thing to show
//! while edit.step()? != Progress::Done {}      // bounded chunks of work
//! edit.finish(&mut editor)?;                   // commit: one undo step, one op in the session
//! ```
//!
//! [`Editor::apply`] is [`Editor::begin`] then [`Edit::finish`], which runs the steps that
//! are left. The app runs the very same steps, only choosing when: each frame it steps the
//! edit in progress while a time budget lasts, draws what the edit shows, and finishes it
//! once [`Progress::Done`]. So a committed edit, its replay and the tests give bit-identical
//! documents by construction, and the app has no special case for any op.
//!
//! **Why steps.** Some ops take longer than a frame. A creation factors two systems (about
//! five times the cost of its seed) and then iterates 4–15 times: run at once it would
//! freeze the page, and the user would see nothing until it converged. As steps, the seed
//! shows at [`Editor::begin`], the first step factors and iterates once, and every later
//! step is one more iteration the app can draw. Every op has the same shape, even those
//! whose result is one step today (the curve ops, import, over-sketch), so splitting them
//! later changes no caller.
//!
//! **Why one loop.** The steps of a creation are those of
//! [`FairSurface::run`](crate::fibermesh::FairSurface::run)'s convergence loop,
//! [`Convergence`](crate::fibermesh::Convergence), the same object every settle of the
//! curve ops runs:
//! the stopping rule and the divergence guard (a run whose steps grow is refused with
//! [`SolveError::Diverged`](crate::solve::SolveError::Diverged)) live in one place. The app
//! used to refine creations with a copy of that loop without the guard, so tests exercised
//! one loop and users ran the other.
//!
//! **Gestures.** [`Editor::begin_gesture`] begins an op whose stroke is still being drawn.
//! [`Edit::extend`] adds pointer samples to the op's stroke, and steps keep a preview up to
//! date with the latest sample, skipping the ones in between: a pull factors the region
//! around the grabbed point once (its first step) and then back-substitutes once per
//! followed sample; an over-sketch finds each model's silhouettes once and matches the
//! stroke so far against them every few samples. [`Edit::end_gesture`] (or
//! [`Edit::finish`]) closes the stroke, and the next steps compute the committed result from
//! the op alone, exactly as `apply` does: a preview only shows where the result will land.
//!
//! **What to draw meanwhile.** [`Edit::document`] (the document the edit began on, or the
//! state it is building: a shape being created), [`Edit::moved_model`] (a pull's preview:
//! one model's vertices elsewhere, same topology, cheap to upload every frame) and
//! [`Edit::outline`] (the outline piece an over-sketch stroke would redraw, on screen).
//! [`Edit::revision`] changes whenever the document shown does (rebuild what is drawn),
//! [`Edit::generation`] whenever anything shown does (a pull's vertices moved).
//!
//! **Refusals and cancels change nothing.** An error at begin, at a step or at finish leaves
//! the editor's document, history and log as they were; after a failed step the edit only
//! repeats its error. [`Edit::cancel`] drops the edit. A result depends on the document the
//! edit began on and the op only; if the editor's document changed meanwhile (another edit
//! finished, a session was replayed), [`Edit::finish`] computes the op again on the current
//! document, as replaying the session will. Edits run one at a time: the app finishes the
//! one in progress before beginning the next, so ops are logged in the order they were made.
//!
//! **Work done elsewhere.** An import's long part is a pure function of its files
//! ([`import_files`](super::import_files)): the page reads them in a Web Worker and hands
//! the result to [`Edit::supply_import`], and the edit finishes as it would have here. The
//! committed result of a curve op or an over-sketch (a pull's release at 40k vertices takes
//! a second in the page) is a pure function of the models and the op
//! ([`model_op`](super::model_op)): the page computes it in the worker too
//! ([`Edit::model_op_to_run`], [`Edit::supply_model`]), while the pull's last preview stays
//! on screen. So do the previews of a pull's drag and of a control curve's new shape
//! ([`Edit::preview_to_run`], [`Edit::preview_elsewhere`], [`Edit::supply_preview`]): the
//! worker keeps its own edit of the drag, factors once and follows the samples the page
//! sends, and the page shows each preview that comes back, so neither a pull's region
//! refactor when the peel outgrows it (0.2–0.5 s in the page at 40k vertices) nor a curve's
//! volumetric graph and factorization (1–1.6 s) stalls a frame; the curve's commit then
//! comes from that kept edit ([`Edit::finish_elsewhere`]).

use std::sync::Arc;

use crate::io::Previewed;
use crate::mesh::VertexId;
use crate::model::MirrorPlane;
use crate::region_edit::{Levels, RegionEdit};
use glam::{DVec2, DVec3};

use super::arrange::TransformPreview;
use super::create::{CreateJob, is_stepped};
use super::curve_edit::PullPreview;
use super::feature::FeaturePreview;
use super::next::Outcome;
use super::optimize::OptimizePreview;
use super::outcome::{made_by, outcome, sharing_looks, with_imported, with_model};
use super::oversketch::{OutlinePiece, OutlinePreview};
use super::paint::{PaintPreview, with_colors_carried};
use super::region_edit::RegionPreview;
use super::skeleton::HandleDrag;
use super::symmetry::{even_outline, mirrored_outcome, with_twin_shown};
use super::volumetric::CurvePreview;
use super::{CommandError, Document, Editor, ImportInput, Model, Op, RegionEditInput};
use crate::io::Imported;

/// What [`Edit::step`] left to do.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Progress {
    /// More work is ready: step again (in this frame if time allows, else the next).
    Working,
    /// A gesture's preview is up to date: nothing to do until its stroke grows or ends.
    Waiting,
    /// The result is ready: [`Edit::finish`] commits it without more work.
    Done,
}

/// An op being applied: begun by [`Editor::begin`] (or [`Editor::begin_gesture`] while its
/// stroke is drawn), advanced by [`Edit::step`], then [`Edit::finish`]ed (one undo step, one
/// op in the session) or [`Edit::cancel`]led (nothing changes).
///
/// ```
/// # use sketchmesh_core::document::{CreateInput, Editor, Op, Progress};
/// # use sketchmesh_core::camera::Camera;
/// let ellipse = (0..=90).map(|i| {
///     let a = std::f64::consts::TAU * f64::from(i) / 90.0;
///     [400.0 + 160.0 * a.cos(), 300.0 + 110.0 * a.sin(), 0.5]
/// });
/// let op = Op::Create(CreateInput {
///     viewport: [800.0, 600.0],
///     camera: Camera::default(),
///     stroke: ellipse.collect(),
///     vertices: None,
/// });
/// let mut editor = Editor::new();
/// let mut edit = editor.begin(op.clone())?; // the seed shape, shown at once
/// let mut frames = 0;
/// while edit.step()? != Progress::Done {
///     frames += 1; // draw edit.document() here
/// }
/// edit.finish(&mut editor)?;
/// let mut applied = Editor::new();
/// applied.apply(op)?; // begin, then finish: the same steps
/// assert_eq!(editor.document(), applied.document());
/// assert!(frames > 2);
/// # Ok::<(), sketchmesh_core::document::CommandError>(())
/// ```
///
/// Why steps, why one convergence loop, gestures and refusals: see `document/edit.rs`.
#[derive(Debug)]
pub struct Edit {
    /// The op as made, without its symmetry.
    op: Op,
    /// The plane the op mirrors about, when it was made with symmetry on: its result is
    /// made symmetric once computed ([`mirrored_outcome`]).
    mirror: Option<MirrorPlane>,
    /// Whether the result ([`Work::Done`]) is made symmetric already.
    is_mirrored: bool,
    /// The op as drawn, when what is computed differs from it (an outline across the plane
    /// made even, [`even_outline`]): the session logs it, and a replay evens it the same way.
    drawn: Option<Op>,
    /// The document the edit began on; the result is computed from it and the op alone.
    base: Document,
    /// Whether the op's stroke is still being drawn.
    is_gesture: bool,
    work: Work,
    /// Changes whenever [`Edit::document`] does.
    revision: u64,
    /// Changes whenever anything the edit shows does.
    generation: u64,
    /// A preview's positions (model index, positions) when they were computed elsewhere
    /// ([`Edit::supply_preview`]), or a pull's last ones, still shown while its committed
    /// result is computed elsewhere, so the shape does not jump back meanwhile.
    held: Option<(usize, Vec<DVec3>)>,
    /// The amount a feature's preview computed elsewhere was cut back to, if it was.
    held_limit: Option<f64>,
    /// How far the gesture's op has come: 1 as begun, one more for each sample added and
    /// each revision.
    version: usize,
    /// The [`Edit::version`] the preview computed elsewhere shows; `None` while none was
    /// supplied (steps here compute the preview).
    elsewhere: Option<usize>,
}

/// Where an edit is.
#[derive(Debug)]
enum Work {
    /// A gesture with nothing to preview: waits for its end.
    Gesture,
    /// A pull's live preview.
    Pull(Box<PullPreview>),
    /// An over-sketch's live outline piece.
    Outline(Box<OutlinePreview>),
    /// An optimization's live result, following the op's settings.
    Optimize(Box<OptimizePreview>),
    /// A feature sketch's live shape, following the op's amount.
    Feature(Box<FeaturePreview>),
    /// A control curve's new shape being drawn: the volume follows each sample.
    Curve(Box<CurvePreview>),
    /// A region edit's live shape, following the op's transform and levels.
    Region(Box<RegionPreview>),
    /// A model moving with a dragged handle, following the op's matrix.
    Transform(Box<TransformPreview>),
    /// A paint stroke's colours so far.
    Paint(Box<PaintPreview>),
    /// A model or cloud following a curve handle's pose.
    Handle(Box<HandleDrag>),
    /// A creation, refining step by step.
    Create(Box<CreateJob>),
    /// Nothing computed yet: the next step computes the result whole.
    Whole,
    /// The result, ready to commit.
    Done(Outcome),
    /// A step failed; the edit repeats the error.
    Failed(CommandError),
}

impl Work {
    /// The work of a complete op: a creation up to [`super::STEPPED_MAX_VERTICES`] steps,
    /// everything else is one step.
    fn complete(base: &Document, op: &Op) -> Result<Work, CommandError> {
        Ok(match op {
            Op::Create(input) if is_stepped(input)? => {
                Work::Create(Box::new(CreateJob::start(base, input)?))
            }
            _ => Work::Whole,
        })
    }

    /// Whether a gesture with this work may have its preview computed elsewhere
    /// ([`Edit::preview_to_run`]): the drags whose previews factor.
    fn previews_elsewhere(&self) -> bool {
        matches!(
            self,
            Work::Pull(_) | Work::Curve(_) | Work::Optimize(_) | Work::Feature(_)
        )
    }

    /// The work of an op whose stroke is still being drawn: a preview where there is one.
    fn gesture(base: &Document, op: &Op) -> Result<Work, CommandError> {
        Ok(match op {
            Op::Pull(input) => Work::Pull(Box::new(PullPreview::start(base, input)?)),
            Op::Oversketch(input) => Work::Outline(Box::new(OutlinePreview::new(input))),
            Op::Optimize(input) => Work::Optimize(Box::new(OptimizePreview::start(base, input)?)),
            Op::SketchFeature(_) => Work::Feature(Box::new(FeaturePreview::new())),
            Op::CurveDeform(_) => Work::Curve(Box::default()),
            Op::RegionEdit(_) => Work::Region(Box::new(RegionPreview::new())),
            Op::Transform(input) => {
                Work::Transform(Box::new(TransformPreview::start(base, input)?))
            }
            Op::HandleEdit(input) => Work::Handle(Box::new(HandleDrag::start(base, input)?)),
            Op::Paint(_) => Work::Paint(Box::default()),
            _ => Work::Gesture,
        })
    }
}

impl Editor {
    /// Begins applying `op` to the current document (see [`Edit`]). Cheap: it checks what
    /// can be checked at once and prepares the first display (a creation's seed shape).
    ///
    /// Errors: a refusal that needs no work ([`CommandError::NothingToUndo`], a stroke that
    /// cannot make a shape, …); nothing changes.
    pub fn begin(&self, op: Op) -> Result<Edit, CommandError> {
        Edit::begin(self, op, false)
    }

    /// Begins `op` while its stroke is still being drawn (a drag, an over-sketch stroke):
    /// [`Edit::extend`] adds samples, steps keep the preview up to date, and
    /// [`Edit::end_gesture`] or [`Edit::finish`] closes the stroke.
    ///
    /// Errors: as [`Editor::begin`], and a pull that grabs no curve.
    pub fn begin_gesture(&self, op: Op) -> Result<Edit, CommandError> {
        Edit::begin(self, op, true)
    }

    /// Applies one op: [`Editor::begin`], then [`Edit::finish`], which steps to the end. On
    /// success the op is appended to the log (undo and redo included); on failure the
    /// document, the history and the log are unchanged.
    pub fn apply(&mut self, op: Op) -> Result<(), CommandError> {
        self.begin(op)?.finish(self)
    }
}

impl Edit {
    fn begin(editor: &Editor, op: Op, is_gesture: bool) -> Result<Edit, CommandError> {
        match op {
            Op::Undo if !editor.can_undo() => return Err(CommandError::NothingToUndo),
            Op::Redo if !editor.can_redo() => return Err(CommandError::NothingToRedo),
            _ => {}
        }
        Edit::begin_on(editor.document().clone(), op, is_gesture)
    }

    /// What the page's worker runs for [`Edit::preview_to_run`]: the preview of the gesture
    /// `op` on `models`, followed up to `op`'s last sample. `kept` is the worker's edit of
    /// the previous request; when `op` continues it ([`Edit::is_continued_by`]), it goes on
    /// from there, so what it factored is factored once per drag, as here. Returns the edit
    /// to keep, whose [`Edit::moved_model`] is the preview for [`Edit::supply_preview`].
    ///
    /// Errors: the gesture's refusal (no curve under the grab, a failed solve).
    pub fn preview_elsewhere(
        kept: Option<Edit>,
        models: Vec<Arc<Model>>,
        op: Op,
    ) -> Result<Edit, CommandError> {
        let mut edit = match kept.filter(|edit| edit.is_continued_by(&models, &op)) {
            Some(mut edit) => {
                edit.revise(op);
                edit
            }
            None => {
                let base = Document {
                    models,
                    ..Document::default()
                };
                Edit::begin_on(base, op, true)?
            }
        };
        while edit.step()? == Progress::Working {}
        Ok(edit)
    }

    /// What the page's worker runs for [`Edit::model_op_to_run`]: [`model_op`] of `op` on
    /// `models`, or, when `kept` is the worker's edit of the same gesture
    /// ([`Edit::preview_elsewhere`]) and keeps what the op needs (a curve's factored
    /// volumetric energy), the result from it: the same model, bit for bit, without
    /// factoring again.
    ///
    /// Errors: the op's refusal.
    ///
    /// [`model_op`]: super::model_op
    pub fn finish_elsewhere(
        kept: Option<Edit>,
        models: Vec<Arc<Model>>,
        op: &Op,
    ) -> Result<(usize, Model), CommandError> {
        if let Some(mut edit) = kept.filter(|edit| edit.is_continued_by(&models, op)) {
            let made = match (&mut edit.work, op) {
                (Work::Curve(preview), Op::CurveDeform(input)) => {
                    Some(preview.result(&edit.base, input))
                }
                (Work::Optimize(preview), Op::Optimize(input)) => {
                    Some(preview.result(&edit.base, input))
                }
                (Work::Feature(preview), Op::SketchFeature(input)) => {
                    Some(preview.result(&edit.base, input))
                }
                _ => None,
            };
            if let Some(made) = made {
                return Ok(with_colors_carried(&edit.base, op, made?));
            }
        }
        let doc = Document {
            models,
            ..Document::default()
        };
        super::model_op(&doc, op)
    }

    /// Whether `op` on `models` goes on with this gesture, on the very same models: a drag's
    /// op whose stroke is this one's and maybe more, or an optimization with any settings
    /// (its preview keeps its optimizer only while it serves them).
    fn is_continued_by(&self, models: &[Arc<Model>], op: &Op) -> bool {
        let mut start = op.clone();
        let followed = self.op.stroke().map_or(0, <[_]>::len);
        if let Some(stroke) = start.stroke_mut() {
            stroke.truncate(followed);
        }
        let continues = match (op, &self.op) {
            (Op::Optimize(_), Op::Optimize(_)) | (Op::SketchFeature(_), Op::SketchFeature(_)) => {
                true
            }
            _ => start == self.op,
        };
        self.is_gesture && continues && same_items(&self.base.models, models)
    }

    /// [`Edit::begin`] on `base`, with no editor.
    fn begin_on(base: Document, op: Op, is_gesture: bool) -> Result<Edit, CommandError> {
        let (op, mirror) = op.into_parts();
        let (op, drawn) = match mirror.and_then(|plane| even_outline(&op, &plane)) {
            Some(even) => (even, Some(op)),
            None => (op, None),
        };
        let work = if is_gesture {
            Work::gesture(&base, &op)?
        } else {
            Work::complete(&base, &op)?
        };
        // A creation shows its seed at once.
        let shown = u64::from(matches!(work, Work::Create(_)));
        Ok(Edit {
            op,
            mirror,
            is_mirrored: false,
            drawn,
            base,
            is_gesture,
            work,
            revision: shown,
            generation: shown,
            held: None,
            held_limit: None,
            version: 1,
            elsewhere: None,
        })
    }

    /// Runs one bounded chunk of work: a creation's factorization or one of its iterations,
    /// a gesture's preview for its latest sample, or an op's whole result.
    ///
    /// Errors: the op's refusal; the edit then only repeats it (drop it: nothing changed).
    pub fn step(&mut self) -> Result<Progress, CommandError> {
        match self
            .advance()
            .and_then(|advanced| self.mirror_result().map(|()| advanced))
        {
            Ok((progress, did_work)) => {
                let rebuilt = match &mut self.work {
                    Work::Region(preview) => preview.take_rebuilt(),
                    Work::Handle(drag) => drag.take_rebuilt(),
                    _ => false,
                };
                if rebuilt {
                    self.revision += 1;
                }
                if did_work {
                    self.generation += 1;
                    if matches!(
                        self.work,
                        Work::Create(_)
                            | Work::Done(Outcome::Document(_) | Outcome::Imported { .. })
                    ) {
                        self.revision += 1;
                    }
                }
                Ok(progress)
            }
            Err(error) => {
                self.work = Work::Failed(error.clone());
                Err(error)
            }
        }
    }

    /// Makes a result ready to commit symmetric, once, when the op was made with symmetry on.
    ///
    /// Errors: [`mirrored_outcome`]'s refusal.
    fn mirror_result(&mut self) -> Result<(), CommandError> {
        let Some(plane) = self.mirror.filter(|_| !self.is_mirrored) else {
            return Ok(());
        };
        if !matches!(self.work, Work::Done(_)) {
            return Ok(());
        }
        if let Work::Done(outcome) = std::mem::replace(&mut self.work, Work::Whole) {
            self.work = Work::Done(mirrored_outcome(&self.base, &self.op, plane, outcome)?);
            self.is_mirrored = true;
        }
        Ok(())
    }

    /// The op as the session logs it: with its plane, when made with symmetry on.
    fn logged_op(&self) -> Op {
        let op = self.drawn.as_ref().unwrap_or(&self.op).clone();
        match self.mirror {
            Some(plane) => op.mirrored(plane),
            None => op,
        }
    }

    /// [`Edit::step`]'s work: what is left, and whether anything was done.
    fn advance(&mut self) -> Result<(Progress, bool), CommandError> {
        let (base, op) = (&self.base, &self.op);
        if let Work::Failed(error) = &self.work {
            return Err(error.clone());
        }
        if self.is_gesture {
            let stroke = op.stroke().unwrap_or_default();
            let stepped = match (&mut self.work, op) {
                // Its preview is computed elsewhere ([`Edit::supply_preview`]).
                (work, _) if work.previews_elsewhere() && self.elsewhere.is_some() => None,
                (Work::Pull(preview), _) => preview.step(stroke)?,
                (Work::Outline(preview), _) => preview.step(base, stroke),
                (Work::Optimize(preview), Op::Optimize(input)) => preview.step(base, input)?,
                (Work::Feature(preview), Op::SketchFeature(input)) => preview.step(base, input)?,
                (Work::Curve(preview), Op::CurveDeform(input)) => preview.step(base, input)?,
                (Work::Region(preview), Op::RegionEdit(input)) => preview.step(base, input)?,
                (Work::Transform(preview), Op::Transform(input)) => preview.step(base, input)?,
                (Work::Paint(preview), Op::Paint(input)) => {
                    preview.step(base, input, self.mirror.as_ref())?
                }
                (Work::Handle(drag), Op::HandleEdit(input)) => drag.step(base, input)?,
                _ => None,
            };
            return Ok(match stepped {
                Some(true) => (Progress::Working, true),
                Some(false) => (Progress::Waiting, true),
                None => (Progress::Waiting, false),
            });
        }
        match &mut self.work {
            Work::Done(_) => Ok((Progress::Done, false)),
            Work::Create(job) => {
                if !job.step()? {
                    return Ok((Progress::Working, true));
                }
                if let Work::Create(job) = std::mem::replace(&mut self.work, Work::Whole) {
                    self.work = Work::Done(Outcome::Document(job.into_document()));
                }
                Ok((Progress::Done, true))
            }
            Work::Whole => {
                self.work = Work::Done(outcome(base, op)?);
                Ok((Progress::Done, true))
            }
            // An optimization's gesture ended: its kept optimizer gives the exact result (or,
            // when the preview was computed elsewhere, the kept optimizer there).
            Work::Optimize(preview) => {
                let kept = match self.elsewhere {
                    None => optimized(preview, base, op)?,
                    Some(_) => None,
                };
                let Some(model) = kept else {
                    self.work = Work::complete(base, op)?;
                    return Ok((Progress::Working, true));
                };
                self.work = Work::Done(with_model(base, model));
                Ok((Progress::Done, true))
            }
            // A feature's drag ended: its kept edit gives the exact result, or, when the
            // preview was computed elsewhere, the kept edit there.
            Work::Feature(preview) => {
                let (Op::SketchFeature(input), None) = (op, self.elsewhere) else {
                    self.work = Work::complete(base, op)?;
                    return Ok((Progress::Working, true));
                };
                self.work = Work::Done(with_model(base, preview.result(base, input)?));
                Ok((Progress::Done, true))
            }
            // A curve's new shape is drawn: its kept edit gives the exact result, or, when
            // the preview was computed elsewhere, the op computed whole (elsewhere too).
            Work::Curve(preview) => {
                let (Op::CurveDeform(input), None) = (op, self.elsewhere) else {
                    self.work = Work::complete(base, op)?;
                    return Ok((Progress::Working, true));
                };
                self.work = Work::Done(with_model(base, preview.result(base, input)?));
                Ok((Progress::Done, true))
            }
            // A region edit's drag ended: its kept region gives the exact result.
            Work::Region(preview) => {
                let Op::RegionEdit(input) = op else {
                    self.work = Work::complete(base, op)?;
                    return Ok((Progress::Working, true));
                };
                self.work = Work::Done(with_model(base, preview.result(base, input)?));
                Ok((Progress::Done, true))
            }
            // A handle's drag ended: its kept binding gives the exact result.
            Work::Handle(drag) => {
                let Op::HandleEdit(input) = op else {
                    self.work = Work::complete(base, op)?;
                    return Ok((Progress::Working, true));
                };
                self.work = Work::Done(Outcome::Document(drag.result(base, input)?));
                Ok((Progress::Done, true))
            }
            // A gesture ended: its preview goes, and the committed result begins.
            Work::Gesture
            | Work::Pull(_)
            | Work::Outline(_)
            | Work::Transform(_)
            | Work::Paint(_)
            | Work::Failed(_) => {
                if let Work::Pull(preview) = std::mem::replace(&mut self.work, Work::Whole)
                    && self.held.is_none()
                {
                    self.held = Some(preview.into_moved());
                }
                self.work = Work::complete(base, op)?;
                Ok((Progress::Working, true))
            }
        }
    }

    /// Replaces the op of a gesture in progress by `op`, of the same kind, with new settings
    /// (a slider moved): the next step previews it, and finishing commits it. Ignored after
    /// the gesture ended or for an op of another kind.
    pub fn revise(&mut self, op: Op) {
        debug_assert!(self.is_gesture, "revise after the gesture ended");
        if self.is_gesture && op.name() == self.op.name() {
            self.op = op.into_parts().0;
            self.version += 1;
        }
    }

    /// Adds a pointer sample `[x, y, pressure]` to the stroke of a gesture's op; the next
    /// step previews it. A sample at the last one's position adds nothing (pointer events
    /// often repeat), nor does one after the gesture ended or for an op without a stroke.
    pub fn extend(&mut self, sample: [f64; 3]) {
        debug_assert!(self.is_gesture, "extend after the gesture ended");
        if !self.is_gesture {
            return;
        }
        let Some(stroke) = self.op.stroke_mut() else {
            return;
        };
        if stroke
            .last()
            .is_none_or(|last| [last[0], last[1]] != [sample[0], sample[1]])
        {
            stroke.push(sample);
            self.version += 1;
        }
    }

    /// Closes a gesture's stroke: the next steps compute the committed result.
    pub fn end_gesture(&mut self) {
        self.is_gesture = false;
    }

    /// Whether the op's stroke is still being drawn.
    pub fn is_gesture(&self) -> bool {
        self.is_gesture
    }

    /// Commits the edit: closes a gesture, runs the steps that are left, and applies the
    /// result as one undo step, logging the op. If the editor's document is no longer the
    /// one the edit began on, the op is computed again on the current one.
    ///
    /// Errors: the op's refusal; the document, the history and the log are unchanged.
    pub fn finish(mut self, editor: &mut Editor) -> Result<(), CommandError> {
        if !same_document(&self.base, editor.document()) {
            return editor.begin(self.logged_op())?.finish(editor);
        }
        self.is_gesture = false;
        loop {
            self.mirror_result()?;
            let logged = self.logged_op();
            match std::mem::replace(&mut self.work, Work::Whole) {
                Work::Done(outcome) => return editor.commit(logged, outcome),
                work => self.work = work,
            }
            self.step()?;
        }
    }

    /// Drops the edit: the editor stays as it is.
    pub fn cancel(self) {}

    /// The files of an import whose result is not computed yet: the page reads them in its
    /// worker with [`import_files`](super::import_files), a pure function of the files, and
    /// hands the result to [`Edit::supply_import`], so the long part of an import never
    /// runs in a frame. `None` for any other edit, and once the import is computed.
    pub fn import_to_read(&self) -> Option<&ImportInput> {
        match (&self.work, &self.op) {
            (Work::Whole, Op::Import(input)) if !self.is_gesture => Some(input),
            _ => None,
        }
    }

    /// Completes an import with what [`import_files`](super::import_files) made of its
    /// files elsewhere: the same result, placed the same way, as stepping it here. Ignored
    /// for any other edit, or once its result is computed.
    pub fn supply_import(&mut self, imported: Result<Imported, CommandError>) {
        let Some(input) = self.import_to_read() else {
            return;
        };
        self.work = match imported {
            Ok(imported) => Work::Done(with_imported(&self.base, input, imported)),
            Err(error) => Work::Failed(error),
        };
        self.revision += 1;
        self.generation += 1;
    }

    /// An op that [makes one model](Op::makes_one_model), not computed yet: the page
    /// computes it in its worker with [`model_op`](super::model_op) on a copy of these models
    /// and hands the result to [`Edit::supply_model`], so a long curve op, over-sketch,
    /// region edit or fine creation never runs in a frame (a creation that steps in the
    /// frames is not one). `None` for any other edit, and once the result is computed.
    pub fn model_op_to_run(&self) -> Option<(&[Arc<Model>], &Op)> {
        // A region edit's drag that ended is computed whole elsewhere too (a remesh, 0.1 s
        // for the bunny), its preview still shown meanwhile; here, its kept region gives it.
        let to_compute = matches!(self.work, Work::Whole | Work::Region(_));
        (to_compute && !self.is_gesture && self.op.makes_one_model())
            .then_some((&self.base.models[..], &self.op))
    }

    /// Completes an op of [`Edit::model_op_to_run`] with what
    /// [`model_op`](super::model_op) made of the models elsewhere: the same result, landed
    /// the same way, as stepping it here. Ignored for any other edit, or once its result is
    /// computed.
    pub fn supply_model(&mut self, changed: Result<(usize, Model), CommandError>) {
        if self.model_op_to_run().is_none() {
            return;
        }
        let landed = changed.and_then(|(index, model)| {
            let model = match self.base.models.get(index) {
                Some(before) => sharing_looks(before, model),
                None if index == self.base.models.len() => model,
                None => return Err(CommandError::NoSuchModel(index)),
            };
            Ok(made_by(&self.base, &self.op, (index, model)))
        });
        self.work = match landed {
            Ok(outcome) => Work::Done(outcome),
            Err(error) => Work::Failed(error),
        };
        if let Err(error) = self.mirror_result() {
            self.work = Work::Failed(error);
        }
        self.revision += 1;
        self.generation += 1;
    }

    /// A pull's drag, a control curve's new shape being drawn or an optimization's
    /// settings whose preview does not show the op's latest [`Edit::version`] yet: the page
    /// computes the preview in its worker ([`Edit::preview_elsewhere`] on a copy of these
    /// models and this op) and hands it to [`Edit::supply_preview`], so that no frame
    /// factors: not a pull's region around the grab, nor again each time the peel outgrows
    /// it (0.2–0.5 s in the page at 40k vertices), nor a curve's volumetric graph and energy
    /// (about 1 s in the page at 30k graph points), nor an optimizer (0.5 s for the bunny).
    /// Once a preview was supplied, steps here leave it to the worker, and the committed
    /// result is computed elsewhere too ([`Edit::model_op_to_run`], from the worker's kept
    /// edit: [`Edit::finish_elsewhere`]). Returns the models, the op and its version; `None`
    /// for any other edit, once the gesture ended, and while the preview is up to date.
    #[allow(clippy::type_complexity)] // The models, the op so far and its version.
    pub fn preview_to_run(&self) -> Option<(&[Arc<Model>], &Op, usize)> {
        let behind = self.version > self.elsewhere.unwrap_or(0);
        (self.work.previews_elsewhere() && self.is_gesture && behind).then_some((
            &self.base.models[..],
            &self.op,
            self.version,
        ))
    }

    /// How far a gesture's op has come: 1 as begun, one more for each sample
    /// [`Edit::extend`] added and each [`Edit::revise`].
    pub fn version(&self) -> usize {
        self.version
    }

    /// Takes the gesture's preview back from elsewhere (the page's worker failed in the middle
    /// of a drag): the next step here computes it for the op so far, as if it had never
    /// gone, so the shape keeps following the pen. Nothing changes for an edit whose preview
    /// was never computed elsewhere, or once its gesture ended.
    pub fn preview_here(&mut self) {
        if self.is_gesture && self.work.previews_elsewhere() && self.elsewhere.is_some() {
            self.elsewhere = None;
            self.held = None;
            self.held_limit = None;
            self.generation += 1;
        }
    }

    /// Shows a preview of [`Edit::preview_to_run`] computed elsewhere: the same positions a
    /// step here would show for that version of the op. A preview older than the one shown
    /// is ignored, as is one for another edit or after the result is computed; once
    /// the gesture ended, the preview shown until the result lands is replaced. A refusal
    /// (no curve under the grab, a failed solve) fails the edit, as a step here would.
    pub fn supply_preview(&mut self, previewed: Result<Previewed, CommandError>) {
        let previews = match &self.work {
            Work::Whole => self.elsewhere.is_some(),
            work => work.previews_elsewhere() && self.is_gesture,
        };
        if !previews {
            return;
        }
        let fits = |moved: &Option<(usize, Vec<DVec3>)>| match moved {
            Some((index, positions)) => (self.base.models.get(*index))
                .is_some_and(|m| m.mesh.positions().len() == positions.len()),
            None => true,
        };
        match previewed {
            Ok(previewed) if !fits(&previewed.moved) => {
                self.work = Work::Failed(CommandError::Elsewhere(String::from(
                    "The preview computed elsewhere does not fit the model.",
                )));
            }
            Ok(previewed) if previewed.version > self.elsewhere.unwrap_or(0) => {
                if previewed.moved.is_some() {
                    self.held = previewed.moved;
                    self.held_limit = previewed.limited;
                    self.generation += 1;
                }
                self.elsewhere = Some(previewed.version);
            }
            Ok(_) => {}
            Err(error) => self.work = Work::Failed(error),
        }
    }

    /// The op as far as it is known (a gesture's stroke grows).
    pub fn op(&self) -> &Op {
        &self.op
    }

    /// The document to draw meanwhile: the one the edit began on, or the state the edit
    /// is building (a shape being created; a region edit's model with its curves embedded),
    /// or the result once it is ready.
    pub fn document(&self) -> &Document {
        match &self.work {
            Work::Create(job) => job.document(),
            Work::Region(preview) => preview.document().unwrap_or(&self.base),
            Work::Handle(drag) => drag.document().unwrap_or(&self.base),
            Work::Paint(preview) => preview.document().unwrap_or(&self.base),
            Work::Done(Outcome::Document(next) | Outcome::Imported { next, .. }) => next,
            _ => &self.base,
        }
    }

    /// What to draw while a creation made with symmetry on inflates: its shape and, when it
    /// lies wholly on one side of the plane, the mirror twin the result will add, so the
    /// preview shows both sides. `None` for anything else: draw [`Edit::document`].
    pub fn mirrored_creation(&self) -> Option<Document> {
        let plane = self.mirror.filter(|_| !self.is_mirrored)?;
        let Work::Create(job) = &self.work else {
            return None;
        };
        with_twin_shown(job.document(), self.base.models.len(), &plane)
    }

    /// A pull's, an optimization's, a feature's or a transform's preview: the index of a model
    /// of [`Edit::document`] and where its vertices are drawn (the same topology).
    pub fn moved_model(&self) -> Option<(usize, &[DVec3])> {
        match &self.work {
            Work::Pull(preview) => Some(match &self.held {
                Some((index, positions)) => (*index, &positions[..]),
                None => preview.moved(),
            }),
            work if work.previews_elsewhere() && self.elsewhere.is_some() => {
                (self.held.as_ref()).map(|(index, positions)| (*index, &positions[..]))
            }
            Work::Optimize(preview) => match &self.op {
                Op::Optimize(input) => Some(preview.moved(input)),
                _ => None,
            },
            Work::Feature(preview) => preview.moved(),
            Work::Curve(preview) => match &self.op {
                Op::CurveDeform(input) => preview.moved(input),
                _ => None,
            },
            Work::Region(preview) => preview.moved(),
            Work::Transform(preview) => Some(preview.moved()),
            Work::Handle(drag) => drag.moved_model(),
            Work::Whole => (self.held.as_ref()).map(|(index, positions)| (*index, &positions[..])),
            _ => None,
        }
    }

    /// A region edit's model, the vertices of its region and their weights (1 moves fully,
    /// 0 stays), once the region is found: what the fall-off overlay shows.
    pub fn region_falloff(&self) -> Option<(usize, &[VertexId], &[f64])> {
        match &self.work {
            Work::Region(preview) => preview.falloff(),
            _ => None,
        }
    }

    /// [`Edit::region_levels`] while the region has not moved: the view shades the fall-off
    /// in gray levels until a drag, a handle or a profile moves the region, and from then on
    /// draws the surface lit, as its release commits it (issue 49: the flat gray bands of a
    /// dragged region looked stair-stepped until the release).
    pub fn region_shade_levels(&self) -> Option<usize> {
        match self.op() {
            Op::RegionEdit(input) if input.moves_region() => None,
            _ => self.region_levels(),
        }
    }

    /// How many levels a region edit's fall-off has (the op's, else the default's), which
    /// the view shades its weights in as many grays; `None` for any other edit.
    pub fn region_levels(&self) -> Option<usize> {
        match self.op() {
            Op::RegionEdit(input) => Some(
                input
                    .levels
                    .as_ref()
                    .map_or_else(|| Levels::default().weights().len(), Vec::len),
            ),
            _ => None,
        }
    }

    /// A region edit's region once it is found, when it was found for the curves of `curves`
    /// (in the same view; the motion and fall-off aside): what a tool places handles on and
    /// cuts cross-sections from, without finding it again in a frame.
    pub fn region_found_for(&self, curves: &RegionEditInput) -> Option<&RegionEdit> {
        match &self.work {
            Work::Region(preview) => preview.found_for(curves),
            _ => None,
        }
    }

    /// A region edit's region laid flat in the unit disc, in the order of
    /// [`Edit::region_falloff`]'s vertices, or why it cannot be: the fall-off panel.
    pub fn region_disc(&self) -> Option<Result<&[DVec2], &crate::region_edit::RegionError>> {
        match &self.work {
            Work::Region(preview) => preview.disc(),
            _ => None,
        }
    }

    /// The amount a feature's preview shows when the one asked for would fold the surface
    /// over (the committed result is held there too).
    pub fn limited_amount(&self) -> Option<f64> {
        match &self.work {
            Work::Feature(_) | Work::Whole if self.elsewhere.is_some() => self.held_limit,
            Work::Feature(preview) => preview.limited_to(),
            _ => None,
        }
    }

    /// The fraction of a handle's move shown when all of it would fold the surface through
    /// itself (the committed result is held there too).
    pub fn limited_move(&self) -> Option<f64> {
        match &self.work {
            Work::Handle(drag) => drag.limited(),
            _ => None,
        }
    }

    /// The outline piece an over-sketch stroke being drawn would redraw, on screen.
    pub fn outline(&self) -> Option<&OutlinePiece> {
        match &self.work {
            Work::Outline(preview) => preview.shown(),
            _ => None,
        }
    }

    /// A counter that changes whenever [`Edit::document`] does; 0 while it is the document
    /// the edit began on. A renderer rebuilds what it draws when this changes.
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// A counter that changes whenever anything the edit shows does: its document, its
    /// moved model or its outline piece. A renderer uploads again when this changes.
    pub fn generation(&self) -> u64 {
        self.generation
    }
}

/// The committed model of an optimization, computed by its preview's kept optimizer.
fn optimized(
    preview: &mut OptimizePreview,
    base: &Document,
    op: &Op,
) -> Result<Option<(usize, super::Model)>, CommandError> {
    match op {
        Op::Optimize(input) => preview.result(base, input).map(Some),
        _ => Ok(None),
    }
}

/// Whether two documents hold the very same models, sketches and point clouds.
fn same_document(a: &Document, b: &Document) -> bool {
    same_items(&a.models, &b.models)
        && same_items(&a.sketches, &b.sketches)
        && same_items(&a.point_clouds, &b.point_clouds)
}

/// Whether `a` and `b` hold the very same shared items, in order.
fn same_items<T>(a: &[Arc<T>], b: &[Arc<T>]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| Arc::ptr_eq(x, y))
}
