//! Long work off the frame: in the page, a Web Worker runs this same wasm in its own
//! instance (`web/worker.js`), so reading a million triangles or computing a curve op on a
//! 40k-vertex shape never freezes the view; orbiting, drawing the scene and the Cancel
//! button keep working.
//!
//! The worker runs the pure part of an edit: an import's [`import_files`] (files in, models
//! out), a curve op's, over-sketch's or volumetric curve deformation's [`model_op`] (the
//! document's models and the op in, the changed model out), or the preview of a pull, of a
//! control curve's new shape or of an optimization while it is adjusted
//! ([`Edit::preview_elsewhere`]: the op so far in, the moved positions out; the worker keeps
//! its edit of the gesture between requests, so what it factors is factored once per
//! gesture, and a pull's region is refactored there when the peel outgrows it, not in a
//! frame). Both cross as transferable buffers
//! (`sketchmesh_core::io::transfer`); the worker keeps the models of its last op, so an op
//! sends only the models that changed since (a scan beside the shape being pulled crosses
//! once, not at every pull). The edit in progress takes the answer
//! ([`Edit::supply_import`], [`Edit::supply_model`]) and finishes as it would have on the
//! main thread: the same code on the same build, so replaying the session gives the same
//! document. The order of ops is kept: while an import runs, ops are refused (see the app's
//! `is_busy`); an op made while a curve op or a fine creation is computed waits for it (the
//! app's `waiting`), and a drag begun then is refused with a sentence (its live preview
//! needs the result, and computing it in the frame would freeze the page).
//!
//! Natively, and when the page cannot start a worker, nothing is offloaded: [`Offload::poll`]
//! says so and the app steps the edit itself, as before.
//!
//! [`import_files`]: sketchmesh_core::document::import_files
//! [`model_op`]: sketchmesh_core::document::model_op
//! [`Edit::supply_import`]: sketchmesh_core::document::Edit::supply_import
//! [`Edit::supply_model`]: sketchmesh_core::document::Edit::supply_model
//! [`Edit::preview_elsewhere`]: sketchmesh_core::document::Edit::preview_elsewhere

use std::sync::Arc;

use sketchmesh_core::document::{CommandError, ImportInput, Model, Op};
use sketchmesh_core::io::{Imported, Previewed};

/// The work of an edit the worker can do.
#[derive(Clone, Copy, Debug)]
pub enum Work<'a> {
    /// Read an import's files.
    Import(&'a ImportInput),
    /// Compute an op that changes one model, from the document's models.
    ModelOp(&'a [Arc<Model>], &'a Op),
    /// Preview a gesture's op so far (its version), from the document's models.
    Preview(&'a [Arc<Model>], &'a Op, usize),
}

/// The worker's answer to a [`Work`].
#[derive(Debug)]
pub enum Answer {
    /// What the import's files hold.
    Imported(Result<Imported, CommandError>),
    /// The changed model's index and its next version.
    /// Boxed: a model is large beside the other answers, and an answer is moved each frame.
    Model(Box<Result<(usize, Model), CommandError>>),
    /// A gesture's preview.
    Moved(Result<Previewed, CommandError>),
}

/// What became of the work the edit in progress needs.
#[derive(Debug)]
pub enum Poll {
    /// No worker: step the edit here.
    NotOffloaded,
    /// The worker is on it; its answer repaints.
    Pending,
    /// The worker's answer.
    Arrived(Answer),
}

/// One piece of work for the worker: the import or the op of one edit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct JobId(u64);

/// The page's worker and the job it runs (none natively).
#[derive(Default)]
pub struct Offload {
    #[cfg(target_arch = "wasm32")]
    worker: Option<page::Worker>,
    /// How many jobs were handed out.
    jobs: u64,
}

impl Offload {
    /// Starts the page's worker; natively there is none.
    pub fn new(ctx: &egui::Context) -> Offload {
        #[cfg(target_arch = "wasm32")]
        {
            let worker = page::Worker::spawn(ctx.clone())
                .inspect_err(|why| log::warn!("No worker, imports run in the frame: {why}"))
                .ok();
            Offload { worker, jobs: 0 }
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            let _ = ctx;
            Offload::default()
        }
    }

