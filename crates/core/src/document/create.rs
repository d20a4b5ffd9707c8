//! The `create` op as steps: FiberMesh's surface appears at once and refines step by step.
//!
//! Starting costs no factorization: it builds the seed shape (already rotund) and shows it.
//! The first step factors the two fair-surface systems and runs one iteration
//! ([`first_iteration`]); each later step runs one more of [`CreateParams::refinement`],
//! the fair surface's only convergence loop ([`Convergence`], with its divergence guard).
//! The shape is built in place in the document the edit shows, so the last step leaves the
//! document to commit.
//!
//! Past [`STEPPED_MAX_VERTICES`] a creation is one piece of work ([`create_op`]), which the
//! page runs in its worker: its seed and its factorization are each longer than a frame.

use std::sync::Arc;

use super::{CommandError, ControlCurve, CreateInput, Document, Model, StrokeInput};
use crate::fibermesh::{
    Convergence, CreateError, CreateParams, FairSurface, first_iteration, seed_from_stroke,
};
use crate::model::CurveKind;

/// The finest creation that steps in the frames: natively the factorizations and first
/// iteration take 12 ms at 2,000 vertices and 105 ms at 10,000 (BENCHMARKS.md), and the
/// page's wasm is 2–3× slower, so past about 5,000 one step would stall a frame.
pub const STEPPED_MAX_VERTICES: usize = 5_000;

/// The resolutions a `create` op may ask for: below, a shape is too coarse to edit; above,
/// it takes minutes in a page.
pub const CREATE_VERTICES: std::ops::RangeInclusive<usize> = 500..=100_000;

/// Whether `input`'s creation steps in the frames ([`CreateJob`]) rather than being
/// computed whole ([`create_op`]).
///
/// Errors: [`CommandError::CreateVertices`], at once, whichever way it is computed.
pub(super) fn is_stepped(input: &CreateInput) -> Result<bool, CommandError> {
    let vertices = params(input).target_vertices;
    match CREATE_VERTICES.contains(&vertices) {
        true => Ok(vertices <= STEPPED_MAX_VERTICES),
        false => Err(CommandError::CreateVertices(vertices)),
    }
}

/// The creation `input` makes of `doc`, whole: the new model's index (after the others)
/// and the model.
///
/// Errors: as [`CreateJob::start`] and [`CreateJob::step`].
pub(super) fn create_op(
    doc: &Document,
    input: &CreateInput,
) -> Result<(usize, Model), CommandError> {
    let mut job = CreateJob::start(doc, input)?;
    while !job.step()? {}
    let index = job.index;
    let model = job.document.models.swap_remove(index);
    Ok((index, Arc::unwrap_or_clone(model)))
}

/// The settings `input` asks for.
fn params(input: &CreateInput) -> CreateParams {
    let default = CreateParams::default();
    CreateParams {
        target_vertices: input.vertices.unwrap_or(default.target_vertices),
        ..default
    }
}

/// A closed stroke being inflated into a new model, the last of its document.
#[derive(Debug)]
pub(super) struct CreateJob {
    /// The document the edit began on, plus the new model.
    document: Document,
    /// The new model's index in `document`: its last.
    index: usize,
    params: CreateParams,
    /// The factored surface and its run; `None` until the first step.
    solve: Option<(FairSurface, Convergence)>,
}

impl CreateJob {
    /// Meshes the stroke and builds the seed shape, cheaply: no factorization yet.
    ///
    /// Errors: the stroke's problems as sentences, see [`CommandError`], and a resolution
    /// outside [`CREATE_VERTICES`].
    pub(super) fn start(base: &Document, input: &CreateInput) -> Result<Self, CommandError> {
        is_stepped(input)?;
        let params = params(input);
        let stroke = StrokeInput::of_create(input);
        let viewport = stroke.checked_viewport()?;
        let seed = seed_from_stroke(&stroke.points(), &stroke.camera, viewport, &params)?;
        let model = Model {
            curves: vec![ControlCurve {
                vertices: seed.curve_vertices,
                is_closed: true,
                kind: CurveKind::Smooth,
            }],
            mesh: seed.mesh,
            ..Model::default()
        };
        let mut document = base.clone();
        document.models.push(Arc::new(model));
        Ok(CreateJob {
            index: base.models.len(),
            document,
            params,
            solve: None,
        })
    }

