//! A triplet builder for [`SparseMatrix`]: push `(row, col, value)` in any order, then build.
//!
//! Assembly code (Laplacians, constraint rows) pushes one entry per contribution and lets
//! `build` sum duplicates, which keeps each assembly loop local to one element.

use faer::sparse::{SparseColMat, SymbolicSparseColMat};

use super::SparseMatrix;

/// Collects `(row, col, value)` entries in any order; [`Triplets::build`] sums duplicates.
#[derive(Clone, Debug, Default)]
pub struct Triplets {
    nrows: usize,
    ncols: usize,
    entries: Vec<(u32, u32, f64)>,
}

impl Triplets {
    /// An empty `nrows x ncols` builder.
    pub fn new(nrows: usize, ncols: usize) -> Triplets {
        Triplets {
            nrows,
            ncols,
            entries: Vec::new(),
        }
    }

    /// An empty builder with room for `capacity` entries.
    pub fn with_capacity(nrows: usize, ncols: usize, capacity: usize) -> Triplets {
        Triplets {
            nrows,
            ncols,
            entries: Vec::with_capacity(capacity),
        }
    }

    /// Number of rows of the matrix being built.
    pub fn nrows(&self) -> usize {
        self.nrows
    }

    /// Number of columns of the matrix being built.
    pub fn ncols(&self) -> usize {
        self.ncols
    }

    /// Number of entries pushed so far (duplicates counted).
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// Whether nothing was pushed.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// Adds `value` at `(row, col)`; entries at the same place are summed by `build`.
    ///
    /// # Panics
    /// When `row >= nrows` or `col >= ncols`: that is a bug in the caller.
    pub fn push(&mut self, row: usize, col: usize, value: f64) {
        assert!(
            row < self.nrows && col < self.ncols,
            "triplet ({row}, {col}) outside {}x{}",
            self.nrows,
            self.ncols
        );
        self.entries.push((row as u32, col as u32, value));
    }

    /// Adds `scale * matrix` with its top-left corner at `(row_offset, col_offset)`, for
    /// stacking systems such as `[L; w I_c]`.
    ///
    /// # Panics
    /// When the block does not fit.
    pub fn push_matrix(
        &mut self,
        matrix: &SparseMatrix,
        row_offset: usize,
        col_offset: usize,
        scale: f64,
    ) {
        for col in 0..matrix.ncols() {
            for (row, value) in matrix.column(col) {
                self.push(row_offset + row, col_offset + col, scale * value);
            }
        }
    }

    /// The compressed matrix; duplicates summed, explicit zeros kept.
    pub fn build(&self) -> SparseMatrix {
        let mut entries = self.entries.clone();
        entries.sort_unstable_by_key(|&(row, col, _)| (col, row));
        let mut col_ptr = vec![0u32; self.ncols + 1];
        let mut row_idx = Vec::with_capacity(entries.len());
        let mut values: Vec<f64> = Vec::with_capacity(entries.len());
        let mut last = None;
        for (row, col, value) in entries {
            if last == Some((row, col)) {
                if let Some(sum) = values.last_mut() {
                    *sum += value;
                }
                continue;
            }
            last = Some((row, col));
            col_ptr[col as usize + 1] += 1;
            row_idx.push(row);
            values.push(value);
        }
        for col in 0..self.ncols {
            col_ptr[col + 1] += col_ptr[col];
        }
        let symbolic =
            SymbolicSparseColMat::new_checked(self.nrows, self.ncols, col_ptr, None, row_idx);
        SparseMatrix::from_faer(SparseColMat::new(symbolic, values))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    #[test]
    fn build_sums_duplicates_and_keeps_zeros() {
        let mut t = Triplets::new(3, 2);
        t.push(2, 1, 1.5);
        t.push(0, 0, 1.0);
        t.push(2, 1, 2.0);
        t.push(1, 0, 0.0);
        let m = t.build();
        assert_eq!(m.nnz(), 3);
        assert_eq!(m.col_ptr(), &[0, 2, 3]);
        assert_eq!(m.row_indices(), &[0, 1, 2]);
        assert_eq!(
            m.to_dense(),
            vec![vec![1.0, 0.0], vec![0.0, 0.0], vec![0.0, 3.5]]
        );
        assert_eq!(m.get(2, 1), 3.5);
        assert_eq!(m.get(2, 0), 0.0);
    }

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