    /// A new job's id.
    pub fn job(&mut self) -> JobId {
        self.jobs += 1;
        JobId(self.jobs)
    }

    /// Sends `job`'s work to the worker the first time it is asked about it, and says
    /// whether the answer is there. While the worker runs another job, this one is not
    /// offloaded (it runs in the frame).
    pub fn poll(&mut self, job: JobId, work: Work<'_>) -> Poll {
        #[cfg(target_arch = "wasm32")]
        if let Some(worker) = self.worker.as_mut() {
            return worker.poll(job.0, work);
        }
        let _ = (job, work);
        Poll::NotOffloaded
    }

    /// `job`'s answer if it has arrived, without sending anything.
    pub fn answer(&mut self, job: JobId) -> Option<Answer> {
        #[cfg(target_arch = "wasm32")]
        if let Some(worker) = self.worker.as_mut() {
            return worker.answer(job.0);
        }
        let _ = job;
        None
    }

    /// Stops `job` if the worker runs it (the worker is replaced, so the cores are free at
    /// once).
    pub fn cancel(&mut self, job: JobId) {
        #[cfg(target_arch = "wasm32")]
        if let Some(worker) = self.worker.as_mut() {
            worker.cancel(job.0);
        }
        let _ = job;
    }
}

/// For each of `models`, its index among the models the worker `known`s from its last op,
/// or -1 where it must be sent.
#[cfg(any(target_arch = "wasm32", test))]
fn kept(known: &[std::sync::Weak<Model>], models: &[Arc<Model>]) -> Vec<i32> {
    (models.iter())
        .map(|model| {
            let held = known.iter().position(|k| k.as_ptr() == Arc::as_ptr(model));
            held.and_then(|j| i32::try_from(j).ok()).unwrap_or(-1)
        })
        .collect()
}

/// The models [`kept`] described: `previous` ones at the indices it gives, the `fresh` ones
/// in order where it says -1; `None` when they do not fit together.
#[cfg(any(target_arch = "wasm32", test))]
fn with_kept(previous: &[Arc<Model>], kept: &[i32], fresh: Vec<Model>) -> Option<Vec<Arc<Model>>> {
    let mut fresh = fresh.into_iter().map(Arc::new);
    let models = (kept.iter())
        .map(|&k| match usize::try_from(k) {
            Ok(j) => previous.get(j).cloned(),
            Err(_) => fresh.next(),
        })
        .collect();
    fresh.next().is_none().then_some(models).flatten()
}

#[cfg(target_arch = "wasm32")]
mod page {
    use std::cell::RefCell;
    use std::rc::Rc;
    use std::sync::{Arc, Weak};

    use js_sys::{Array, Int32Array, Object, Reflect, Uint8Array};
    use sketchmesh_core::document::{
        CommandError, Edit, FileInput, ImportInput, Model, Op, import_files,
    };
    use sketchmesh_core::io::{
        TransferError, TransferSource, UncheckedImport, decode_changed, decode_imported_unchecked,
        decode_models, decode_moved, encode_changed, encode_imported, encode_models, encode_moved,
    };
    use wasm_bindgen::JsCast as _;
    use wasm_bindgen::prelude::*;

    use super::{Answer, Poll, Work};

    /// The script the worker runs, next to the page.
    const SCRIPT: &str = "worker.js";

    /// A job's message: the encoded result (still in JavaScript's memory: it is copied into
    /// the wasm when the edit takes it, in the frame that lands it, not when it arrives), or
    /// the sentence of its refusal and whether the instance broke (it trapped, or its wasm
    /// did not load) rather than refused.
    type Message = (u64, Result<Uint8Array, (String, bool)>);

    /// What a job sent to the worker computes.
    #[derive(Clone, Copy, PartialEq, Eq)]
    enum Kind {
        Import,
        ModelOp,
        Preview,
    }

