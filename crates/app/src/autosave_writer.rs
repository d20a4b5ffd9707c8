//! The page's autosave: the document handed to the page's store when it is due, its work
//! spread over frames so that it never shares one with a large result's landing.

use std::cell::RefCell;

use crate::autosave;
use crate::clock;
use crate::scene_view::SceneView;
use crate::shared::Shared;
use crate::status::Status;

/// How many busy frames in a row may leave the autosave to the next one: more than the app
/// spreads a large result's landing over (checked and committed; a large model's normals;
/// its arrays; their upload begun).
const AUTOSAVE_WAITS: u8 = 5;

/// The autosave readies the session's new text in steps while this lasts in a frame (ms),
/// and writes in a later frame when a step ran past it.
const AUTOSAVE_STEP_MS: f64 = 8.0;

/// How many busy frames in a row have left the autosave to the next.
#[derive(Debug, Default)]
pub struct AutosaveWriter {
    /// At most [`AUTOSAVE_WAITS`].
    waits: u8,
}

impl AutosaveWriter {
    /// Hands the document to the page's autosave when it is due, and keeps frames coming
    /// while a change waits for it; a frame already spent ([`crate::scene_view::SPREAD_AFTER_MS`]), or one of
    /// a rebuild spread over frames, leaves the write to one of the next [`AUTOSAVE_WAITS`].
    pub fn run(
        &mut self,
        ctx: &egui::Context,
        shared: &RefCell<Shared>,
        scene: &SceneView,
        status: &mut Status,
        now: f64,
    ) {
        let (revision, view, pending) = {
            let shared = shared.borrow();
            let (revision, view) = (shared.revision(), shared.camera);
            (revision, view, shared.autosave.is_pending(revision, view))
        };
        let waits = scene.is_pending() || scene.is_frame_spent(ctx);
        if pending && self.waits < AUTOSAVE_WAITS && waits {
            self.waits += 1;
            return;
        }
        self.waits = 0;
        let mut shared = shared.borrow_mut();
        if !shared.autosave.due(revision, view, now) {
            if shared.autosave.is_pending(revision, view) {
                let wait = autosave::INTERVAL.min(autosave::VIEW_SETTLE);
                ctx.request_repaint_after(std::time::Duration::from_secs_f64(wait));
            }
            return;
        }
        let started = clock::now_ms();
        let record = if shared.ready_op_texts(started, AUTOSAVE_STEP_MS) {
            shared.autosave_pieces()
        } else {
            // A long op's text took this frame: the write comes in a later one.
            ctx.request_repaint();
            None
        };
        let written = record.map(crate::page_store::write_autosave);
        // The frame's share of the write: the session's new text readied, or the record
        // handed to the page's queue (the page benchmark reads it as "autosave").
        let ms = clock::now_ms() - started;
        clock::record(&mut shared.timings.of("autosave").frame_ms, ms);
        drop(shared);
        if let Some(Err(why)) = written {
            status.refuse(format!("Could not autosave: {why}"), now);
        }
    }
}
