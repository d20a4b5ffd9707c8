//! Stroke samples: a screen position and a pen pressure.

use glam::DVec2;

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

/// Total length of the polyline through the points.
pub fn arc_length(points: &[StrokePoint]) -> f64 {
    points
        .windows(2)
        .map(|pair| pair[0].pos.distance(pair[1].pos))
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(points: &[(f64, f64)]) -> Vec<StrokePoint> {
        points
            .iter()
            .map(|&(x, y)| StrokePoint::new(DVec2::new(x, y), 0.5))
            .collect()
    }

    #[test]
    fn arc_length_of_a_polyline() {
        assert_eq!(
            arc_length(&line(&[(0.0, 0.0), (3.0, 4.0), (3.0, 10.0)])),
            11.0
        );
        assert_eq!(arc_length(&line(&[(1.0, 1.0)])), 0.0);
        assert_eq!(arc_length(&[]), 0.0);
    }
}