    /// The page's worker, its message handlers, and the job in hand.
    pub(super) struct Worker {
        worker: web_sys::Worker,
        /// The worker's answers and failures land here.
        inbox: Rc<RefCell<Option<Message>>>,
        /// Set when the worker itself failed (its script did not load).
        broken: Rc<RefCell<bool>>,
        /// The job sent and not yet answered, and what it computes.
        sent: Option<(u64, Kind)>,
        /// An import's answer decoded in an earlier frame, its meshes checked in the next: a
        /// million triangles' landing then takes two frames of about 35 ms, not one of 70.
        unchecked: Option<(u64, UncheckedImport)>,
        /// The models the worker keeps from its last op, in order: an op sends only the
        /// models not among them (a scan beside the shape being pulled is sent once).
        /// Weak, so that a model the document dropped is not kept alive, and its address is
        /// not reused while it is listed here.
        known: Vec<Weak<Model>>,
        ctx: egui::Context,
        _on_message: Closure<dyn FnMut(web_sys::MessageEvent)>,
        _on_error: Closure<dyn FnMut(web_sys::Event)>,
    }

    impl Worker {
        pub(super) fn spawn(ctx: egui::Context) -> Result<Worker, String> {
            let options = web_sys::WorkerOptions::new();
            options.set_type(web_sys::WorkerType::Module);
            let worker = web_sys::Worker::new_with_options(SCRIPT, &options)
                .map_err(|e| format!("{e:?}"))?;
            let inbox = Rc::new(RefCell::new(None));
            let broken = Rc::new(RefCell::new(false));
            let on_message = {
                let (inbox, ctx) = (inbox.clone(), ctx.clone());
                Closure::<dyn FnMut(_)>::new(move |event: web_sys::MessageEvent| {
                    *inbox.borrow_mut() = Some(message(&event.data()));
                    mark_answer();
                    ctx.request_repaint();
                })
            };
            let on_error = {
                let (broken, ctx) = (broken.clone(), ctx.clone());
                Closure::<dyn FnMut(_)>::new(move |_: web_sys::Event| {
                    log::warn!("The worker failed; imports run in the frame.");
                    *broken.borrow_mut() = true;
                    ctx.request_repaint();
                })
            };
            worker.set_onmessage(Some(on_message.as_ref().unchecked_ref()));
            worker.set_onerror(Some(on_error.as_ref().unchecked_ref()));
            // This instance's compiled module first: the worker shares its machine code,
            // already optimized while the page ran, instead of fetching and compiling the
            // file again.
            let module = Object::new();
            Reflect::set(&module, &"module".into(), &wasm_bindgen::module())
                .and_then(|_| worker.post_message(&module))
                .map_err(|e| format!("{e:?}"))?;
            Ok(Worker {
                worker,
                inbox,
                broken,
                sent: None,
                unchecked: None,
                known: Vec::new(),
                ctx,
                _on_message: on_message,
                _on_error: on_error,
            })
        }

        pub(super) fn poll(&mut self, id: u64, work: Work<'_>) -> Poll {
            if *self.broken.borrow() {
                return Poll::NotOffloaded;
            }
            if self.sent.is_some_and(|(sent, _)| sent != id) {
                return Poll::NotOffloaded;
            }
            if self.sent.is_none() {
                let (sent, kind) = match work {
                    // The edit says which file is missing.
                    Work::Import(input) if input.files.iter().any(|f| f.data.is_none()) => {
                        return Poll::NotOffloaded;
                    }
                    Work::Import(input) => (self.send_import(id, &input.files), Kind::Import),
                    Work::ModelOp(models, op) => {
                        (self.send_op(id, models, op, None), Kind::ModelOp)
                    }
                    Work::Preview(models, op, version) => {
                        (self.send_op(id, models, op, Some(version)), Kind::Preview)
                    }
                };
                if let Err(why) = sent {
                    log::warn!("Could not hand the work to the worker: {why:?}");
                    return Poll::NotOffloaded;
                }
                self.sent = Some((id, kind));
            }
            match self.answer(id) {
                Some(answer) => Poll::Arrived(answer),
                None => Poll::Pending,
            }
        }