    /// Factors and iterates once (first step), or iterates once more; returns whether the
    /// run is over (converged or out of iterations).
    ///
    /// Errors: a failed solve or a diverging run, as [`CommandError::Create`].
    pub(super) fn step(&mut self) -> Result<bool, CommandError> {
        if self.solve.as_ref().is_some_and(|(_, run)| run.is_done()) {
            return Ok(true);
        }
        // The job holds the only reference, so this does not copy the mesh.
        let model = Arc::make_mut(&mut self.document.models[self.index]);
        let done = match &mut self.solve {
            None => {
                let outline = ControlCurve {
                    vertices: model.curves[0].vertices.clone(),
                    is_closed: true,
                    kind: CurveKind::Smooth,
                };
                let surface = first_iteration(&mut model.mesh, &outline)?;
                let run = self.params.refinement();
                let done = run.is_done();
                self.solve = Some((surface, run));
                done
            }
            Some((surface, run)) => run
                .step(surface, model.mesh.positions_mut())
                .map_err(|e| CommandError::Create(CreateError::Solve(e)))?,
        };
        Ok(done)
    }

    /// The document with the shape as it is now.
    pub(super) fn document(&self) -> &Document {
        &self.document
    }

    /// The document with the shape as it is now, to commit.
    pub(super) fn into_document(self) -> Document {
        self.document
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::camera::Camera;
    use crate::document::{Editor, Op, Progress};

    /// A closed ellipse stroke on an 800 × 600 view (other tests of the document use it).
    pub(in crate::document) fn ellipse() -> StrokeInput {
        let n = 90;
        StrokeInput {
            viewport: [800.0, 600.0],
            camera: Camera::default(),
            stroke: (0..=n)
                .map(|i| {
                    let a = std::f64::consts::TAU * i as f64 / n as f64;
                    [400.0 + 160.0 * a.cos(), 300.0 + 110.0 * a.sin(), 0.5]
                })
                .collect(),
        }
    }

    #[test]
    fn the_seed_shows_at_once_then_every_step_refines_it_to_what_apply_gives() {
        let mut progressive = Editor::new();
        let mut edit = progressive
            .begin(Op::Create(ellipse().into()))
            .expect("begin");
        let seed = edit.document().models[0].clone();
        assert!(progressive.document().is_empty(), "nothing committed yet");
        assert_eq!((edit.revision(), edit.generation()), (1, 1));
        let mut shown = vec![seed.mesh.positions().to_vec()];
        while edit.step().expect("step") == Progress::Working {
            shown.push(edit.document().models[0].mesh.positions().to_vec());
            assert_eq!(edit.revision() as usize, shown.len());
        }
        // The seed, the first iteration (after the factorization), and more: each different.
        assert!(shown.len() >= 3, "{} displays", shown.len());
        assert!(shown.windows(2).all(|w| w[0] != w[1]));
        edit.finish(&mut progressive).expect("finish");
        let mut direct = Editor::new();
        direct.apply(Op::Create(ellipse().into())).expect("apply");
        assert_eq!(progressive.document(), direct.document());
        assert_eq!(progressive.session_json(), direct.session_json());
        let replayed = Editor::replay_json(&progressive.session_json()).expect("replay");
        assert_eq!(replayed.document(), direct.document());
        // The outline is a smooth closed control curve through its vertices.
        let model = &direct.document().models[0];
        let curve = &model.curves[0];
        assert!(curve.is_closed && !curve.is_sharp());
        assert!(curve.vertices.len() > 8);
    }

    /// A creation at `vertices` of the [`ellipse`].
    fn fine_ellipse(vertices: usize) -> Op {
        Op::Create(CreateInput {
            vertices: Some(vertices),
            ..ellipse().into()
        })
    }

    #[test]
    fn a_fine_creation_is_computed_whole_and_lands_as_if_stepped_here() {
        let mut editor = Editor::new();
        editor
            .apply(Op::Create(ellipse().into()))
            .expect("a first shape");
        let op = fine_ellipse(12_000);
        let mut edit = editor.begin(op.clone()).expect("begin");
        // Nothing is computed in a frame: the document shown is the one before.
        assert_eq!(edit.document(), editor.document());
        let (models, to_run) = edit.model_op_to_run().expect("computed elsewhere");
        let elsewhere = Document {
            models: models.to_vec(),
            ..Document::default()
        };
        let made = super::super::model_op(&elsewhere, to_run);
        let (index, model) = made.clone().expect("created");
        assert_eq!(index, 1, "after the first shape");
        let n = model.mesh.n_vertices();
        assert!((10_800..=13_200).contains(&n), "{n} vertices for 12,000");
        edit.supply_model(made);
        edit.finish(&mut editor).expect("lands");
        let mut applied = Editor::new();
        applied
            .apply(Op::Create(ellipse().into()))
            .expect("a first shape");
        applied.apply(op).expect("apply");
        assert_eq!(editor.document(), applied.document());
        let json = editor.session_json();
        assert!(json.contains(r#""vertices":12000"#), "{json}");
        assert_eq!(
            Editor::replay_json(&json).expect("replay").document(),
            applied.document()
        );
    }

    #[test]
    fn a_creation_computed_whole_is_the_stepped_one() {
        let op = fine_ellipse(STEPPED_MAX_VERTICES);
        let mut stepped = Editor::new();
        let mut edit = stepped.begin(op.clone()).expect("begin");
        assert!(edit.model_op_to_run().is_none(), "steps in the frames");
        while edit.step().expect("step") == Progress::Working {}
        edit.finish(&mut stepped).expect("finish");
        let (_, whole) = super::super::model_op(&Document::default(), &op).expect("whole");
        assert_eq!(*stepped.document().models[0], whole);
    }

    #[test]
    fn a_resolution_out_of_range_is_refused_at_once() {
        let editor = Editor::new();
        for vertices in [0, 499, 100_001] {
            let error = editor.begin(fine_ellipse(vertices)).expect_err("refused");
            assert_eq!(error, CommandError::CreateVertices(vertices));
            assert!(error.to_string().contains("500 to 100,000"), "{error}");
        }
    }

    #[test]
    fn undo_and_redo_of_a_creation_restore_exact_documents() {
        let mut editor = Editor::new();
        editor
            .apply(Op::Stroke(StrokeInput {
                stroke: vec![[10.0, 10.0, 0.5], [90.0, 40.0, 0.5]],
                ..ellipse()
            }))
            .expect("ink");
        let before = editor.document().clone();
        editor.apply(Op::Create(ellipse().into())).expect("create");
        let after = editor.document().clone();
        assert_eq!(after.stats().models, 1);
        editor.undo().expect("undo");
        assert_eq!(editor.document(), &before);
        editor.redo().expect("redo");
        assert_eq!(editor.document(), &after);
    }

    #[test]
    fn a_refused_creation_leaves_the_editor_untouched() {
        let mut editor = Editor::new();
        editor.apply(Op::Create(ellipse().into())).expect("create");
        let (doc, ops) = (editor.document().clone(), editor.ops().len());
        let open = StrokeInput {
            stroke: ellipse().stroke[..40].to_vec(),
            ..ellipse()
        };
        // Refused at begin, before any work.
        let error = editor
            .begin(Op::Create(open.clone().into()))
            .expect_err("open");
        assert!(error.to_string().contains("Close the outline"), "{error}");
        assert_eq!(editor.apply(Op::Create(open.into())), Err(error));
        assert_eq!(editor.document(), &doc);
        assert_eq!(editor.ops().len(), ops);
        assert!(editor.can_undo() && !editor.can_redo());
    }
}
