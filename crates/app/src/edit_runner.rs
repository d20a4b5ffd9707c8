//! The edit runner: begins a tool's op as an [`Edit`] of the [`Editor`](sketchmesh_core::document::Editor)
//! (at pointer-down when the op previews while drawn), steps it every frame within
//! [`FRAME_BUDGET_MS`], hands its long, pure part to the page's worker and lands the answer,
//! and finishes it once done: the same edit `Editor::apply` runs, with no special case for
//! any op. Imports and the page API's replays run through it too.

use std::cell::RefCell;
use std::collections::VecDeque;

use sketchmesh_core::document::{Edit, ImportInput, Op, Progress, Replay, Session};
use sketchmesh_core::model::MirrorPlane;

use crate::clock;
use crate::files;
use crate::offload::{Answer, JobId, Offload, Poll, Work};
use crate::shared::Shared;
use crate::status::Status;
use crate::tools::{Scene, ToolOutput, ToolSet};

/// Why an op is refused while an import or a replay runs (see [`EditRunner::is_busy`]).
const BUSY: &str = "Wait for the import or replay in progress to land, or cancel it (Esc).";

/// The sentence for a drag begun while the worker computes the last change.
const COMPUTING: &str = "Wait for the change being computed to land, or cancel it (Esc).";

/// How long an op may run in the page's worker before the progress line says so, in seconds.
const PROGRESS_AFTER_S: f64 = 0.25;

/// How long the steps of the edit in progress may run in one frame, in ms. At least one step
/// runs every frame, whatever it costs (a factorization can take longer).
pub const FRAME_BUDGET_MS: f64 = 12.0;

/// What the runner works with, lent by the app for one call.
pub struct Cx<'a> {
    /// The document and its history, the camera and the edits' timings.
    pub shared: &'a RefCell<Shared>,
    /// The tools: told when the edit of their gesture is refused or steps, asked what to
    /// say once an edit lands.
    pub tools: &'a mut ToolSet,
    /// The status line.
    pub status: &'a mut Status,
    /// Frame everything after the view's next rebuild (set when an import lands or a
    /// session opens).
    pub frame_all: &'a mut bool,
    /// The frame's clock, in seconds.
    pub now: f64,
}

/// The edit in progress and the work around it: the worker's job, the ops waiting for it,
/// an import or a replay running off the frame.
#[derive(Default)]
pub struct EditRunner {
    /// The edit in progress: begun from a tool's op, stepped every frame, finished when done.
    edit: Option<Edit>,
    /// The page's worker, which reads imports and computes long ops off the frame.
    offload: Offload,
    /// The import the edit in progress is, if it is one.
    import: Option<ImportInProgress>,
    /// The worker's job for the long part of the edit in progress (an import's read, a
    /// curve op's result), and when it was handed over (seconds).
    worker_job: Option<(JobId, f64)>,
    /// Ops made while the worker computes the edit in progress (a stroke drawn while a
    /// fine shape is created), in order: begun one at a time once it lands, so that no
    /// frame has to finish the worker's op itself.
    waiting: VecDeque<Op>,
    /// A session being replayed over frames (the page API's `replay`), to replace the
    /// document once it is through.
    replay: Option<ReplayInProgress>,
    /// How many edits were begun: tells apart the documents of two edits of equal revision.
    edits_begun: u64,
    /// Whether the edit in progress was begun this frame: it is drawn once before its first
    /// step, so what it shows at once (a creation's seed) is seen at once.
    is_edit_new: bool,
    /// Where the time of the edit in progress goes.
    edit_clock: EditClock,
    /// The plane the edit in progress mirrors about, when it was made with symmetry on: the
    /// view then shows its preview on both sides.
    edit_mirror: Option<MirrorPlane>,
}

impl EditRunner {
    /// A runner whose long work goes to the page's worker (see [`Offload::new`]).
    pub fn new(ctx: &egui::Context) -> Self {
        EditRunner {
            offload: Offload::new(ctx),
            ..Self::default()
        }
    }

