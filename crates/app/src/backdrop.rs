//! A reference image over the view, to trace a drawn motion frame by frame (Zhou et al.
//! 2005, §4.2: cartoon curves retargeted onto the model). The browser decodes the file (no
//! image codec in the wasm); the image is shown half transparent, fitted into the view,
//! under the strokes and overlays.

use std::cell::RefCell;
use std::rc::Rc;

/// The longest side an image is kept at: sharp enough to trace on a 4K screen's view, a
/// few MB of texture at most.
#[cfg(target_arch = "wasm32")]
const MAX_SIDE: u32 = 2048;

/// How opaque the image is drawn (of 255): the model stays visible through it.
const OPACITY: u8 = 110;

/// A decoded image or why there is none, waiting for the next frame.
type Arrival = Rc<RefCell<Option<Result<egui::ColorImage, String>>>>;

/// The backdrop: the image shown, and one on its way.
#[derive(Default)]
pub struct Backdrop {
    /// The app's context (from the first [`Backdrop::poll`]), to repaint when an image
    /// arrives.
    ctx: Option<egui::Context>,
    arrived: Arrival,
    texture: Option<egui::TextureHandle>,
}

impl Backdrop {
    /// Opens the file picker for an image; it shows once the browser has decoded it.
    ///
    /// Errors: a sentence when there is no picker (a native build).
    pub fn pick(&self) -> Result<(), String> {
        #[cfg(target_arch = "wasm32")]
        {
            let (arrived, ctx) = (Rc::clone(&self.arrived), self.ctx.clone());
            crate::files::open_picker("image/*", false, move |files| {
                let Some(file) = files.into_iter().next() else {
                    return;
                };
                wasm_bindgen_futures::spawn_local(async move {
                    let name = file.name();
                    let decoded = decode(file)
                        .await
                        .map_err(|why| format!("{name} could not be shown as a backdrop: {why}."));
                    *arrived.borrow_mut() = Some(decoded);
                    if let Some(ctx) = ctx {
                        ctx.request_repaint();
                    }
                });
            })
        }
        #[cfg(not(target_arch = "wasm32"))]
        {
            Err(String::from("A backdrop image is loaded in the browser."))
        }
    }

    /// Takes an image that arrived since the last frame, once a frame; a sentence if it
    /// could not be read (the backdrop shown stays).
    pub fn poll(&mut self, ctx: &egui::Context) -> Option<String> {
        self.ctx.get_or_insert_with(|| ctx.clone());
        let arrived = self.arrived.borrow_mut().take()?;
        match arrived {
            Ok(image) => {
                let options = egui::TextureOptions::LINEAR;
                self.texture = Some(ctx.load_texture("backdrop", image, options));
                None
            }
            Err(message) => Some(message),
        }
    }

    /// Removes the image.
    pub fn remove(&mut self) {
        self.texture = None;
    }

    /// Draws the image, fitted into `viewport` and centred.
    pub fn paint(&self, ui: &egui::Ui, viewport: egui::Rect) {
        let Some(texture) = &self.texture else {
            return;
        };
        let size = texture.size_vec2();
        let scale = (viewport.width() / size.x).min(viewport.height() / size.y);
        let rect = egui::Rect::from_center_size(viewport.center(), size * scale);
        let uv = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0));
        let tint = egui::Color32::from_white_alpha(OPACITY);
        ui.painter().image(texture.id(), rect, uv, tint);
    }
}

/// The pixels of an image file, decoded by the browser and scaled to fit [`MAX_SIDE`].
#[cfg(target_arch = "wasm32")]
async fn decode(file: web_sys::File) -> Result<egui::ColorImage, String> {
    use wasm_bindgen::JsCast as _;
    let window = web_sys::window().ok_or("no window")?;
    let unreadable = |_| String::from("the browser cannot read it as an image");
    let promise = window
        .create_image_bitmap_with_blob(&file)
        .map_err(unreadable)?;
    let bitmap: web_sys::ImageBitmap = wasm_bindgen_futures::JsFuture::from(promise)
        .await
        .map_err(unreadable)?
        .dyn_into()
        .map_err(unreadable)?;
    let (w, h) = (bitmap.width().max(1), bitmap.height().max(1));
    let shrink = (MAX_SIDE as f64 / w.max(h) as f64).min(1.0);
    let (w, h) = (
        ((w as f64 * shrink).round() as u32).max(1),
        ((h as f64 * shrink).round() as u32).max(1),
    );
    let failed = |e: wasm_bindgen::JsValue| format!("{e:?}");
    let canvas: web_sys::HtmlCanvasElement = window
        .document()
        .ok_or("no document")?
        .create_element("canvas")
        .map_err(failed)?
        .dyn_into()
        .map_err(|_| "not a canvas")?;
    canvas.set_width(w);
    canvas.set_height(h);
    let context: web_sys::CanvasRenderingContext2d = canvas
        .get_context("2d")
        .map_err(failed)?
        .ok_or("no 2D canvas")?
        .dyn_into()
        .map_err(|_| "not a 2D context")?;
    context
        .draw_image_with_image_bitmap_and_dw_and_dh(&bitmap, 0.0, 0.0, w.into(), h.into())
        .map_err(failed)?;
    let pixels = context
        .get_image_data(0.0, 0.0, w.into(), h.into())
        .map_err(failed)?
        .data();
    Ok(egui::ColorImage::from_rgba_unmultiplied(
        [w as usize, h as usize],
        &pixels,
    ))
}
