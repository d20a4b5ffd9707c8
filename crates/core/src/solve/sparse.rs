//! Compressed sparse column matrices of `f64`, and a triplet builder for them.
//!
//! [`SparseMatrix`] wraps faer's `SparseColMat<u32, f64>` (u32 indices halve the index memory
//! and match the mesh ids) and keeps every entry pushed to a [`Triplets`], zeros included:
//! [`crate::solve::Prefactored::refactor_values`] needs the pattern to stay the same when a
//! weight happens to be zero.

use faer::sparse::{SparseColMat, SparseColMatRef};
use glam::DVec3;

use super::Triplets;

/// A sparse `nrows x ncols` matrix in compressed sparse column form, rows sorted within each
/// column, no duplicate entries.
#[derive(Clone, Debug)]
pub struct SparseMatrix {
    inner: SparseColMat<u32, f64>,
}

impl SparseMatrix {
    /// Wraps a faer matrix (for results of faer's own algorithms).
    pub fn from_faer(inner: SparseColMat<u32, f64>) -> SparseMatrix {
        SparseMatrix { inner }
    }

    /// The `n x n` identity.
    pub fn identity(n: usize) -> SparseMatrix {
        SparseMatrix::diagonal(&vec![1.0; n])
    }

    /// A square diagonal matrix.
    pub fn diagonal(values: &[f64]) -> SparseMatrix {
        let mut triplets = Triplets::with_capacity(values.len(), values.len(), values.len());
        for (i, &value) in values.iter().enumerate() {
            triplets.push(i, i, value);
        }
        triplets.build()
    }

    /// Number of rows.
    pub fn nrows(&self) -> usize {
        self.inner.nrows()
    }

    /// Number of columns.
    pub fn ncols(&self) -> usize {
        self.inner.ncols()
    }

    /// Number of stored entries.
    pub fn nnz(&self) -> usize {
        self.inner.val().len()
    }

    /// Start of each column in [`SparseMatrix::row_indices`] and [`SparseMatrix::values`]
    /// (`ncols + 1` entries).
    pub fn col_ptr(&self) -> &[u32] {
        self.inner.symbolic().col_ptr()
    }

    /// Row of each stored entry.
    pub fn row_indices(&self) -> &[u32] {
        self.inner.symbolic().row_idx()
    }

    /// Value of each stored entry.
    pub fn values(&self) -> &[f64] {
        self.inner.val()
    }

    /// Mutable values; the pattern stays fixed.
    pub fn values_mut(&mut self) -> &mut [f64] {
        self.inner.val_mut()
    }