    /// The edit in progress, if any.
    pub fn edit(&self) -> Option<&Edit> {
        self.edit.as_ref()
    }

    /// The plane the edit in progress mirrors about, if it was made with symmetry on.
    pub fn edit_mirror(&self) -> Option<MirrorPlane> {
        self.edit.as_ref().and(self.edit_mirror)
    }

    /// How many edits were begun.
    pub fn edits_begun(&self) -> u64 {
        self.edits_begun
    }

    /// Whether the worker computes the edit in progress's op.
    pub fn is_computing(&self) -> bool {
        self.worker_job.is_some()
    }

    /// Ops waiting for the worker's edit to land, in order.
    pub fn waiting(&self) -> impl Iterator<Item = &Op> {
        self.waiting.iter()
    }

    /// Applies what a tool produced to the edit; what is not for the edit (the view, the
    /// backdrop, playing) is given back.
    pub fn take_output(&mut self, output: ToolOutput, cx: &mut Cx<'_>) -> Option<ToolOutput> {
        let gesture = self.edit.as_mut().filter(|edit| edit.is_gesture());
        match output {
            ToolOutput::None => {}
            ToolOutput::Commit(op) => self.begin_made(op, false, cx),
            ToolOutput::CommitAsMade(op) => self.begin(op, false, cx),
            ToolOutput::CommitAll(ops) => {
                for op in ops {
                    self.begin_made(op, false, cx);
                }
            }
            ToolOutput::Begin(op) => self.begin_made(op, true, cx),
            ToolOutput::Extend(sample) => {
                if let Some(edit) = gesture {
                    edit.extend(sample);
                }
            }
            ToolOutput::End(sample) => {
                if let Some(edit) = gesture {
                    edit.extend(sample);
                    edit.end_gesture();
                }
            }
            ToolOutput::Revise(op) => match gesture {
                Some(edit) if edit.op().name() == op.name() => edit.revise(op),
                // The preview was committed meanwhile (another edit began): open a new one.
                _ => self.begin_made(op, true, cx),
            },
            ToolOutput::Finish => {
                if let Some(edit) = gesture {
                    edit.end_gesture();
                }
            }
            ToolOutput::FinishWith(op) => match gesture {
                Some(edit) if edit.op().name() == op.name() => {
                    edit.revise(op);
                    edit.end_gesture();
                }
                _ => self.begin_made(op, false, cx),
            },
            ToolOutput::Cancel => self.cancel_gesture(),
            ToolOutput::Refused(message) => cx.status.refuse(message, cx.now),
            other @ (ToolOutput::Face { .. } | ToolOutput::Backdrop(_) | ToolOutput::Play(_)) => {
                return Some(other);
            }
        }
        None
    }

    /// Begins `op` (as a gesture when its stroke is still being drawn) after finishing the
    /// edit in progress, so ops are logged in the order they were made; this frame's steps
    /// run it. While the worker computes the edit in progress, an op that is not a gesture
    /// waits for it instead ([`EditRunner::begin_waiting`]); a gesture is refused with a
    /// sentence, as its live preview needs the result: finishing the worker's op here would
    /// freeze the page for as long as the worker takes, and the gesture would come before
    /// the ops waiting for it. A refusal becomes a status message; nothing changes then.
    pub fn begin(&mut self, op: Op, is_gesture: bool, cx: &mut Cx<'_>) {
        if self.is_busy() {
            cx.status.working(String::from(BUSY), cx.now);
            return;
        }
        let behind_the_worker = self.worker_job.is_some() || !self.waiting.is_empty();
        if behind_the_worker && is_gesture {
            cx.tools.gesture_refused();
            cx.status.working(String::from(COMPUTING), cx.now);
            return;
        }
        if behind_the_worker {
            self.waiting.push_back(op);
            return;
        }
        self.begin_now(op, is_gesture, cx);
    }

