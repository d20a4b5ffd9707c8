//! Undo and redo as stacks of whole-document snapshots.
//!
//! A [`Document`] clone copies only `Arc` pointers, so a snapshot per change costs a few
//! words per model and restores the previous state exactly, whatever the op did.

use super::Document;

/// Undo and redo stacks.
#[derive(Clone, Debug, Default)]
pub(crate) struct History {
    undo: Vec<Document>,
    redo: Vec<Document>,
}

impl History {
    /// Records the state before a new change; the redo stack is dropped.
    pub(crate) fn record(&mut self, before: Document) {
        self.undo.push(before);
        self.redo.clear();
    }

    pub(crate) fn can_undo(&self) -> bool {
        !self.undo.is_empty()
    }

    pub(crate) fn can_redo(&self) -> bool {
        !self.redo.is_empty()
    }

    /// Swaps `current` with the last undo snapshot; `false` if there is none.
    pub(crate) fn undo(&mut self, current: &mut Document) -> bool {
        let Some(previous) = self.undo.pop() else {
            return false;
        };
        self.redo.push(std::mem::replace(current, previous));
        true
    }

    /// Swaps `current` with the last redo snapshot; `false` if there is none.
    pub(crate) fn redo(&mut self, current: &mut Document) -> bool {
        let Some(next) = self.redo.pop() else {
            return false;
        };
        self.undo.push(std::mem::replace(current, next));
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::document::SketchCurve;
    use std::sync::Arc;

    #[test]
    fn undo_redo_swap_snapshots() {
        let empty = Document::default();
        let mut one = empty.clone();
        one.sketches.push(Arc::new(SketchCurve::default()));
        let mut history = History::default();
        let mut current = one.clone();
        history.record(empty.clone());
        assert!(history.undo(&mut current));
        assert_eq!(current, empty);
        assert!(!history.undo(&mut current));
        assert!(history.redo(&mut current));
        assert_eq!(current, one);
        assert!(!history.redo(&mut current));
        // A new change drops the redo stack.
        assert!(history.undo(&mut current));
        history.record(current.clone());
        assert!(!history.can_redo());
        assert!(history.can_undo());
    }
}
