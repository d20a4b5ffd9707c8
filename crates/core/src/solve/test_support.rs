//! Small systems and a dense reference solver for the tests of the solvers and their users.

#![allow(clippy::needless_range_loop)]

use super::{SparseMatrix, Triplets};

/// Solves a small dense system by Gaussian elimination with partial pivoting.
pub(crate) fn dense_solve(mut m: Vec<Vec<f64>>, mut rhs: Vec<f64>) -> Vec<f64> {
    let n = rhs.len();
    for k in 0..n {
        let pivot = (k..n)
            .max_by(|&i, &j| m[i][k].abs().total_cmp(&m[j][k].abs()))
            .unwrap();
        m.swap(k, pivot);
        rhs.swap(k, pivot);
        for i in k + 1..n {
            let factor = m[i][k] / m[k][k];
            for j in k..n {
                m[i][j] -= factor * m[k][j];
            }
            rhs[i] -= factor * rhs[k];
        }
    }
    let mut x = vec![0.0; n];
    for k in (0..n).rev() {
        x[k] = (rhs[k] - (k + 1..n).map(|j| m[k][j] * x[j]).sum::<f64>()) / m[k][k];
    }
    x
}

/// A random sparse `m x n` system: a strong diagonal block keeps it well posed, plus
/// scattered off-diagonal entries.
pub(crate) fn random_system(m: usize, n: usize, entries: &[(usize, usize, f64)]) -> SparseMatrix {
    let mut t = Triplets::new(m, n);
    for j in 0..n.min(m) {
        t.push(j, j, 4.0);
    }
    for &(r, c, v) in entries {
        t.push(r % m, c % n, v);
    }
    t.build()
}
