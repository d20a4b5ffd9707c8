//! Files in and out: dropped and picked files become import ops or open sessions, exports and
//! saved sessions become downloads.
//!
//! Browsers read files asynchronously, so files arrive in an [`ImportQueue`] that the app
//! drains at the start of a frame; the app shows "Importing…" for a frame before it parses,
//! so a large file never leaves the page looking frozen without a word.

use std::cell::RefCell;
use std::collections::VecDeque;
use std::rc::Rc;
use std::sync::Arc;

use sketchmesh_core::document::{FileInput, ImportInput};

/// Files waiting for the next frame.
pub type ImportQueue = Rc<RefCell<VecDeque<Incoming>>>;

/// What a drop, the picker or the page API brought.
#[derive(Debug)]
pub enum Incoming {
    /// glTF files to import into the document, and who waits to hear how it went.
    Import(ImportInput, Reply),
    /// A session (JSON) to replay in place of the document (the page API's `replay`), and
    /// who waits to hear how it went.
    Replay(String, Reply),
    /// A session file (`.json`) to open in place of the document.
    Session {
        /// The file's name.
        name: String,
        /// Its bytes (UTF-8 JSON, if it is what it says).
        bytes: Vec<u8>,
    },
}

/// Who waits for an import to land (the page API's `loadGlb` Promise): told once, when the
/// import is in the document or when it is refused or cancelled (with the sentence).
#[derive(Default)]
pub struct Reply(Option<Box<dyn FnOnce(Landed)>>);

/// How an import went: in the document, or the sentence of its refusal or cancel.
pub type Landed = Result<(), String>;

impl Reply {
    /// A reply that calls `tell`.
    pub fn to(tell: impl FnOnce(Landed) + 'static) -> Reply {
        Reply(Some(Box::new(tell)))
    }

    /// Tells how it went (nothing when nobody waits).
    pub fn send(self, result: Landed) {
        if let Some(tell) = self.0 {
            tell(result);
        }
    }
}

impl std::fmt::Debug for Reply {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.is_some() {
            "Reply(waited for)"
        } else {
            "Reply(none)"
        })
    }
}

/// A session file among `files` (the first `.json`), else their glTF import, else `None`.
pub fn incoming(mut files: Vec<(String, Vec<u8>)>) -> Option<Incoming> {
    let session = files
        .iter()
        .position(|(name, _)| name.to_ascii_lowercase().ends_with(".json"));
    match session {
        Some(index) => {
            let (name, bytes) = files.swap_remove(index);
            Some(Incoming::Session { name, bytes })
        }
        None => import_input(files).map(|input| Incoming::Import(input, Reply::default())),
    }
}

/// A kind of file the app writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Download {
    /// The document as glTF binary.
    Glb,
    /// The session (`docs/session-format.md`).
    Session,
}

impl Download {
    fn extension(self) -> &'static str {
        match self {
            Download::Glb => "glb",
            Download::Session => "sketchmesh.json",
        }
    }
}

/// The files of one import, main file (.glb or .gltf) first, to land beside what the
/// document holds; `None` if none is glTF.
pub fn import_input(mut files: Vec<(String, Vec<u8>)>) -> Option<ImportInput> {
    let is_main = |name: &str| {
        let name = name.to_ascii_lowercase();
        name.ends_with(".glb") || name.ends_with(".gltf")
    };
    let main = files.iter().position(|(name, _)| is_main(name))?;
    files.swap(0, main);
    Some(ImportInput {
        files: files
            .into_iter()
            .map(|(name, bytes)| FileInput {
                name,
                data: Some(Arc::new(bytes)),
            })
            .collect(),
        beside: true,
    })
}

/// How many bytes the loaded files of an import hold: what the progress line says.
pub fn import_bytes(input: &ImportInput) -> usize {
    (input.files.iter())
        .filter_map(|f| f.data.as_ref())
        .map(|d| d.len())
        .sum()
}

