//! Playing the key-framed animation in the page: every model with two or more keys follows
//! its timeline (the core's in-betweens, each pair of keys factored when play starts), from
//! the first key's time to the last, once; the document itself does not change.

use glam::DVec3;
use sketchmesh_core::animation::Timeline;
use sketchmesh_core::document::Document;

/// An animation being played.
#[derive(Debug)]
pub struct Playback {
    /// Each animated model's index, timeline and current pose.
    models: Vec<(usize, Timeline, Vec<DVec3>)>,
    /// The clock (ms) when play started.
    started_ms: f64,
    start: f64,
    end: f64,
}

impl Playback {
    /// Starts playing `doc`'s animation at clock time `now_ms`; `Err` with a sentence when
    /// there is nothing to play.
    pub fn start(doc: &Document, now_ms: f64) -> Result<Playback, String> {
        let mut models = Vec::new();
        for (index, model) in doc.models.iter().enumerate() {
            match Timeline::new(model) {
                Ok(Some(timeline)) => {
                    let pose = vec![DVec3::ZERO; model.mesh.n_vertices()];
                    models.push((index, timeline, pose));
                }
                Ok(None) => {}
                Err(err) => return Err(format!("The animation cannot be played: {err}")),
            }
        }
        let start = models
            .iter()
            .map(|(_, t, _)| t.start())
            .fold(f64::INFINITY, f64::min);
        let end = models
            .iter()
            .map(|(_, t, _)| t.end())
            .fold(f64::NEG_INFINITY, f64::max);
        if models.is_empty() {
            return Err(String::from(
                "Key two poses at different times to play them.",
            ));
        }
        Ok(Playback {
            models,
            started_ms: now_ms,
            start,
            end,
        })
    }

    /// The animation's time at clock time `now_ms` (s), `None` once it has played through.
    pub fn time(&self, now_ms: f64) -> Option<f64> {
        let t = self.start + (now_ms - self.started_ms) / 1e3;
        (t <= self.end).then_some(t)
    }

    /// Each animated model's index and pose at time `t`.
    pub fn poses(&mut self, t: f64) -> impl Iterator<Item = (usize, &[DVec3])> {
        self.models
            .iter_mut()
            .filter_map(move |(index, timeline, pose)| {
                timeline.pose(t, pose).ok()?;
                Some((*index, pose.as_slice()))
            })
    }
}
