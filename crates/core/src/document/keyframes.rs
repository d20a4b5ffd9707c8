//! The `keyframe`, `delete_keyframe` and `pose_at` ops: every model's current pose stored as
//! its key at a time, the keys at a time removed, or every animated model put in its pose at
//! a time (to edit a pose between keys, or to pose each frame from the same rest pose, as
//! retargeting a sequence of drawn curves does).

use std::sync::Arc;

use serde::{Deserialize, Serialize};

use super::{CommandError, Document, Keyframe, Model};
use crate::animation::Timeline;

/// `{"op":"keyframe","time":t}` and `{"op":"delete_keyframe","time":t}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KeyframeInput {
    /// Seconds from the start of the animation; finite and not negative.
    pub time: f64,
}

/// `base` with every model's current pose as its key at `input.time` (replacing a key
/// there).
///
/// Errors: [`CommandError::BadKeyTime`], [`CommandError::NothingToKey`].
pub(super) fn keyframe_op(
    base: &Document,
    input: &KeyframeInput,
) -> Result<Document, CommandError> {
    let time = checked_time(input.time)?;
    if base.models.is_empty() {
        return Err(CommandError::NothingToKey);
    }
    let mut next = base.clone();
    for model in &mut next.models {
        let mut keyed = Model::clone(model);
        let n = keyed.mesh.n_vertices();
        keyed
            .keyframes
            .retain(|k| k.time != time && k.positions.len() == n);
        let at = keyed.keyframes.partition_point(|k| k.time < time);
        keyed.keyframes.insert(
            at,
            Keyframe {
                time,
                positions: Arc::new(keyed.mesh.positions().to_vec()),
            },
        );
        *model = Arc::new(keyed);
    }
    Ok(next)
}

/// `base` without the keys at `input.time`.
///
/// Errors: [`CommandError::BadKeyTime`], [`CommandError::NoKeyAt`].
pub(super) fn delete_keyframe_op(
    base: &Document,
    input: &KeyframeInput,
) -> Result<Document, CommandError> {
    let time = checked_time(input.time)?;
    let mut next = base.clone();
    let mut found = false;
    for model in &mut next.models {
        if model.keyframes.iter().any(|k| k.time == time) {
            found = true;
            let mut unkeyed = Model::clone(model);
            unkeyed.keyframes.retain(|k| k.time != time);
            *model = Arc::new(unkeyed);
        }
    }
    if !found {
        return Err(CommandError::NoKeyAt(time));
    }
    Ok(next)
}

/// `base` with every model that has key frames in its pose at `input.time` (held before the
/// first key and after the last); its keys stay.
///
/// Errors: [`CommandError::BadKeyTime`], [`CommandError::NoKeyframes`], and a failed
/// interpolation.
pub(super) fn pose_at_op(base: &Document, input: &KeyframeInput) -> Result<Document, CommandError> {
    let time = checked_time(input.time)?;
    let mut next = base.clone();
    let mut posed = false;
    for model in &mut next.models {
        let keys: Vec<&Keyframe> = model.keyframes().collect();
        let pose = match keys.as_slice() {
            [] => continue,
            [only] => only.positions.to_vec(),
            _ => {
                let mut pose = vec![glam::DVec3::ZERO; model.mesh.n_vertices()];
                if let Some(mut timeline) = Timeline::new(model).map_err(CommandError::Surface)? {
                    timeline
                        .pose(time, &mut pose)
                        .map_err(CommandError::Surface)?;
                }
                pose
            }
        };
        let mut moved = Model::clone(model);
        moved.mesh.positions_mut().copy_from_slice(&pose);
        *model = Arc::new(moved);
        posed = true;
    }
    if !posed {
        return Err(CommandError::NoKeyframes);
    }
    Ok(next)
}

fn checked_time(time: f64) -> Result<f64, CommandError> {
    if time.is_finite() && time >= 0.0 {
        Ok(time)
    } else {
        Err(CommandError::BadKeyTime)
    }
}
