//! Imported models' base-colour textures, decoded for drawing.
//!
//! The document keeps each texture as its encoded file (to export it unchanged); the browser
//! decodes it here, asynchronously, the first time a model shows it, and the view is rebuilt
//! when it arrives (meanwhile the model shows its colours without the texture). Each image
//! gets a mip chain averaged in linear light, so a texture seen small neither shimmers nor
//! darkens. Native builds have no decoder and draw without textures.

use std::cell::RefCell;
use std::collections::{HashMap, HashSet};
use std::rc::Rc;
use std::sync::Arc;

use sketchmesh_core::document::Document;
use sketchmesh_core::model::Image;

/// The longest side a texture is kept at.
#[cfg(target_arch = "wasm32")]
const MAX_SIDE: u32 = 2048;

/// A decoded texture: sRGB RGBA8 pixels, level 0 first, each level half the last.
#[derive(Debug, PartialEq)]
pub struct TextureImage {
    /// Level 0's width and height.
    pub size: [u32; 2],
    /// Each level's pixels, row by row.
    pub levels: Vec<Vec<u8>>,
}

/// The key of an encoded image: the document shares one `Arc` per image across revisions.
fn key(image: &Arc<Image>) -> usize {
    Arc::as_ptr(image) as usize
}

/// Decoded images waiting for the next frame (`None`: the browser could not read it).
type Arrivals = Rc<RefCell<Vec<(usize, Option<egui::ColorImage>)>>>;

/// The textures decoded so far and those on their way.
#[derive(Default)]
pub struct Textures {
    decoded: HashMap<usize, Arc<TextureImage>>,
    asked: HashSet<usize>,
    arrivals: Arrivals,
    /// Changes whenever a texture arrives, so the view is rebuilt with it.
    pub version: u64,
}

impl Textures {
    /// Asks for every texture `doc`'s models show that is not decoded or on its way, and
    /// takes those that arrived.
    pub fn poll(&mut self, doc: &Document, ctx: &egui::Context) {
        for model in &doc.models {
            let Some(look) = model.appearance.as_deref() else {
                continue;
            };
            let textures = || (look.materials.iter()).filter_map(|m| m.base_color_texture.as_ref());
            // Whether the look still fits compares every triangle (12 MB at a million
            // triangles, about 1 ms a frame in the page): only when a texture is still to
            // ask for.
            let to_ask = textures().any(|t| !self.asked.contains(&key(&t.image)));
            if !to_ask || !look.fits(&model.mesh) {
                continue;
            }
            for texture in textures() {
                if self.asked.insert(key(&texture.image)) {
                    self.ask(&texture.image, ctx);
                }
            }
        }
        let arrived: Vec<_> = self.arrivals.borrow_mut().drain(..).collect();
        for (key, image) in arrived {
            if let Some(image) = image {
                self.decoded.insert(key, Arc::new(mip_chain(&image)));
                self.version += 1;
            }
        }
    }

    /// The decoded texture of `image`, once it is here.
    pub fn get(&self, image: &Arc<Image>) -> Option<Arc<TextureImage>> {
        self.decoded.get(&key(image)).cloned()
    }

    #[cfg(target_arch = "wasm32")]
    fn ask(&self, image: &Arc<Image>, ctx: &egui::Context) {
        let (key, arrivals, ctx) = (key(image), Rc::clone(&self.arrivals), ctx.clone());
        let bytes = js_sys::Uint8Array::from(image.bytes.as_slice());
        let options = web_sys::BlobPropertyBag::new();
        options.set_type(&image.mime_type);
        let parts = js_sys::Array::of1(&bytes);
        let Ok(blob) = web_sys::Blob::new_with_u8_array_sequence_and_options(&parts, &options)
        else {
            return;
        };
        wasm_bindgen_futures::spawn_local(async move {
            let decoded = crate::image_decode::decode(&blob, MAX_SIDE).await;
            if let Err(why) = &decoded {
                log::warn!("A texture could not be decoded: {why}");
            }
            arrivals.borrow_mut().push((key, decoded.ok()));
            ctx.request_repaint();
        });
    }

    #[cfg(not(target_arch = "wasm32"))]
    fn ask(&self, _image: &Arc<Image>, _ctx: &egui::Context) {}
}

/// `image` and its halvings down to one pixel, each pixel of a level the mean of four of
/// the level above in linear light.
fn mip_chain(image: &egui::ColorImage) -> TextureImage {
    let [w, h] = image.size.map(|s| s as u32);
    let mut levels = vec![image.as_raw().to_vec()];
    let (mut lw, mut lh) = (w, h);
    let linear: Vec<f32> = (0..=255u8)
        .map(|v| (f32::from(v) / 255.0).powf(2.2))
        .collect();
    while lw > 1 || lh > 1 {
        let (nw, nh) = ((lw / 2).max(1), (lh / 2).max(1));
        let above = &levels[levels.len() - 1];
        let mut next = Vec::with_capacity((4 * nw * nh) as usize);
        for y in 0..nh {
            for x in 0..nw {
                for c in 0..4 {
                    let texel = |dx: u32, dy: u32| {
                        let (sx, sy) = ((2 * x + dx).min(lw - 1), (2 * y + dy).min(lh - 1));
                        above[(4 * (sy * lw + sx) + c) as usize]
                    };
                    let texels = [texel(0, 0), texel(1, 0), texel(0, 1), texel(1, 1)];
                    let value = if c == 3 {
                        texels.iter().map(|&t| f32::from(t)).sum::<f32>() / 4.0
                    } else {
                        let mean = texels.iter().map(|&t| linear[t as usize]).sum::<f32>() / 4.0;
                        255.0 * mean.powf(1.0 / 2.2)
                    };
                    next.push(value.round().clamp(0.0, 255.0) as u8);
                }
            }
        }
        levels.push(next);
        (lw, lh) = (nw, nh);
    }
    TextureImage {
        size: [w, h],
        levels,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_checkerboard_mips_to_its_linear_mean_grey() {
        let pixels: Vec<egui::Color32> = (0..16)
            .map(|k| {
                let v = if (k % 4 + k / 4) % 2 == 0 { 255 } else { 0 };
                egui::Color32::from_rgba_unmultiplied(v, v, v, 255)
            })
            .collect();
        let image = egui::ColorImage::new([4, 4], pixels);
        let chain = mip_chain(&image);
        assert_eq!(chain.levels.len(), 3);
        assert_eq!(chain.levels[1].len(), 4 * 2 * 2);
        assert_eq!(chain.levels[2].len(), 4);
        // Half white, half black is 50% light: 0.5^(1/2.2) of 255, not 128.
        assert_eq!(chain.levels[2][0], 186);
        assert_eq!(chain.levels[2][3], 255);
    }
}
