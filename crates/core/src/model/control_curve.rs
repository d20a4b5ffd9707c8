//! Control curves: chains of mesh vertices that define the surface, smooth or sharp.
//!
//! This is the one control-curve type: a document's models store it ([`super::Model`]'s
//! `curves`), the FiberMesh solver takes it and the curve tools edit it. A curve
//! holds no positions of its own; where it is follows from the mesh it lies on
//! ([`ControlCurve::points`]), so a deformation or a remesh can never leave it behind.

use glam::DVec3;
use serde::{Deserialize, Serialize};

use crate::mesh::{Mesh, VertexId};

/// How a control curve constrains the surface across it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum CurveKind {
    /// The surface passes through the curve and is smooth across it (drawn blue).
    #[default]
    Smooth,
    /// The surface passes through the curve with a crease along it (drawn red).
    Sharp,
}

/// A chain of mesh vertices the surface passes through: consecutive vertices share a mesh
/// edge (and so do the last and the first of a closed curve).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct ControlCurve {
    /// The chain, in order.
    pub vertices: Vec<VertexId>,
    /// Whether the last vertex connects back to the first (the first is not repeated).
    pub is_closed: bool,
    /// Smooth or sharp.
    pub kind: CurveKind,
}

impl ControlCurve {
    /// The curve's points: the positions of its vertices on `mesh`, in order.
    ///
    /// Panics if a vertex is not in `mesh` (the curve belongs to another mesh).
    pub fn points(&self, mesh: &Mesh) -> Vec<DVec3> {
        self.vertices.iter().map(|&v| mesh.position(v)).collect()
    }

    /// Whether the surface has a crease along the curve.
    pub fn is_sharp(&self) -> bool {
        self.kind == CurveKind::Sharp
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    #[test]
    fn points_follow_the_mesh() {
        let mut mesh = primitives::icosphere(1.0, 1);
        let curve = ControlCurve {
            vertices: vec![VertexId(0), VertexId(1), VertexId(2)],
            is_closed: true,
            kind: CurveKind::Sharp,
        };
        assert_eq!(curve.points(&mesh)[1], mesh.position(VertexId(1)));
        mesh.positions_mut()[1] = DVec3::new(2.0, 0.0, 0.0);
        assert_eq!(curve.points(&mesh)[1], DVec3::new(2.0, 0.0, 0.0));
        assert!(curve.is_sharp());
        assert!(!ControlCurve::default().is_sharp());
    }
}
