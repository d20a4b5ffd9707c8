//! Web shell: the `start` entry point and the page API, `window.sketchmesh`.
//!
//! The page API lets pages embed and automate Sketchmesh (and lets the browser tests
//! check real outcomes). Calls that fail throw a JavaScript `Error` with a plain sentence
//! and leave the document as it was.

use std::cell::RefCell;
use std::rc::Rc;

use js_sys::{Object, Reflect, Uint8Array};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::app::SketchApp;
use crate::autosave::Record;
use crate::input::web_pointer::WebPointer;
use crate::page_store::write_autosave;
use crate::shared::Shared;

/// Starts Sketchmesh on the canvas with id `canvas_id`.
#[wasm_bindgen]
pub async fn start(canvas_id: String) -> Result<(), JsValue> {
    let _ = eframe::WebLogger::init(log::LevelFilter::Info);
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or_else(|| JsValue::from_str("No document to run in."))?;
    let canvas = document
        .get_element_by_id(&canvas_id)
        .ok_or_else(|| JsValue::from_str(&format!("No element with id {canvas_id:?}.")))?
        .dyn_into::<web_sys::HtmlCanvasElement>()?;
    let listen_on = canvas.clone();
    // eframe's panic hook logs a panic and stops the app; ours, after it, tells the page.
    let runner = eframe::WebRunner::new();
    tell_the_page_on_panic();
    runner
        .start(
            canvas,
            eframe::WebOptions::default(),
            Box::new(move |cc| {
                let mut app = SketchApp::new(cc);
                app.set_coarse_pointer(is_pointer_coarse());
                app.start_intro(crate::page_store::intro_seen());
                let ctx = cc.egui_ctx.clone();
                let pointer =
                    WebPointer::listen(&listen_on, app.pointer.web_samples.clone(), move || {
                        ctx.request_repaint()
                    })
                    .map_err(|e| format!("Could not listen to pointer events: {e:?}"))?;
                // The listeners live as long as the page.
                std::mem::forget(pointer);
                if let Some(on) = crate::page_store::symmetry_for_new() {
                    app.shared().borrow_mut().symmetry.choose(on);
                }
                install_page_api(app.shared(), cc.egui_ctx.clone())
                    .map_err(|e| format!("Could not install window.sketchmesh: {e:?}"))?;
                Ok(Box::new(app))
            }),
        )
        .await
}

/// Whether the page's main pointer is coarse (a finger), as CSS's `(pointer: coarse)` says.
fn is_pointer_coarse() -> bool {
    web_sys::window()
        .and_then(|w| w.match_media("(pointer: coarse)").ok().flatten())
        .is_some_and(|query| query.matches())
}

/// Chains a panic hook after the installed one (eframe's, which logs the panic and stops the
/// app) that hands the page a sentence (`window.sketchmeshPanicked`, in `index.html`): it
/// shows it with "Copy bug report" and "Reload", and writes no more autosaves, so the record
/// of the last committed op is what the reload restores.
fn tell_the_page_on_panic() {
    let logged = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        logged(info);
        let what = info.payload_as_str().unwrap_or("an unknown failure");
        let place = info.location().map(ToString::to_string).unwrap_or_default();
        let sentence = format!(
            "Sketchmesh {} stopped because of a bug: {what} (at {place}).",
            env!("CARGO_PKG_VERSION")
        );
        let notice = web_sys::window()
            .and_then(|window| Reflect::get(&window, &JsValue::from_str("sketchmeshPanicked")).ok())
            .and_then(|notice| notice.dyn_into::<js_sys::Function>().ok());
        if let Some(notice) = notice {
            let _ = notice.call1(&JsValue::NULL, &JsValue::from_str(&sentence));
        }
    }));
}

/// The status line as the page API gives it: `{text, kind}`.
#[derive(serde::Serialize)]
struct StatusJs<'a> {
    text: &'a str,
    kind: crate::status::Tone,
}

/// The introduction as the page API gives it: `{step, skip: [x, y]}`.
#[derive(serde::Serialize)]
struct IntroJs {
    step: u8,
    skip: Option<[f32; 2]>,
}

