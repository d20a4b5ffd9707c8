//! A creation in progress: FiberMesh's surface appears at once and refines over frames.
//!
//! The first display is the seed shape (no factorization yet, already rotund); the first
//! [`PendingCreate::step`] factors the two fair-surface systems and runs one iteration, and
//! each later step runs one more, so the app shows every intermediate surface and blocks
//! for at most one factorization or one iteration per frame. [`Editor::apply`](super::Editor::apply) of a `create` op runs the very
//! same steps to convergence, so a committed creation and its replay are bit-identical.

use super::{CommandError, ControlCurve, Model, StrokeInput};
use crate::fibermesh::{CreateError, CreateParams, Creation, SeedShape, seed_from_stroke};
use crate::mesh::{Mesh, VertexId};
use crate::solve::SolveError;

/// The error of a creation whose factorization already failed.
fn failed() -> CommandError {
    CommandError::Create(CreateError::Solve(SolveError::NotPositiveDefinite))
}

/// Where a creation is: seeded, or factored and iterating.
#[derive(Debug)]
enum Stage {
    Seed(Box<SeedShape>),
    Optimizing(Box<Creation>),
    /// The factorization failed; the step that saw it reported the error.
    Failed,
}

/// A closed stroke being inflated.
#[derive(Debug)]
pub struct PendingCreate {
    input: StrokeInput,
    stage: Stage,
    params: CreateParams,
    iterations: usize,
    converged: bool,
}

impl PendingCreate {
    /// Meshes the stroke and builds the seed shape, cheaply: no factorization yet.
    ///
    /// Errors: the stroke's problems as sentences, see [`CommandError`].
    pub fn start(input: StrokeInput) -> Result<Self, CommandError> {
        let viewport = input.viewport_size();
        if !viewport.is_finite() || viewport.min_element() <= 0.0 || !input.camera.is_valid() {
            return Err(CommandError::BadView);
        }
        let params = CreateParams::default();
        let seed = seed_from_stroke(&input.points(), &input.camera, viewport, &params)?;
        Ok(Self {
            input,
            stage: Stage::Seed(Box::new(seed)),
            params,
            iterations: 0,
            converged: false,
        })
    }

    /// Factors and iterates once (first step) or iterates once more, unless converged;
    /// returns whether it has converged: no vertex moved more than the tolerance times the
    /// bounding-box diagonal, or the iteration cap was reached.
    ///
    /// Errors: a failed solve, as [`CommandError::Create`].
    pub fn step(&mut self) -> Result<bool, CommandError> {
        if self.converged {
            return Ok(true);
        }
        if matches!(self.stage, Stage::Seed(_)) {
            if let Stage::Seed(seed) = std::mem::replace(&mut self.stage, Stage::Failed) {
                self.stage = Stage::Optimizing(Box::new(seed.into_creation()?));
            }
            self.iterations = 1;
            self.converged = self.params.max_iterations <= 1;
            return Ok(self.converged);
        }
        let Stage::Optimizing(creation) = &mut self.stage else {
            return Err(failed());
        };
        let diagonal = creation
            .mesh
            .bounding_box()
            .map_or(0.0, |(lo, hi)| lo.distance(hi));
        let moved = creation
            .surface
            .iterate(creation.mesh.positions_mut())
            .map_err(|e| CommandError::Create(CreateError::Solve(e)))?;
        self.iterations += 1;
        self.converged = moved <= self.params.tolerance * diagonal
            || self.iterations >= self.params.max_iterations;
        Ok(self.converged)
    }

    /// Steps until converged and returns the model.
    ///
    /// Errors: those of [`PendingCreate::step`].
    pub fn finish(mut self) -> Result<(StrokeInput, Model), CommandError> {
        while !self.step()? {}
        let model = self.model().ok_or_else(failed)?;
        Ok((self.input, model))
    }

    /// The surface as it is now, for display; `None` after a failed factorization.
    pub fn mesh(&self) -> Option<&Mesh> {
        self.parts().map(|(mesh, _)| mesh)
    }

    fn parts(&self) -> Option<(&Mesh, &[VertexId])> {
        match &self.stage {
            Stage::Seed(seed) => Some((&seed.mesh, &seed.curve_vertices)),
            Stage::Optimizing(c) => Some((&c.mesh, &c.curve_vertices)),
            Stage::Failed => None,
        }
    }

    /// Steps run so far (the first one factors): changes whenever the surface does.
    pub fn iterations(&self) -> usize {
        self.iterations
    }

    /// The model in its current state, its outline as a smooth control curve; `None`
    /// after a failed factorization.
    pub fn model(&self) -> Option<Model> {
        let (mesh, vertices) = self.parts()?;
        Some(Model {
            curves: vec![ControlCurve {
                vertices: vertices.to_vec(),
                is_closed: true,
                kind: crate::fibermesh::CurveKind::Smooth,
            }],
            mesh: mesh.clone(),
            ..Model::default()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::Camera;
    use crate::document::{Editor, Op};

    fn ellipse() -> StrokeInput {
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
    fn refining_over_frames_then_committing_equals_applying_the_op() {
        let mut pending = PendingCreate::start(ellipse()).expect("start");
        let first = pending.mesh().expect("seed").clone();
        let mut frames = 0;
        while !pending.step().expect("step") {
            frames += 1;
        }
        assert!(
            frames >= 1,
            "the first display is not the converged surface"
        );
        assert_ne!(Some(&first), pending.mesh());
        let mut progressive = Editor::new();
        progressive.commit_create(pending).expect("commit");
        let mut direct = Editor::new();
        direct.apply(Op::Create(ellipse())).expect("apply");
        assert_eq!(progressive.document(), direct.document());
        assert_eq!(progressive.session_json(), direct.session_json());
        let replayed = Editor::replay_json(&progressive.session_json()).expect("replay");
        assert_eq!(replayed.document(), direct.document());
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
        editor.apply(Op::Create(ellipse())).expect("create");
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
        editor.apply(Op::Create(ellipse())).expect("create");
        let (doc, ops) = (editor.document().clone(), editor.ops().len());
        let open = StrokeInput {
            stroke: ellipse().stroke[..40].to_vec(),
            ..ellipse()
        };
        let error = editor.apply(Op::Create(open)).expect_err("open outline");
        assert!(error.to_string().contains("Close the outline"), "{error}");
        assert_eq!(editor.document(), &doc);
        assert_eq!(editor.ops().len(), ops);
        assert!(editor.can_undo() && !editor.can_redo());
    }
}