/// `sketchmesh-YYYYMMDD-HHMM.<extension>` for a local date and time.
pub fn file_name(
    kind: Download,
    year: i32,
    month: u32,
    day: u32,
    hour: u32,
    minute: u32,
) -> String {
    let extension = kind.extension();
    format!("sketchmesh-{year:04}{month:02}{day:02}-{hour:02}{minute:02}.{extension}")
}

/// Queues files dropped on the app (read asynchronously in the browser).
pub fn accept_dropped(
    files: Vec<egui::DroppedFileHandle>,
    queue: &ImportQueue,
    ctx: &egui::Context,
) {
    if files.is_empty() {
        return;
    }
    #[cfg(target_arch = "wasm32")]
    {
        let (queue, ctx) = (queue.clone(), ctx.clone());
        wasm_bindgen_futures::spawn_local(async move {
            let mut read = Vec::new();
            for file in &files {
                let name = file.path().to_string_lossy().into_owned();
                match file.bytes_async().await {
                    Ok(bytes) => read.push((name, bytes)),
                    Err(error) => log::warn!("Could not read {name}: {error}"),
                }
            }
            queue_files(read, &queue, &ctx);
        });
    }
    #[cfg(not(target_arch = "wasm32"))]
    {
        let read = files
            .iter()
            .filter_map(|file| {
                let name = file.path().file_name()?.to_string_lossy().into_owned();
                Some((name, file.bytes().ok()?))
            })
            .collect();
        queue_files(read, queue, ctx);
    }
}

fn queue_files(files: Vec<(String, Vec<u8>)>, queue: &ImportQueue, ctx: &egui::Context) {
    if let Some(incoming) = incoming(files) {
        queue.borrow_mut().push_back(incoming);
        ctx.request_repaint();
    }
}

/// Opens the browser's file picker; chosen files are queued. Native builds import by drop.
#[cfg(target_arch = "wasm32")]
pub fn pick_files(queue: &ImportQueue, ctx: &egui::Context) -> Result<(), String> {
    let (queue, ctx) = (queue.clone(), ctx.clone());
    open_picker(
        ".glb,.gltf,.bin,.png,.jpg,.jpeg,.json",
        true,
        move |files| {
            wasm_bindgen_futures::spawn_local(async move {
                let mut read = Vec::new();
                for file in files {
                    let Ok(buffer) =
                        wasm_bindgen_futures::JsFuture::from(file.array_buffer()).await
                    else {
                        continue;
                    };
                    read.push((file.name(), js_sys::Uint8Array::new(&buffer).to_vec()));
                }
                queue_files(read, &queue, &ctx);
            });
        },
    )
}

/// Opens the browser's file picker for files matching `accept` (one, or several when
/// `multiple`); `chosen` gets them once the user picks.
#[cfg(target_arch = "wasm32")]
pub fn open_picker(
    accept: &str,
    multiple: bool,
    chosen: impl FnOnce(Vec<web_sys::File>) + 'static,
) -> Result<(), String> {
    use wasm_bindgen::JsCast as _;
    use wasm_bindgen::prelude::Closure;
    let describe = |e: wasm_bindgen::JsValue| format!("{e:?}");
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let input: web_sys::HtmlInputElement = document
        .create_element("input")
        .map_err(describe)?
        .dyn_into()
        .map_err(|_| "not an input element")?;
    input.set_type("file");
    input.set_multiple(multiple);
    input.set_accept(accept);
    let target = input.clone();
    let on_change = Closure::once_into_js(move || {
        let Some(list) = target.files() else { return };
        chosen((0..list.length()).filter_map(|i| list.get(i)).collect());
    });
    input.set_onchange(Some(on_change.unchecked_ref()));
    input.click();
    Ok(())
}

/// Native builds import by dropping files on the window.
#[cfg(not(target_arch = "wasm32"))]
pub fn pick_files(_queue: &ImportQueue, _ctx: &egui::Context) -> Result<(), String> {
    Err(String::from(
        "Drop a .glb or .gltf file on the window to import it.",
    ))
}

