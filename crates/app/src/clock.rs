//! A millisecond clock for timing work inside a frame (`performance.now()` in the page), and
//! the recent costs of edits the page benchmark reads.

use std::collections::BTreeMap;

/// Milliseconds since an arbitrary start, with sub-millisecond resolution where available.
#[cfg(target_arch = "wasm32")]
pub fn now_ms() -> f64 {
    web_sys::window()
        .and_then(|w| w.performance())
        .map_or(0.0, |p| p.now())
}

/// Milliseconds since the first call.
#[cfg(not(target_arch = "wasm32"))]
pub fn now_ms() -> f64 {
    use std::sync::OnceLock;
    use std::time::Instant;
    static START: OnceLock<Instant> = OnceLock::new();
    START.get_or_init(Instant::now).elapsed().as_secs_f64() * 1e3
}

/// How many recent samples each list of [`EditTimings`] keeps.
const KEPT: usize = 1024;

/// Recent costs of the edits the app ran, per op name (`"pull"`, `"oversketch"`, …), in ms:
/// what the page benchmark reads.
#[derive(Clone, Debug, Default, serde::Serialize)]
#[serde(transparent)]
pub struct Timings(BTreeMap<&'static str, EditTimings>);

/// Recent costs of one kind of edit, in ms.
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct EditTimings {
    /// Beginning the edit, with the steps of the frame it began in while its gesture goes on
    /// (a pull's grab: picking the curve and factoring the region around it).
    pub begin_ms: Vec<f64>,
    /// The steps of each later frame while its gesture goes on (a pull's drag frames).
    pub frame_ms: Vec<f64>,
    /// Everything after its input was complete, over however many frames: the steps left and
    /// the commit (a pull's release, a whole over-sketch or creation), in the page's frames.
    pub finish_ms: Vec<f64>,
    /// The page's worker's part, from handing it over to its answer landing (an import's
    /// read, a curve op's result): time the page kept drawing.
    pub elsewhere_ms: Vec<f64>,
    /// Each preview of its gesture the worker computed, from asked to shown (a pull's drag,
    /// a control curve's new shape: what they factor is factored there).
    pub preview_ms: Vec<f64>,
}

impl Timings {
    /// The timings of edits of the op named `name`.
    pub fn of(&mut self, name: &'static str) -> &mut EditTimings {
        self.0.entry(name).or_default()
    }

    /// Takes everything recorded so far.
    pub fn take(&mut self) -> Timings {
        std::mem::take(self)
    }
}

/// Records one cost; the oldest half of a full list goes.
pub fn record(list: &mut Vec<f64>, ms: f64) {
    if list.len() == KEPT {
        list.drain(..KEPT / 2);
    }
    list.push(ms);
}