    /// The stored `(row, value)` entries of one column.
    pub fn column(&self, col: usize) -> impl ExactSizeIterator<Item = (usize, f64)> + '_ {
        let range = self.col_ptr()[col] as usize..self.col_ptr()[col + 1] as usize;
        self.row_indices()[range.clone()]
            .iter()
            .zip(&self.values()[range])
            .map(|(&r, &v)| (r as usize, v))
    }

    /// The entry at `(row, col)`, zero when not stored.
    pub fn get(&self, row: usize, col: usize) -> f64 {
        self.column(col)
            .find(|&(r, _)| r == row)
            .map_or(0.0, |(_, v)| v)
    }

    /// Whether both matrices have the same shape and the same stored entries.
    pub fn has_same_pattern(&self, other: &SparseMatrix) -> bool {
        self.nrows() == other.nrows()
            && self.col_ptr() == other.col_ptr()
            && self.row_indices() == other.row_indices()
    }

    /// The faer view, for faer's own algorithms.
    pub fn as_faer(&self) -> SparseColMatRef<'_, u32, f64> {
        self.inner.as_ref()
    }

    /// `out = A x`.
    ///
    /// # Panics
    /// When `x.len() != ncols` or `out.len() != nrows`.
    pub fn mul_vec(&self, x: &[f64], out: &mut [f64]) {
        assert_eq!(
            (x.len(), out.len()),
            (self.ncols(), self.nrows()),
            "mul_vec: wrong vector lengths"
        );
        out.fill(0.0);
        for (col, &x_col) in x.iter().enumerate() {
            for (row, value) in self.column(col) {
                out[row] += value * x_col;
            }
        }
    }

    /// `out = A x` applied to x, y and z at once.
    ///
    /// # Panics
    /// When `x.len() != ncols` or `out.len() != nrows`.
    pub fn mul_dvec3(&self, x: &[DVec3], out: &mut [DVec3]) {
        assert_eq!(
            (x.len(), out.len()),
            (self.ncols(), self.nrows()),
            "mul_dvec3: wrong vector lengths"
        );
        out.fill(DVec3::ZERO);
        for (col, &x_col) in x.iter().enumerate() {
            for (row, value) in self.column(col) {
                out[row] += value * x_col;
            }
        }
    }

    /// The matrix made of the listed rows, in that order (rows may repeat), as when only the
    /// Laplacian rows of free vertices take part in a system.
    ///
    /// # Panics
    /// When a row is out of range.
    pub fn select_rows(&self, rows: &[usize]) -> SparseMatrix {
        let mut new_rows_of_old: Vec<Vec<usize>> = vec![Vec::new(); self.nrows()];
        for (new, &old) in rows.iter().enumerate() {
            new_rows_of_old[old].push(new);
        }
        let mut triplets = Triplets::new(rows.len(), self.ncols());
        for col in 0..self.ncols() {
            for (row, value) in self.column(col) {
                for &new in &new_rows_of_old[row] {
                    triplets.push(new, col, value);
                }
            }
        }
        triplets.build()
    }

    /// Dense row-major copy, for tests and debugging of small matrices.
    pub fn to_dense(&self) -> Vec<Vec<f64>> {
        let mut dense = vec![vec![0.0; self.ncols()]; self.nrows()];
        for col in 0..self.ncols() {
            for (row, value) in self.column(col) {
                if let Some(entry) = dense.get_mut(row).and_then(|r| r.get_mut(col)) {
                    *entry = value;
                }
            }
        }
        dense
    }
}

impl PartialEq for SparseMatrix {
    fn eq(&self, other: &SparseMatrix) -> bool {
        self.has_same_pattern(other)
            && self.ncols() == other.ncols()
            && self.values() == other.values()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_match_dense_arithmetic() {
        let mut t = Triplets::new(2, 3);
        for (r, c, v) in [(0, 0, 1.0), (0, 2, -2.0), (1, 1, 3.0), (1, 2, 0.5)] {
            t.push(r, c, v);
        }
        let m = t.build();
        let mut out = [0.0; 2];
        m.mul_vec(&[1.0, 2.0, 3.0], &mut out);
        assert_eq!(out, [-5.0, 7.5]);
        let mut out3 = [DVec3::ZERO; 2];
        m.mul_dvec3(&[DVec3::X, DVec3::Y, DVec3::Z], &mut out3);
        assert_eq!(
            out3,
            [DVec3::new(1.0, 0.0, -2.0), DVec3::new(0.0, 3.0, 0.5)]
        );
    }

    #[test]
    fn stacking_blocks() {
        let mut t = Triplets::new(4, 2);
        t.push_matrix(&SparseMatrix::identity(2), 0, 0, 1.0);
        t.push_matrix(&SparseMatrix::diagonal(&[2.0, 3.0]), 2, 0, 10.0);
        let m = t.build();
        assert_eq!(
            m.to_dense(),
            vec![
                vec![1.0, 0.0],
                vec![0.0, 1.0],
                vec![20.0, 0.0],
                vec![0.0, 30.0]
            ]
        );
        assert!(m.has_same_pattern(&m.clone()));
        let picked = m.select_rows(&[3, 0, 3]);
        assert_eq!(
            picked.to_dense(),
            vec![vec![0.0, 30.0], vec![1.0, 0.0], vec![0.0, 30.0]]
        );
        assert_eq!(m, m.clone());
    }
}