/// The Symmetry switch as the page API gives it: `{on, forNew, plane: [nx, ny, nz, d]}`,
/// the plane the document's mirrored ops use.
#[derive(serde::Serialize)]
#[serde(rename_all = "camelCase")]
struct SymmetryJs {
    on: bool,
    for_new: bool,
    plane: sketchmesh_core::model::MirrorPlane,
}

fn install_page_api(shared: Rc<RefCell<Shared>>, ctx: egui::Context) -> Result<(), JsValue> {
    let api = Object::new();
    let set = |name: &str, f: JsValue| Reflect::set(&api, &JsValue::from_str(name), &f).map(|_| ());

    let s = shared.clone();
    set(
        "stats",
        getter(move || json(&s.borrow().editor.document().stats())),
    )?;
    let s = shared.clone();
    set(
        "session",
        getter(move || Ok(JsValue::from_str(&s.borrow().editor.session_json()))),
    )?;
    let s = shared.clone();
    set("camera", getter(move || json(&s.borrow().camera.camera())))?;
    let s = shared.clone();
    set("tool", getter(move || json(&s.borrow().mode)))?;
    let s = shared.clone();
    set(
        "bounds",
        getter(move || {
            let shared = s.borrow();
            let boxes: Vec<_> = (shared.editor.document().models.iter())
                .map(|m| {
                    m.mesh
                        .bounding_box()
                        .map(|(lo, hi)| [lo.to_array(), hi.to_array()])
                })
                .collect();
            json(&boxes)
        }),
    )?;
    let s = shared.clone();
    set(
        "backend",
        getter(move || Ok(JsValue::from_str(&s.borrow().backend))),
    )?;
    let s = shared.clone();
    set(
        "exportGlb",
        getter(move || {
            Ok(Uint8Array::from(
                sketchmesh_core::io::write_glb(s.borrow().editor.document()).as_slice(),
            )
            .into())
        }),
    )?;
    let s = shared.clone();
    set("notes", getter(move || json(&s.borrow().notes.shown)))?;
    let s = shared.clone();
    set("progress", getter(move || json(&s.borrow().progress)))?;
    let c = ctx.clone();
    set(
        "layout",
        getter(move || json(&crate::panels::readout::read(&c))),
    )?;
    let s = shared.clone();
    set(
        "hint",
        getter(move || Ok(JsValue::from_str(&s.borrow().hint))),
    )?;
    let s = shared.clone();
    set(
        "status",
        getter(move || {
            let shared = s.borrow();
            let said = (shared.status.as_ref()).map(|(text, kind)| StatusJs { text, kind: *kind });
            json(&said)
        }),
    )?;
    let s = shared.clone();
    set(
        "intro",
        getter(move || {
            let intro = s.borrow().intro.map(|(step, skip)| IntroJs {
                step,
                skip: skip.map(|at| [at.x, at.y]),
            });
            json(&intro)
        }),
    )?;
    let s = shared.clone();
    set(
        "opCount",
        getter(move || Ok(JsValue::from(s.borrow().editor.ops().len() as u32))),
    )?;
    let s = shared.clone();
    set(
        "symmetry",
        getter(move || {
            let shared = s.borrow();
            let plane = shared.editor.document().symmetry.unwrap_or_default();
            json(&SymmetryJs {
                on: shared.symmetry.is_on,
                for_new: shared.symmetry.for_new,
                plane,
            })
        }),
    )?;
    let (s, c) = (shared.clone(), ctx.clone());
    set(
        "setSymmetry",
        Closure::<dyn Fn(bool)>::new(move |on: bool| {
            s.borrow_mut().choose_symmetry(on);
            c.request_repaint();
        })
        .into_js_value(),
    )?;
    let s = shared.clone();
    set(
        "timings",
        getter(move || json(&s.borrow_mut().timings.take())),
    )?;
    let (s, c) = (shared.clone(), ctx.clone());
    set(
        "replay",
        Closure::<dyn Fn(String) -> js_sys::Promise>::new(move |session: String| {
            let imports = s.borrow().imports.clone();
            c.request_repaint();
            let mut session = Some(session);
            promise_of(&mut |reply| {
                if let Some(session) = session.take() {
                    let incoming = crate::files::Incoming::Replay(session, reply);
                    imports.borrow_mut().push_back(incoming);
                }
            })
        })
        .into_js_value(),
    )?;
    let (s, c) = (shared.clone(), ctx.clone());
    set(
        "playMaking",
        Closure::<dyn Fn(String, JsValue) -> js_sys::Promise>::new(
            move |session: String, captions: JsValue| {
                let captions = match captions.is_array() {
                    true => js_sys::Array::from(&captions)
                        .iter()
                        .map(|c| c.as_string().unwrap_or_default())
                        .collect(),
                    false => Vec::new(),
                };
                let asked = (session, captions);
                let mut asked = Some(asked);
                let s = s.clone();
                c.request_repaint();
                promise_of(&mut |reply| {
                    if let Some((session, captions)) = asked.take() {
                        s.borrow_mut().making_asked = Some((session, captions, reply));
                    }
                })
            },
        )
        .into_js_value(),
    )?;
    let s = shared.clone();
    set(
        "making",
        getter(move || match &s.borrow().making {
            Some(standing) => json(standing),
            None => Ok(JsValue::NULL),
        }),
    )?;
    let (s, c) = (shared.clone(), ctx.clone());
    set(
        "loadGlb",
        Closure::<dyn Fn(Uint8Array, Option<String>) -> js_sys::Promise>::new(
            move |bytes: Uint8Array, name: Option<String>| {
                let name = name.unwrap_or_else(|| String::from("loaded.glb"));
                let mut input = crate::files::import_input(vec![(name, bytes.to_vec())]);
                let imports = s.borrow().imports.clone();
                c.request_repaint();
                promise_of(&mut |reply| match input.take() {
                    Some(input) => {
                        let incoming = crate::files::Incoming::Import(input, reply);
                        imports.borrow_mut().push_back(incoming);
                    }
                    None => reply.send(Err(String::from(
                        "The file name must end in .glb or .gltf.",
                    ))),
                })
            },
        )
        .into_js_value(),
    )?;
    for (name, op) in [
        ("undo", sketchmesh_core::document::Op::Undo),
        ("redo", sketchmesh_core::document::Op::Redo),
    ] {
        let (s, c) = (shared.clone(), ctx.clone());
        set(
            name,
            Closure::<dyn Fn() -> Result<(), JsValue>>::new(move || {
                let result = s.borrow_mut().editor.apply(op.clone());
                c.request_repaint();
                result.map_err(|e| js_error(&e.to_string()))
            })
            .into_js_value(),
        )?;
    }
    let (s, c) = (shared.clone(), ctx.clone());
    set(
        "restore",
        Closure::<dyn Fn(Option<String>, Option<bool>) -> Result<(), JsValue>>::new(
            move |text: Option<String>, at_start: Option<bool>| {
                let at_start = at_start.unwrap_or(false);
                let result = restore(&mut s.borrow_mut(), text.as_deref(), at_start);
                c.request_repaint();
                result.map_err(|e| js_error(&e))
            },
        )
        .into_js_value(),
    )?;
    let (s, c) = (shared.clone(), ctx.clone());
    set(
        "flushAutosave",
        Closure::<dyn Fn() -> Result<(), JsValue>>::new(move || {
            let mut shared = s.borrow_mut();
            let (revision, view) = (shared.revision(), shared.camera);
            if !shared.autosave.is_pending(revision, view) {
                return Ok(());
            }
            if let Some(record) = shared.autosave_pieces() {
                write_autosave(record).map_err(|e| js_error(&e))?;
            }
            // The frames' clock, which the schedule compares with (not the wall clock).
            let now = c.input(|i| i.time);
            shared.autosave.mark_saved(revision, view, now);
            Ok(())
        })
        .into_js_value(),
    )?;
    let (s, c) = (shared.clone(), ctx.clone());
    set(
        "notify",
        Closure::<dyn Fn(String)>::new(move |sentence: String| {
            s.borrow_mut().notice = Some(sentence);
            c.request_repaint();
        })
        .into_js_value(),
    )?;
    let (s, c) = (shared.clone(), ctx.clone());
    set(
        "thumbnail",
        getter(move || {
            let promise = js_sys::Promise::new(&mut |resolve, _reject| {
                s.borrow_mut().thumbnails.ask(Box::new(move |thumbnail| {
                    let _ = resolve.call1(&JsValue::NULL, &thumbnail_object(thumbnail));
                }));
            });
            c.request_repaint();
            Ok(promise.into())
        }),
    )?;
    // The browser suite's forced failure (issue 18). It is in the shipped page because the
    // suite tests the page that ships; it does no more than any bug would, and the failure
    // screen and the autosave (the state before the last op) are there for it.
    set(
        "panicForTest",
        Closure::<dyn Fn()>::new(|| panic!("a panic forced by the browser suite")).into_js_value(),
    )?;
    let window = web_sys::window().ok_or_else(|| JsValue::from_str("No window."))?;
    Reflect::set(&window, &JsValue::from_str("sketchmesh"), &api)?;
    Ok(())
}

