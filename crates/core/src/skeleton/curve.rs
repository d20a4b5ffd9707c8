//! The handle's curve through its control points (Blanco App. A, §7).
//!
//! An interpolating Catmull-Rom spline with the end points repeated, so it passes through
//! every control point with no tangent to edit. The thesis prints the basis without its
//! factor ½ (`p(0)` would be `2 p_i`); it is restored here. The global parameter `t ∈ [0, 1]`
//! is split uniformly over the spans (A.10–A.11; the last span is clamped rather than
//! padded). A *rigid-limb* curve (§7's skeleton constraint) is a Hermite span per pair of
//! control points with tangents a fifth of Catmull-Rom's: straight limbs, slightly bent at
//! the joints.

use glam::DVec3;

/// How short a rigid limb's tangents are, as a fraction of Catmull-Rom's (the thesis says
/// only "small").
const RIGID_TANGENT: f64 = 0.2;

/// A curve through control points, evaluated by global parameter.
#[derive(Clone, Copy, Debug)]
pub struct Spline<'a> {
    points: &'a [DVec3],
    is_rigid: bool,
}

impl<'a> Spline<'a> {
    /// The curve through `points` (at least two); `is_rigid` for rigid limbs.
    pub fn new(points: &'a [DVec3], is_rigid: bool) -> Self {
        debug_assert!(points.len() >= 2);
        Spline { points, is_rigid }
    }

    /// The parameter at control point `k`.
    pub fn parameter_of(&self, k: usize) -> f64 {
        k as f64 / (self.points.len() - 1) as f64
    }

    /// The point and the derivative (per unit of global parameter) at `t`.
    pub fn eval(&self, t: f64) -> (DVec3, DVec3) {
        let spans = self.points.len() - 1;
        let scaled = t.clamp(0.0, 1.0) * spans as f64;
        let span = (scaled.floor() as usize).min(spans - 1);
        let s = scaled - span as f64;
        let at = |i: isize| self.points[i.clamp(0, spans as isize) as usize];
        let i = span as isize;
        let (p0, p1, p2, p3) = (at(i - 1), at(i), at(i + 1), at(i + 2));
        let (point, derivative) = if self.is_rigid {
            let m1 = RIGID_TANGENT * 0.5 * (p2 - p0);
            let m2 = RIGID_TANGENT * 0.5 * (p3 - p1);
            hermite(p1, m1, p2, m2, s)
        } else {
            catmull_rom(p0, p1, p2, p3, s)
        };
        (point, derivative * spans as f64)
    }
}

/// Catmull-Rom on one span, with App. A's coefficients and the factor ½.
fn catmull_rom(p0: DVec3, p1: DVec3, p2: DVec3, p3: DVec3, s: f64) -> (DVec3, DVec3) {
    let a = -p0 + 3.0 * p1 - 3.0 * p2 + p3;
    let b = 2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3;
    let c = -p0 + p2;
    let d = 2.0 * p1;
    let point = 0.5 * (((a * s + b) * s + c) * s + d);
    let derivative = 0.5 * ((3.0 * a * s + 2.0 * b) * s + c);
    (point, derivative)
}

/// A cubic Hermite span from `p1` (tangent `m1`) to `p2` (tangent `m2`).
fn hermite(p1: DVec3, m1: DVec3, p2: DVec3, m2: DVec3, s: f64) -> (DVec3, DVec3) {
    let (s2, s3) = (s * s, s * s * s);
    let point = (2.0 * s3 - 3.0 * s2 + 1.0) * p1
        + (s3 - 2.0 * s2 + s) * m1
        + (-2.0 * s3 + 3.0 * s2) * p2
        + (s3 - s2) * m2;
    let derivative = (6.0 * s2 - 6.0 * s) * p1
        + (3.0 * s2 - 4.0 * s + 1.0) * m1
        + (-6.0 * s2 + 6.0 * s) * p2
        + (3.0 * s2 - 2.0 * s) * m2;
    (point, derivative)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points() -> Vec<DVec3> {
        vec![
            DVec3::ZERO,
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(2.0, 0.0, 1.0),
            DVec3::new(3.0, 2.0, 0.0),
        ]
    }

    #[test]
    fn the_curve_passes_through_every_control_point() {
        let points = points();
        for is_rigid in [false, true] {
            let spline = Spline::new(&points, is_rigid);
            for (k, &p) in points.iter().enumerate() {
                let (at, _) = spline.eval(spline.parameter_of(k));
                assert!(at.distance(p) < 1e-12, "{k}: {at} against {p}");
            }
        }
    }

    #[test]
    fn the_derivative_matches_finite_differences() {
        let points = points();
        let spline = Spline::new(&points, false);
        for t in [0.1, 0.4, 0.8] {
            let h = 1e-6;
            let numeric = (spline.eval(t + h).0 - spline.eval(t - h).0) / (2.0 * h);
            assert!(numeric.distance(spline.eval(t).1) < 1e-5);
        }
    }

    #[test]
    fn a_rigid_limb_stays_near_its_chord() {
        let points = points();
        let spline = Spline::new(&points, true);
        let (a, b) = (points[1], points[2]);
        let (mid, _) = spline.eval((spline.parameter_of(1) + spline.parameter_of(2)) / 2.0);
        let chord = (b - a).normalize();
        let off = (mid - a) - (mid - a).dot(chord) * chord;
        let smooth = Spline::new(&points, false).eval(0.5).0;
        let smooth_off = (smooth - a) - (smooth - a).dot(chord) * chord;
        assert!(off.length() < 0.3 * smooth_off.length().max(1e-3) + 0.05);
        assert!(off.length() < 0.05 * (b - a).length());
    }
}
