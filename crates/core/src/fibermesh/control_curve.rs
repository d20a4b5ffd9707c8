//! Control curves: chains of mesh vertices that define the surface, smooth or sharp.

use serde::{Deserialize, Serialize};

use crate::mesh::VertexId;

/// How a control curve constrains the surface across it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum CurveKind {
    /// The surface passes through the curve and is smooth across it (drawn blue).
    Smooth,
    /// The surface passes through the curve with a crease along it (drawn red).
    Sharp,
}

/// A chain of mesh vertices the surface passes through.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ControlCurve {
    /// The chain, in order.
    pub vertices: Vec<VertexId>,
    /// Whether the last vertex connects back to the first.
    pub is_closed: bool,
    /// Smooth or sharp.
    pub kind: CurveKind,
}
