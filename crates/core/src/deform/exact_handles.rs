//! Hard constraints `C x = t` for handles inside edges and faces, on top of a prefactored
//! least-squares system, by the Schur complement (range-space method).
//!
//! A handle at a vertex is simply a fixed unknown. A point inside an edge or face couples
//! two or three unknowns (Eq. 4.2), so it cannot be fixed; instead, with `N = A_fᵀ A_f` the
//! factored normal matrix and `x0` the unconstrained minimiser, the constrained minimiser of
//! `||A x - b||²` subject to `C x = t` is
//!
//! `x = x0 - N⁻¹ Cᵀ λ`, with `S λ = C x0 - t`, `S = C N⁻¹ Cᵀ` (k x k, positive definite).
//!
//! With the factor `N = Pᵀ L Lᵀ P` and `Y = L⁻¹ P Cᵀ`, `S = Yᵀ Y`, `C x0 = Yᵀ u` for the
//! intermediate `u = L⁻¹ P r` of the solve, and the correction is `u ← u - Y λ` before the
//! backward substitution ([`Prefactored::solve_with`]). The constrained unknowns are ordered
//! last ([`Prefactored::with_last`]), so `Y` lives in the factor's trailing rows: setting up
//! costs a forward substitution over those rows only, not the `k` full solves that the
//! Green's functions `N⁻¹ Cᵀ` would take (24 of 39 ms on a 5k-vertex ROI with 105 handles,
//! before this), and a frame adds two small dense products. Rows of `C` touching fixed
//! unknowns use their free part in `Y` and the fixed part, with the fixed values, in the
//! residual.
//!
//! Dependent handles (three points on one edge, or a handle whose vertices are all fixed)
//! make `S` singular and are reported.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::{
    LltRegularization, cholesky_in_place, cholesky_in_place_scratch,
};
use faer::linalg::cholesky::llt::solve::solve_in_place;
use faer::linalg::matmul::matmul;
use faer::{Accum, Mat, MatMut, Par};
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
    /// The terms of each row on fixed unknowns.
    fixed_terms: Vec<ConstraintRow>,
    /// First row of `Y` (in the factor's order) that can be nonzero.
    first_row: usize,
    /// Rows `first_row..` of `Y = L⁻¹ P C_fᵀ`.
    green: Mat<f64>,
    /// Lower Cholesky factor of `S = Yᵀ Y`.
    schur_factor: Mat<f64>,
    /// `C x - t`, then `λ`, as a `k × 3` matrix.
    lambda: Mat<f64>,
}

impl ExactConstraints {
    /// Precomputes `Y` and the factor of `S` for `rows` of `C`, with `solver` factored over
    /// `n` unknowns, the constrained ones best ordered last.
    ///
    /// Errors: [`SolveError::Singular`] when the constraints are dependent.
    pub(crate) fn new(
        solver: &Prefactored,
        rows: Vec<ConstraintRow>,
    ) -> Result<ExactConstraints, SolveError> {
        let k = rows.len();
        let (first_row, green) = solver.forward_sparse_columns(&rows);
        let mut schur = Mat::<f64>::zeros(k, k);
        matmul(
            schur.as_mut(),
            Accum::Replace,
            green.transpose(),
            green.as_ref(),
            1.0,
            Par::Seq,
        );
        let diagonal: Vec<f64> = (0..k).map(|m| schur[(m, m)]).collect();
        let mut memory = MemBuffer::try_new(cholesky_in_place_scratch::<f64>(
            k,
            Par::Seq,
            Default::default(),
        ))
        .map_err(|_| SolveError::Factorization("out of memory".to_owned()))?;
        cholesky_in_place(
            schur.as_mut(),
            LltRegularization::default(),
            Par::Seq,
            MemStack::new(&mut memory),
            Default::default(),
        )
        .map_err(|_| SolveError::Singular)?;
        let dependent = (0..k).any(|m| {
            let pivot = schur[(m, m)] * schur[(m, m)];
            pivot.is_nan() || pivot <= MIN_RELATIVE_PIVOT * diagonal[m]
        });
        if dependent {
            return Err(SolveError::Singular);
        }
        let fixed = solver.fixed();
        let fixed_terms = rows
            .into_iter()
            .map(|row| row.into_iter().filter(|&(j, _)| fixed[j]).collect())
            .collect();
        Ok(ExactConstraints {
            fixed_terms,
            first_row,
            green,
            schur_factor: schur,
            lambda: Mat::zeros(k, 3),
        })
    }

    /// Number of constraints.
    pub(crate) fn len(&self) -> usize {
        self.fixed_terms.len()
    }

