//! The normal matrix `A_fᵀ A_f` of a least-squares system restricted to its free columns.
//!
//! The pattern is computed once (the classic symbolic `AᵀA`: two columns interact when they
//! share a row) and only values are refilled when `A` changes. Values are assembled column by
//! column with a dense scatter buffer, so a refill allocates nothing. Only the lower triangle
//! is stored, since Cholesky reads one side; the diagonal is always stored, even for a column
//! that appears in no row, so an undetermined unknown shows up as a zero pivot instead of
//! a missing one.

use faer::sparse::{SparseColMat, SymbolicSparseColMat};

use super::SparseMatrix;

/// Marks a fixed column in the free numbering.
const FIXED: u32 = u32::MAX;

/// Free/fixed split of the columns of `A`, a row-wise view of `A` and the normal matrix.
#[derive(Clone, Debug)]
pub(crate) struct NormalSystem {
    /// Free number of every column of `A`, or [`FIXED`].
    free_of_col: Vec<u32>,
    /// For each row of `A`: the range of its entries in `row_entry_pos`.
    row_ptr: Vec<u32>,
    /// Position (in `A`'s value array) of each entry, grouped by row.
    row_entry_pos: Vec<u32>,
    /// Column of each entry, grouped by row.
    row_entry_col: Vec<u32>,
    /// Lower triangle of `A_fᵀ A_f`, rows sorted, diagonal first in each column.
    normal: SparseColMat<u32, f64>,
    /// Dense accumulator of one column of the normal matrix; all zero between uses.
    scatter: Vec<f64>,
}

impl NormalSystem {
    /// The pattern for `a` with the given fixed columns, and its values.
    pub(crate) fn new(a: &SparseMatrix, fixed: &[bool]) -> NormalSystem {
        debug_assert_eq!(fixed.len(), a.ncols());
        let mut n_free = 0u32;
        let free_of_col: Vec<u32> = fixed
            .iter()
            .map(|&is_fixed| {
                if is_fixed {
                    FIXED
                } else {
                    n_free += 1;
                    n_free - 1
                }
            })
            .collect();
        let (row_ptr, row_entry_pos, row_entry_col) = row_view(a);
        let mut system = NormalSystem {
            free_of_col,
            row_ptr,
            row_entry_pos,
            row_entry_col,
            normal: SparseColMat::new(
                SymbolicSparseColMat::new_checked(0, 0, vec![0], None, Vec::new()),
                Vec::new(),
            ),
            scatter: vec![0.0; n_free as usize],
        };
        system.normal = system.symbolic_normal(a, n_free as usize);
        system.fill_values(a);
        system
    }

    /// Number of free unknowns (the order of the normal matrix).
    pub(crate) fn n_free(&self) -> usize {
        self.scatter.len()
    }

    /// Free number of column `col`, or `None` when it is fixed.
    pub(crate) fn free_index(&self, col: usize) -> Option<usize> {
        let f = self.free_of_col[col];
        (f != FIXED).then_some(f as usize)
    }

    /// The normal matrix (lower triangle).
    pub(crate) fn normal(&self) -> &SparseColMat<u32, f64> {
        &self.normal
    }

    /// Diagonal entry `f` of the normal matrix.
    pub(crate) fn diagonal(&self, f: usize) -> f64 {
        self.normal.val()[self.normal.symbolic().col_ptr()[f] as usize]
    }

    /// Recomputes the values of the normal matrix from `a`, which must have the pattern the
    /// system was built with.
    pub(crate) fn fill_values(&mut self, a: &SparseMatrix) {
        let a_values = a.values();
        for col in 0..a.ncols() {
            let Some(fq) = self.free_index(col) else {
                continue;
            };
            for (row, a_row_col) in a.column(col) {
                let entries = self.row_ptr[row] as usize..self.row_ptr[row + 1] as usize;
                for (&pos, &other) in self.row_entry_pos[entries.clone()]
                    .iter()
                    .zip(&self.row_entry_col[entries])
                {
                    let fp = self.free_of_col[other as usize];
                    if fp != FIXED && fp as usize >= fq {
                        self.scatter[fp as usize] += a_row_col * a_values[pos as usize];
                    }
                }
            }
            let slots = self.normal.symbolic().col_ptr()[fq] as usize
                ..self.normal.symbolic().col_ptr()[fq + 1] as usize;
            for slot in slots {
                let fp = self.normal.symbolic().row_idx()[slot] as usize;
                self.normal.val_mut()[slot] = std::mem::take(&mut self.scatter[fp]);
            }
        }
    }

