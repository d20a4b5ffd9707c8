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
                    let decoded = crate::image_decode::decode(&file, MAX_SIDE)
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
