//! A model's animation through time: its key poses held before the first and after the
//! last, the in-betweens of each pair of neighbouring keys by [`KeyBlend`].

use glam::DVec3;

use super::KeyBlend;
use crate::model::Model;
use crate::solve::SolveError;

/// In-betweens per second an export bakes between keys (besides the keys themselves).
pub const SAMPLES_PER_SECOND: f64 = 12.0;

/// A model's animation, each pair of neighbouring keys factored once.
#[derive(Debug)]
pub struct Timeline {
    times: Vec<f64>,
    blends: Vec<KeyBlend>,
    first: Vec<DVec3>,
}

impl Timeline {
    /// The animation of `model`'s keys that fit its mesh; `None` with fewer than two.
    ///
    /// Errors: those of [`KeyBlend::new`].
    pub fn new(model: &Model) -> Result<Option<Timeline>, SolveError> {
        let keys: Vec<_> = model.keyframes().collect();
        if keys.len() < 2 {
            return Ok(None);
        }
        let blends = keys
            .windows(2)
            .map(|pair| KeyBlend::new(&model.mesh, &pair[0].positions, &pair[1].positions))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(Some(Timeline {
            times: keys.iter().map(|k| k.time).collect(),
            blends,
            first: keys[0].positions.to_vec(),
        }))
    }

    /// The first key's time.
    pub fn start(&self) -> f64 {
        self.times[0]
    }

    /// The last key's time.
    pub fn end(&self) -> f64 {
        self.times[self.times.len() - 1]
    }

    /// The keys' times.
    pub fn key_times(&self) -> &[f64] {
        &self.times
    }

    /// The pose at time `t` into `out`.
    ///
    /// Errors: [`SolveError::DimensionMismatch`] when `out` has the wrong length.
    pub fn pose(&mut self, t: f64, out: &mut [DVec3]) -> Result<(), SolveError> {
        if t <= self.start() {
            crate::solve::check_len("pose", self.first.len(), out.len())?;
            out.copy_from_slice(&self.first);
            return Ok(());
        }
        let pair = self
            .times
            .partition_point(|&k| k <= t)
            .min(self.times.len() - 1)
            - 1;
        let (t0, t1) = (self.times[pair], self.times[pair + 1]);
        self.blends[pair].at((t - t0) / (t1 - t0), out)
    }

    /// The times an export bakes: every key, and [`SAMPLES_PER_SECOND`] evenly between each
    /// pair.
    pub fn sample_times(&self) -> Vec<f64> {
        let mut times = vec![self.start()];
        for pair in self.times.windows(2) {
            let steps = ((pair[1] - pair[0]) * SAMPLES_PER_SECOND).ceil().max(1.0) as usize;
            for k in 1..=steps {
                times.push(pair[0] + (pair[1] - pair[0]) * k as f64 / steps as f64);
            }
        }
        times
    }
}
