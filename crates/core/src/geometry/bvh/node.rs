//! The pieces of the hierarchy: boxes and nodes.

use glam::DVec3;

use crate::mesh::{FaceId, Mesh};

/// A box and either a leaf's face range (`count > 0`) or an inner node's children
/// (`first` and `first + 1`, `count == 0`).
#[derive(Clone, Copy, Debug)]
pub(super) struct Node {
    pub(super) bounds: Aabb,
    pub(super) first: u32,
    pub(super) count: u32,
}

/// An axis-aligned box, empty when `lo > hi`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Aabb {
    /// Smallest corner.
    pub(super) lo: DVec3,
    /// Largest corner.
    pub(super) hi: DVec3,
}

impl Aabb {
    /// Grows to anything.
    pub(super) const EMPTY: Self = Self {
        lo: DVec3::INFINITY,
        hi: DVec3::NEG_INFINITY,
    };

    pub(super) fn grow(&mut self, other: Self) {
        self.lo = self.lo.min(other.lo);
        self.hi = self.hi.max(other.hi);
    }
}

/// The box around one triangle.
pub(super) fn triangle_box(mesh: &Mesh, f: u32) -> Aabb {
    let [a, b, c] = mesh.face_positions(FaceId(f));
    Aabb {
        lo: a.min(b).min(c),
        hi: a.max(b).max(c),
    }
}