/// Opens a document from the page's store: the document and view of the record, or with
/// none an empty document, replace what is shown (in Sketch, see [`Shared::open`]), and
/// autosaving (to the document the page now has open) begins. A record that does not replay
/// changes nothing and is refused with a sentence (the page sets it aside, then calls again
/// without).
///
/// `at_start`: the page's first call, once its store has answered. Without a record, what
/// was done meanwhile (a stroke drawn, a session replayed while the store was read) stays:
/// it is the new document's first work, not something to clear.
fn restore(shared: &mut Shared, text: Option<&str>, at_start: bool) -> Result<(), String> {
    if let Some(text) = text {
        let restored = Record::from_json(text)
            .map_err(|e| format!("the autosave record is not readable ({e})"))
            .and_then(|record| Ok((record.replay()?, record)));
        match restored {
            Ok((editor, record)) => {
                shared.open(editor);
                shared.camera = record.camera;
            }
            Err(why) => {
                let sentence = format!(
                    "The autosaved work could not be restored: {why}. It was set aside; the \
                     page starts empty."
                );
                shared.notice = Some(sentence.clone());
                return Err(sentence);
            }
        }
    } else if at_start && !shared.editor.ops().is_empty() {
        // Done while the store was read: not written yet (the revision is not one the store
        // holds), so it goes into the new document at the next autosave.
        shared.autosave.start_unwritten();
        return Ok(());
    } else if !at_start {
        // New (or the document shown deleted): empty, in the default view and in Sketch,
        // even when the one shown was empty already.
        shared.open_empty();
    }
    let (revision, view) = (shared.revision(), shared.camera);
    shared.autosave.start(revision, view);
    Ok(())
}