/// Offers `bytes` as a download named for the current local time; returns the name.
#[cfg(target_arch = "wasm32")]
pub fn download(bytes: &[u8], kind: Download) -> Result<String, String> {
    use wasm_bindgen::JsCast as _;
    let describe = |e: wasm_bindgen::JsValue| format!("{e:?}");
    let now = js_sys::Date::new_0();
    let name = file_name(
        kind,
        now.get_full_year() as i32,
        now.get_month() + 1,
        now.get_date(),
        now.get_hours(),
        now.get_minutes(),
    );
    let parts = js_sys::Array::of1(&js_sys::Uint8Array::from(bytes));
    let options = web_sys::BlobPropertyBag::new();
    options.set_type(match kind {
        Download::Glb => "model/gltf-binary",
        Download::Session => "application/json",
    });
    let blob = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)
        .map_err(describe)?;
    let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(describe)?;
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let anchor: web_sys::HtmlAnchorElement = document
        .create_element("a")
        .map_err(describe)?
        .dyn_into()
        .map_err(|_| "not an anchor element")?;
    anchor.set_href(&url);
    anchor.set_download(&name);
    anchor.click();
    web_sys::Url::revoke_object_url(&url).map_err(describe)?;
    Ok(name)
}

/// Writes `bytes` to the working directory, named for the current UTC time.
#[cfg(not(target_arch = "wasm32"))]
pub fn download(bytes: &[u8], kind: Download) -> Result<String, String> {
    let seconds = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_err(|e| e.to_string())?
        .as_secs();
    let (year, month, day) = civil_from_days((seconds / 86_400) as i64);
    let minutes = (seconds % 86_400) / 60;
    let name = file_name(
        kind,
        year,
        month,
        day,
        (minutes / 60) as u32,
        (minutes % 60) as u32,
    );
    std::fs::write(&name, bytes).map_err(|e| format!("Could not write {name}: {e}"))?;
    Ok(name)
}

/// The Gregorian date of a day count since 1970-01-01 (Howard Hinnant's algorithm).
#[cfg(not(target_arch = "wasm32"))]
fn civil_from_days(days: i64) -> (i32, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let month = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let year = (yoe + era * 400 + i64::from(month <= 2)) as i32;
    (year, month, day)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_gltf_file_goes_first() {
        let input = import_input(vec![
            (String::from("a.bin"), vec![1]),
            (String::from("A.GLTF"), vec![2]),
        ])
        .unwrap();
        assert_eq!(input.files[0].name, "A.GLTF");
        assert_eq!(input.files[1].name, "a.bin");
        assert!(import_input(vec![(String::from("a.png"), vec![])]).is_none());
    }

    #[test]
    fn a_json_file_is_a_session_to_open() {
        let files = vec![
            (String::from("a.glb"), vec![1]),
            (String::from("work.sketchmesh.JSON"), vec![b'{']),
        ];
        match incoming(files) {
            Some(Incoming::Session { name, bytes }) => {
                assert_eq!((name.as_str(), bytes), ("work.sketchmesh.JSON", vec![b'{']));
            }
            other => panic!("expected a session, got {other:?}"),
        }
        let glb = incoming(vec![(String::from("a.glb"), vec![1])]);
        assert!(matches!(glb, Some(Incoming::Import(..))));
        assert!(incoming(vec![(String::from("a.txt"), vec![])]).is_none());
    }

    #[test]
    fn names_and_dates() {
        assert_eq!(
            file_name(Download::Glb, 2026, 11, 2, 9, 5),
            "sketchmesh-20261102-0905.glb"
        );
        assert_eq!(
            file_name(Download::Session, 2026, 11, 2, 9, 5),
            "sketchmesh-20261102-0905.sketchmesh.json"
        );
        #[cfg(not(target_arch = "wasm32"))]
        {
            assert_eq!(civil_from_days(0), (1970, 1, 1));
            assert_eq!(civil_from_days(20_779), (2026, 11, 22));
            assert_eq!(civil_from_days(11_016), (2000, 2, 29));
        }
    }
}
