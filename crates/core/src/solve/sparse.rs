//! Compressed sparse column matrices of `f64`.
//!
//! [`SparseMatrix`] wraps faer's `SparseColMat<u32, f64>` (u32 indices halve the index memory
//! and match the mesh ids) and keeps every entry it is built with, zeros included (see
//! [`crate::solve::Triplets`]): [`crate::solve::Prefactored::refactor_values`] needs the
//! pattern to stay the same when a weight happens to be zero.

use faer::sparse::{SparseColMat, SparseColMatRef, SymbolicSparseColMat};
use glam::DVec3;

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

    /// A square diagonal matrix (zeros on the diagonal are stored).
    pub fn diagonal(values: &[f64]) -> SparseMatrix {
        let n = values.len();
        let col_ptr = (0..=n as u32).collect();
        SparseMatrix::from_columns(n, col_ptr, (0..n as u32).collect(), values.to_vec())
    }

    /// An `nrows × (col_ptr.len() − 1)` matrix from compressed columns: column `j` holds
    /// `rows[col_ptr[j]..col_ptr[j + 1]]`, strictly increasing, with their `values`.
    pub fn from_columns(
        nrows: usize,
        col_ptr: Vec<u32>,
        rows: Vec<u32>,
        values: Vec<f64>,
    ) -> SparseMatrix {
        let ncols = col_ptr.len() - 1;
        let symbolic = SymbolicSparseColMat::new_checked(nrows, ncols, col_ptr, None, rows);
        SparseMatrix::from_faer(SparseColMat::new(symbolic, values))
    }

    /// This matrix with row `i` multiplied by `weights[i]`: same pattern, new values.
    pub fn scale_rows(&self, weights: &[f64]) -> SparseMatrix {
        let mut out = self.clone();
        let rows = self.inner.symbolic().row_idx();
        for (value, &row) in out.values_mut().iter_mut().zip(rows) {
            *value *= weights[row as usize];
        }
        out
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

    /// `out = Aᵀ y` applied to x, y and z at once.
    ///
    /// # Panics
    /// When `y.len() != nrows` or `out.len() != ncols`.
    pub fn mul_transpose_dvec3(&self, y: &[DVec3], out: &mut [DVec3]) {
        assert_eq!(
            (y.len(), out.len()),
            (self.nrows(), self.ncols()),
            "mul_transpose_dvec3: wrong vector lengths"
        );
        for (col, out) in out.iter_mut().enumerate() {
            *out = self
                .column(col)
                .fold(DVec3::ZERO, |sum, (row, value)| sum + value * y[row]);
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
        let mut col_ptr = Vec::with_capacity(self.ncols() + 1);
        col_ptr.push(0u32);
        let mut row_indices = Vec::new();
        let mut values = Vec::new();
        let mut column: Vec<(u32, f64)> = Vec::new();
        for col in 0..self.ncols() {
            column.clear();
            for (row, value) in self.column(col) {
                column.extend(new_rows_of_old[row].iter().map(|&new| (new as u32, value)));
            }
            // Each new row comes from one old row, so a column holds it at most once.
            column.sort_unstable_by_key(|&(row, _)| row);
            row_indices.extend(column.iter().map(|&(row, _)| row));
            values.extend(column.iter().map(|&(_, value)| value));
            col_ptr.push(row_indices.len() as u32);
        }
        let symbolic =
            SymbolicSparseColMat::new_checked(rows.len(), self.ncols(), col_ptr, None, row_indices);
        SparseMatrix::from_faer(SparseColMat::new(symbolic, values))
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
    fn diagonals_keep_zeros_and_rows_can_be_picked_again() {
        let m = SparseMatrix::diagonal(&[2.0, 0.0, 3.0]);
        assert_eq!((m.nrows(), m.ncols(), m.nnz()), (3, 3, 3));
        assert_eq!(
            SparseMatrix::identity(2).to_dense(),
            vec![vec![1.0, 0.0], vec![0.0, 1.0]]
        );
        let picked = m.select_rows(&[2, 0, 2]);
        assert_eq!(picked.col_ptr(), &[0, 1, 1, 3]);
        assert_eq!(
            picked.to_dense(),
            vec![
                vec![0.0, 0.0, 3.0],
                vec![2.0, 0.0, 0.0],
                vec![0.0, 0.0, 3.0]
            ]
        );
    }
}