/// `{width, height, pixels}`, the pixels an `Uint8ClampedArray` ready for `ImageData`.
fn thumbnail_object(thumbnail: &crate::thumbnail::Thumbnail) -> JsValue {
    let object = Object::new();
    let pixels = js_sys::Uint8ClampedArray::from(thumbnail.rgba.as_slice());
    for (key, value) in [
        ("width", JsValue::from(thumbnail.width as u32)),
        ("height", JsValue::from(thumbnail.height as u32)),
        ("pixels", pixels.into()),
    ] {
        let _ = Reflect::set(&object, &JsValue::from_str(key), &value);
    }
    object.into()
}

fn getter(f: impl Fn() -> Result<JsValue, JsValue> + 'static) -> JsValue {
    Closure::<dyn Fn() -> Result<JsValue, JsValue>>::new(f).into_js_value()
}

fn json(value: &impl serde::Serialize) -> Result<JsValue, JsValue> {
    let text = serde_json::to_string(value).map_err(|e| js_error(&e.to_string()))?;
    js_sys::JSON::parse(&text)
}

/// A Promise settled by the [`Reply`](crate::files::Reply) `queue` is given: resolved when
/// the work is in the document, rejected with an `Error` holding the sentence otherwise.
fn promise_of(queue: &mut dyn FnMut(crate::files::Reply)) -> js_sys::Promise {
    js_sys::Promise::new(&mut |resolve, reject| {
        queue(crate::files::Reply::to(move |landed| {
            let _ = match landed {
                Ok(()) => resolve.call0(&JsValue::NULL),
                Err(why) => reject.call1(&JsValue::NULL, &js_error(&why)),
            };
        }));
    })
}

fn js_error(message: &str) -> JsValue {
    js_sys::Error::new(message).into()
}
