//! Images decoded by the browser (PNG, JPEG, whatever it reads): the wasm carries no image
//! codec. Used for the backdrop and for imported models' textures.

/// The pixels of an encoded image (a file, or a glTF texture's bytes in a `Blob`), decoded
/// by the browser and scaled down to fit `max_side`.
pub async fn decode(blob: &web_sys::Blob, max_side: u32) -> Result<egui::ColorImage, String> {
    use wasm_bindgen::JsCast as _;
    let window = web_sys::window().ok_or("no window")?;
    let unreadable = |_| String::from("the browser cannot read it as an image");
    let promise = window
        .create_image_bitmap_with_blob(blob)
        .map_err(unreadable)?;
    let bitmap: web_sys::ImageBitmap = wasm_bindgen_futures::JsFuture::from(promise)
        .await
        .map_err(unreadable)?
        .dyn_into()
        .map_err(unreadable)?;
    let (w, h) = (bitmap.width().max(1), bitmap.height().max(1));
    let shrink = (f64::from(max_side) / f64::from(w.max(h))).min(1.0);
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
