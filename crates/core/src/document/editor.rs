//! The editor: a document, its undo history and the log of applied ops.

use std::sync::Arc;

use super::curve_edit;
use super::history::History;
use super::{
    Document, ImportInput, Model, Op, OversketchInput, PendingCreate, SketchCurve, StrokeInput,
};
use crate::curve::{StrokeError, process_stroke};
use crate::fibermesh::CreateError;
use crate::fibermesh::add_curve::AddCurveError;
use crate::fibermesh::curve_pull::PullError;
use crate::io::{GltfError, ImportFile, ImportLimits, Imported, import_gltf};
use crate::mesh::remesh::RemeshError;
use crate::oversketch::{
    BendOptions, OversketchError, Oversketched, oversketch_manual, oversketch_with,
};
use crate::solve::SolveError;

/// Why an op was refused. The messages are sentences for the user.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CommandError {
    /// The stroke has too few points or is too short.
    #[error("That stroke is too short to use; draw a longer line.")]
    StrokeTooShort,
    /// The stroke contains NaN or infinite numbers.
    #[error("That stroke has coordinates that are not numbers; draw it again.")]
    StrokeNotFinite,
    /// The camera or viewport sent with the op cannot project anything.
    #[error("The camera or viewport of that op is not usable (degenerate view or zero size).")]
    BadView,
    /// A stroke point's ray misses the drawing plane.
    #[error("That stroke could not be placed in the scene; look at the scene and draw again.")]
    StrokeOffPlane,
    /// Undo with an empty undo history.
    #[error("Nothing to undo.")]
    NothingToUndo,
    /// Redo with an empty redo history.
    #[error("Nothing to redo.")]
    NothingToRedo,
    /// A closed stroke did not become a shape.
    #[error("{0}")]
    Create(#[from] CreateError),
    /// An import op names a file whose contents were not loaded.
    #[error("The contents of {0} are not in the session; replay it next to that file.")]
    FileNotLoaded(String),
    /// An import op has no files.
    #[error("The import has no file.")]
    NoFile,
    /// A file could not be imported.
    #[error("{0}")]
    Import(#[from] GltfError),
    /// An over-sketch was refused.
    #[error("{0}")]
    Oversketch(#[from] OversketchError),
    /// A curve tool started where no visible control curve is.
    #[error("No control curve there: start on a curve (the blue and red lines on a shape).")]
    NoCurveHere,
    /// A curve was drawn where no model with control curves is.
    #[error("Draw the curve on a shape made here; imported models are edited with over-sketch.")]
    NotOnModel,
    /// An erase would leave a shape with no curve to hold it.
    #[error("That would erase the last curve holding the shape; a shape needs at least one.")]
    LastCurve,
    /// A curve could not be pulled.
    #[error("{0}")]
    Pull(#[from] PullError),
    /// A curve could not be put on the surface.
    #[error("{0}")]
    AddCurve(#[from] AddCurveError),
    /// The surface could not be remeshed after a curve edit.
    #[error("{0}")]
    Remesh(#[from] RemeshError),
    /// The surface could not be re-optimized through its curves.
    #[error("The surface could not be re-optimized: {0}")]
    Surface(SolveError),
}

impl From<StrokeError> for CommandError {
    fn from(error: StrokeError) -> Self {
        match error {
            StrokeError::TooFewPoints { .. } | StrokeError::TooShort { .. } => {
                CommandError::StrokeTooShort
            }
            StrokeError::NonFinite { .. } => CommandError::StrokeNotFinite,
        }
    }
}

/// A document with undo/redo and the log of applied ops (the session).
#[derive(Clone, Debug, Default)]
pub struct Editor {
    document: Document,
    history: History,
    log: Vec<Op>,
    revision: u64,
}

impl Editor {
    /// An empty document with no history.
    pub fn new() -> Self {
        Self::default()
    }

    /// Applies one op. On success the op is appended to the log (undo and redo included); on
    /// failure the document, the history and the log are unchanged.
    pub fn apply(&mut self, op: Op) -> Result<(), CommandError> {
        match &op {
            Op::Stroke(input) => {
                let sketch = place_stroke(input)?;
                let mut next = self.document.clone();
                next.sketches.push(Arc::new(sketch));
                let before = std::mem::replace(&mut self.document, next);
                self.history.record(before);
            }
            Op::Create(input) => {
                let (_, model) = PendingCreate::start(input.clone())?.finish()?;
                self.add_model(model);
            }
            Op::Import(input) => {
                let imported = import_files(input)?;
                let mut next = self.document.clone();
                next.models
                    .extend(imported.models.into_iter().map(Arc::new));
                next.sketches
                    .extend(imported.sketches.into_iter().map(Arc::new));
                next.point_clouds
                    .extend(imported.point_clouds.into_iter().map(Arc::new));
                let before = std::mem::replace(&mut self.document, next);
                self.history.record(before);
            }
            Op::Oversketch(input) => {
                self.replace_model(oversketch_document(&self.document, input)?);
            }
            Op::Pull(input) => self.replace_model(curve_edit::pull_op(&self.document, input)?),
            Op::AddCurve(input) => {
                self.replace_model(curve_edit::add_curve_op(&self.document, input)?);
            }
            Op::Erase(input) => self.replace_model(curve_edit::erase_op(&self.document, input)?),
            Op::SetCurveType(input) => {
                self.replace_model(curve_edit::set_curve_type_op(&self.document, input)?);
            }
            Op::Rub(input) => self.replace_model(curve_edit::rub_op(&self.document, input)?),
            Op::Undo => {
                if !self.history.undo(&mut self.document) {
                    return Err(CommandError::NothingToUndo);
                }
            }
            Op::Redo => {
                if !self.history.redo(&mut self.document) {
                    return Err(CommandError::NothingToRedo);
                }
            }
        }
        self.log.push(op);
        self.revision += 1;
        Ok(())
    }

    /// Commits a creation the app refined over frames: finishes it (the same steps as
    /// `apply` of its `create` op, so replay gives the same mesh) and logs the op.
    ///
    /// Errors: a failed solve; the document is unchanged then.
    pub fn commit_create(&mut self, pending: PendingCreate) -> Result<(), CommandError> {
        let (input, model) = pending.finish()?;
        self.add_model(model);
        self.log.push(Op::Create(input));
        self.revision += 1;
        Ok(())
    }

    /// Records the current document and puts `model` at `index`.
    fn replace_model(&mut self, (index, model): (usize, Model)) {
        let mut next = self.document.clone();
        next.models[index] = Arc::new(model);
        let before = std::mem::replace(&mut self.document, next);
        self.history.record(before);
    }

    fn add_model(&mut self, model: Model) {
        let mut next = self.document.clone();
        next.models.push(Arc::new(model));
        let before = std::mem::replace(&mut self.document, next);
        self.history.record(before);
    }

    /// Undoes the last change; the same as `apply(Op::Undo)`.
    pub fn undo(&mut self) -> Result<(), CommandError> {
        self.apply(Op::Undo)
    }

    /// Redoes the last undone change; the same as `apply(Op::Redo)`.
    pub fn redo(&mut self) -> Result<(), CommandError> {
        self.apply(Op::Redo)
    }

    /// Whether [`Editor::undo`] would succeed.
    pub fn can_undo(&self) -> bool {
        self.history.can_undo()
    }

    /// Whether [`Editor::redo`] would succeed.
    pub fn can_redo(&self) -> bool {
        self.history.can_redo()
    }

    /// The current document.
    pub fn document(&self) -> &Document {
        &self.document
    }

    /// A counter that changes whenever the document changes (after every applied op), so a
    /// renderer knows when to upload again.
    pub fn revision(&self) -> u64 {
        self.revision
    }

    /// The ops applied so far, in order.
    pub fn ops(&self) -> &[Op] {
        &self.log
    }
}

/// Processes the stroke in screen space and projects each point onto the plane through the
/// camera target facing the camera.
fn place_stroke(input: &StrokeInput) -> Result<SketchCurve, CommandError> {
    let viewport = input.viewport_size();
    let viewport_ok = viewport.is_finite() && viewport.x > 0.0 && viewport.y > 0.0;
    if !viewport_ok || !input.camera.is_valid() {
        return Err(CommandError::BadView);
    }
    let processed = process_stroke(&input.points())?;
    let mut sketch = SketchCurve {
        points: Vec::with_capacity(processed.len()),
        pressures: Vec::with_capacity(processed.len()),
    };
    for point in &processed {
        let Some(point_in_world) = input.camera.point_on_target_plane(point.pos, viewport) else {
            return Err(CommandError::StrokeOffPlane);
        };
        sketch.points.push(point_in_world);
        sketch.pressures.push(point.pressure);
    }
    Ok(sketch)
}

/// Over-sketches the model whose outline the stroke matches best (highest match score
/// among the models that accept it), returning its index and its new version: new
/// positions (its control curves, chains of its vertices, follow).
///
/// Errors: [`CommandError::BadView`], [`CommandError::StrokeTooShort`],
/// [`CommandError::StrokeNotFinite`], or the most telling refusal over all models
/// (a failed edit, then a doubtful match, then no match).
fn oversketch_document(
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
    let mut best: Option<(usize, Oversketched)> = None;
    let mut refusal = OversketchError::NoMatch;
    for (index, model) in document.models.iter().enumerate() {
        let (mesh, camera) = (&model.mesh, &input.camera);
        let result = match &input.handle {
            Some(handle) => oversketch_manual(mesh, camera, viewport, handle, &stroke, options),
            None => oversketch_with(mesh, camera, viewport, &stroke, options),
        };
        match result {
            Ok(result) => {
                if best.as_ref().is_none_or(|(_, b)| result.score > b.score) {
                    best = Some((index, result));
                }
            }
            Err(error) => {
                if refusal_rank(&error) > refusal_rank(&refusal) {
                    refusal = error;
                }
            }
        }
    }
    let (index, result) = best.ok_or(refusal)?;
    let mut model = Model::clone(&document.models[index]);
    model
        .mesh
        .positions_mut()
        .copy_from_slice(&result.positions);
    Ok((index, model))
}

/// How much a refusal tells the user: a failed edit, then a doubtful match, then none.
fn refusal_rank(error: &OversketchError) -> u8 {
    match error {
        OversketchError::NoMatch => 0,
        OversketchError::LowConfidence | OversketchError::HandleLost | OversketchError::NoPart => 1,
        OversketchError::Deform(_) => 2,
    }
}

/// Imports the files of an import op with the default limits.
fn import_files(input: &ImportInput) -> Result<Imported, CommandError> {
    let files = input
        .files
        .iter()
        .map(|file| match &file.data {
            Some(data) => Ok(ImportFile {
                name: &file.name,
                bytes: data.as_slice(),
            }),
            None => Err(CommandError::FileNotLoaded(file.name.clone())),
        })
        .collect::<Result<Vec<_>, _>>()?;
    let (main, others) = files.split_first().ok_or(CommandError::NoFile)?;
    Ok(import_gltf(main, others, &ImportLimits::default())?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::camera::Camera;
    use glam::{DVec2, DVec3};

    fn stroke(points: &[[f64; 3]]) -> Op {
        Op::Stroke(StrokeInput {
            viewport: [800.0, 600.0],
            camera: Camera::default(),
            stroke: points.to_vec(),
        })
    }

    fn horizontal_stroke() -> Op {
        stroke(&[
            [300.0, 300.0, 0.5],
            [400.0, 300.0, 0.6],
            [500.0, 300.0, 0.7],
        ])
    }

    #[test]
    fn stroke_lands_on_the_target_plane() {
        let mut editor = Editor::new();
        editor.apply(horizontal_stroke()).unwrap();
        let sketch = &editor.document().sketches[0];
        // 200 px resampled at 4 px: 51 points, all on z = 0 and y = 0 (the screen centre row).
        assert_eq!(sketch.points.len(), 51);
        assert_eq!(sketch.pressures.len(), 51);
        let half_width = 5.0 * 22.5f64.to_radians().tan() * 800.0 / 600.0;
        let expected_first = DVec3::new(-100.0 / 400.0 * half_width, 0.0, 0.0);
        assert!((sketch.points[0] - expected_first).length() < 1e-12);
        assert!((sketch.points[50] + expected_first).length() < 1e-12);
        for point in &sketch.points {
            assert!(point.z.abs() < 1e-12 && point.y.abs() < 1e-12);
        }
        assert_eq!(sketch.pressures[0], 0.5);
        assert_eq!(sketch.pressures[50], 0.7);
        // Its screen projection is where it was drawn.
        let pixel = Camera::default()
            .screen_from_world(sketch.points[25], DVec2::new(800.0, 600.0))
            .unwrap();
        assert!((pixel.truncate() - DVec2::new(400.0, 300.0)).length() < 1e-9);
    }

    #[test]
    fn undo_and_redo_restore_exact_states() {
        let mut editor = Editor::new();
        let before = editor.document().clone();
        assert!(!editor.can_undo());
        editor.apply(horizontal_stroke()).unwrap();
        let after = editor.document().clone();
        assert_ne!(after, before);
        assert!(editor.can_undo() && !editor.can_redo());
        editor.undo().unwrap();
        assert_eq!(*editor.document(), before);
        assert!(editor.can_redo() && !editor.can_undo());
        editor.redo().unwrap();
        assert_eq!(*editor.document(), after);
        assert!(Arc::ptr_eq(
            &editor.document().sketches[0],
            &after.sketches[0]
        ));
        assert_eq!(editor.ops().len(), 3);
        assert_eq!(editor.revision(), 3);
        assert_eq!(editor.redo(), Err(CommandError::NothingToRedo));
        editor.undo().unwrap();
        assert_eq!(editor.undo(), Err(CommandError::NothingToUndo));
        assert_eq!(editor.ops().len(), 4);
    }

    #[test]
    fn failed_ops_change_nothing() {
        let mut editor = Editor::new();
        editor.apply(horizontal_stroke()).unwrap();
        let document = editor.document().clone();
        let revision = editor.revision();
        let failures = [
            (stroke(&[[10.0, 10.0, 0.5]]), CommandError::StrokeTooShort),
            (
                stroke(&[[10.0, 10.0, 0.5], [11.0, 10.0, 0.5]]),
                CommandError::StrokeTooShort,
            ),
            (
                stroke(&[[10.0, 10.0, 0.5], [f64::NAN, 10.0, 0.5], [90.0, 10.0, 0.5]]),
                CommandError::StrokeNotFinite,
            ),
            (
                Op::Stroke(StrokeInput {
                    viewport: [0.0, 600.0],
                    camera: Camera::default(),
                    stroke: vec![[10.0, 10.0, 0.5], [90.0, 10.0, 0.5]],
                }),
                CommandError::BadView,
            ),
            (
                Op::Stroke(StrokeInput {
                    viewport: [800.0, 600.0],
                    camera: Camera {
                        target: DVec3::new(0.0, 0.0, 5.0),
                        ..Camera::default()
                    },
                    stroke: vec![[10.0, 10.0, 0.5], [90.0, 10.0, 0.5]],
                }),
                CommandError::BadView,
            ),
            (Op::Redo, CommandError::NothingToRedo),
        ];
        for (op, expected) in failures {
            assert_eq!(editor.apply(op), Err(expected));
            assert_eq!(*editor.document(), document);
            assert!(editor.can_undo() && !editor.can_redo());
            assert_eq!(editor.ops().len(), 1);
            assert_eq!(editor.revision(), revision);
        }
        assert_eq!(
            CommandError::StrokeTooShort.to_string(),
            "That stroke is too short to use; draw a longer line."
        );
    }

    #[test]
    fn a_new_stroke_drops_redo() {
        let mut editor = Editor::new();
        editor.apply(horizontal_stroke()).unwrap();
        editor.undo().unwrap();
        editor
            .apply(stroke(&[[100.0, 100.0, 0.5], [100.0, 200.0, 0.5]]))
            .unwrap();
        assert!(!editor.can_redo());
        assert_eq!(editor.document().sketches.len(), 1);
        assert_eq!(editor.document().sketches[0].points.len(), 26);
    }
}