    /// Begins an op the user just made (a tool's, the context menu's) as
    /// [`EditRunner::begin`] does: with the Symmetry switch on, made with symmetry on about
    /// the document's plane (the default one, `x = 0`, until an op or a file sets another).
    /// Ops that cannot mirror (undo, redo, import, symmetrize) stay as they are.
    pub fn begin_made(&mut self, op: Op, is_gesture: bool, cx: &mut Cx<'_>) {
        let op = {
            let shared = cx.shared.borrow();
            match shared.symmetry.is_on {
                true => op.mirrored(shared.editor.document().symmetry.unwrap_or_default()),
                false => op,
            }
        };
        self.begin(op, is_gesture, cx);
    }

    /// Begins the next op that waited for the worker, once the edit it waited for is over.
    fn begin_waiting(&mut self, cx: &mut Cx<'_>) {
        if self.edit.is_none()
            && let Some(op) = self.waiting.pop_front()
        {
            self.begin_now(op, false, cx);
        }
    }

    /// [`EditRunner::begin`], without waiting for the worker.
    fn begin_now(&mut self, op: Op, is_gesture: bool, cx: &mut Cx<'_>) {
        self.finish_edit(cx);
        let name = op.name();
        let mirror = match &op {
            Op::Mirrored(mirrored) => Some(mirrored.plane),
            _ => None,
        };
        let started = clock::now_ms();
        let begun = {
            let editor = &cx.shared.borrow().editor;
            if is_gesture {
                editor.begin_gesture(op)
            } else {
                editor.begin(op)
            }
        };
        let ms = clock::now_ms() - started;
        match begun {
            Ok(edit) => {
                let timings = &mut cx.shared.borrow_mut().timings;
                self.edit_clock = EditClock::begun(name, ms, is_gesture, timings);
                self.edit = Some(edit);
                self.edit_mirror = mirror;
                self.edits_begun += 1;
                self.is_edit_new = true;
            }
            Err(e) => cx.status.refuse(e.to_string(), cx.now),
        }
    }

    /// Whether an import or a replay runs off the frame. The next op must apply to its
    /// result, as it will in the session: begun now, it would finish the import here, in one
    /// long frame, or be lost under the replayed document. So it is refused (the view still
    /// orbits, and Cancel, Esc or undo stops the work).
    pub fn is_busy(&self) -> bool {
        self.import.is_some() || self.replay.is_some()
    }

    /// Runs the steps of the edit in progress while [`FRAME_BUDGET_MS`] lasts (at least
    /// one; none in the frame it was begun in), and finishes it once done.
    pub fn step_edit(&mut self, ctx: &egui::Context, cx: &mut Cx<'_>) {
        let now = cx.now;
        self.begin_waiting(cx);
        if !self.waiting.is_empty() && self.worker_job.is_none() {
            ctx.request_repaint();
        }
        let Some(edit) = self.edit.as_mut() else {
            return;
        };
        if std::mem::take(&mut self.is_edit_new) {
            ctx.request_repaint();
            return;
        }
        let was_gesture = edit.is_gesture();
        let started = clock::now_ms();
        let stepped = loop {
            match hand_over(&mut self.offload, &mut self.worker_job, edit, now) {
                HandOver::Waiting => break None,
                HandOver::Landed { seconds } => {
                    let timings = &mut cx.shared.borrow_mut().timings;
                    self.edit_clock.elsewhere(1000.0 * seconds, timings);
                }
                HandOver::Previewed { seconds } => {
                    let timings = &mut cx.shared.borrow_mut().timings;
                    self.edit_clock.previewed(1000.0 * seconds, timings);
                    // The next preview, or the committed result, goes to the worker too.
                    continue;
                }
                HandOver::Here => {}
            }
            match edit.step() {
                Ok(Progress::Working) if clock::now_ms() - started < FRAME_BUDGET_MS => {}
                other => break Some(other),
            }
        };
        let ms = clock::now_ms() - started;
        self.edit_clock
            .stepped(ms, was_gesture, &mut cx.shared.borrow_mut().timings);
        cx.tools.edit_stepped(edit);
        // With the worker: its answer repaints; one repaint shows the progress line once it
        // is due, and its ring then ticks. Nothing else repaints: every frame draws the whole
        // scene, which costs the worker its core on a machine without a GPU.
        let Some(stepped) = stepped else {
            if let Some((_, since)) = self.worker_job
                && since + PROGRESS_AFTER_S > now
            {
                let due = since + PROGRESS_AFTER_S - now;
                ctx.request_repaint_after(std::time::Duration::from_secs_f64(due));
            }
            return;
        };
        match stepped {
            Ok(Progress::Done) => self.finish_edit(cx),
            // More work, or a gesture whose next samples may come from the page's listeners.
            Ok(Progress::Working | Progress::Waiting) => ctx.request_repaint(),
            Err(e) => {
                self.edit = None;
                if was_gesture {
                    cx.tools.gesture_refused();
                }
                cx.status.refuse(e.to_string(), cx.now);
                self.settle_import(Err(e.to_string()), cx);
            }
        }
    }

