//! The pointer's state between frames: the router that sends samples to the tool or the
//! camera, the samples queued by the page's listeners, a stroke held back while the app is
//! busy, and the tool a pen's eraser stroke switched from.

use std::cell::RefCell;
use std::collections::VecDeque;
use std::rc::Rc;

use crate::input::PointerSample;
use crate::input::router::{InputRouter, ToolEvent};
use crate::tools::Mode;

/// What the app keeps of the pointer.
#[derive(Default)]
pub struct Pointer {
    /// Sends samples to the tool or the camera.
    pub router: InputRouter,
    /// egui's pointer, read natively.
    #[cfg(not(target_arch = "wasm32"))]
    egui_pointer: crate::input::egui_pointer::EguiPointer,
    /// Samples queued by the browser's pointer listeners.
    pub web_samples: Rc<RefCell<VecDeque<PointerSample>>>,
    /// Whether the stroke in progress began while work ran off the frame: it reaches no
    /// tool, to its end.
    holding_stroke: bool,
    /// The tool to go back to when the pen's eraser stroke (eraser end or barrel button)
    /// in progress ends.
    pub erasing_from: Option<Mode>,
}

impl Pointer {
    /// This frame's samples: egui's (natively) and those the page's listeners queued.
    pub fn take_samples(&mut self, ctx: &egui::Context) -> Vec<PointerSample> {
        let mut samples = Vec::new();
        #[cfg(not(target_arch = "wasm32"))]
        ctx.input(|i| self.egui_pointer.collect(i, &mut samples));
        #[cfg(target_arch = "wasm32")]
        let _ = ctx;
        samples.extend(self.web_samples.borrow_mut().drain(..));
        samples
    }

    /// Whether `event` belongs to a stroke begun while the app was busy (see
    /// [`crate::edit_runner::EditRunner::is_busy`]): such a stroke draws nothing, from its beginning to its end.
    pub fn holds_stroke(&mut self, event: &ToolEvent, busy: bool) -> bool {
        if matches!(event, ToolEvent::Begin(_)) {
            self.holding_stroke = busy;
        }
        let held = self.holding_stroke;
        if matches!(event, ToolEvent::End(_) | ToolEvent::Cancel) {
            self.holding_stroke = false;
        }
        held
    }
}
