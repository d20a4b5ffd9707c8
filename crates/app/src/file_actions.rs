//! The files the user opens and saves: imports (dropped, picked or from the page API) and
//! replays begun through the edit runner, session files opened as documents of their own,
//! the session and the glTF downloaded, the page's documents panel.

use sketchmesh_core::document::Editor;

use crate::edit_runner::{Cx, EditRunner};
use crate::files;

/// Imports announced in one frame and read in the next.
#[derive(Default)]
pub struct FileActions {
    /// An import announced this frame, parsed in the next one.
    announced: Option<files::Incoming>,
}

impl FileActions {
    /// Imports files in two frames: this frame says what is being imported, the next one
    /// parses (the page cannot repaint while the parser runs).
    pub fn run_imports(&mut self, ctx: &egui::Context, runner: &mut EditRunner, cx: &mut Cx<'_>) {
        let dropped = ctx.input(|i| i.raw.dropped_files.clone());
        let imports = cx.shared.borrow().imports.clone();
        files::accept_dropped(dropped, &imports, ctx);
        if runner.is_busy() {
            // What comes next applies to the imported or replayed document: it waits.
            return;
        }
        if let Some(incoming) = self.announced.take() {
            match incoming {
                files::Incoming::Import(input, reply) => runner.begin_import(input, reply, cx),
                files::Incoming::Session { name, bytes } => {
                    self.open_session(&name, bytes, runner, cx)
                }
                files::Incoming::Replay(json, reply) => runner.begin_replay(&json, reply, cx),
            }
        }
        let incoming = imports.borrow_mut().pop_front();
        if let Some(files::Incoming::Replay(json, reply)) = incoming {
            runner.begin_replay(&json, reply, cx);
        } else if let Some(incoming) = incoming {
            let (name, bytes): (&str, usize) = match &incoming {
                files::Incoming::Import(input, _) => {
                    (&input.files[0].name, files::import_bytes(input))
                }
                files::Incoming::Session { name, bytes } => (name, bytes.len()),
                files::Incoming::Replay(json, _) => ("the session", json.len()),
            };
            let what = format!("Opening {name} ({:.1} MB)…", bytes as f64 / 1e6);
            cx.status.working(what, cx.now);
            self.announced = Some(incoming);
            ctx.request_repaint();
        }
    }

    /// Opens a session file as a document of its own (its history comes with it). A file
    /// that does not replay changes nothing. In the page, the document shown is kept first
    /// (the documents panel lists it) and the autosave then follows the opened one.
    fn open_session(
        &mut self,
        name: &str,
        bytes: Vec<u8>,
        runner: &mut EditRunner,
        cx: &mut Cx<'_>,
    ) {
        let replayed = String::from_utf8(bytes)
            .map_err(|_| String::from("it is not text"))
            .and_then(|text| Editor::replay_json(&text).map_err(|e| e.to_string()));
        let editor = match replayed {
            Ok(editor) => editor,
            Err(why) => {
                let sentence = format!("Could not open {name}: {why}. Nothing changed.");
                return cx.status.refuse(sentence, cx.now);
            }
        };
        runner.cancel_gesture();
        let had_work = !cx.shared.borrow().editor.ops().is_empty();
        #[cfg(target_arch = "wasm32")]
        {
            let title = name
                .trim_end_matches(".json")
                .trim_end_matches(".sketchmesh");
            let record = cx.shared.borrow_mut().autosave_pieces();
            if let Err(why) = crate::page_store::keep_and_start(record, title) {
                let sentence =
                    format!("Did not open {name}: the work shown could not be kept ({why}).");
                return cx.status.refuse(sentence, cx.now);
            }
        }
        cx.shared.borrow_mut().open(editor);
        *cx.frame_all = true;
        let kept = match had_work {
            true => " The previous document is kept under Documents.",
            false => "",
        };
        cx.status.done(format!("Opened {name}.{kept}"), cx.now);
    }

    /// The page's documents panel: `"show"` it, or `"newDocument"` (which keeps the document
    /// shown). The desktop build has no store, and its toolbar disables both.
    pub fn page_documents(&self, method: &str, runner: &mut EditRunner, cx: &mut Cx<'_>) {
        runner.finish_edit(cx);
        #[cfg(target_arch = "wasm32")]
        if let Err(why) = crate::page_store::documents(method) {
            cx.status
                .refuse(format!("Could not open the documents: {why}"), cx.now);
        }
        #[cfg(not(target_arch = "wasm32"))]
        let _ = method;
    }

    /// Downloads the session, with the edit in progress finished.
    pub fn save_session(&self, runner: &mut EditRunner, cx: &mut Cx<'_>) {
        runner.finish_edit(cx);
        let text = cx.shared.borrow().editor.session_json();
        match files::download(text.as_bytes(), files::Download::Session) {
            Ok(name) => (cx.status).done(format!("Saved the session as {name}."), cx.now),
            Err(error) => {
                (cx.status).refuse(format!("Could not save the session: {error}"), cx.now)
            }
        }
    }

    /// Asks the user for files to import.
    pub fn import_files(&self, ctx: &egui::Context, cx: &mut Cx<'_>) {
        let imports = cx.shared.borrow().imports.clone();
        if let Err(message) = files::pick_files(&imports, ctx) {
            cx.status.refuse(message, cx.now);
        }
    }

    /// Downloads the document as .glb, with the edit in progress finished.
    pub fn export(&self, runner: &mut EditRunner, cx: &mut Cx<'_>) {
        runner.finish_edit(cx);
        let bytes = sketchmesh_core::io::write_glb(cx.shared.borrow().editor.document());
        match files::download(&bytes, files::Download::Glb) {
            Ok(name) => {
                let said = format!("Exported {name} ({:.1} MB).", bytes.len() as f64 / 1e6);
                cx.status.done(said, cx.now);
                cx.shared.borrow_mut().exports += 1;
            }
            Err(error) => (cx.status).refuse(format!("Could not export: {error}"), cx.now),
        }
    }
}
