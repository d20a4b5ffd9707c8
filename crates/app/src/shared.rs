//! The state the app shares with the page API (`window.sketchmesh`), which runs outside
//! frames: the document, the view, the tool, and what the page reads or asks for.

use sketchmesh_core::document::Editor;

use crate::camera::OrbitCamera;
use crate::files::ImportQueue;
use crate::tools::Mode;
use crate::{autosave, clock, panels};

/// The Symmetry switch (issue 50): whether the ops the user makes are made with symmetry on
/// (one stroke makes both arms, one pull moves both sides), and what a new document starts
/// with. An import turns it off for its document (a scan is rarely symmetric, and every edit
/// on it would be refused) without changing what the next new document starts with: that
/// stays as the user last left the switch.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SymmetrySwitch {
    /// Whether the ops the user makes now mirror about the document's plane.
    pub is_on: bool,
    /// What a new document starts with: the user's last choice (kept by the page).
    pub for_new: bool,
}

impl Default for SymmetrySwitch {
    /// On: most things people model (characters, animals, vehicles) are symmetric.
    fn default() -> Self {
        SymmetrySwitch {
            is_on: true,
            for_new: true,
        }
    }
}

impl SymmetrySwitch {
    /// The user turned the switch on or off: for this document and the new ones.
    pub fn choose(&mut self, on: bool) {
        *self = SymmetrySwitch {
            is_on: on,
            for_new: on,
        };
    }
}

/// State shared with the page API (`window.sketchmesh`), which runs outside frames.
pub struct Shared {
    /// The document and its history.
    pub editor: Editor,
    /// The view's camera.
    pub camera: OrbitCamera,
    /// The graphics backend in use, for the page API and the help panel.
    pub backend: String,
    /// Files waiting to be imported.
    pub imports: ImportQueue,
    /// Recent costs of edits, for the page benchmark.
    pub timings: clock::Timings,
    /// The tool in use; a document opened sets it back to Sketch, and the app follows.
    pub mode: Mode,
    /// When to autosave.
    pub autosave: autosave::Schedule,
    /// A sentence for the user from outside the app (the page's restore), shown next frame.
    pub notice: Option<String>,
    /// Thumbnails of the view the page asked for (`window.sketchmesh.thumbnail()`).
    pub thumbnails: crate::thumbnail::Capture,
    /// The notes panel (an import's repairs), which the page API reads too.
    pub notes: panels::notes::Notes,
    /// What the progress line says while work runs off the frame (an import, a replay).
    pub progress: Option<String>,
    /// What the line at the top of the view says (the tool's hint), for the page API.
    pub hint: String,
    /// The status line's sentence and tone, for the page API.
    pub status: Option<(String, crate::status::Tone)>,
    /// The introduction's step shown (1 to 3) and where its Skip button is, for the page
    /// API.
    pub intro: Option<(u8, Option<egui::Pos2>)>,
    /// How many exports were downloaded since the page opened (the introduction's last
    /// step waits for one).
    pub exports: u32,
    /// The page's request to play how a session was made (`window.sketchmesh.playMaking`):
    /// its JSON, a caption per op, and who waits for it to begin.
    pub making_asked: Option<(String, Vec<String>, crate::files::Reply)>,
    /// How the playing of a making stands (see `making::Standing`), for the page API.
    pub making: Option<serde_json::Value>,
    /// The Symmetry switch: whether the ops the user makes mirror about the plane.
    pub symmetry: SymmetrySwitch,
    /// Editors that replaced the first one (see [`autosave::Revision`]).
    opened: u64,
    /// The ops' session text as JavaScript strings, for the autosave.
    #[cfg(target_arch = "wasm32")]
    pub op_texts: crate::page_store::OpTexts,
}

impl Shared {
    /// An empty document in the default view, drawn by `backend`.
    pub fn new(backend: String) -> Self {
        Shared {
            editor: Editor::new(),
            camera: OrbitCamera::default(),
            backend,
            imports: ImportQueue::default(),
            timings: clock::Timings::default(),
            mode: Mode::default(),
            autosave: autosave::Schedule::default(),
            notice: None,
            thumbnails: Default::default(),
            notes: Default::default(),
            progress: None,
            hint: String::new(),
            status: None,
            intro: None,
            exports: 0,
            making_asked: None,
            making: None,
            symmetry: SymmetrySwitch::default(),
            opened: 0,
            #[cfg(target_arch = "wasm32")]
            op_texts: Default::default(),
        }
    }

    /// Replaces the document and its history by `editor`'s (a session opened or restored, a
    /// new document), in Sketch: the tool that makes shapes, whatever the last document was
    /// left in, so that a first outline does what the empty view's hint says.
    pub fn open(&mut self, editor: Editor) {
        self.editor = editor;
        self.opened += 1;
        self.mode = Mode::Sketch;
    }

    /// The user turned the Symmetry switch `on` or off (the toolbar, its key, the page API):
    /// for this document and, kept by the page, for new ones. Returns what to tell them.
    pub fn choose_symmetry(&mut self, on: bool) -> &'static str {
        self.symmetry.choose(on);
        #[cfg(target_arch = "wasm32")]
        crate::page_store::keep_symmetry(on);
        match on {
            true => {
                "Symmetry on: what you draw or change on one side is mirrored across the \
                 plane (X turns it off)."
            }
            false => "Symmetry off: edits change only the side you touch (X turns it on).",
        }
    }

    /// Starts an empty document in the default view.
    pub fn open_empty(&mut self) {
        self.open(Editor::new());
        self.symmetry.is_on = self.symmetry.for_new;
        self.camera = OrbitCamera::default();
    }

    /// Which document is shown: changes with every op, and when another editor comes in.
    pub fn revision(&self) -> autosave::Revision {
        autosave::Revision {
            opened: self.opened,
            edits: self.editor.revision(),
        }
    }

    /// Readies the autosave's op texts while `budget_ms` lasts from `started`; whether every
    /// op is ready (see [`crate::page_store::ready_op_texts`]).
    #[cfg(target_arch = "wasm32")]
    pub fn ready_op_texts(&mut self, started: f64, budget_ms: f64) -> bool {
        let opened = self.opened;
        crate::page_store::ready_op_texts(
            &self.editor,
            &mut self.op_texts,
            opened,
            started,
            budget_ms,
        )
    }

    /// The autosave record of what is shown, in pieces (see
    /// [`crate::page_store::autosave_pieces`]); `None` without ops.
    #[cfg(target_arch = "wasm32")]
    pub fn autosave_pieces(&mut self) -> Option<js_sys::Array> {
        let opened = self.opened;
        crate::page_store::autosave_pieces(&self.editor, &mut self.op_texts, opened, self.camera)
    }
}
