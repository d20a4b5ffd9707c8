//! A session replayed as steps, so the page can replay one over frames: each op is an
//! [`Edit`] begun, stepped and finished exactly as [`Editor::replay`] does in one go (which
//! runs these very steps), with an import's files read by the page's worker in between
//! ([`Replay::edit_mut`], [`Edit::supply_import`]).

use super::session_error::SessionError;
use super::{CommandError, Edit, Editor, Op, Progress};

/// A session being replayed onto a new editor.
#[derive(Debug)]
pub struct Replay {
    editor: Editor,
    ops: std::vec::IntoIter<Op>,
    /// The position of the op in progress (or next) in the session.
    index: usize,
    /// How many ops the session has.
    total: usize,
    /// The op in progress.
    edit: Option<Edit>,
    /// The refusal that stopped the replay, repeated by every later step.
    failed: Option<CommandError>,
}

impl Replay {
    /// Begins replaying `ops` (a session's) onto a new editor; nothing is computed yet.
    pub fn new(ops: Vec<Op>) -> Replay {
        Replay {
            editor: Editor::new(),
            total: ops.len(),
            ops: ops.into_iter(),
            index: 0,
            edit: None,
            failed: None,
        }
    }

    /// Runs one bounded chunk: begins the next op, steps the one in progress, or finishes it.
    ///
    /// Errors: the first op refused, as [`SessionError::Command`] with its index; the replay
    /// then only repeats it.
    pub fn step(&mut self) -> Result<Progress, SessionError> {
        let stepped = match &self.failed {
            Some(error) => Err(error.clone()),
            None => self.advance(),
        };
        stepped.map_err(|source| {
            self.edit = None;
            self.failed = Some(source.clone());
            SessionError::Command {
                index: self.index,
                source,
            }
        })
    }

    /// [`Replay::step`]'s work.
    fn advance(&mut self) -> Result<Progress, CommandError> {
        let Some(edit) = self.edit.as_mut() else {
            let Some(op) = self.ops.next() else {
                return Ok(Progress::Done);
            };
            let edit = self.editor.begin(op)?;
            self.edit = Some(edit);
            return Ok(Progress::Working);
        };
        if edit.step()? == Progress::Done
            && let Some(edit) = self.edit.take()
        {
            edit.finish(&mut self.editor)?;
            self.index += 1;
            // Done with the last op's finish, not one step later: the page lands the last
            // op and opens the document in one frame, not over two.
            if self.ops.len() == 0 {
                return Ok(Progress::Done);
            }
        }
        Ok(Progress::Working)
    }

    /// The op in progress, to hand it an import read elsewhere.
    pub fn edit_mut(&mut self) -> Option<&mut Edit> {
        self.edit.as_mut()
    }

    /// How many ops are replayed, of how many.
    pub fn done_of(&self) -> (usize, usize) {
        (self.index, self.total)
    }

    /// The editor the session rebuilt, once [`Replay::step`] said [`Progress::Done`].
    pub fn into_editor(self) -> Editor {
        debug_assert!(self.edit.is_none(), "the replay is not over");
        self.editor
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::document::create::tests::ellipse;

    #[test]
    fn a_replay_is_done_with_its_last_op() {
        let mut replay = Replay::new(vec![Op::Create(ellipse().into())]);
        while replay.step().expect("replays") == Progress::Working {
            assert_eq!(replay.done_of(), (0, 1), "working on the creation");
        }
        assert_eq!(replay.done_of(), (1, 1));
        assert_eq!(replay.into_editor().document().models.len(), 1);
    }

    #[test]
    fn stepping_a_replay_counts_its_ops_and_stops_at_the_first_refusal() {
        let mut replay = Replay::new(vec![Op::Create(ellipse().into()), Op::Undo, Op::Undo]);
        assert_eq!(replay.done_of(), (0, 3));
        let mut steps = 0;
        let error = loop {
            match replay.step() {
                Ok(progress) => {
                    assert_eq!(progress, Progress::Working, "not done: an op is refused")
                }
                Err(error) => break error,
            }
            steps += 1;
        };
        // The creation takes several steps; the first undo one; the second is refused.
        assert!(steps > 4, "{steps} steps");
        assert_eq!(replay.done_of(), (2, 3));
        assert!(matches!(
            error,
            SessionError::Command {
                index: 2,
                source: CommandError::NothingToUndo
            }
        ));
        assert!(replay.step().is_err(), "it repeats the refusal");
    }
}
