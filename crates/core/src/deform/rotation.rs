//! The rotation closest to a 3x3 matrix: the orthogonal Procrustes / Kabsch problem.
//!
//! `best_rotation(M)` maximises `tr(Rᵀ M)` over proper rotations. For an ARAP covariance
//! `M = Σ w e' eᵀ` (deformed edges `e'` against rest edges `e`) that is the `R` minimising
//! `Σ w ||e' - R e||²` (Sorkine & Alexa 2007, Eq. 5). The answer is the polar factor
//! `U diag(1, 1, ±1) Vᵀ` of the SVD `M = U Σ Vᵀ`, with the sign making `det R = +1`.
//!
//! glam has no SVD, so this computes it the small way: cyclic Jacobi on the symmetric
//! `MᵀM = V Σ² Vᵀ` gives `V`; then `u1 = M v1 / |M v1|`, `u2` is `M v2` made orthogonal to `u1`,
//! and `u3 = u1 × u2`. Building `u3` by a cross product instead of from `M v3` is what makes
//! this robust: a flat one-ring has a rank-2 covariance (`σ3 = 0`), and `M v3` is then noise,
//! but the rotation is still determined by `u1, u2` and orientation. With `U` proper by
//! construction, `R = U diag(1, 1, det V) Vᵀ` (the Kabsch sign rule rewritten for this `U`).
//!
//! A current limitation: for a rank-1 covariance (all edges collinear) the rotation about
//! that line is not determined, and this returns one of the optimal rotations, not the one
//! closest to the identity.

use glam::{DMat3, DVec3};

/// Jacobi sweeps; 3x3 converges quadratically, in 4 or 5 sweeps to round-off.
const MAX_SWEEPS: usize = 12;

/// The proper rotation `R` maximising `tr(Rᵀ m)`; the identity for a zero matrix.
pub(crate) fn best_rotation(m: DMat3) -> DMat3 {
    let (eigenvalues, v) = symmetric_eigen(m.transpose() * m);
    // Columns of V by decreasing eigenvalue (singular value squared).
    let mut order = [0, 1, 2];
    order.sort_by(|&a, &b| eigenvalues[b].total_cmp(&eigenvalues[a]));
    let [v1, v2, v3] = order.map(|k| v.col(k));
    let det_v = v1.cross(v2).dot(v3).signum();

    let m_v1 = m * v1;
    let scale = m_v1.length();
    if scale <= f64::MIN_POSITIVE || !scale.is_finite() {
        return DMat3::IDENTITY;
    }
    let u1 = m_v1 / scale;
    let m_v2 = m * v2;
    let mut u2 = m_v2 - u1.dot(m_v2) * u1;
    if u2.length() <= 1e-12 * scale {
        // Rank 1: any direction orthogonal to u1 is optimal; take the one nearest v2.
        u2 = v2 - u1.dot(v2) * u1;
        if u2.length() <= 1e-6 {
            u2 = u1.any_orthonormal_vector();
        }
    }
    let u2 = u2.normalize();
    let u3 = u1.cross(u2);
    outer(u1, v1) + outer(u2, v2) + outer(u3, v3) * det_v
}

/// [`best_rotation`] warm-started from a nearby rotation `start`, as in the ARAP local step,
/// where each vertex's rotation changes little between iterations.
///
/// Newton's method on `f(ω) = tr((R exp[ω]ₓ)ᵀ M)`: with `S = Rᵀ M`, the gradient at `ω = 0`
/// is the axial vector of `S - Sᵀ` and the Hessian `-(tr(S) I - sym(S))`, so a step solves
/// a 3x3 system. It converges quadratically from a good start; when the Hessian is not
/// clearly definite (a start far off, or a rank-1 covariance) or a step is large, this falls
/// back to the SVD route.
pub(crate) fn refine_rotation(m: DMat3, start: DMat3) -> DMat3 {
    let mut r = start;
    for _ in 0..MAX_NEWTON_STEPS {
        let s = r.transpose() * m;
        let gradient = DVec3::new(
            s.y_axis.z - s.z_axis.y,
            s.z_axis.x - s.x_axis.z,
            s.x_axis.y - s.y_axis.x,
        );
        let symmetric = (s + s.transpose()) * 0.5;
        let trace = s.x_axis.x + s.y_axis.y + s.z_axis.z;
        let hessian = DMat3::from_diagonal(DVec3::splat(trace)) - symmetric;
        if !is_clearly_positive_definite(hessian, trace) {
            return best_rotation(m);
        }
        let step = hessian.inverse() * gradient;
        let angle = step.length();
        if angle.is_nan() || angle >= MAX_NEWTON_ANGLE {
            return best_rotation(m);
        }
        if angle <= NEWTON_TOLERANCE {
            break;
        }
        r *= DMat3::from_axis_angle(step / angle, angle);
    }
    r
}

