//! Hard constraints `C x = t` for handles inside edges and faces, on top of a prefactored
//! least-squares system, by the Schur complement (range-space method).
//!
//! A handle at a vertex is simply a fixed unknown. A point inside an edge or face couples
//! two or three unknowns (Eq. 4.2), so it cannot be fixed; instead, with `N = A_fᵀ A_f` the
//! factored normal matrix and `x0` the unconstrained minimiser, the constrained minimiser of
//! `||A x - b||²` subject to `C x = t` is
//!
//! `x = x0 - Z λ`, with `Z = N⁻¹ Cᵀ` and `S λ = C x0 - t`, `S = C Z` (k x k, positive definite).
//!
//! `Z` (one Green's function per handle) and the dense Cholesky factor of `S` are computed
//! once with the same factorization; each solve then costs `O(k · n)` on top of the usual
//! back-substitution and nothing is refactored. Rows of `C` touching fixed unknowns only use
//! their free part; `C x0 - t` already includes the fixed values.
//!
//! A current limitation: `Z` is dense, `n × k` numbers, so this suits up to a few hundred
//! such handles (100 handles on a 5k-vertex region: 4 MB). Dependent handles (three points on
//! one edge, or a handle whose vertices are all fixed) make `S` singular and are reported.

use faer::linalg::matmul::matmul;
use faer::{Accum, Mat, Par};
use glam::DVec3;

use crate::solve::{Prefactored, SolveError};

/// A pivot of `S` below this fraction of its diagonal entry means the constraint repeats
/// others (up to round-off).
const MIN_RELATIVE_PIVOT: f64 = 1e-10;

/// One constraint row: up to three `(unknown, coefficient)` terms.
pub(crate) type ConstraintRow = Vec<(usize, f64)>;

/// Precomputed Schur complement for hard barycentric constraints; see the module docs.
#[derive(Clone, Debug)]
pub(crate) struct ExactConstraints {
    rows: Vec<ConstraintRow>,
    /// `Z = N⁻¹ Cᵀ`, `n × k` (zero rows for fixed unknowns).
    green: Mat<f64>,
    /// Lower Cholesky factor of `S`, row-major `k × k`.
    schur_factor: Vec<f64>,
    /// `C x - t`, then `λ`.
    lambda: Vec<DVec3>,
    /// `λ` as a `k × 3` matrix, and `Z λ` (`n × 3`): the correction is one dense product
    /// (faer's blocked SIMD kernel, several times faster than a loop over `DVec3`s).
    lambda_matrix: Mat<f64>,
    correction: Mat<f64>,
}

impl ExactConstraints {
    /// Precomputes `Z` and the factor of `S` for `rows` of `C`, with `solver` factored over
    /// `n` unknowns.
    ///
    /// Errors: [`SolveError::Singular`] when the constraints are dependent, and those of
    /// [`Prefactored::solve_normal_columns`].
    pub(crate) fn new(
        solver: &mut Prefactored,
        rows: Vec<ConstraintRow>,
    ) -> Result<ExactConstraints, SolveError> {
        let (n, k) = (solver.n_unknowns(), rows.len());
        let mut columns = Mat::<f64>::zeros(n, k);
        for (m, row) in rows.iter().enumerate() {
            for &(j, c) in row {
                columns[(j, m)] += c;
            }
        }
        solver.solve_normal_columns(columns.as_mut())?;
        let green = columns;
        let mut schur = vec![0.0; k * k];
        for (m, row) in rows.iter().enumerate() {
            for &(j, c) in row {
                for l in 0..k {
                    schur[m * k + l] += c * green[(j, l)];
                }
            }
        }
        cholesky_in_place(&mut schur, k)?;
        Ok(ExactConstraints {
            rows,
            green,
            schur_factor: schur,
            lambda: vec![DVec3::ZERO; k],
            lambda_matrix: Mat::zeros(k, 3),
            correction: Mat::zeros(n, 3),
        })
    }

    /// Number of constraints.
    pub(crate) fn len(&self) -> usize {
        self.rows.len()
    }

    /// Moves the unconstrained minimiser `x` onto `C x = targets` (the constrained minimiser).
    pub(crate) fn project(&mut self, targets: impl Fn(usize) -> DVec3, x: &mut [DVec3]) {
        let k = self.rows.len();
        if k == 0 {
            return;
        }
        for (m, row) in self.rows.iter().enumerate() {
            let cx: DVec3 = row.iter().map(|&(j, c)| c * x[j]).sum();
            self.lambda[m] = cx - targets(m);
        }
        // S λ = r with S = L Lᵀ: forward, then backward substitution.
        let l = &self.schur_factor;
        for m in 0..k {
            let sum: DVec3 = (0..m).map(|p| l[m * k + p] * self.lambda[p]).sum();
            self.lambda[m] = (self.lambda[m] - sum) / l[m * k + m];
        }
        for m in (0..k).rev() {
            let sum: DVec3 = (m + 1..k).map(|p| l[p * k + m] * self.lambda[p]).sum();
            self.lambda[m] = (self.lambda[m] - sum) / l[m * k + m];
        }
        debug_assert_eq!(x.len(), self.correction.nrows());
        for (m, lambda) in self.lambda.iter().enumerate() {
            for (c, value) in lambda.to_array().into_iter().enumerate() {
                self.lambda_matrix[(m, c)] = value;
            }
        }
        matmul(
            self.correction.as_mut(),
            Accum::Replace,
            self.green.as_ref(),
            self.lambda_matrix.as_ref(),
            1.0,
            Par::Seq,
        );
        for (j, xj) in x.iter_mut().enumerate() {
            let c = &self.correction;
            *xj -= DVec3::new(c[(j, 0)], c[(j, 1)], c[(j, 2)]);
        }
    }
}

