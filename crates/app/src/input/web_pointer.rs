//! Browser input: `PointerEvent`s read straight from the canvas.
//!
//! eframe's web backend reduces pointer events to bare button presses, losing
//! `pointerType` and pressure, which a drawing app needs. These listeners queue a
//! [`PointerSample`] per event, expanding `pointermove` with `getCoalescedEvents()` so a
//! fast pen stroke keeps every sample the hardware produced, not one per frame.

use std::cell::RefCell;
use std::collections::VecDeque;
use std::rc::Rc;

use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;

use super::{Phase, PointerKind, PointerSample};

/// Samples waiting for the next frame.
pub type SampleQueue = Rc<RefCell<VecDeque<PointerSample>>>;

/// Keeps the listeners alive for the page's lifetime.
pub struct WebPointer {
    _listeners: Vec<Closure<dyn FnMut(web_sys::PointerEvent)>>,
}

impl WebPointer {
    /// Listens on `canvas`; `wake` is called after each event so the app repaints.
    pub fn listen(
        canvas: &web_sys::HtmlCanvasElement,
        queue: SampleQueue,
        wake: impl Fn() + Clone + 'static,
    ) -> Result<Self, JsValue> {
        let mut listeners = Vec::new();
        for (name, phase) in [
            ("pointerdown", Phase::Down),
            ("pointermove", Phase::Move),
            ("pointerup", Phase::Up),
            ("pointercancel", Phase::Cancel),
            // A hovering pen that leaves: its cursor goes (other pointers' leaves are not
            // cancels: a captured drag goes on outside the canvas).
            ("pointerleave", Phase::Cancel),
        ] {
            let is_leave = name == "pointerleave";
            let (queue, wake, target) = (queue.clone(), wake.clone(), canvas.clone());
            let closure = Closure::<dyn FnMut(web_sys::PointerEvent)>::new(
                move |e: web_sys::PointerEvent| {
                    if is_leave && (e.pointer_type() != "pen" || e.buttons() != 0) {
                        return;
                    }
                    if phase == Phase::Down {
                        // Keep receiving this pointer's moves when it leaves the canvas.
                        let _ = target.set_pointer_capture(e.pointer_id());
                    }
                    let origin = target.get_bounding_client_rect();
                    let mut queue = queue.borrow_mut();
                    if phase == Phase::Move {
                        let coalesced = e.get_coalesced_events();
                        if coalesced.length() > 1 {
                            for event in coalesced.iter() {
                                if let Ok(event) = event.dyn_into::<web_sys::PointerEvent>() {
                                    queue.push_back(sample(&event, phase, &origin));
                                }
                            }
                            drop(queue);
                            wake();
                            return;
                        }
                    }
                    queue.push_back(sample(&e, phase, &origin));
                    drop(queue);
                    wake();
                },
            );
            canvas.add_event_listener_with_callback(name, closure.as_ref().unchecked_ref())?;
            listeners.push(closure);
        }
        Ok(Self {
            _listeners: listeners,
        })
    }
}

fn sample(e: &web_sys::PointerEvent, phase: Phase, origin: &web_sys::DomRect) -> PointerSample {
    let kind = match e.pointer_type().as_str() {
        "pen" => PointerKind::Pen,
        "touch" => PointerKind::Touch,
        _ => PointerKind::Mouse,
    };
    PointerSample {
        id: i64::from(e.pointer_id()),
        phase,
        pos_in_screen: egui::pos2(
            (fractional(e, "clientX") - origin.left()) as f32,
            (fractional(e, "clientY") - origin.top()) as f32,
        ),
        pressure: PointerSample::drawing_pressure(kind, e.pressure()),
        kind,
        buttons: e.buttons(),
        contact: match kind {
            PointerKind::Touch => fractional(e, "width").max(fractional(e, "height")) as f32,
            _ => 0.0,
        },
        time: e.time_stamp() / 1000.0,
    }
}

/// Reads a coordinate with its fraction: web-sys types `clientX` as an integer, but pens
/// report sub-pixel positions that make strokes smoother.
fn fractional(e: &web_sys::PointerEvent, name: &str) -> f64 {
    js_sys::Reflect::get(e, &JsValue::from_str(name))
        .ok()
        .and_then(|v| v.as_f64())
        .unwrap_or_default()
}
