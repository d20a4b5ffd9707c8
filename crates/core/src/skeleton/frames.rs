//! The frame field along a handle's curve (Blanco §5.1, Alg. 6; §5.3).
//!
//! [`FRAMES`] frames at evenly spaced parameters, each a point `p`, a unit tangent `u` (the
//! normal of the frame's plane) and two unit axes `v`, `w` across the curve with a scale
//! each. The first rest frame follows Alg. 6 (the tangent projected onto the world XZ
//! plane, or XY when the tangent is mostly vertical, turned by 90°). The thesis then
//! propagates `v` by projecting it onto the next plane and flips `w` when it turns over,
//! which drifts on finite steps and can leave a left-handed frame (digest §3.4); the
//! double-reflection rotation-minimising frames of Wang et al. 2008 are used instead, the
//! drop-in replacement the digest suggests. A deformed curve's first frame is the rest
//! one turned by the smallest rotation taking the old tangent to the new one, and never
//! Alg. 6 again (its plane could switch and the frames would diverge); the rest propagate
//! at the same parameters. Twist and scale (§5.3) turn `v`, `w` about `u` and scale them,
//! interpolated linearly between control points.

use glam::{DQuat, DVec3};

use super::curve::Spline;

/// Frames per curve: the thesis uses 200 in every example.
pub const FRAMES: usize = 200;

/// One frame: a point on the curve, the plane normal and the scaled axes across.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// The curve point.
    pub p: DVec3,
    /// The unit normal of the frame's plane: the curve's tangent.
    pub u: DVec3,
    /// The first unit axis across.
    pub v: DVec3,
    /// The second unit axis across, `u × v`.
    pub w: DVec3,
    /// The scales along `v` and `w`.
    pub scale: [f64; 2],
}

impl Frame {
    /// A local point `(α, β, γ)` (along `u`, `v`, `w`; `β`, `γ` in scaled units) in world.
    pub fn to_world(&self, alpha: f64, beta: f64, gamma: f64) -> DVec3 {
        self.p + alpha * self.u + beta * self.scale[0] * self.v + gamma * self.scale[1] * self.w
    }

    /// The local coordinates of a world point (the inverse of [`Frame::to_world`]).
    pub fn to_local(&self, x: DVec3) -> DVec3 {
        let q = x - self.p;
        DVec3::new(
            q.dot(self.u),
            q.dot(self.v) / self.scale[0],
            q.dot(self.w) / self.scale[1],
        )
    }

    /// The signed distance of `x` in front of the frame's plane.
    pub fn height(&self, x: DVec3) -> f64 {
        (x - self.p).dot(self.u)
    }

    /// Turns the frame's axes by `rotation` (its point stays).
    pub fn turned(self, rotation: DQuat) -> Frame {
        Frame {
            u: (rotation * self.u).normalize(),
            v: (rotation * self.v).normalize(),
            w: (rotation * self.w).normalize(),
            ..self
        }
    }
}

/// The parameter of frame `i`.
pub fn frame_parameter(i: usize) -> f64 {
    i as f64 / (FRAMES - 1) as f64
}

/// The curve's twist (radians) and scales per control point.
#[derive(Clone, Copy, Debug)]
pub struct Shaping<'a> {
    /// Twist about the tangent at each control point.
    pub twist: &'a [f64],
    /// Scales of `v` and `w` at each control point.
    pub scale: &'a [[f64; 2]],
}

/// The rest frames of a curve: Alg. 6's first frame, propagated.
pub fn rest_frames(spline: &Spline, shaping: Shaping) -> Vec<Frame> {
    let (points, tangents) = samples(spline);
    let v = first_axis(tangents[0]);
    propagate(&points, &tangents, v, shaping)
}

/// The frames of a deformed curve: the first untwisted rest axis (from the rest curve's
/// first tangent `rest_u`) turned onto the new tangent, propagated at the same parameters.
/// The same curve gives the same frames bit for bit.
pub fn deformed_frames(spline: &Spline, rest_u: DVec3, shaping: Shaping) -> Vec<Frame> {
    let (points, tangents) = samples(spline);
    let v = first_axis(rest_u);
    let v = if tangents[0] == rest_u {
        v
    } else {
        DQuat::from_rotation_arc(rest_u, tangents[0]) * v
    };
    propagate(&points, &tangents, v, shaping)
}

/// The first frame's axis across a unit tangent `u` (Alg. 6): `u` projected onto the world
/// XZ plane (XY when `u` is mostly vertical) and turned by 90° in it.
fn first_axis(u: DVec3) -> DVec3 {
    let v = if u.x.abs() >= u.y.abs() {
        DVec3::new(-u.z, 0.0, u.x)
    } else {
        DVec3::new(-u.y, u.x, 0.0)
    };
    v.try_normalize()
        .unwrap_or_else(|| u.any_orthonormal_vector())
}

/// Points and unit tangents at the frame parameters.
fn samples(spline: &Spline) -> (Vec<DVec3>, Vec<DVec3>) {
    let (points, derivatives): (Vec<DVec3>, Vec<DVec3>) =
        (0..FRAMES).map(|i| spline.eval(frame_parameter(i))).unzip();
    let tangents = (0..FRAMES)
        .map(|i| {
            derivatives[i].try_normalize().unwrap_or_else(|| {
                let (a, b) = (i.saturating_sub(1), (i + 1).min(FRAMES - 1));
                (points[b] - points[a]).try_normalize().unwrap_or(DVec3::X)
            })
        })
        .collect();
    (points, tangents)
}