        pub(super) fn answer(&mut self, id: u64) -> Option<Answer> {
            let (_, kind) = self.sent.filter(|&(sent, _)| sent == id)?;
            if let Some((_, unchecked)) = self.unchecked.take_if(|(job, _)| *job == id) {
                self.sent = None;
                return Some(Answer::Imported(unchecked.checked().map_err(unreadable)));
            }
            let (_, answer) = self.inbox.borrow_mut().take_if(|(job, _)| *job == id)?;
            if answer.as_ref().is_err_and(|&(_, broke)| broke) {
                // A trapped instance is never used again: the next job gets a new one.
                self.cancel(id);
            } else if answer.is_err() && kind != Kind::Import {
                // Which models the worker kept is not sure: the next op sends them all.
                self.known.clear();
            }
            let bytes = answer.map(JsBytes).map_err(|(why, _)| why);
            let bytes = bytes.map_err(CommandError::Elsewhere);
            self.sent = None;
            Some(match (kind, bytes) {
                (Kind::Import, Ok(bytes)) => return self.decoded(id, &bytes),
                (Kind::Import, Err(refused)) => Answer::Imported(Err(refused)),
                (Kind::ModelOp, bytes) => Answer::Model(Box::new(
                    bytes.and_then(|bytes| decode_changed(&bytes).map_err(unreadable)),
                )),
                (Kind::Preview, bytes) => {
                    Answer::Moved(bytes.and_then(|bytes| decode_moved(&bytes).map_err(unreadable)))
                }
            })
        }

        /// An import's answer with its arrays copied out now and its meshes checked in the
        /// next frame, when the edit polls again (the job stays in hand until then).
        fn decoded(&mut self, id: u64, bytes: &JsBytes) -> Option<Answer> {
            match decode_imported_unchecked(bytes) {
                Ok(unchecked) => {
                    self.sent = Some((id, Kind::Import));
                    self.unchecked = Some((id, unchecked));
                    self.ctx.request_repaint();
                    None
                }
                Err(e) => Some(Answer::Imported(Err(unreadable(e)))),
            }
        }

        pub(super) fn cancel(&mut self, id: u64) {
            if self.sent.is_none_or(|(sent, _)| sent != id) {
                return;
            }
            self.worker.set_onmessage(None);
            self.worker.set_onerror(None);
            self.worker.terminate();
            match Worker::spawn(self.ctx.clone()) {
                Ok(fresh) => *self = fresh,
                Err(why) => {
                    log::warn!("No new worker after a cancel, imports run in the frame: {why}");
                    *self.broken.borrow_mut() = true;
                }
            }
        }

        /// Posts `{id, models, kept, op, preview}`: for each of the document's models where
        /// the worker holds it already (`kept`, its index there, or -1), the others in one
        /// transferred buffer, the op as its session JSON, and, to preview it (a gesture's
        /// op so far) rather than compute it, the op's version.
        fn send_op(
            &mut self,
            id: u64,
            models: &[Arc<Model>],
            op: &Op,
            preview: Option<usize>,
        ) -> Result<(), JsValue> {
            let kept = super::kept(&self.known, models);
            let fresh: Vec<&Model> = (models.iter().zip(&kept))
                .filter(|&(_, &k)| k < 0)
                .map(|(model, _)| &**model)
                .collect();
            let bytes = Uint8Array::from(encode_models(&fresh).as_slice());
            let message = Object::new();
            Reflect::set(&message, &"id".into(), &JsValue::from_f64(id as f64))?;
            Reflect::set(&message, &"models".into(), &bytes)?;
            Reflect::set(&message, &"kept".into(), &Int32Array::from(kept.as_slice()))?;
            Reflect::set(&message, &"op".into(), &JsValue::from_str(&op.to_json()))?;
            if let Some(version) = preview {
                Reflect::set(
                    &message,
                    &"preview".into(),
                    &JsValue::from_f64(version as f64),
                )?;
            }
            self.worker
                .post_message_with_transfer(&message, &Array::of1(&bytes.buffer()))?;
            self.known = models.iter().map(Arc::downgrade).collect();
            Ok(())
        }

        /// Posts `{id, names, files}`; the files are copied (the op keeps its bytes for
        /// the session).
        fn send_import(&self, id: u64, files: &[FileInput]) -> Result<(), JsValue> {
            let (names, datas, transfer) = (Array::new(), Array::new(), Array::new());
            for file in files {
                names.push(&JsValue::from_str(&file.name));
                let bytes = file.data.as_deref().map_or(&[][..], Vec::as_slice);
                let data = Uint8Array::from(bytes);
                transfer.push(&data.buffer());
                datas.push(&data);
            }
            let message = Object::new();
            Reflect::set(&message, &"id".into(), &JsValue::from_f64(id as f64))?;
            Reflect::set(&message, &"names".into(), &names)?;
            Reflect::set(&message, &"files".into(), &datas)?;
            self.worker.post_message_with_transfer(&message, &transfer)
        }
    }

