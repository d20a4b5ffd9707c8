//! Stroke samples: a screen position and a pen pressure. Their own file, because both the
//! stroke clean-up and the smoothing use them.

use glam::DVec2;

use super::polyline::PolylinePoint;

/// One sample of a pointer stroke.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrokePoint {
    /// Position in screen space (CSS px, y down, origin top-left).
    pub pos: DVec2,
    /// Pen pressure in 0..=1; 0.5 for a mouse or a touch without force.
    pub pressure: f64,
}

impl StrokePoint {
    /// A point with the given position and pressure.
    pub fn new(pos: DVec2, pressure: f64) -> Self {
        Self { pos, pressure }
    }
}

/// Resampling interpolates pressure linearly along with the position.
impl PolylinePoint for StrokePoint {
    fn position(&self) -> DVec2 {
        self.pos
    }

    fn interpolate(self, other: Self, t: f64) -> Self {
        StrokePoint {
            pos: self.pos.lerp(other.pos, t),
            pressure: self.pressure + (other.pressure - self.pressure) * t,
        }
    }
}