/// Newton steps before giving up on convergence (quadratic: 2 or 3 from a warm start).
const MAX_NEWTON_STEPS: usize = 4;
/// A Newton step longer than this (radians) means the start was far off.
const MAX_NEWTON_ANGLE: f64 = 0.5;
/// Steps below this angle (radians) end the iteration.
const NEWTON_TOLERANCE: f64 = 1e-12;

/// Whether the symmetric `h` is positive definite with its smallest pivot above `1e-6 scale`.
fn is_clearly_positive_definite(h: DMat3, scale: f64) -> bool {
    let floor = 1e-6 * scale.abs();
    let minor1 = h.x_axis.x;
    let minor2 = h.x_axis.x * h.y_axis.y - h.x_axis.y * h.y_axis.x;
    // Leading minors over their predecessors are the Cholesky pivots.
    minor1 > floor && minor2 > floor * minor1 && h.determinant() > floor * minor2
}

/// `a bᵀ`.
fn outer(a: DVec3, b: DVec3) -> DMat3 {
    DMat3::from_cols(a * b.x, a * b.y, a * b.z)
}

/// Eigenvalues and eigenvectors (columns) of a symmetric 3x3 matrix, by cyclic Jacobi
/// rotations (Golub & Van Loan, Algorithm 8.5.3).
fn symmetric_eigen(s: DMat3) -> ([f64; 3], DMat3) {
    // a[row][col]; symmetric, so the column-major DMat3 reads the same.
    let mut a = s.to_cols_array_2d();
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let norm2: f64 = a.iter().flatten().map(|x| x * x).sum();
    for _ in 0..MAX_SWEEPS {
        let off2 = 2.0 * (a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2]);
        if off2 <= 1e-32 * norm2 || off2 == 0.0 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            let tau = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = tau.signum() / (tau.abs() + (1.0 + tau * tau).sqrt());
            let c = 1.0 / (1.0 + t * t).sqrt();
            let s = t * c;
            // A <- Jᵀ A J with J the rotation in the (p, q) plane.
            for row in &mut a {
                let (x, y) = (row[p], row[q]);
                row[p] = c * x - s * y;
                row[q] = s * x + c * y;
            }
            let (row_p, row_q) = (a[p], a[q]);
            a[p] = std::array::from_fn(|k| c * row_p[k] - s * row_q[k]);
            a[q] = std::array::from_fn(|k| s * row_p[k] + c * row_q[k]);
            // V <- V J, with V stored as rows of columns: v[col][row].
            let (vp, vq) = (v[p], v[q]);
            v[p] = std::array::from_fn(|k| c * vp[k] - s * vq[k]);
            v[q] = std::array::from_fn(|k| s * vp[k] + c * vq[k]);
        }
    }
    ([a[0][0], a[1][1], a[2][2]], DMat3::from_cols_array_2d(&v))
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;

    /// A deterministic pseudo-random unit quaternion per seed.
    fn rotation(seed: u32) -> DMat3 {
        let s = seed as f64;
        let q = DQuat::from_xyzw(
            (s * 1.7).sin(),
            (s * 2.3 + 0.4).cos(),
            (s * 0.9 + 1.1).sin(),
            (s * 3.1 + 0.2).cos(),
        );
        DMat3::from_quat(q.normalize())
    }

    fn points(seed: u32, n: usize) -> Vec<DVec3> {
        (0..n)
            .map(|k| {
                let t = (seed as f64) * 0.37 + k as f64;
                DVec3::new((t * 1.3).sin(), (t * 0.7 + 1.0).cos(), (t * 2.1).sin())
            })
            .collect()
    }

    fn covariance(deformed: &[DVec3], rest: &[DVec3]) -> DMat3 {
        deformed
            .iter()
            .zip(rest)
            .fold(DMat3::ZERO, |m, (&a, &b)| m + outer(a, b))
    }

    fn assert_rotation_close(got: DMat3, want: DMat3, tolerance: f64) {
        assert!(
            (got.determinant() - 1.0).abs() < 1e-12,
            "det {}",
            got.determinant()
        );
        let error = (got - want)
            .to_cols_array()
            .iter()
            .map(|x| x.abs())
            .fold(0.0, f64::max);
        assert!(error < tolerance, "{got} vs {want}: {error}");
    }

    #[test]
    fn recovers_a_rotation_from_rotated_points() {
        for seed in 0..50 {
            let r = rotation(seed);
            let rest = points(seed, 6);
            let deformed: Vec<DVec3> = rest.iter().map(|&p| r * p).collect();
            assert_rotation_close(best_rotation(covariance(&deformed, &rest)), r, 1e-12);
        }
    }

    #[test]
    fn recovers_a_rotation_from_a_flat_one_ring() {
        // Edges of a planar hexagon fan: rank-2 covariance, the ARAP case on a flat patch.
        let rest: Vec<DVec3> = (0..6)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / 6.0 + 0.2;
                DVec3::new(a.cos(), a.sin(), 0.0) * (1.0 + 0.1 * k as f64)
            })
            .collect();
        for seed in 0..50 {
            let r = rotation(seed);
            let deformed: Vec<DVec3> = rest.iter().map(|&p| r * p).collect();
            assert_rotation_close(best_rotation(covariance(&deformed, &rest)), r, 1e-12);
        }
        // The undeformed flat ring gives exactly the identity up to round-off.
        assert_rotation_close(
            best_rotation(covariance(&rest, &rest)),
            DMat3::IDENTITY,
            1e-14,
        );
    }

    #[test]
    fn beats_every_sampled_rotation_when_a_reflection_fits_best() {
        let rest = points(3, 7);
        // A mirror image: the best proper rotation is not the polar factor.
        let deformed: Vec<DVec3> = rest
            .iter()
            .map(|p| DVec3::new(-p.x, p.y, p.z) * 1.5)
            .collect();
        let m = covariance(&deformed, &rest);
        let best = best_rotation(m);
        assert!((best.determinant() - 1.0).abs() < 1e-12);
        let score = |r: DMat3| {
            (r.transpose() * m)
                .to_cols_array()
                .iter()
                .step_by(4)
                .sum::<f64>()
        };
        for seed in 0..2000 {
            assert!(score(best) >= score(rotation(seed)) - 1e-12);
        }
    }

    #[test]
    fn warm_starts_converge_to_the_same_rotation() {
        let rest = points(5, 6);
        let flat: Vec<DVec3> = rest.iter().map(|p| DVec3::new(p.x, p.y, 0.0)).collect();
        for seed in 0..50 {
            let r = rotation(seed);
            for shape in [&rest, &flat] {
                // Deformed by the rotation and a small shear, so the optimum is not exact.
                let deformed: Vec<DVec3> = shape
                    .iter()
                    .map(|&p| r * (p + 0.1 * p.y * DVec3::X))
                    .collect();
                let m = covariance(&deformed, shape);
                let nearby = r * DMat3::from_axis_angle(DVec3::new(1.0, 2.0, 2.0) / 3.0, 0.3);
                assert_rotation_close(refine_rotation(m, nearby), best_rotation(m), 1e-10);
                // A start on the far side still gives the optimum (by the fallback).
                let far = r * DMat3::from_rotation_x(3.0);
                assert_rotation_close(refine_rotation(m, far), best_rotation(m), 1e-10);
            }
        }
        // The identity stays exactly the identity for an undeformed ring.
        let m = covariance(&rest, &rest);
        assert_eq!(refine_rotation(m, DMat3::IDENTITY), DMat3::IDENTITY);
    }

    #[test]
    fn degenerate_covariances_give_rotations() {
        assert_eq!(best_rotation(DMat3::ZERO), DMat3::IDENTITY);
        let line = outer(DVec3::X, DVec3::Y);
        let r = best_rotation(line);
        assert!((r.determinant() - 1.0).abs() < 1e-12);
        assert!((r * DVec3::Y - DVec3::X).length() < 1e-12);
    }
}