    /// Before a new gesture: it acts on the document with the edit in progress committed (a
    /// shape still refining is finished first), unless the worker computes that edit. Then
    /// the gesture sees the document as shown, and what it makes waits for the worker
    /// ([`EditRunner::begin`]): a frame that finished the worker's op would stall for as long
    /// as the worker takes (seconds for a 40k shape), and an orbit or a stroke must not.
    pub fn finish_edit_unless_offloaded(&mut self, cx: &mut Cx<'_>) {
        if self.worker_job.is_none() {
            self.finish_edit(cx);
        }
    }

    /// Finishes the edit in progress, if any (closing its gesture and running the steps it
    /// has left); a refusal becomes a status message.
    pub fn finish_edit(&mut self, cx: &mut Cx<'_>) {
        let Some(mut edit) = self.edit.take() else {
            return;
        };
        // The worker's answer, if it is there, lands now; else the edit is finished here.
        if let Some((job, _)) = self.worker_job.take() {
            if let Some(answer) = self.offload.answer(job) {
                supply(&mut edit, answer);
            }
            self.offload.cancel(job);
        }
        let before = cx.shared.borrow().editor.document().clone();
        let started = clock::now_ms();
        let result = edit.finish(&mut cx.shared.borrow_mut().editor);
        let ms = clock::now_ms() - started;
        self.edit_clock
            .finished(ms, &mut cx.shared.borrow_mut().timings);
        if self.import.is_some() {
            let settled = result.as_ref().map(|_| ()).map_err(ToString::to_string);
            // Everything, the models there before included: framing only the new one would
            // leave the others as a clipped close-up.
            *cx.frame_all |= settled.is_ok();
            self.settle_import(settled, cx);
        }
        match result {
            Err(e) => cx.status.refuse(e.to_string(), cx.now),
            Ok(()) => {
                // The op just logged is the edit's.
                let shared = cx.shared.borrow();
                let (editor, tools) = (&shared.editor, &cx.tools);
                let report = (editor.ops().last())
                    .and_then(|op| tools.report(op, &before, editor.document()));
                drop(shared);
                if let Some(report) = report {
                    cx.status.done(report, cx.now);
                }
            }
        }
    }

    /// What the progress line says while the worker computes the edit's op, once it has
    /// taken [`PROGRESS_AFTER_S`] (a quick one shows no line that flickers).
    fn computing(&self, now: f64) -> Option<String> {
        let (_, since) = self.worker_job?;
        let edit = self
            .edit
            .as_ref()
            .filter(|e| e.model_op_to_run().is_some())?;
        let name = edit.op().title();
        (now - since >= PROGRESS_AFTER_S).then(|| format!("Computing the {name}…"))
    }

    /// Drops the edit in progress if it is an import, or if the worker computes its op:
    /// nothing changes.
    pub fn cancel_offloaded(&mut self, cx: &mut Cx<'_>) {
        let job = self.worker_job.take();
        if let Some((job, _)) = job {
            self.offload.cancel(job);
        }
        if self.import.is_some() {
            self.edit = None;
            self.settle_import(Err(String::from("The import was cancelled.")), cx);
        } else if let Some(edit) = self.edit.take_if(|_| job.is_some()) {
            let said = format!("The {} was cancelled.", edit.op().title());
            cx.status.say(crate::status::Tone::Info, said, cx.now);
        }
    }