    /// Marks the arrival of the worker's last answer in the page's performance timeline
    /// ([`ANSWER_MARK`], the previous one cleared): the frames after it land the answer, the
    /// ones before it were the work's (what the browser suite tells apart).
    fn mark_answer() {
        if let Some(performance) = web_sys::window().and_then(|w| w.performance()) {
            performance.clear_marks_with_mark_name(ANSWER_MARK);
            let _ = performance.mark(ANSWER_MARK);
        }
    }

    /// The name of [`mark_answer`]'s mark.
    const ANSWER_MARK: &str = "sketchmesh:answer";

    /// The sentence for an answer that does not decode.
    fn unreadable(e: TransferError) -> CommandError {
        CommandError::Elsewhere(e.to_string())
    }

    /// A buffer from the other instance, still in JavaScript's memory: decoding copies each
    /// array out of it once, straight into its place, not the whole buffer first (54 MB for
    /// a million triangles: the landing's decode took 106–118 ms in the page, now 84–93).
    struct JsBytes(Uint8Array);

    impl TransferSource for JsBytes {
        fn size(&self) -> usize {
            self.0.length() as usize
        }

        fn copy_out(&self, at: usize, into: &mut [u8]) {
            // wasm32: a usize is a u32.
            let (from, to) = (at as u32, (at + into.len()) as u32);
            self.0.subarray(from, to).copy_to(into);
        }
    }

    /// A message from the worker: `{id, bytes}` or `{id, error}`.
    fn message(data: &JsValue) -> Message {
        let field = |name: &str| Reflect::get(data, &name.into()).unwrap_or(JsValue::UNDEFINED);
        let id = field("id").as_f64().unwrap_or(-1.0) as u64;
        let result = match field("bytes").dyn_into::<Uint8Array>() {
            Ok(bytes) => Ok(bytes),
            Err(_) => Err((
                field("error")
                    .as_string()
                    .unwrap_or_else(|| String::from("The worker gave no answer.")),
                !field("refused").is_truthy(),
            )),
        };
        (id, result)
    }

    /// The worker's entry (`web/worker.js` calls it): reads an import's files, as the
    /// editor would, into one buffer for [`decode_imported`].
    ///
    /// Errors: the import's refusal, as the sentence the editor would show.
    #[wasm_bindgen]
    pub fn read_import(names: Array, files: Array) -> Result<Uint8Array, JsValue> {
        let files = names
            .iter()
            .zip(files.iter())
            .map(|(name, data)| FileInput {
                name: name.as_string().unwrap_or_default(),
                data: Some(std::sync::Arc::new(
                    data.unchecked_into::<Uint8Array>().to_vec(),
                )),
            })
            .collect();
        let input = ImportInput {
            files,
            beside: false,
        };
        match import_files(&input) {
            Ok(imported) => Ok(Uint8Array::from(encode_imported(&imported).as_slice())),
            Err(error) => Err(JsValue::from_str(&error.to_string())),
        }
    }

    thread_local! {
        /// In the worker's instance: the models of its last op, which the next one may keep.
        static KEPT: RefCell<Vec<Arc<Model>>> = RefCell::default();
        /// In the worker's instance: its edit of the gesture it last previewed.
        static PREVIEWING: RefCell<Option<Edit>> = RefCell::default();
    }

    /// The worker's entry for an op that makes one model (`web/worker.js` calls it):
    /// computes it on the document's models, as the editor would (from the worker's edit of
    /// the op's gesture where it keeps what the op needs), into one buffer for
    /// [`decode_changed`]. The models are those of the worker's last op at the indices
    /// `kept` gives, the ones in `models` where it says -1.
    ///
    /// Errors: the op's refusal, as the sentence the editor would show.
    #[wasm_bindgen]
    pub fn run_model_op(
        models: Uint8Array,
        kept: Vec<i32>,
        op: String,
    ) -> Result<Uint8Array, JsValue> {
        let (models, op) = received(&models, &kept, &op)?;
        match Edit::finish_elsewhere(PREVIEWING.take(), models, &op) {
            Ok((index, model)) => Ok(Uint8Array::from(encode_changed(index, &model).as_slice())),
            Err(error) => Err(JsValue::from_str(&error.to_string())),
        }
    }