    /// Pattern of the lower triangle of `A_fᵀ A_f`, with every diagonal entry present.
    fn symbolic_normal(&self, a: &SparseMatrix, n_free: usize) -> SparseColMat<u32, f64> {
        let mut col_ptr = Vec::with_capacity(n_free + 1);
        col_ptr.push(0u32);
        let mut row_idx = Vec::new();
        // `last_seen[fp] == fq` marks free column fp as already in column fq.
        let mut last_seen = vec![FIXED; n_free];
        for col in 0..a.ncols() {
            let Some(fq) = self.free_index(col) else {
                continue;
            };
            let start = row_idx.len();
            last_seen[fq] = fq as u32;
            row_idx.push(fq as u32);
            for (row, _) in a.column(col) {
                let entries = self.row_ptr[row] as usize..self.row_ptr[row + 1] as usize;
                for &other in &self.row_entry_col[entries] {
                    let fp = self.free_of_col[other as usize];
                    if fp != FIXED && fp as usize > fq && last_seen[fp as usize] != fq as u32 {
                        last_seen[fp as usize] = fq as u32;
                        row_idx.push(fp);
                    }
                }
            }
            row_idx[start..].sort_unstable();
            col_ptr.push(row_idx.len() as u32);
        }
        let values = vec![0.0; row_idx.len()];
        SparseColMat::new(
            SymbolicSparseColMat::new_checked(n_free, n_free, col_ptr, None, row_idx),
            values,
        )
    }
}

/// Row-wise index of a column-major matrix: `(row_ptr, entry position, entry column)`.
fn row_view(a: &SparseMatrix) -> (Vec<u32>, Vec<u32>, Vec<u32>) {
    let mut row_ptr = vec![0u32; a.nrows() + 1];
    for &row in a.row_indices() {
        row_ptr[row as usize + 1] += 1;
    }
    for row in 0..a.nrows() {
        row_ptr[row + 1] += row_ptr[row];
    }
    let mut next = row_ptr.clone();
    let mut entry_pos = vec![0u32; a.nnz()];
    let mut entry_col = vec![0u32; a.nnz()];
    for col in 0..a.ncols() {
        for pos in a.col_ptr()[col]..a.col_ptr()[col + 1] {
            let row = a.row_indices()[pos as usize] as usize;
            let slot = next[row] as usize;
            entry_pos[slot] = pos;
            entry_col[slot] = col as u32;
            next[row] += 1;
        }
    }
    (row_ptr, entry_pos, entry_col)
}

#[cfg(test)]
#[allow(clippy::needless_range_loop)]
mod tests {
    use super::*;
    use crate::solve::Triplets;

    fn dense_normal(a: &[Vec<f64>], free: &[usize]) -> Vec<Vec<f64>> {
        free.iter()
            .map(|&p| {
                free.iter()
                    .map(|&q| a.iter().map(|row| row[p] * row[q]).sum())
                    .collect()
            })
            .collect()
    }

    #[test]
    fn normal_matrix_matches_dense_product() {
        let mut t = Triplets::new(4, 4);
        for (r, c, v) in [
            (0, 0, 1.0),
            (0, 1, 2.0),
            (1, 1, -1.0),
            (1, 3, 4.0),
            (2, 0, 3.0),
            (2, 2, 0.5),
            (3, 3, 2.0),
            (3, 1, 1.0),
        ] {
            t.push(r, c, v);
        }
        let a = t.build();
        let fixed = [false, true, false, false];
        let system = NormalSystem::new(&a, &fixed);
        assert_eq!(system.n_free(), 3);
        assert_eq!(system.free_index(1), None);
        assert_eq!(system.free_index(3), Some(2));
        let expected = dense_normal(&a.to_dense(), &[0, 2, 3]);
        let normal = system.normal();
        for i in 0..3 {
            for j in 0..3 {
                let stored = normal
                    .as_ref()
                    .get(i.max(j), i.min(j))
                    .copied()
                    .unwrap_or(0.0);
                assert_eq!(stored, expected[i][j], "entry ({i}, {j})");
            }
            assert_eq!(system.diagonal(i), expected[i][i]);
        }
    }

    #[test]
    fn refill_after_value_change_matches_fresh_build() {
        let mut t = Triplets::new(3, 3);
        for (r, c, v) in [
            (0, 0, 1.0),
            (0, 1, -1.0),
            (1, 1, 1.0),
            (1, 2, -1.0),
            (2, 2, 1.0),
        ] {
            t.push(r, c, v);
        }
        let mut a = t.build();
        let mut system = NormalSystem::new(&a, &[false; 3]);
        a.values_mut()
            .iter_mut()
            .enumerate()
            .for_each(|(i, v)| *v *= 1.0 + i as f64);
        system.fill_values(&a);
        let fresh = NormalSystem::new(&a, &[false; 3]);
        assert_eq!(system.normal().val(), fresh.normal().val());
    }

    #[test]
    fn an_unused_column_still_gets_a_diagonal_slot() {
        let mut t = Triplets::new(1, 2);
        t.push(0, 0, 2.0);
        let system = NormalSystem::new(&t.build(), &[false, false]);
        assert_eq!(system.normal().symbolic().col_ptr(), &[0, 1, 2]);
        assert_eq!(system.diagonal(0), 4.0);
        assert_eq!(system.diagonal(1), 0.0);
    }
}