    /// Ends the import in progress: says how it went, and tells who waits for it.
    fn settle_import(&mut self, result: Result<(), String>, cx: &mut Cx<'_>) {
        let Some(import) = self.import.take() else {
            return;
        };
        if result.is_ok() {
            // An import is rarely symmetric: with the switch on, every edit of it would be
            // refused (see [`crate::shared::SymmetrySwitch`]).
            cx.shared.borrow_mut().symmetry.is_on = false;
        }
        match &result {
            Ok(()) => cx.status.done(format!("Imported {}.", import.name), cx.now),
            Err(why) => cx.status.refuse(why.clone(), cx.now),
        }
        import.reply.send(result);
    }

    /// Drops the edit in progress if its gesture is still going on: nothing changes.
    pub fn cancel_gesture(&mut self) {
        if let Some(edit) = self.edit.take_if(|edit| edit.is_gesture()) {
            edit.cancel();
            // The worker's job can only be the gesture's preview.
            if let Some((job, _)) = self.worker_job.take() {
                self.offload.cancel(job);
            }
        }
    }

    /// Begins replaying a session (the page API's `replay`): parsed now, its ops applied over
    /// the next frames (an import's files read by the worker), the document replaced once
    /// it is through. Bad JSON or a refused op changes nothing.
    pub fn begin_replay(&mut self, json: &str, reply: files::Reply, cx: &mut Cx<'_>) {
        match Session::from_json(json) {
            Ok(session) => {
                self.replay = Some(ReplayInProgress {
                    replay: Replay::new(session.ops),
                    job: None,
                    reply,
                });
            }
            Err(e) => {
                cx.status.refuse(e.to_string(), cx.now);
                reply.send(Err(e.to_string()));
            }
        }
    }

    /// Runs the replay's steps while [`FRAME_BUDGET_MS`] lasts, and opens its document once
    /// it is through; whether it did (the app then follows the page at once: a replay the
    /// page starts as soon as this one's Promise resolves would be taken for the old
    /// document's, and cancelled).
    pub fn step_replay(&mut self, ctx: &egui::Context, cx: &mut Cx<'_>) -> bool {
        let now = cx.now;
        let Some(replaying) = self.replay.as_mut() else {
            return false;
        };
        let started = clock::now_ms();
        let stepped = loop {
            // An import's read and a curve op's or fine creation's result: in the worker,
            // as when the user makes them.
            if let Some(edit) = replaying.replay.edit_mut()
                && let HandOver::Waiting =
                    hand_over(&mut self.offload, &mut replaying.job, edit, now)
            {
                break Ok(false);
            }
            match replaying.replay.step() {
                Ok(Progress::Done) => break Ok(true),
                Ok(_) if clock::now_ms() - started < FRAME_BUDGET_MS => {}
                Ok(_) => {
                    ctx.request_repaint();
                    break Ok(false);
                }
                Err(e) => break Err(e),
            }
        };
        match stepped {
            Ok(false) => false,
            Ok(true) => {
                if let Some(replaying) = self.replay.take() {
                    cx.shared.borrow_mut().open(replaying.replay.into_editor());
                    replaying.reply.send(Ok(()));
                }
                ctx.request_repaint();
                true
            }
            Err(e) => {
                if let Some(replaying) = self.replay.take() {
                    replaying.reply.send(Err(e.to_string()));
                }
                cx.status
                    .refuse(format!("Could not replay the session: {e}"), cx.now);
                false
            }
        }
    }

    /// Drops the replay in progress: the document stays as it was.
    pub fn cancel_replay(&mut self, cx: &mut Cx<'_>) {
        let Some(replaying) = self.replay.take() else {
            return;
        };
        if let Some((job, _)) = replaying.job {
            self.offload.cancel(job);
        }
        let why = String::from("The replay was cancelled.");
        cx.status.refuse(why.clone(), cx.now);
        replaying.reply.send(Err(why));
    }

