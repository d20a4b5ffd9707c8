//! Thumbnails of the 3D view for the documents panel: a screenshot of the canvas, cut to the
//! view (no toolbar) and shrunk with a box filter.
//!
//! The page asks for one (`window.sketchmesh.thumbnail()`) when it keeps a document; the
//! screenshot is eframe's (read back after the next frame is painted, on WebGPU and WebGL2
//! alike), because a WebGL or WebGPU canvas keeps no pixels the page could read later.

use std::sync::{Arc, Mutex};

/// Width and height, in pixels, that a thumbnail fits in.
pub const MAX_SIZE: [usize; 2] = [240, 160];

/// A small RGBA image, rows top to bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct Thumbnail {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// RGBA bytes, `width * height * 4`.
    pub rgba: Vec<u8>,
}

impl Thumbnail {
    /// The part of `image` inside `view` (in points, `pixels_per_point` pixels each), shrunk
    /// to fit [`MAX_SIZE`] with its aspect kept. Each thumbnail pixel averages the image
    /// pixels it covers, so thin lines fade rather than flicker in and out.
    pub fn of_view(image: &egui::ColorImage, view: egui::Rect, pixels_per_point: f32) -> Thumbnail {
        let [image_w, image_h] = image.size;
        let clamp =
            |v: f32, max: usize| (v * pixels_per_point).round().clamp(0.0, max as f32) as usize;
        let (x0, x1) = (clamp(view.min.x, image_w), clamp(view.max.x, image_w));
        let (y0, y1) = (clamp(view.min.y, image_h), clamp(view.max.y, image_h));
        let (w, h) = (x1.saturating_sub(x0).max(1), y1.saturating_sub(y0).max(1));
        let scale = (MAX_SIZE[0] as f64 / w as f64)
            .min(MAX_SIZE[1] as f64 / h as f64)
            .min(1.0);
        let width = ((w as f64 * scale).round() as usize).max(1);
        let height = ((h as f64 * scale).round() as usize).max(1);
        let mut rgba = Vec::with_capacity(width * height * 4);
        for ty in 0..height {
            let (sy0, sy1) = span(ty, height, h);
            for tx in 0..width {
                let (sx0, sx1) = span(tx, width, w);
                let mut sum = [0u32; 4];
                for y in (y0 + sy0)..(y0 + sy1).min(image_h) {
                    for x in (x0 + sx0)..(x0 + sx1).min(image_w) {
                        let pixel = image.pixels[y * image_w + x].to_array();
                        for (s, p) in sum.iter_mut().zip(pixel) {
                            *s += u32::from(p);
                        }
                    }
                }
                let count = ((sy1 - sy0) * (sx1 - sx0)).max(1) as u32;
                rgba.extend(sum.map(|s| (s / count) as u8));
            }
        }
        Thumbnail {
            width,
            height,
            rgba,
        }
    }
}

/// The source pixels `[start, end)` that thumbnail pixel `i` of `n` covers in `len` pixels
/// (at least one).
fn span(i: usize, n: usize, len: usize) -> (usize, usize) {
    let start = i * len / n;
    let end = ((i + 1) * len / n).max(start + 1);
    (start, end)
}

/// Called with the thumbnail once it is taken.
pub type Waiter = Box<dyn FnOnce(&Thumbnail)>;

type Screenshot = Arc<egui::ColorImage>;

/// Thumbnails asked for and not yet taken: the screenshot is requested once for all of them,
/// and arrives in a later frame through [`Capture::slot`].
#[derive(Default)]
pub struct Capture {
    waiters: Vec<Waiter>,
    /// Where the screenshot callback (which must be `Send`) leaves the image, with the number
    /// of its request.
    slot: Arc<Mutex<Option<(u64, Screenshot)>>>,
    /// Requests made: a screenshot that arrives after its request was given up is not taken
    /// for a later one's.
    requests: u64,
    /// Whether a screenshot was requested and has not arrived.
    requested: bool,
    /// Frames since the screenshot was requested.
    frames_waited: u32,
}

/// Frames after which a screenshot that has not arrived is given up (the page waits a few
/// seconds and goes on without a thumbnail; the view shows its hints again).
const GIVE_UP_FRAMES: u32 = 300;

