//! Writing a model's key-framed animation: its poses baked at the keys and
//! [`SAMPLES_PER_SECOND`](crate::animation::SAMPLES_PER_SECOND) in-betweens a second (the
//! Laplacian-coordinate interpolation, which a file cannot express), each pose a morph
//! target, and a weights animation that shows one target at its time and blends linearly
//! between neighbours. Every player plays morph-target weights (three.js's `AnimationMixer`,
//! Blender's shape keys); a skin would need bones the deformation does not have.
//!
//! The mesh in the file keeps the model's current pose; a target is a pose's displacement
//! from it. The animation's extras name the key times
//! (`{"sketchmesh":{"keyframes":[t, ...]}}`), so that import takes the keys back and not
//! every baked in-between.

use glam::{DVec3, Vec3};
use gltf::json;
use json::validation::Checked::Valid;
use serde::{Deserialize, Serialize};
use serde_json::value::RawValue;

use super::glb::Writer;
use crate::animation::Timeline;
use crate::model::Model;

/// A model's animation as written: the poses in the written vertex order.
pub(super) struct Baked {
    /// Seconds of each pose.
    pub times: Vec<f64>,
    /// One pose per time, each one position per written vertex.
    pub poses: Vec<Vec<DVec3>>,
    /// The key times among `times`.
    pub key_times: Vec<f64>,
}

/// The `extras` of an animation written here.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct AnimationExtras {
    pub(crate) sketchmesh: KeyTimes,
}

/// The key times of an animation written here.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub(crate) struct KeyTimes {
    pub(crate) keyframes: Vec<f64>,
}

/// `model`'s animation baked for writing, `None` with fewer than two keys that fit it (or
/// keys that cannot be interpolated, which only non-finite poses cause).
pub(super) fn bake(model: &Model) -> Option<Baked> {
    let mut timeline = Timeline::new(model).ok()??;
    let times = timeline.sample_times();
    let mut pose = vec![DVec3::ZERO; model.mesh.n_vertices()];
    let mut poses = Vec::with_capacity(times.len());
    for &t in &times {
        timeline.pose(t, &mut pose).ok()?;
        poses.push(written_positions(model, &pose));
    }
    Some(Baked {
        key_times: timeline.key_times().to_vec(),
        times,
        poses,
    })
}

/// A pose of the model's mesh in the order its vertices are written: the mesh's, or an
/// imported soup's.
fn written_positions(model: &Model, pose: &[DVec3]) -> Vec<DVec3> {
    match model.as_imported() {
        Some(input) => {
            let mut mesh = model.mesh.clone();
            mesh.positions_mut().copy_from_slice(pose);
            input.positions_of(&mesh)
        }
        None => pose.to_vec(),
    }
}

/// One morph target per pose: displacements of the written `base` positions (and of its
/// normals, when given with each pose's own).
pub(super) fn morph_targets(
    writer: &mut Writer,
    base: &[Vec3],
    poses: impl Iterator<Item = (Vec<Vec3>, Option<Vec<Vec3>>)>,
    base_normals: Option<&[Vec3]>,
) -> Vec<json::mesh::MorphTarget> {
    poses
        .map(|(positions, normals)| {
            let moved: Vec<Vec3> = positions.iter().zip(base).map(|(p, b)| *p - *b).collect();
            let normals = normals.zip(base_normals).map(|(normals, base)| {
                let turned: Vec<Vec3> = normals.iter().zip(base).map(|(n, b)| *n - *b).collect();
                writer.vec3s(&turned, None)
            });
            json::mesh::MorphTarget {
                positions: Some(writer.positions(&moved)),
                normals,
                tangents: None,
            }
        })
        .collect()
}

/// The weights animation of `node`: at the `k`-th time, target `k` alone.
pub(super) fn weights_animation(
    writer: &mut Writer,
    node: json::Index<json::Node>,
    baked: &Baked,
    name: String,
) {
    let times: Vec<f32> = baked.times.iter().map(|&t| t as f32).collect();
    let n = times.len();
    let mut weights = vec![0.0f32; n * n];
    for k in 0..n {
        weights[k * n + k] = 1.0;
    }
    let input = writer.scalars(&times, true);
    let output = writer.scalars(&weights, false);
    let extras = serde_json::to_string(&AnimationExtras {
        sketchmesh: KeyTimes {
            keyframes: baked.key_times.clone(),
        },
    })
    .ok()
    .and_then(|json| RawValue::from_string(json).ok());
    writer.root.push(json::Animation {
        extensions: None,
        extras,
        channels: vec![json::animation::Channel {
            sampler: json::Index::new(0),
            target: json::animation::Target {
                extensions: None,
                extras: None,
                node,
                path: Valid(json::animation::Property::MorphTargetWeights),
            },
            extensions: None,
            extras: None,
        }],
        name: Some(name),
        samplers: vec![json::animation::Sampler {
            extensions: None,
            extras: None,
            input,
            interpolation: Valid(json::animation::Interpolation::Linear),
            output,
        }],
    });
}
