//! Sparse least-squares solves: factor once, solve many.
//!
//! As geometry-central pairs a one-off function with a stateful solver, this module offers
//! [`solve_least_squares`] for a single solve and [`Prefactored`] for repeated solves with the
//! same matrix (a drag re-solves every frame with new right-hand sides). Both minimise
//! `||A x - b||²` with some unknowns fixed, through the normal equations and faer's sparse
//! Cholesky; see [`prefactored`](Prefactored) for the method and its limits. A square
//! symmetric positive definite system (a Laplacian with its boundary fixed) is factored
//! itself, not its normal equations, by [`SpdSystem`], in two halves a caller may put in
//! frames of their own.

mod error;
mod normal;
mod ordering;
mod prefactored;
mod singular;
mod sparse;
mod spd;
#[cfg(test)]
pub(crate) mod test_support;
mod triplets;

use glam::DVec3;

pub use error::SolveError;
pub use prefactored::Prefactored;
pub(crate) use prefactored::check_len;
pub use sparse::SparseMatrix;
pub use spd::SpdSystem;
pub use triplets::Triplets;

/// One-off: minimises `||A x - b||²` with `x[j] = fixed_values[j]` wherever `fixed[j]`.
///
/// `a` is `m x n`, `b` has length `m`, `fixed` and `fixed_values` length `n` (free entries of
/// `fixed_values` are ignored). Returns all `n` unknowns. For repeated solves with the same
/// matrix, keep a [`Prefactored`]. Errors are those of [`Prefactored::new`] and
/// [`Prefactored::solve`].
pub fn solve_least_squares(
    a: &SparseMatrix,
    b: &[DVec3],
    fixed: &[bool],
    fixed_values: &[DVec3],
) -> Result<Vec<DVec3>, SolveError> {
    let mut solver = Prefactored::new(a, fixed)?;
    let mut x = vec![DVec3::ZERO; a.ncols()];
    solver.solve(b, fixed_values, &mut x)?;
    Ok(x)
}

#[cfg(test)]
#[allow(clippy::needless_range_loop)]
mod tests {
    use super::test_support::{dense_solve, random_system};
    use super::*;
    use crate::geometry::uniform_laplacian;
    use crate::mesh::{Mesh, primitives};
    use proptest::prelude::*;

    /// The constrained least-squares minimiser of one coordinate, by dense normal equations.
    pub(crate) fn dense_least_squares(
        a: &[Vec<f64>],
        b: &[f64],
        fixed: &[bool],
        fixed_values: &[f64],
    ) -> Vec<f64> {
        let free: Vec<usize> = (0..fixed.len()).filter(|&j| !fixed[j]).collect();
        let residual: Vec<f64> = a
            .iter()
            .zip(b)
            .map(|(row, &b)| {
                b - (0..fixed.len())
                    .filter(|&j| fixed[j])
                    .map(|j| row[j] * fixed_values[j])
                    .sum::<f64>()
            })
            .collect();
        let normal = free
            .iter()
            .map(|&p| {
                free.iter()
                    .map(|&q| a.iter().map(|r| r[p] * r[q]).sum())
                    .collect()
            })
            .collect();
        let projected = free
            .iter()
            .map(|&p| a.iter().zip(&residual).map(|(r, s)| r[p] * s).sum())
            .collect();
        let x_free = dense_solve(normal, projected);
        let mut x = fixed_values.to_vec();
        for (&j, value) in free.iter().zip(x_free) {
            x[j] = value;
        }
        x
    }

    proptest! {
        #[test]
        fn least_squares_matches_dense_elimination(
            extra_rows in 0usize..6,
            entries in prop::collection::vec((0usize..40, 0usize..40, -1.0..1.0f64), 0..60),
            fixed_mask in prop::collection::vec(prop::bool::weighted(0.3), 12),
            values in prop::collection::vec(-5.0..5.0f64, 3 * 18 + 3 * 12),
        ) {
            let n = 12;
            let m = n + extra_rows;
            let a = random_system(m, n, &entries);
            let b: Vec<DVec3> = (0..m).map(|i| DVec3::new(values[3 * i], values[3 * i + 1], values[3 * i + 2])).collect();
            let fixed_values: Vec<DVec3> = (0..n).map(|j| DVec3::from_slice(&values[54 + 3 * j..])).collect();
            let x = solve_least_squares(&a, &b, &fixed_mask, &fixed_values).unwrap();
            for axis in 0..3 {
                let b_axis: Vec<f64> = b.iter().map(|v| v[axis]).collect();
                let fixed_axis: Vec<f64> = fixed_values.iter().map(|v| v[axis]).collect();
                let expected = dense_least_squares(&a.to_dense(), &b_axis, &fixed_mask, &fixed_axis);
                for j in 0..n {
                    prop_assert!((x[j][axis] - expected[j]).abs() < 1e-9, "x[{j}][{axis}] = {} vs {}", x[j][axis], expected[j]);
                }
            }
        }
    }