    /// The worker's entry for a gesture's preview (`web/worker.js` calls it): previews the
    /// op so far (`version` of it) on the document's models, going on with the edit of the
    /// last request when it is the same gesture, into one buffer for [`decode_moved`]. The
    /// models are received as [`run_model_op`]'s.
    ///
    /// Errors: the gesture's refusal, as the sentence the editor would show.
    #[wasm_bindgen]
    pub fn run_preview(
        models: Uint8Array,
        kept: Vec<i32>,
        op: String,
        version: f64,
    ) -> Result<Uint8Array, JsValue> {
        let (models, op) = received(&models, &kept, &op)?;
        let previous = PREVIEWING.take();
        match Edit::preview_elsewhere(previous, models, op) {
            Ok(edit) => {
                let bytes =
                    encode_moved(version as usize, edit.moved_model(), edit.limited_amount());
                PREVIEWING.set(Some(edit));
                Ok(Uint8Array::from(bytes.as_slice()))
            }
            Err(error) => Err(JsValue::from_str(&error.to_string())),
        }
    }

    /// The document's models (those the worker keeps at the indices `kept` gives, the ones
    /// in `models` where it says -1), now kept for the next request, and the op.
    fn received(
        models: &Uint8Array,
        kept: &[i32],
        op: &str,
    ) -> Result<(Vec<Arc<Model>>, Op), JsValue> {
        let refused = |why: String| JsValue::from_str(&why);
        let fresh = decode_models(&JsBytes(models.clone())).map_err(|e| refused(e.to_string()))?;
        let models = KEPT.with_borrow(|previous| super::with_kept(previous, kept, fresh));
        let models = models.ok_or_else(|| refused(String::from("The worker lost a model.")))?;
        KEPT.set(models.clone());
        let op: Op = serde_json::from_str(op).map_err(|e| refused(e.to_string()))?;
        Ok((models, op))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn model(size: f64) -> Arc<Model> {
        let mut editor = sketchmesh_core::document::Editor::new();
        let ellipse = (0..=60).map(|i| {
            let a = std::f64::consts::TAU * f64::from(i) / 60.0;
            [400.0 + size * a.cos(), 300.0 + 0.7 * size * a.sin(), 0.5]
        });
        let op = Op::Create(
            sketchmesh_core::document::StrokeInput {
                viewport: [800.0, 600.0],
                camera: sketchmesh_core::camera::Camera::default(),
                stroke: ellipse.collect(),
            }
            .into(),
        );
        editor.apply(op).expect("creates");
        Arc::clone(&editor.document().models[0])
    }

    /// What the page sends and what the worker rebuilds agree: kept models are the very same,
    /// changed ones cross, and a description that does not fit is refused.
    #[test]
    fn the_worker_rebuilds_the_models_the_page_describes() {
        let (a, b, c) = (model(100.0), model(150.0), model(200.0));
        let known: Vec<_> = [&a, &b].iter().map(|m| Arc::downgrade(m)).collect();
        let now = [Arc::clone(&b), Arc::clone(&c), Arc::clone(&a)];
        let kept = kept(&known, &now);
        assert_eq!(kept, [1, -1, 0]);
        let previous = [Arc::clone(&a), Arc::clone(&b)];
        let rebuilt = with_kept(&previous, &kept, vec![Model::clone(&c)]).expect("fits");
        assert!(Arc::ptr_eq(&rebuilt[0], &b) && Arc::ptr_eq(&rebuilt[2], &a));
        assert_eq!(*rebuilt[1], *c);
        assert_eq!(
            with_kept(&previous, &[2], Vec::new()),
            None,
            "an index past the kept"
        );
        assert_eq!(
            with_kept(&previous, &[-1], Vec::new()),
            None,
            "a model missing"
        );
        let extra = vec![Model::clone(&c)];
        assert_eq!(with_kept(&previous, &[0], extra), None, "one too many");
    }
}