impl Capture {
    /// Asks for a thumbnail of the view; `done` gets it after the next frames are painted.
    pub fn ask(&mut self, done: Waiter) {
        self.waiters.push(done);
    }

    /// Whether a screenshot is on its way: the view then hides its hints and messages, so that
    /// the thumbnail shows the shapes only.
    pub fn is_capturing(&self) -> bool {
        !self.waiters.is_empty()
    }

    /// Runs once per frame: requests the screenshot the waiters need, and hands them the
    /// thumbnail of `view` once it has arrived. Frames keep coming meanwhile: the read-back
    /// completes in a later frame (on WebGL2, only when the device is polled again).
    pub fn run(&mut self, ctx: &egui::Context, view: egui::Rect) {
        if self.waiters.is_empty() {
            return;
        }
        ctx.request_repaint();
        let arrived = (self.slot.lock().map(|mut slot| slot.take()).unwrap_or(None))
            .filter(|(request, _)| *request == self.requests)
            .map(|(_, image)| image);
        match arrived {
            Some(image) => {
                self.requested = false;
                let thumbnail = Thumbnail::of_view(&image, view, ctx.pixels_per_point());
                for done in self.waiters.drain(..) {
                    done(&thumbnail);
                }
            }
            None if self.requested && self.frames_waited >= GIVE_UP_FRAMES => {
                self.requested = false;
                self.waiters.clear();
            }
            None if self.requested => self.frames_waited += 1,
            None => {
                self.requested = true;
                self.frames_waited = 0;
                self.requests += 1;
                let (slot, repaint, request) = (self.slot.clone(), ctx.clone(), self.requests);
                ctx.request_screenshot(move |image| {
                    if let Ok(mut slot) = slot.lock() {
                        *slot = Some((request, image));
                    }
                    repaint.request_repaint();
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_view_is_cut_out_and_shrunk_by_averaging() {
        // A 1000x800 image at 2 pixels per point: a 60 point toolbar of white at the top, the
        // view below it black with a red square of 200x200 pixels in its middle.
        let (w, h) = (1000, 800);
        let mut pixels = vec![egui::Color32::BLACK; w * h];
        for (i, pixel) in pixels.iter_mut().enumerate() {
            let (x, y) = (i % w, i / w);
            if y < 120 {
                *pixel = egui::Color32::WHITE;
            } else if (400..600).contains(&x) && (360..560).contains(&y) {
                *pixel = egui::Color32::RED;
            }
        }
        let image = egui::ColorImage::new([w, h], pixels);
        let view = egui::Rect::from_min_max(egui::pos2(0.0, 60.0), egui::pos2(500.0, 400.0));
        let thumbnail = Thumbnail::of_view(&image, view, 2.0);
        // 1000x680 pixels of view fit 240x160 at 0.2353: 235x160.
        assert_eq!((thumbnail.width, thumbnail.height), (235, 160));
        assert_eq!(thumbnail.rgba.len(), 235 * 160 * 4);
        let at = |x: usize, y: usize| {
            let i = (y * thumbnail.width + x) * 4;
            [
                thumbnail.rgba[i],
                thumbnail.rgba[i + 1],
                thumbnail.rgba[i + 2],
            ]
        };
        assert_eq!(at(0, 0), [0, 0, 0], "no toolbar in the thumbnail");
        assert_eq!(at(117, 80), [255, 0, 0], "the square at the middle");
        // The square's 200 pixels are 47 thumbnail pixels.
        let red: usize = (0..thumbnail.width).filter(|&x| at(x, 80)[0] > 0).count();
        assert!((47..=48).contains(&red), "{red} red pixels across");
    }

    #[test]
    fn a_small_view_is_kept_at_its_size() {
        let image = egui::ColorImage::new([40, 30], vec![egui::Color32::BLUE; 1200]);
        let view = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(40.0, 30.0));
        let thumbnail = Thumbnail::of_view(&image, view, 1.0);
        assert_eq!((thumbnail.width, thumbnail.height), (40, 30));
        assert!(thumbnail.rgba.chunks(4).all(|p| p == [0, 0, 255, 255]));
    }
}
