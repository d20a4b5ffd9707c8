//! Reading morph-target animations back as key poses: for each node whose weights an
//! animation drives, the weights at each time of its sampler, then each triangle
//! primitive's positions at those weights. A file written here names its key times in the
//! animation's extras ([`AnimationExtras`]): only those come back, not the baked
//! in-betweens. A foreign file's every sampled time becomes a key, at most
//! [`MAX_KEYS`] of them.

use std::collections::HashMap;

use glam::DVec3;

use super::GltfError;
use super::accessor::read_f64;
use super::animation_write::AnimationExtras;
use super::resources::Buffers;

/// The most key poses read for one node (evenly chosen among more).
pub(crate) const MAX_KEYS: usize = 256;

/// The weights animation of one node: per key time, one weight per morph target.
#[derive(Clone, Debug, Default)]
pub(crate) struct NodeAnimation {
    /// Seconds.
    pub(crate) times: Vec<f64>,
    /// The weights at each time.
    pub(crate) weights: Vec<Vec<f64>>,
    /// How many sampled times were left out (over [`MAX_KEYS`]).
    pub(crate) skipped: usize,
}

/// The first weights animation of each node that has one, by node index.
pub(crate) fn node_animations(
    document: &gltf::Document,
    buffers: &Buffers,
) -> Result<HashMap<usize, NodeAnimation>, GltfError> {
    let mut found = HashMap::new();
    for animation in document.animations() {
        let key_times = animation
            .extras()
            .as_ref()
            .and_then(|raw| serde_json::from_str::<AnimationExtras>(raw.get()).ok())
            .map(|extras| extras.sketchmesh.keyframes);
        for channel in animation.channels() {
            let target = channel.target();
            if target.property() != gltf::animation::Property::MorphTargetWeights {
                continue;
            }
            let node = target.node();
            let Some(mesh) = node.mesh() else { continue };
            let n_targets = mesh
                .primitives()
                .map(|p| p.morph_targets().len())
                .max()
                .unwrap_or(0);
            if n_targets == 0 || found.contains_key(&node.index()) {
                continue;
            }
            let sampler = channel.sampler();
            let times = read_f64::<1>(&sampler.input(), buffers, usize::MAX)?;
            let values = read_f64::<1>(&sampler.output(), buffers, usize::MAX)?;
            // Cubic splines store an in-tangent, the value and an out-tangent per time.
            let per_time = match sampler.interpolation() {
                gltf::animation::Interpolation::CubicSpline => 3 * n_targets,
                _ => n_targets,
            };
            let skip = usize::from(per_time == 3 * n_targets) * n_targets;
            let mut rows: Vec<(f64, Vec<f64>)> = times
                .iter()
                .enumerate()
                .filter_map(|(k, t)| {
                    let start = k * per_time + skip;
                    let row = values.get(start..start + n_targets)?;
                    Some((t[0], row.iter().map(|v| v[0]).collect()))
                })
                .collect();
            if let Some(keys) = &key_times {
                rows.retain(|(t, _)| keys.iter().any(|&k| k as f32 == *t as f32));
                for (row, &key) in rows.iter_mut().zip(keys) {
                    row.0 = key;
                }
            }
            let total = rows.len();
            if total > MAX_KEYS {
                rows = (0..MAX_KEYS)
                    .map(|k| rows[k * (total - 1) / (MAX_KEYS - 1)].clone())
                    .collect();
            }
            let (times, weights) = rows.into_iter().unzip();
            found.insert(
                node.index(),
                NodeAnimation {
                    times,
                    weights,
                    skipped: total.saturating_sub(MAX_KEYS),
                },
            );
        }
    }
    Ok(found)
}

/// The node-space positions of `primitive` at each of `animation`'s times: `base` plus its
/// morph targets' displacements at the weights of that time.
pub(crate) fn posed(
    primitive: &gltf::Primitive,
    buffers: &Buffers,
    animation: &NodeAnimation,
    base: &[DVec3],
) -> Result<Vec<Vec<DVec3>>, GltfError> {
    let mut displacements = Vec::new();
    for target in primitive.morph_targets() {
        let moved = match target.positions() {
            Some(accessor) => read_f64::<3>(&accessor, buffers, base.len())?,
            None => Vec::new(),
        };
        displacements.push(moved);
    }
    Ok(animation
        .weights
        .iter()
        .map(|row| {
            let mut pose = base.to_vec();
            for (w, moved) in row.iter().zip(&displacements) {
                if *w == 0.0 {
                    continue;
                }
                for (p, d) in pose.iter_mut().zip(moved) {
                    *p += *w * DVec3::from(*d);
                }
            }
            pose
        })
        .collect())
}
