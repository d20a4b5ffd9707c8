//! A millisecond clock for timing work inside a frame (`performance.now()` in the page), and
//! the recent pull and over-sketch costs the page benchmark reads.

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

/// How many recent samples [`Timings`] keeps.
const KEPT: usize = 1024;

/// Recent costs of pulls and over-sketches, in ms: what the page benchmark reads.
#[derive(Clone, Debug, Default, serde::Serialize)]
pub struct Timings {
    /// Pointer-down: grabbing a curve and factoring the region around it.
    pub grab_ms: Vec<f64>,
    /// Each frame of a drag: curve deformation plus surface update.
    pub frame_ms: Vec<f64>,
    /// Release: applying the `pull` op (full re-optimization and remesh).
    pub commit_ms: Vec<f64>,
    /// Applying an `oversketch` op: silhouettes, matching, factorization and the edit.
    pub oversketch_ms: Vec<f64>,
}

impl Timings {
    /// Records one cost; the oldest half of a full buffer goes.
    pub fn record(buffer: &mut Vec<f64>, ms: f64) {
        if buffer.len() == KEPT {
            buffer.drain(..KEPT / 2);
        }
        buffer.push(ms);
    }

    /// Takes everything recorded so far.
    pub fn take(&mut self) -> Timings {
        std::mem::take(self)
    }
}