    /// Begins importing: in the page the worker reads the files while the view keeps
    /// drawing, with a progress line and Cancel; the import lands as one undoable step.
    pub fn begin_import(&mut self, input: ImportInput, reply: files::Reply, cx: &mut Cx<'_>) {
        let name = input.files[0].name.clone();
        let bytes = files::import_bytes(&input);
        cx.status.clear();
        self.begin(Op::Import(input), false, cx);
        if self.edit.is_none() {
            let why = cx.status.message().map(str::to_owned);
            return reply.send(Err(why.unwrap_or_default()));
        }
        self.import = Some(ImportInProgress {
            name,
            megabytes: bytes as f64 / 1e6,
            reply,
        });
    }

    /// Undoes the last op, once the edit in progress is finished (see [`EditRunner::begin`]).
    pub fn undo(&mut self, cx: &mut Cx<'_>) {
        self.begin(Op::Undo, false, cx);
    }

    /// Redoes the last op undone (see [`EditRunner::begin`]).
    pub fn redo(&mut self, cx: &mut Cx<'_>) {
        self.begin(Op::Redo, false, cx);
    }

    /// What the tools draw over from: `shared`'s document as the edit in progress shows it,
    /// in `viewport`.
    pub fn scene<'a>(&'a self, shared: &'a Shared, viewport: egui::Rect) -> Scene<'a> {
        let doc = shared.editor.document();
        Scene {
            shown: self.edit().map_or(doc, Edit::document),
            doc,
            edit: self.edit(),
            computing: self.is_computing(),
            camera: shared.camera.camera(),
            viewport,
            played: &[],
            symmetry: None,
        }
    }

    /// What the progress line says while work runs off the frame: an import, a replay, the
    /// worker's op.
    pub fn progress(&self, now: f64) -> Option<String> {
        match (&self.import, &self.replay) {
            (Some(import), _) => Some(format!(
                "Importing {} ({:.1} MB)…",
                import.name, import.megabytes
            )),
            (None, Some(replaying)) => {
                let (done, of) = replaying.replay.done_of();
                Some(format!(
                    "Replaying the session: op {} of {of}…",
                    (done + 1).min(of)
                ))
            }
            (None, None) => self.computing(now),
        }
    }

    /// Drops everything in progress: the document it was for was replaced.
    pub fn drop_all(&mut self, cx: &mut Cx<'_>) {
        self.cancel_offloaded(cx);
        // A replay still running would replace the document opened meanwhile.
        self.cancel_replay(cx);
        self.cancel_gesture();
        self.edit = None;
        self.waiting.clear();
    }
}

/// What became of the long part of an edit, see [`hand_over`].
enum HandOver {
    /// Nothing for the worker: step the edit here.
    Here,
    /// The worker is on it: nothing to step here meanwhile.
    Waiting,
    /// The worker's answer landed in the edit, this long after it was handed over.
    Landed { seconds: f64 },
    /// The worker's preview of a gesture landed in the edit, this long after it was asked.
    Previewed { seconds: f64 },
}

