//! Propagating the handles' transforms through the volume (Zhou et al. 2005, §3.3
//! "Propagation of Local Transforms"): each point gets the weighted mean of the handles'
//! similarities, weighted by inverse geodesic distance to each handle (the paper's choice
//! with the Gaussian, "works best"), blended toward the identity by a strength field that
//! decays away from the handles.
//!
//! The paper's field decays with the geodesic distance to the control curve over a radius
//! it leaves to the user. With a fixed part the natural radius is the way to it: the field
//! is a function of `t = d_F / (d_F + d_H)`, the share of the way from the fixed part (0)
//! to the nearest handle (1), so a bend is spread over exactly the free length between
//! them. Without a fixed part the field is 1 everywhere.
//!
//! Blending toward the identity turns the rotation by part of its angle about its own
//! axis and interpolates the scale (a lerp of matrices with the identity, as printed,
//! would shrink a turned coordinate; the digest makes the same remark).

use super::Similarity;
use super::similarity::weighted_mean;

/// How the strength field decays from the handles (1) to the fixed part (0).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Falloff {
    /// Full strength wherever the handles reach.
    Constant,
    /// Strength `t`.
    #[default]
    Linear,
    /// A Gaussian bell of the distance from the handles (σ = 0.4 of the way), shifted and
    /// scaled to run from 0 at the fixed part to 1 at the handles: the bend gathers near the
    /// handles.
    Gaussian,
}

/// The Gaussian field's σ, as a share of the way from the handles to the fixed part.
const GAUSSIAN_SIGMA: f64 = 0.4;

impl Falloff {
    /// The strength at share `t` of the way from the fixed part to the handles.
    pub fn strength(self, t: f64) -> f64 {
        let t = t.clamp(0.0, 1.0);
        match self {
            Falloff::Constant => f64::from(u8::from(t > 0.0)),
            Falloff::Linear => t,
            Falloff::Gaussian => {
                let bell = |u: f64| (-(u * u) / (2.0 * GAUSSIAN_SIGMA * GAUSSIAN_SIGMA)).exp();
                (bell(1.0 - t) - bell(1.0)) / (1.0 - bell(1.0))
            }
        }
    }
}

/// Each point's similarity: `handles[h]` with `handle_distances[h][i]` the geodesic distance
/// from point `i` to handle `h`, `fixed_distances[i]` the distance to the fixed part
/// (infinite everywhere when there is none). Writes into `out`, one per point.
pub fn spread(
    handles: &[Similarity],
    handle_distances: &[Vec<f64>],
    fixed_distances: &[f64],
    falloff: Falloff,
    out: &mut [Similarity],
) {
    for (i, out) in out.iter_mut().enumerate() {
        let nearest = handle_distances
            .iter()
            .map(|d| d[i])
            .fold(f64::INFINITY, f64::min);
        if !nearest.is_finite() {
            *out = Similarity::IDENTITY;
            continue;
        }
        let mean = if nearest == 0.0 {
            let h = handle_distances
                .iter()
                .position(|d| d[i] == 0.0)
                .unwrap_or(0);
            handles[h]
        } else {
            let weighted = handles
                .iter()
                .zip(handle_distances)
                .filter(|(_, d)| d[i].is_finite())
                .map(|(&s, d)| (s, 1.0 / d[i]));
            weighted_mean(weighted).unwrap_or(Similarity::IDENTITY)
        };
        let fixed = fixed_distances[i];
        let t = if fixed.is_finite() {
            fixed / (fixed + nearest)
        } else {
            1.0
        };
        *out = mean.part(falloff.strength(t));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DMat3;

    #[test]
    fn fields_run_from_zero_at_the_fixed_part_to_one_at_the_handles() {
        for falloff in [Falloff::Linear, Falloff::Gaussian] {
            assert_eq!(falloff.strength(0.0), 0.0);
            assert!((falloff.strength(1.0) - 1.0).abs() < 1e-12);
            let samples: Vec<f64> = (0..=10)
                .map(|k| falloff.strength(k as f64 / 10.0))
                .collect();
            assert!(
                samples.windows(2).all(|w| w[1] > w[0]),
                "{falloff:?} {samples:?}"
            );
        }
        assert_eq!(Falloff::Constant.strength(0.3), 1.0);
    }

    #[test]
    fn a_point_halfway_turns_half_way() {
        let turn = Similarity::nearest(DMat3::from_rotation_z(1.0)).unwrap();
        let mut out = [Similarity::IDENTITY; 3];
        spread(
            &[turn],
            &[vec![0.0, 1.0, 3.0]],
            &[2.0, 1.0, 0.0],
            Falloff::Linear,
            &mut out,
        );
        assert_eq!(out[0], turn);
        let (_, angle) = out[1].rotation.to_axis_angle();
        assert!((angle - 0.5).abs() < 1e-12);
        assert_eq!(out[2], Similarity::IDENTITY);
    }
}
