//! A rotation with an isotropic scale: what the paper lets a point's Laplacian coordinate
//! undergo ("a rotation and isotropic scale", after Sorkine et al. 2004, since a general
//! linear map could fit away the detail).

use glam::{DMat3, DQuat, DVec3};

use crate::deform::best_rotation;

/// `x ↦ scale · rotation · x`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Similarity {
    /// The rotation, a unit quaternion.
    pub rotation: DQuat,
    /// The isotropic scale, positive.
    pub scale: f64,
}

impl Similarity {
    /// Leaves every vector as it is.
    pub const IDENTITY: Similarity = Similarity {
        rotation: DQuat::IDENTITY,
        scale: 1.0,
    };

    /// The similarity nearest to the linear map `m`: its polar rotation and the cube root
    /// of its determinant; `None` when `m` is not finite, singular or mirrors.
    pub fn nearest(m: DMat3) -> Option<Similarity> {
        let det = m.determinant();
        let largest = m
            .to_cols_array()
            .iter()
            .map(|x| x.abs())
            .fold(0.0, f64::max);
        // A determinant this small next to the entries is a flattening map.
        if !m.is_finite() || det.is_nan() || det <= 1e-12 * largest.powi(3) {
            return None;
        }
        let rotation = DQuat::from_mat3(&best_rotation(m)).normalize();
        Some(Similarity {
            rotation,
            scale: det.cbrt(),
        })
    }

    /// The same rotation about the axis turned the other way round (`θ − 2π` for `θ`):
    /// the same map, but a different path from the identity.
    pub fn the_long_way(self) -> Similarity {
        Similarity {
            rotation: -self.rotation,
            ..self
        }
    }

    /// The part `f ∈ [0, 1]` of the way from the identity to `self`: the rotation's angle
    /// times `f` (about the same axis, along the quaternion's own hemisphere) and the scale
    /// interpolated linearly.
    pub fn part(self, f: f64) -> Similarity {
        if f == 1.0 {
            return self;
        }
        if f == 0.0 {
            return Similarity::IDENTITY;
        }
        Similarity {
            rotation: power(self.rotation, f),
            scale: 1.0 + f * (self.scale - 1.0),
        }
    }

    /// The map as a matrix.
    pub fn matrix(self) -> DMat3 {
        DMat3::from_quat(self.rotation) * self.scale
    }

    /// `self` applied to `v`.
    pub fn apply(self, v: DVec3) -> DVec3 {
        self.rotation * v * self.scale
    }
}

/// `q^f` along `q`'s own hemisphere (glam's `slerp` would take the shorter arc, which for a
/// half turn flips with round-off).
fn power(q: DQuat, f: f64) -> DQuat {
    let w = q.w.clamp(-1.0, 1.0);
    let half_angle = w.acos();
    let sin = half_angle.sin();
    if sin.abs() < 1e-15 {
        return DQuat::IDENTITY;
    }
    let axis = DVec3::new(q.x, q.y, q.z) / sin;
    let scaled = half_angle * f;
    let (s, c) = scaled.sin_cos();
    DQuat::from_xyzw(axis.x * s, axis.y * s, axis.z * s, c)
}

/// The weighted mean of similarities: quaternions aligned with the first one's hemisphere,
/// summed and normalised (Markley et al.'s chordal mean, adequate for nearby rotations), and
/// the scales' weighted mean; exactly the one similarity when all are the same. `None` for
/// no weight.
pub fn weighted_mean(items: impl Iterator<Item = (Similarity, f64)>) -> Option<Similarity> {
    let mut first: Option<Similarity> = None;
    let mut all_same = true;
    let mut sum = DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    let mut scale = 0.0;
    let mut total = 0.0;
    for (s, w) in items {
        let reference = first.get_or_insert(s).rotation;
        all_same &= first == Some(s);
        let aligned = if reference.dot(s.rotation) < 0.0 {
            -s.rotation
        } else {
            s.rotation
        };
        sum += aligned * w;
        scale += s.scale * w;
        total += w;
    }
    if all_same && total > 0.0 {
        // Exactly the one similarity (normalising its weighted sum could round it).
        return first;
    }
    (total > 0.0 && sum.length() > 0.0).then(|| Similarity {
        rotation: sum.normalize(),
        scale: scale / total,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn half_of_a_half_turn_is_a_quarter_turn_in_the_chosen_direction() {
        let half = Similarity::nearest(DMat3::from_rotation_z(PI) * 2.0).unwrap();
        assert!((half.scale - 2.0).abs() < 1e-12);
        let quarter = half.part(0.5);
        let the_other = half.the_long_way().part(0.5);
        let x = quarter.apply(DVec3::X);
        let y = the_other.apply(DVec3::X);
        assert!((x.length() - 1.5).abs() < 1e-12);
        assert!(x.normalize().dot(y.normalize()) < -0.999, "{x} {y}");
        assert!(x.x.abs() < 1e-9 && y.x.abs() < 1e-9);
        assert_eq!(half.part(1.0), half);
        assert_eq!(half.part(0.0), Similarity::IDENTITY);
    }

    #[test]
    fn mirrors_and_singular_maps_have_no_similarity() {
        assert!(Similarity::nearest(DMat3::from_diagonal(DVec3::new(1.0, 1.0, -1.0))).is_none());
        assert!(Similarity::nearest(DMat3::ZERO).is_none());
        assert!(
            Similarity::nearest(DMat3::from_diagonal(DVec3::new(1.0, f64::NAN, 1.0))).is_none()
        );
    }

    #[test]
    fn the_mean_of_two_turns_is_the_turn_between() {
        let a = Similarity::nearest(DMat3::from_rotation_y(0.2)).unwrap();
        let b = Similarity::nearest(DMat3::from_rotation_y(0.6)).unwrap();
        let mean = weighted_mean([(a, 1.0), (b, 1.0)].into_iter()).unwrap();
        let (axis, angle) = mean.rotation.to_axis_angle();
        assert!(
            (angle - 0.4).abs() < 1e-3 && axis.y > 0.99,
            "{axis} {angle}"
        );
    }
}