/// Double-reflection frames from a first `v`, then the shaping applied.
fn propagate(points: &[DVec3], tangents: &[DVec3], first_v: DVec3, shaping: Shaping) -> Vec<Frame> {
    let mut vs = Vec::with_capacity(FRAMES);
    let mut v = (first_v - first_v.dot(tangents[0]) * tangents[0]).normalize();
    vs.push(v);
    for i in 0..FRAMES - 1 {
        let v1 = points[i + 1] - points[i];
        let c1 = v1.length_squared();
        let (v_l, t_l) = if c1 > 0.0 {
            (
                v - (2.0 / c1) * v1.dot(v) * v1,
                tangents[i] - (2.0 / c1) * v1.dot(tangents[i]) * v1,
            )
        } else {
            (v, tangents[i])
        };
        let v2 = tangents[i + 1] - t_l;
        let c2 = v2.length_squared();
        v = if c2 > 0.0 {
            v_l - (2.0 / c2) * v2.dot(v_l) * v2
        } else {
            v_l
        };
        let u = tangents[i + 1];
        v = (v - v.dot(u) * u).normalize();
        vs.push(v);
    }
    let control_points = shaping.twist.len();
    let scale_v: Vec<f64> = shaping.scale.iter().map(|s| s[0]).collect();
    let scale_w: Vec<f64> = shaping.scale.iter().map(|s| s[1]).collect();
    (0..FRAMES)
        .map(|i| {
            let (u, v) = (tangents[i], vs[i]);
            let t = frame_parameter(i);
            let twist = interpolate(shaping.twist, t, control_points);
            let v = if twist == 0.0 {
                v
            } else {
                DQuat::from_axis_angle(u, twist) * v
            };
            Frame {
                p: points[i],
                u,
                v,
                w: u.cross(v),
                scale: [
                    interpolate(&scale_v, t, control_points),
                    interpolate(&scale_w, t, control_points),
                ],
            }
        })
        .collect()
}

/// A per-control-point value at parameter `t`, linear between control points.
fn interpolate(values: &[f64], t: f64, control_points: usize) -> f64 {
    if control_points < 2 {
        return values.first().copied().unwrap_or(0.0);
    }
    let scaled = t * (control_points - 1) as f64;
    let k = (scaled.floor() as usize).min(control_points - 2);
    let s = scaled - k as f64;
    values[k] + s * (values[k + 1] - values[k])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rest frames of the untwisted, unscaled curve through `points`.
    fn plain_frames(points: &[DVec3]) -> Vec<Frame> {
        let (twist, scale) = (vec![0.0; points.len()], vec![[1.0, 1.0]; points.len()]);
        rest_frames(
            &Spline::new(points, false),
            Shaping {
                twist: &twist,
                scale: &scale,
            },
        )
    }

    #[test]
    fn frames_are_orthonormal_and_right_handed_on_a_bent_curve() {
        let points = [
            DVec3::ZERO,
            DVec3::new(1.0, 0.5, 0.2),
            DVec3::new(1.5, 1.5, -0.4),
            DVec3::new(1.0, 2.5, 0.3),
        ];
        let frames = plain_frames(&points);
        for f in &frames {
            assert!((f.u.length() - 1.0).abs() < 1e-12 && (f.v.length() - 1.0).abs() < 1e-12);
            assert!(f.u.dot(f.v).abs() < 1e-12);
            assert!(f.u.cross(f.v).distance(f.w) < 1e-12);
        }
        for pair in frames.windows(2) {
            assert!(pair[0].v.angle_between(pair[1].v) < 3f64.to_radians());
        }
    }

    #[test]
    fn a_planar_curve_keeps_its_frames_in_and_across_its_plane() {
        let points = [
            DVec3::ZERO,
            DVec3::new(2.0, 0.5, 0.0),
            DVec3::new(3.0, -0.5, 0.0),
            DVec3::new(5.0, 1.0, 0.0),
        ];
        let frames = plain_frames(&points);
        // Alg. 6 picks XZ for a mostly-x tangent: v is the plane normal ±z and stays so.
        for f in &frames {
            assert!(f.v.z.abs() > 1.0 - 1e-9, "{}", f.v);
        }
    }

    #[test]
    fn a_straight_curve_has_constant_frames_and_twist_turns_them_linearly() {
        let points = [DVec3::ZERO, DVec3::X, DVec3::X * 2.0];
        let untwisted = plain_frames(&points);
        let frames = rest_frames(
            &Spline::new(&points, false),
            Shaping {
                twist: &[0.0, 0.0, 1.0],
                scale: &[[1.0, 1.0]; 3],
            },
        );
        for (i, (a, b)) in untwisted.iter().zip(&frames).enumerate() {
            assert!(a.v.distance(untwisted[0].v) < 1e-12);
            let t = frame_parameter(i);
            let expected = (2.0 * t - 1.0).max(0.0);
            assert!((a.v.angle_between(b.v) - expected).abs() < 1e-9);
        }
    }
}
