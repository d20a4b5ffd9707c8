//! Playing the key-framed animation in the page: every model with two or more keys follows
//! its timeline (the core's in-betweens, each pair of keys factored when play starts), from
//! the first key's time to the last, once; the document itself does not change. Time runs
//! with the clock, but a frame advances it by at most [`MAX_STEP_MS`]: on a machine too slow
//! to draw the model smoothly the animation plays slower rather than skipping to its end.

use glam::DVec3;
use sketchmesh_core::animation::Timeline;
use sketchmesh_core::document::Document;

/// The most animation time one frame advances (ms).
const MAX_STEP_MS: f64 = 1000.0 / 15.0;

/// A model the animation moves.
#[derive(Debug)]
struct Animated {
    /// Its index in the document.
    index: usize,
    timeline: Timeline,
    /// Its vertices at the time last asked for.
    pose: Vec<DVec3>,
    /// Whether `pose` holds that time's pose (its solve may fail).
    is_posed: bool,
}

/// An animation being played.
#[derive(Debug)]
pub struct Playback {
    /// Each animated model.
    models: Vec<Animated>,
    /// The clock (ms) at the last frame.
    last_ms: f64,
    /// The animation's time now (s).
    time: f64,
    end: f64,
}

impl Playback {
    /// Starts playing `doc`'s animation at clock time `now_ms`; `Err` with a sentence when
    /// there is nothing to play.
    pub fn start(doc: &Document, now_ms: f64) -> Result<Playback, String> {
        let mut models = Vec::new();
        for (index, model) in doc.models.iter().enumerate() {
            match Timeline::new(model) {
                Ok(Some(timeline)) => models.push(Animated {
                    index,
                    timeline,
                    pose: vec![DVec3::ZERO; model.mesh.n_vertices()],
                    is_posed: false,
                }),
                Ok(None) => {}
                Err(err) => return Err(format!("The animation cannot be played: {err}")),
            }
        }
        let start = models
            .iter()
            .map(|m| m.timeline.start())
            .fold(f64::INFINITY, f64::min);
        let end = models
            .iter()
            .map(|m| m.timeline.end())
            .fold(f64::NEG_INFINITY, f64::max);
        if models.is_empty() {
            return Err(String::from(
                "Key two poses at different times to play them.",
            ));
        }
        Ok(Playback {
            models,
            last_ms: now_ms,
            time: start,
            end,
        })
    }

    /// The animation's time for the frame at clock time `now_ms` (s), `None` once it has
    /// played through.
    pub fn advance(&mut self, now_ms: f64) -> Option<f64> {
        let step = (now_ms - self.last_ms).clamp(0.0, MAX_STEP_MS);
        self.last_ms = now_ms;
        self.time += step / 1e3;
        (self.time <= self.end).then_some(self.time)
    }

    /// Each animated model's index and pose at time `t`.
    pub fn poses(&mut self, t: f64) -> impl Iterator<Item = (usize, &[DVec3])> {
        for model in &mut self.models {
            model.is_posed = model.timeline.pose(t, &mut model.pose).is_ok();
        }
        self.shown()
    }

    /// Each animated model's index and pose at the time last asked for ([`Playback::poses`]).
    pub fn shown(&self) -> impl Iterator<Item = (usize, &[DVec3])> {
        (self.models.iter())
            .filter(|model| model.is_posed)
            .map(|model| (model.index, model.pose.as_slice()))
    }
}
