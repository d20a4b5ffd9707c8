//! Autosave: what is written so that a reload, a closed tab or a discarded background tab
//! loses nothing, and when it is written.
//!
//! The record is the session (which replays exactly, with its undo and redo history) and the
//! view; a document opened starts in Sketch, whatever tool was in use. The page writes it to
//! IndexedDB (`web/store.js`, asynchronous, so the write itself never holds a frame) at most
//! [`INTERVAL`] after an edit, [`VIEW_SETTLE`] after the view stops moving (an orbit, a wheel
//! or a pinch writes once, not at each of its frames), and when the page is hidden; on start
//! the page hands it back (`window.sketchmesh.restore`), and a record that does not replay is
//! set aside with a sentence. Only committed ops are saved:
//! an edit in progress (a drag, a preview) is not part of the document until it ends, so a
//! page left in the middle of one comes back in the last complete state.

use serde::{Deserialize, Serialize};
use sketchmesh_core::document::Editor;

use crate::camera::OrbitCamera;

/// Longest time in seconds from an edit to its autosave.
pub const INTERVAL: f64 = 0.5;

/// How long in seconds the view must hold still before a view changed without an edit is
/// written: a gesture's last frame, not each of its frames.
pub const VIEW_SETTLE: f64 = 0.4;

/// One autosave: the document's session and the view, as read back. Written
/// as [`record_head`], the session file itself (not a string holding it, so that nothing
/// escapes its text again) and [`RECORD_TAIL`]: in the page, the session goes to JavaScript
/// piece by piece, each op's text converted once (`web::autosave_pieces`).
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// The session file's text (`docs/session-format.md`).
    pub session: String,
    /// The view.
    pub camera: OrbitCamera,
}

/// What a record holds before its session: the view and the session's key.
pub fn record_head(camera: OrbitCamera) -> String {
    #[derive(Serialize)]
    struct Fields {
        camera: OrbitCamera,
    }
    let mut json = serde_json::to_string(&Fields { camera }).unwrap_or_else(|error| {
        debug_assert!(false, "a camera always serializes: {error}");
        String::from("{}")
    });
    json.pop();
    if json.len() > 1 {
        json.push(',');
    }
    json.push_str("\"session\":");
    json
}

/// What a record holds after its session.
pub const RECORD_TAIL: &str = "}";

impl Record {
    /// Reads a record, or one from before the session was stored as JSON, whose
    /// `"session"` is a string holding the session file (the tool older records name is
    /// not read).
    ///
    /// Errors: the JSON is not a record.
    pub fn from_json(text: &str) -> Result<Record, serde_json::Error> {
        #[derive(Deserialize)]
        struct Stored {
            session: Box<serde_json::value::RawValue>,
            camera: OrbitCamera,
        }
        let stored: Stored = serde_json::from_str(text)?;
        let raw = stored.session.get();
        let session = if raw.starts_with('"') {
            serde_json::from_str(raw)?
        } else {
            raw.to_owned()
        };
        Ok(Record {
            session,
            camera: stored.camera,
        })
    }

    /// The editor the record's session replays to.
    ///
    /// Errors: a sentence saying why the session does not replay.
    pub fn replay(&self) -> Result<Editor, String> {
        Editor::replay_json(&self.session).map_err(|e| e.to_string())
    }
}

/// Which document the app shows: how many times its editor was replaced (a session opened,
/// a restore, the page's `replay`), and that editor's own revision. The editor's revision
/// alone repeats when another editor replaces it (both at their third op, say), and then
/// neither the view nor the autosave would notice the change.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Revision {
    /// Editors that replaced the first one.
    pub opened: u64,
    /// The editor's revision.
    pub edits: u64,
}

/// When to autosave: not before the page has offered its last record (so that an empty
/// start does not overwrite it), then whenever the document's revision moved and the last
/// write is [`INTERVAL`] old, or the view alone moved and has held still for [`VIEW_SETTLE`].
#[derive(Debug, Default)]
pub struct Schedule {
    /// The revision and view last written (or restored); `None` until the page offered its
    /// record.
    saved: Option<(Revision, OrbitCamera)>,
    /// When the last write happened.
    saved_at: f64,
    /// The view last seen, and since when it has not moved.
    seen: Option<(OrbitCamera, f64)>,
}

impl Schedule {
    /// The page has offered its record (restored or not): from now on `revision` in the view
    /// `view` is what is saved.
    pub fn start(&mut self, revision: Revision, view: OrbitCamera) {
        self.saved = Some((revision, view));
    }

    /// The page has offered no record while the document shown already has work (a file
    /// dropped, a stroke drawn while the store was read): from now on, that work is written
    /// like any change.
    pub fn start_unwritten(&mut self) {
        self.saved = Some((Revision::default(), OrbitCamera::default()));
    }

    /// Whether to write now, at time `now` in seconds, the document at `revision` in the view
    /// `view`; a write is then assumed to happen.
    pub fn due(&mut self, revision: Revision, view: OrbitCamera, now: f64) -> bool {
        if self.seen.is_none_or(|(seen, _)| seen != view) {
            self.seen = Some((view, now));
        }
        let Some((saved, saved_view)) = self.saved else {
            return false;
        };
        let due = if saved != revision {
            now - self.saved_at >= INTERVAL
        } else {
            let still_since = self.seen.map_or(now, |(_, since)| since);
            saved_view != view && now - still_since >= VIEW_SETTLE
        };
        if due {
            self.mark_saved(revision, view, now);
        }
        due
    }

