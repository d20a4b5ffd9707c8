//! Key frames of a model's animation: its vertex positions at a time.

use std::sync::Arc;

use glam::DVec3;

/// The model's pose at `time`: one position per vertex of its mesh.
#[derive(Clone, Debug, PartialEq)]
pub struct Keyframe {
    /// Seconds from the start of the animation.
    pub time: f64,
    /// The pose: one position per mesh vertex, in the mesh's order.
    pub positions: Arc<Vec<DVec3>>,
}