/// Hands the long, pure part of `edit` (an import's read, a curve op's result, a drag's
/// preview) to the page's worker as `job`, or lands the worker's answer in it. A job in
/// hand is polled whatever the edit needs now: a preview asked for while the pointer was
/// down lands (and shows) before the committed result is asked for.
fn hand_over(
    offload: &mut Offload,
    job: &mut Option<(JobId, f64)>,
    edit: &mut Edit,
    now: f64,
) -> HandOver {
    let work = match (edit.import_to_read(), edit.model_op_to_run()) {
        (Some(input), _) => Work::Import(input),
        (None, Some((models, op))) => Work::ModelOp(models, op),
        (None, None) => match edit.preview_to_run() {
            Some((models, op, version)) => Work::Preview(models, op, version),
            // A preview asked for while the pointer was down, polled (what a job computes
            // is sent once, the first time it is polled).
            None if job.is_some() => Work::Preview(&[], edit.op(), edit.version()),
            None => return HandOver::Here,
        },
    };
    let (id, since) = *job.get_or_insert_with(|| (offload.job(), now));
    match offload.poll(id, work) {
        Poll::Pending => HandOver::Waiting,
        Poll::Arrived(Answer::Moved(moved)) => {
            *job = None;
            edit.supply_preview(moved);
            HandOver::Previewed {
                seconds: now - since,
            }
        }
        Poll::Arrived(answer) => {
            *job = None;
            supply(edit, answer);
            HandOver::Landed {
                seconds: now - since,
            }
        }
        Poll::NotOffloaded => {
            *job = None;
            // Should the worker fail in the middle of a drag, the frames preview it again.
            edit.preview_here();
            HandOver::Here
        }
    }
}

/// Lands the worker's answer in the edit it was computed for.
fn supply(edit: &mut Edit, answer: Answer) {
    match answer {
        Answer::Imported(imported) => edit.supply_import(imported),
        Answer::Model(changed) => edit.supply_model(*changed),
        Answer::Moved(moved) => edit.supply_preview(moved),
    }
}

/// An import being read (in the page, by the worker): what the progress line says, and who
/// waits for it to land.
struct ImportInProgress {
    name: String,
    megabytes: f64,
    reply: files::Reply,
}

/// A session being replayed over frames: its steps, the worker's job for the op in progress
/// (as [`hand_over`] keeps it), and who waits for the result.
struct ReplayInProgress {
    replay: Replay,
    job: Option<(JobId, f64)>,
    reply: files::Reply,
}

/// The costs of the edit in progress, recorded in [`clock::Timings`] under its op's name as
/// they become known (see [`clock::EditTimings`]).
#[derive(Debug, Default)]
struct EditClock {
    name: &'static str,
    /// The begin and the steps of its first frame, while the gesture goes on; `None` once
    /// recorded.
    begin_ms: Option<f64>,
    /// The work since the input was complete, so far.
    finish_ms: f64,
}

impl EditClock {
    /// The clock of an edit of `name` whose begin took `ms`.
    fn begun(name: &'static str, ms: f64, is_gesture: bool, timings: &mut clock::Timings) -> Self {
        let mut edit_clock = EditClock {
            name,
            begin_ms: Some(ms),
            finish_ms: 0.0,
        };
        if !is_gesture {
            edit_clock.record_begin(timings);
        }
        edit_clock
    }

    fn record_begin(&mut self, timings: &mut clock::Timings) {
        if let Some(ms) = self.begin_ms.take() {
            clock::record(&mut timings.of(self.name).begin_ms, ms);
        }
    }

    /// One frame's steps, taken while the gesture went on or after.
    fn stepped(&mut self, ms: f64, was_gesture: bool, timings: &mut clock::Timings) {
        match (&mut self.begin_ms, was_gesture) {
            (Some(begin_ms), true) => {
                *begin_ms += ms;
                self.record_begin(timings);
            }
            (None, true) => clock::record(&mut timings.of(self.name).frame_ms, ms),
            (_, false) => {
                self.record_begin(timings);
                self.finish_ms += ms;
            }
        }
    }

    /// The worker's part, which took `ms` while the page drew.
    fn elsewhere(&self, ms: f64, timings: &mut clock::Timings) {
        clock::record(&mut timings.of(self.name).elsewhere_ms, ms);
    }

    /// A preview the worker computed, which took `ms` (asked to shown) while the page drew.
    fn previewed(&self, ms: f64, timings: &mut clock::Timings) {
        clock::record(&mut timings.of(self.name).preview_ms, ms);
    }

    /// The finish, which took `ms`.
    fn finished(&mut self, ms: f64, timings: &mut clock::Timings) {
        self.record_begin(timings);
        clock::record(&mut timings.of(self.name).finish_ms, self.finish_ms + ms);
    }
}