    /// Whether a change waits for its write (the app keeps frames coming until it is due).
    pub fn is_pending(&self, revision: Revision, view: OrbitCamera) -> bool {
        self.saved.is_some_and(|saved| saved != (revision, view))
    }

    /// The document at `revision` in the view `view` was written at `now`, in the seconds of
    /// the frames' clock that [`Schedule::due`] is given (also by a flush when the page hides).
    pub fn mark_saved(&mut self, revision: Revision, view: OrbitCamera, now: f64) {
        if self.saved.is_some() {
            self.saved = Some((revision, view));
            self.saved_at = now;
        }
    }

    /// Whether the page has offered its record yet.
    pub fn is_started(&self) -> bool {
        self.saved.is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nothing_is_written_before_the_page_offered_its_record_then_changes_are() {
        let at = |edits| Revision { opened: 0, edits };
        let view = OrbitCamera::default();
        let mut schedule = Schedule::default();
        assert!(
            !schedule.due(at(3), view, 10.0),
            "an empty start must not overwrite the record"
        );
        schedule.start(at(3), view);
        assert!(!schedule.due(at(3), view, 10.0), "unchanged");
        assert!(schedule.is_pending(at(4), view));
        assert!(schedule.due(at(4), view, 10.0));
        assert!(!schedule.is_pending(at(4), view));
        // A change right after a write waits for the interval, then is written.
        assert!(!schedule.due(at(5), view, 10.0 + INTERVAL / 2.0));
        assert!(schedule.is_pending(at(5), view));
        assert!(schedule.due(at(5), view, 10.0 + INTERVAL));
        // Another editor at the same revision is another document.
        let opened = Revision {
            opened: 1,
            edits: 5,
        };
        assert!(schedule.is_pending(opened, view));
        assert!(schedule.due(opened, view, 10.0 + 2.0 * INTERVAL));
    }

    #[test]
    fn a_view_moved_without_an_edit_is_written_once_it_holds_still() {
        let revision = Revision::default();
        let mut schedule = Schedule::default();
        schedule.start(revision, OrbitCamera::default());
        // An orbit: a new view at every frame, none written while it moves.
        let mut view = OrbitCamera::default();
        let mut now = 1.0;
        for _ in 0..60 {
            view.orbit(glam::DVec2::new(3.0, 1.0));
            now += 1.0 / 60.0;
            assert!(!schedule.due(revision, view, now), "written mid-orbit");
            assert!(schedule.is_pending(revision, view));
        }
        // Held still: not yet, then once.
        assert!(!schedule.due(revision, view, now + VIEW_SETTLE / 2.0));
        // (A little past it: the frames' clock adds up in floating point.)
        assert!(schedule.due(revision, view, now + 1.01 * VIEW_SETTLE));
        assert!(!schedule.is_pending(revision, view));
        assert!(!schedule.due(revision, view, now + 2.0 * VIEW_SETTLE));
        // A pinch's zoom alone is a change of view too.
        view.dolly(0.5);
        assert!(schedule.is_pending(revision, view));
        let later = now + 3.0 * VIEW_SETTLE;
        assert!(!schedule.due(revision, view, later));
        assert!(schedule.due(revision, view, later + 1.01 * VIEW_SETTLE));
    }

    #[test]
    fn work_done_before_the_page_offered_no_record_is_written_first() {
        let mut schedule = Schedule::default();
        let imported = Revision {
            opened: 0,
            edits: 1,
        };
        let view = OrbitCamera::default();
        assert!(!schedule.is_pending(imported, view));
        schedule.start_unwritten();
        assert!(schedule.is_pending(imported, view));
        assert!(schedule.due(imported, view, INTERVAL));
        assert!(!schedule.is_pending(imported, view));
    }

    #[test]
    fn a_record_round_trips_through_json_and_replays() {
        let mut editor = Editor::new();
        editor
            .apply(sketchmesh_core::document::Op::Stroke(
                sketchmesh_core::document::StrokeInput {
                    viewport: [800.0, 600.0],
                    camera: sketchmesh_core::camera::Camera::default(),
                    stroke: vec![[10.0, 10.0, 0.5], [60.0, 40.0, 0.5], [90.0, 20.0, 0.5]],
                },
            ))
            .unwrap_or_else(|e| panic!("ink: {e}"));
        let record = Record {
            session: editor.session_json(),
            camera: OrbitCamera::default(),
        };
        let json = [&record_head(record.camera), &record.session, RECORD_TAIL].concat();
        assert!(
            json.contains(r#""session":{"format":"sketchmesh-session""#),
            "{json}"
        );
        let back = Record::from_json(&json).unwrap_or_else(|e| panic!("{e}"));
        // The session file's last newline is whitespace around the JSON value, not in it.
        let trimmed = Record {
            session: record.session.trim_end().to_owned(),
            ..record.clone()
        };
        assert_eq!(back, trimmed);
        // A record written before the session was stored as JSON: a string holding it, and
        // the tool in use then.
        let old = serde_json::json!({
            "session": record.session,
            "camera": record.camera,
            "mode": "optimize",
        });
        let back = Record::from_json(&old.to_string()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(back, record);
        assert!(Record::from_json("{\"session\": 7}").is_err());
        let replayed = back.replay().unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(replayed.document(), editor.document());
        let corrupt = Record {
            session: String::from("{\"format\": 7"),
            ..record
        };
        assert!(!corrupt.replay().unwrap_err().is_empty());
    }
}
