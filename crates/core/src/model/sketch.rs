//! Free sketch curves: ink strokes placed in 3D.

use glam::DVec3;

/// An ink stroke placed in 3D: the processed screen stroke projected onto a plane.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SketchCurve {
    /// Points in world space, in drawing order.
    pub points: Vec<DVec3>,
    /// Pen pressure (0..=1) at each point; same length as `points`.
    pub pressures: Vec<f64>,
}