/// Overwrites the lower triangle of the symmetric row-major `k × k` matrix `a` with its
/// Cholesky factor.
fn cholesky_in_place(a: &mut [f64], k: usize) -> Result<(), SolveError> {
    for m in 0..k {
        let diagonal = a[m * k + m];
        let pivot = diagonal - (0..m).map(|p| a[m * k + p] * a[m * k + p]).sum::<f64>();
        if pivot.is_nan() || pivot <= MIN_RELATIVE_PIVOT * diagonal {
            return Err(SolveError::Singular);
        }
        let root = pivot.sqrt();
        a[m * k + m] = root;
        for r in m + 1..k {
            let dot: f64 = (0..m).map(|p| a[r * k + p] * a[m * k + p]).sum();
            a[r * k + m] = (a[r * k + m] - dot) / root;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve::Triplets;
    use crate::solve::tests::dense_solve;

    /// A 1D chain: `x_{i+1} - x_i = 1` for 6 unknowns, with x_0 fixed.
    fn chain() -> (Prefactored, Vec<DVec3>, Vec<DVec3>) {
        let n = 6;
        let mut t = Triplets::new(n - 1, n);
        for i in 0..n - 1 {
            t.push(i, i, -1.0);
            t.push(i, i + 1, 1.0);
        }
        let mut fixed = vec![false; n];
        fixed[0] = true;
        let solver = Prefactored::new(&t.build(), &fixed).unwrap();
        (solver, vec![DVec3::ONE; n - 1], vec![DVec3::ZERO; n])
    }

    #[test]
    fn projection_matches_the_kkt_system() {
        let (mut solver, b, fixed_values) = chain();
        let rows = vec![vec![(2, 0.5), (3, 0.5)], vec![(5, 1.0)]];
        let targets = [DVec3::new(4.0, 1.0, 0.0), DVec3::new(3.0, 2.0, -1.0)];
        let mut exact = ExactConstraints::new(&mut solver, rows).unwrap();
        let mut x = vec![DVec3::ZERO; 6];
        solver.solve(&b, &fixed_values, &mut x).unwrap();
        exact.project(|m| targets[m], &mut x);
        assert!((0.5 * (x[2] + x[3]) - targets[0]).length() < 1e-12);
        assert!((x[5] - targets[1]).length() < 1e-12);
        // KKT by dense elimination for the x coordinate: unknowns x1..x5, then μ1, μ2.
        // Energy Σ (x_{i+1} - x_i - 1)² with x0 = 0; gradient/2 = N x - r.
        let mut m = vec![vec![0.0; 7]; 7];
        let mut rhs = vec![0.0; 7];
        for i in 0..5usize {
            // Row of edge (i, i+1) in unknowns x1..x5 (index i-1 and i).
            let (a, c) = (i.checked_sub(1), i);
            for (p, sp) in [(a, -1.0), (Some(c), 1.0)] {
                let Some(p) = p else { continue };
                rhs[p] += sp;
                for (q, sq) in [(a, -1.0), (Some(c), 1.0)] {
                    if let Some(q) = q {
                        m[p][q] += sp * sq;
                    }
                }
            }
        }
        for (row, col, c) in [(5, 1, 0.5), (5, 2, 0.5), (6, 4, 1.0)] {
            m[row][col] = c;
            m[col][row] = c;
        }
        rhs[5] = targets[0].x;
        rhs[6] = targets[1].x;
        let expected = dense_solve(m, rhs);
        for i in 1..6 {
            assert!(
                (x[i].x - expected[i - 1]).abs() < 1e-12,
                "{i}: {} vs {}",
                x[i].x,
                expected[i - 1]
            );
        }
    }

    #[test]
    fn dependent_constraints_are_reported() {
        let (mut solver, _, _) = chain();
        let repeated = vec![vec![(2, 1.0)], vec![(2, 2.0)]];
        assert_eq!(
            ExactConstraints::new(&mut solver, repeated).unwrap_err(),
            SolveError::Singular
        );
        let on_fixed = vec![vec![(0, 1.0)]];
        assert_eq!(
            ExactConstraints::new(&mut solver, on_fixed).unwrap_err(),
            SolveError::Singular
        );
    }
}
