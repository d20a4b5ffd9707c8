//! The editor: a document, its undo history and the log of applied ops. Ops change it only
//! through edits ([`Edit`], in `edit.rs`): [`Editor::apply`] is an edit begun and finished.

use std::sync::OnceLock;

#[cfg(doc)]
use super::Edit;
use super::history::History;
use super::next::Outcome;
use super::{CommandError, Document, Op};

/// A document with undo/redo and the log of applied ops (the session).
#[derive(Clone, Debug, Default)]
pub struct Editor {
    document: Document,
    history: History,
    log: Vec<Op>,
    /// Each logged op as session JSON, written the first time the session is (an import's
    /// op carries its file: re-encoding it at every autosave cost a frame per op).
    log_json: Vec<OnceLock<String>>,
    revision: u64,
    /// What the last op wants the user to know (an import's repairs and textures left
    /// behind); empty after any other op.
    notes: Vec<String>,
}

impl Editor {
    /// An empty document with no history.
    pub fn new() -> Self {
        Self::default()
    }

    /// Applies a finished edit's outcome and logs its op.
    ///
    /// Errors: [`CommandError::NothingToUndo`], [`CommandError::NothingToRedo`]; nothing
    /// changes then.
    pub(super) fn commit(&mut self, op: Op, outcome: Outcome) -> Result<(), CommandError> {
        let mut notes = Vec::new();
        match outcome {
            Outcome::Document(next) => {
                let before = std::mem::replace(&mut self.document, next);
                self.history.record(before);
            }
            Outcome::Imported { next, notes: said } => {
                let before = std::mem::replace(&mut self.document, next);
                self.history.record(before);
                notes = said;
            }
            Outcome::Undo => {
                if !self.history.undo(&mut self.document) {
                    return Err(CommandError::NothingToUndo);
                }
            }
            Outcome::Redo => {
                if !self.history.redo(&mut self.document) {
                    return Err(CommandError::NothingToRedo);
                }
            }
        }
        self.log.push(op);
        self.log_json.push(OnceLock::new());
        self.revision += 1;
        self.notes = notes;
        Ok(())
    }

    /// What the last op wants the user to know, as sentences: an import's repairs and the
    /// textures it left behind. Empty after any other op.
    pub fn notes(&self) -> &[String] {
        &self.notes
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

    /// The ops applied so far as JSON, in order, each written once and kept.
    pub(super) fn ops_json(&self) -> impl Iterator<Item = &str> {
        (0..self.log.len()).filter_map(|index| self.op_json(index))
    }

    /// Op `index`'s JSON, as the session file has it: written once and kept (an import's
    /// carries its files in base64, tens of megabytes for a scan, so a page writes it in a
    /// frame of its own; see [`Editor::is_op_json_written`]). `None` past the last op.
    pub fn op_json(&self, index: usize) -> Option<&str> {
        let (op, json) = (self.log.get(index)?, &self.log_json[index]);
        Some(json.get_or_init(|| op.to_json()))
    }

    /// Whether op `index`'s JSON is written already.
    pub fn is_op_json_written(&self, index: usize) -> bool {
        self.log_json
            .get(index)
            .is_some_and(|json| json.get().is_some())
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Arc;

    use super::*;
    use crate::camera::Camera;
    use crate::document::StrokeInput;
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
    fn an_op_s_json_is_written_once_when_first_asked_for() {
        let mut editor = Editor::new();
        editor.apply(horizontal_stroke()).unwrap();
        assert!(!editor.is_op_json_written(0));
        let json = editor.op_json(0).unwrap().to_owned();
        assert!(editor.is_op_json_written(0));
        assert_eq!(json, editor.ops()[0].to_json());
        assert_eq!(editor.ops_json().collect::<Vec<_>>(), [json.as_str()]);
        assert_eq!(
            (editor.op_json(1), editor.is_op_json_written(1)),
            (None, false)
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