    /// A FiberMesh-like system: a Laplacian block plus soft positional rows `w (x_c = p_c)`.
    fn laplacian_with_soft_rows(
        mesh: &Mesh,
        every: usize,
        weight: f64,
    ) -> (SparseMatrix, Vec<DVec3>) {
        let n = mesh.n_vertices();
        let anchors: Vec<usize> = (0..n).step_by(every).collect();
        let mut t = Triplets::new(n + anchors.len(), n);
        t.push_matrix(&uniform_laplacian(mesh), 0, 0, 1.0);
        let mut b = vec![DVec3::ZERO; n];
        for (k, &v) in anchors.iter().enumerate() {
            t.push(n + k, v, weight);
            b.push(weight * (mesh.positions()[v] + DVec3::Z * 0.1));
        }
        (t.build(), b)
    }

    #[test]
    fn soft_constraints_match_dense_least_squares() {
        let mesh = primitives::icosphere(1.0, 1);
        let (a, b) = laplacian_with_soft_rows(&mesh, 5, 2.0);
        let n = mesh.n_vertices();
        let mut fixed = vec![false; n];
        fixed[3] = true;
        let fixed_values = mesh.positions().to_vec();
        let mut solver = Prefactored::new(&a, &fixed).unwrap();
        let mut x = vec![DVec3::ZERO; n];
        solver.solve(&b, &fixed_values, &mut x).unwrap();
        let b_y: Vec<f64> = b.iter().map(|v| v.y).collect();
        let fixed_y: Vec<f64> = fixed_values.iter().map(|v| v.y).collect();
        let expected = dense_least_squares(&a.to_dense(), &b_y, &fixed, &fixed_y);
        assert!(
            x.iter()
                .zip(&expected)
                .all(|(x, e)| (x.y - e).abs() < 1e-10)
        );
    }

    #[test]
    fn large_system_satisfies_the_normal_equations() {
        // Large enough for faer to pick its supernodal factorization (see `singular.rs`).
        let mesh = primitives::grid(70, 70, 1.0);
        let (a, b) = laplacian_with_soft_rows(&mesh, 37, 1.0);
        let n = mesh.n_vertices();
        let mut solver = Prefactored::new(&a, &vec![false; n]).unwrap();
        let mut x = vec![DVec3::ZERO; n];
        solver.solve(&b, &vec![DVec3::ZERO; n], &mut x).unwrap();
        // Aᵀ (A x - b) = 0, computed column by column.
        let mut ax = vec![DVec3::ZERO; a.nrows()];
        a.mul_dvec3(&x, &mut ax);
        let worst = (0..n)
            .map(|col| {
                a.column(col)
                    .fold(DVec3::ZERO, |s, (row, v)| s + v * (ax[row] - b[row]))
                    .length()
            })
            .fold(0.0, f64::max);
        assert!(worst < 1e-9, "normal-equation residual {worst}");
    }

    #[test]
    fn wrong_lengths_are_reported() {
        let a = SparseMatrix::identity(3);
        let err =
            solve_least_squares(&a, &[DVec3::ZERO; 2], &[false; 3], &[DVec3::ZERO; 3]).unwrap_err();
        assert_eq!(
            err,
            SolveError::DimensionMismatch {
                what: "rhs",
                expected: 3,
                found: 2
            }
        );
        assert_eq!(err.to_string(), "The rhs has length 2, but 3 was expected.");
        let err = Prefactored::new(&a, &[false; 4]).unwrap_err();
        assert_eq!(
            err,
            SolveError::DimensionMismatch {
                what: "fixed",
                expected: 3,
                found: 4
            }
        );
    }
}