    /// Turns the intermediate `u` of an unconstrained solve (see
    /// [`Prefactored::solve_with`]) into that of the solve constrained to `C x = targets`,
    /// with the fixed unknowns at `fixed_values`. Allocates nothing.
    pub(crate) fn correct(
        &mut self,
        u: MatMut<'_, f64>,
        fixed_values: &[DVec3],
        targets: impl Fn(usize) -> DVec3,
    ) {
        if self.len() == 0 {
            return;
        }
        let mut tail = u.subrows_mut(self.first_row, self.green.nrows());
        matmul(
            self.lambda.as_mut(),
            Accum::Replace,
            self.green.transpose(),
            tail.as_ref(),
            1.0,
            Par::Seq,
        );
        for (m, terms) in self.fixed_terms.iter().enumerate() {
            let fixed: DVec3 = terms.iter().map(|&(j, c)| c * fixed_values[j]).sum();
            let residual = fixed - targets(m);
            for (c, value) in residual.to_array().into_iter().enumerate() {
                self.lambda[(m, c)] += value;
            }
        }
        solve_in_place(
            self.schur_factor.as_ref(),
            self.lambda.as_mut(),
            Par::Seq,
            MemStack::new(&mut []),
        );
        matmul(
            tail.as_mut(),
            Accum::Add,
            self.green.as_ref(),
            self.lambda.as_ref(),
            -1.0,
            Par::Seq,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve::Triplets;
    use crate::solve::test_support::dense_solve;

    /// A 1D chain: `x_{i+1} - x_i = 1` for 6 unknowns, with x_0 fixed, and `last` ordered
    /// last.
    fn chain(last: &[usize]) -> (Prefactored, Vec<DVec3>, Vec<DVec3>) {
        let n = 6;
        let mut t = Triplets::new(n - 1, n);
        for i in 0..n - 1 {
            t.push(i, i, -1.0);
            t.push(i, i + 1, 1.0);
        }
        let mut fixed = vec![false; n];
        fixed[0] = true;
        let solver = Prefactored::with_last(&t.build(), &fixed, last).unwrap();
        (solver, vec![DVec3::ONE; n - 1], vec![DVec3::ZERO; n])
    }

    #[test]
    fn correction_matches_the_kkt_system() {
        // Constraints on the middle, in AMD's order or ordered last.
        for last in [&[][..], &[2, 3, 5]] {
            let x = constrained_chain(last);
            assert_kkt_solution(&x);
        }
    }

    /// The chain with `(x2 + x3) / 2` and `x5` constrained.
    fn constrained_chain(last: &[usize]) -> Vec<DVec3> {
        let (mut solver, b, fixed_values) = chain(last);
        let rows = vec![vec![(2, 0.5), (3, 0.5)], vec![(5, 1.0)]];
        let mut exact = ExactConstraints::new(&solver, rows).unwrap();
        let mut x = vec![DVec3::ZERO; 6];
        solver
            .solve_with(&b, &fixed_values, &mut x, |u| {
                exact.correct(u, &fixed_values, |m| TARGETS[m])
            })
            .unwrap();
        x
    }

    const TARGETS: [DVec3; 2] = [DVec3::new(4.0, 1.0, 0.0), DVec3::new(3.0, 2.0, -1.0)];

    fn assert_kkt_solution(x: &[DVec3]) {
        let targets = TARGETS;
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
    fn a_row_with_a_fixed_part_uses_the_fixed_value() {
        let (mut solver, b, mut fixed_values) = chain(&[1]);
        fixed_values[0] = DVec3::splat(-1.0);
        // (x0 + x1) / 2 = 2 with x0 = -1 fixed: x1 = 5.
        let mut exact = ExactConstraints::new(&solver, vec![vec![(0, 0.5), (1, 0.5)]]).unwrap();
        let mut x = vec![DVec3::ZERO; 6];
        solver
            .solve_with(&b, &fixed_values, &mut x, |u| {
                exact.correct(u, &fixed_values, |_| DVec3::splat(2.0))
            })
            .unwrap();
        assert!((x[1] - DVec3::splat(5.0)).length() < 1e-12, "{}", x[1]);
        // The rest of the chain keeps unit steps from there.
        for i in 2..6 {
            assert!((x[i] - x[i - 1] - DVec3::ONE).length() < 1e-12);
        }
    }

    #[test]
    fn dependent_constraints_are_reported() {
        let (solver, _, _) = chain(&[2]);
        let repeated = vec![vec![(2, 1.0)], vec![(2, 2.0)]];
        assert_eq!(
            ExactConstraints::new(&solver, repeated).unwrap_err(),
            SolveError::Singular
        );
        let on_fixed = vec![vec![(0, 1.0)]];
        assert_eq!(
            ExactConstraints::new(&solver, on_fixed).unwrap_err(),
            SolveError::Singular
        );
    }
}
