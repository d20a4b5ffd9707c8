//! Long work off the frame: in the page, an import's files are read by a Web Worker running
//! this same wasm in its own instance (`web/worker.js`), so parsing a million triangles
//! never freezes the view; orbiting, drawing the scene and the Cancel button keep working.
//!
//! The worker runs [`import_files`], the pure part of an import (files in, models out), and
//! sends the result back as one transferable buffer (`sketchmesh_core::io::transfer`). The
//! edit in progress takes it ([`Edit::supply_import`]) and finishes as it would have on the
//! main thread: the same code on the same build, so replaying the session gives the same
//! document. The order of ops is kept: an op begun while the worker reads finishes the
//! import first, on the main thread (that one frame is long; the worker's answer is then
//! dropped).
//!
//! Natively, and when the page cannot start a worker, nothing is offloaded: [`Offload::poll`]
//! says so and the app steps the edit itself, as before.
//!
//! [`import_files`]: sketchmesh_core::document::import_files
//! [`Edit::supply_import`]: sketchmesh_core::document::Edit::supply_import

use sketchmesh_core::document::{CommandError, ImportInput};
use sketchmesh_core::io::Imported;

/// What became of the import the edit in progress needs.
#[derive(Debug)]
pub enum Poll {
    /// No worker: step the edit here.
    NotOffloaded,
    /// The worker is reading it; its answer repaints.
    Pending,
    /// The worker's answer.
    Arrived(Result<Imported, CommandError>),
}

/// One piece of work for the worker: the import of one edit.
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

    /// Sends `job`'s files to the worker the first time it is asked about them, and says
    /// whether the answer is there. While the worker runs another job, this one is not
    /// offloaded (it runs in the frame).
    pub fn poll(&mut self, job: JobId, input: &ImportInput) -> Poll {
        #[cfg(target_arch = "wasm32")]
        if let Some(worker) = self.worker.as_mut() {
            return worker.poll(job.0, input);
        }
        let _ = (job, input);
        Poll::NotOffloaded
    }

    /// `job`'s answer if it has arrived, without sending anything.
    pub fn answer(&mut self, job: JobId) -> Option<Result<Imported, CommandError>> {
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

#[cfg(target_arch = "wasm32")]
mod page {
    use std::cell::RefCell;
    use std::rc::Rc;

    use js_sys::{Array, Object, Reflect, Uint8Array};
    use sketchmesh_core::document::{CommandError, FileInput, ImportInput, import_files};
    use sketchmesh_core::io::{decode_imported, encode_imported};
    use wasm_bindgen::JsCast as _;
    use wasm_bindgen::prelude::*;

    use sketchmesh_core::io::Imported;

    use super::Poll;

    /// The script the worker runs, next to the page.
    const SCRIPT: &str = "worker.js";

    /// A job's answer: the encoded import (still in JavaScript's memory: it is copied into
    /// the wasm when the edit takes it, in the frame that lands it, not when it arrives), or
    /// the sentence of its refusal.
    type Answer = (u64, Result<Uint8Array, String>);

    /// The page's worker, its message handlers, and the job in hand.
    pub(super) struct Worker {
        worker: web_sys::Worker,
        /// The worker's answers and failures land here.
        inbox: Rc<RefCell<Option<Answer>>>,
        /// Set when the worker itself failed (its script did not load).
        broken: Rc<RefCell<bool>>,
        /// The job sent and not yet answered.
        sent: Option<u64>,
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
                    *inbox.borrow_mut() = Some(answer(&event.data()));
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
            Ok(Worker {
                worker,
                inbox,
                broken,
                sent: None,
                ctx,
                _on_message: on_message,
                _on_error: on_error,
            })
        }

        pub(super) fn poll(&mut self, id: u64, input: &ImportInput) -> Poll {
            if *self.broken.borrow() {
                return Poll::NotOffloaded;
            }
            if self.sent.is_some_and(|sent| sent != id) {
                return Poll::NotOffloaded;
            }
            if self.sent.is_none() {
                if input.files.iter().any(|f| f.data.is_none()) {
                    // The edit says which file is missing.
                    return Poll::NotOffloaded;
                }
                if let Err(why) = self.send(id, &input.files) {
                    log::warn!("Could not hand the import to the worker: {why:?}");
                    return Poll::NotOffloaded;
                }
                self.sent = Some(id);
            }
            match self.answer(id) {
                Some(answer) => Poll::Arrived(answer),
                None => Poll::Pending,
            }
        }

        pub(super) fn answer(&mut self, id: u64) -> Option<Result<Imported, CommandError>> {
            let (_, answer) = self.inbox.borrow_mut().take_if(|(job, _)| *job == id)?;
            if answer.is_err() {
                // A refusal may come from a trapped instance: the next job gets a new one.
                self.cancel(id);
            }
            self.sent = None;
            Some(answer.map_err(CommandError::Elsewhere).and_then(|bytes| {
                decode_imported(&bytes.to_vec()).map_err(|e| CommandError::Elsewhere(e.to_string()))
            }))
        }

        pub(super) fn cancel(&mut self, id: u64) {
            if self.sent != Some(id) {
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

        /// Posts `{id, names, files}`; the files are copied (the op keeps its bytes for
        /// the session).
        fn send(&self, id: u64, files: &[FileInput]) -> Result<(), JsValue> {
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

    /// A message from the worker: `{id, bytes}` or `{id, error}`.
    fn answer(data: &JsValue) -> Answer {
        let field = |name: &str| Reflect::get(data, &name.into()).unwrap_or(JsValue::UNDEFINED);
        let id = field("id").as_f64().unwrap_or(-1.0) as u64;
        let result = match field("bytes").dyn_into::<Uint8Array>() {
            Ok(bytes) => Ok(bytes),
            Err(_) => Err(field("error")
                .as_string()
                .unwrap_or_else(|| String::from("The worker gave no answer."))),
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
}
