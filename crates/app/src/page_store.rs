//! The page's store and documents panel (`web/store.js`, `web/documents.js`): what the app
//! hands them, and the autosave record's pieces it readies over frames.

use js_sys::{JsString, Reflect};
use sketchmesh_core::document::{Editor, SessionPiece};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use crate::autosave::{RECORD_TAIL, record_head};
use crate::camera::OrbitCamera;

/// The key under which the page's local storage keeps that the introduction was seen.
const INTRO_KEY: &str = "sketchmesh.intro";

/// The page's local storage, if it has one (a private window may refuse it).
fn local_storage() -> Option<JsValue> {
    let window = web_sys::window()?;
    Reflect::get(&window, &JsValue::from_str("localStorage"))
        .ok()
        .filter(|storage| storage.is_object())
}

/// Calls `method` of the page's local storage with `args`.
fn call_storage(method: &str, args: &[JsValue]) -> Option<JsValue> {
    let storage = local_storage()?;
    let function = Reflect::get(&storage, &JsValue::from_str(method)).ok()?;
    let function = function.dyn_into::<js_sys::Function>().ok()?;
    let args: js_sys::Array = args.iter().collect();
    function.apply(&storage, &args).ok()
}

/// Whether the introduction was seen (ended or skipped) on an earlier visit. A page without
/// storage shows it every time, which costs one Skip.
pub fn intro_seen() -> bool {
    call_storage("getItem", &[JsValue::from_str(INTRO_KEY)]).is_some_and(|v| !v.is_null())
}

/// Keeps that the introduction was seen, so later visits open without it.
pub fn keep_intro_seen() {
    let args = [JsValue::from_str(INTRO_KEY), JsValue::from_str("seen")];
    let _ = call_storage("setItem", &args);
}

/// The key under which the page's local storage keeps what the Symmetry switch was last
/// left at: `"on"` or `"off"`.
const SYMMETRY_KEY: &str = "sketchmesh.symmetry";

/// What the Symmetry switch was last left at on an earlier visit, if the page kept it.
pub fn symmetry_for_new() -> Option<bool> {
    let kept = call_storage("getItem", &[JsValue::from_str(SYMMETRY_KEY)])?;
    kept.as_string().map(|kept| kept == "on")
}

/// Keeps what the user left the Symmetry switch at, for the next new documents and visits.
pub fn keep_symmetry(on: bool) {
    let value = if on { "on" } else { "off" };
    let args = [JsValue::from_str(SYMMETRY_KEY), JsValue::from_str(value)];
    let _ = call_storage("setItem", &args);
}

/// Keeps the document shown (`record`, or nothing when it has no ops) in the page's store and
/// makes a new document, named `title`, the one the autosave writes to: a session file opened
/// becomes a document of its own.
///
/// Errors: a sentence when the page has no store or the call throws at once.
pub fn keep_and_start(record: Option<js_sys::Array>, title: &str) -> Result<(), String> {
    let text = record.map_or(JsValue::NULL, JsValue::from);
    call_page(
        "sketchmeshAutosave",
        "keep",
        &[text, JsValue::from_str(title)],
    )
}

/// Hands `record` (its pieces, see [`autosave_pieces`]) to the page's store
/// (`window.sketchmeshAutosave.save`, from `web/main.js`), which writes it to IndexedDB
/// without blocking the frame.
///
/// Errors: a sentence when the page has no store or the call throws at once.
pub fn write_autosave(record: js_sys::Array) -> Result<(), String> {
    call_page("sketchmeshAutosave", "save", &[record.into()])
}

/// Each op's session text as a JavaScript string, made once per op of the document shown
/// (the editor's log only grows until another editor is opened).
#[derive(Default)]
pub struct OpTexts {
    /// The [`crate::autosave::Revision::opened`] of the editor they are of.
    opened: u64,
    texts: Vec<JsString>,
}

impl OpTexts {
    /// Empties the texts if they are of another editor than `opened`.
    fn renew(&mut self, opened: u64) {
        if self.opened != opened {
            *self = OpTexts {
                opened,
                texts: Vec::new(),
            };
        }
    }
}

/// Readies the autosave's pieces while `budget_ms` lasts from `started` (at least one step
/// when it has not passed): each new op's JSON written, then converted to a JavaScript
/// string, one after the other, so that an import's op (its files in base64, tens of
/// megabytes for a scan) takes a frame for each and the write a third, not one frame for
/// all. Whether every op is ready.
pub fn ready_op_texts(
    editor: &Editor,
    cache: &mut OpTexts,
    opened: u64,
    started: f64,
    budget_ms: f64,
) -> bool {
    cache.renew(opened);
    loop {
        let index = cache.texts.len();
        if index == editor.ops().len() {
            return true;
        }
        if crate::clock::now_ms() - started > budget_ms {
            return false;
        }
        if editor.is_op_json_written(index) {
            let json = editor.op_json(index).unwrap_or_default();
            cache.texts.push(JsString::from(json));
        } else {
            editor.op_json(index);
        }
    }
}

/// The autosave record of what `editor` shows (in the view `camera`), as pieces of text whose concatenation is the
/// record, or `None` for a document without ops (an empty page is not a document worth
/// keeping). Each op is a piece of its own, its text converted once and kept as a JavaScript
/// string, so an autosave after a scan's import neither converts nor copies the session's tens
/// of megabytes again; and the page's store (`web/store.js`) keeps a long piece apart from the
/// record, written once rather than at every change.
pub fn autosave_pieces(
    editor: &Editor,
    cache: &mut OpTexts,
    opened: u64,
    camera: OrbitCamera,
) -> Option<js_sys::Array> {
    if editor.ops().is_empty() {
        return None;
    }
    cache.renew(opened);
    let pieces = js_sys::Array::new();
    pieces.push(&JsString::from(record_head(camera)));
    editor.session_pieces(|piece| {
        let text = match piece {
            SessionPiece::Op(index, json) => {
                if index == cache.texts.len() {
                    cache.texts.push(JsString::from(json));
                }
                cache.texts[index].clone()
            }
            SessionPiece::Text(text) => JsString::from(text),
        };
        pieces.push(&text);
    });
    pieces.push(&JsString::from(RECORD_TAIL));
    Some(pieces)
}

/// The documents panel (`web/documents.js`): `"show"` opens it, `"newDocument"` keeps the
/// document shown and starts an empty one.
///
/// Errors: a sentence when the page has no panel.
pub fn documents(method: &str) -> Result<(), String> {
    call_page("sketchmeshDocuments", method, &[])
}

/// Calls `window[object][method](...args)`.
pub(crate) fn call_page(object: &str, method: &str, args: &[JsValue]) -> Result<(), String> {
    let missing = || format!("the page has no {object}.{method}");
    let window = web_sys::window().ok_or("there is no window")?;
    let target = Reflect::get(&window, &JsValue::from_str(object)).map_err(|_| missing())?;
    let function: js_sys::Function = Reflect::get(&target, &JsValue::from_str(method))
        .ok()
        .and_then(|f| f.dyn_into().ok())
        .ok_or_else(missing)?;
    let args: js_sys::Array = args.iter().collect();
    function
        .apply(&target, &args)
        .map(|_| ())
        .map_err(|e| format!("{e:?}"))
}
