//! A symmetric positive definite system solved in three steps: its pattern analysed (the
//! fill-reducing ordering and the factor's structure), its values factored, then the
//! right-hand sides solved. A caller that must not hold a frame for the whole (the region
//! tool's fall-off disc, 70–80 ms on a 50k-vertex region) does each in a frame of its own:
//! about 30, 40 and 10 ms there.

use faer::dyn_stack::MemStack;
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::sparse::linalg::cholesky::{
    LltRef, SymbolicCholesky, SymmetricOrdering, factorize_symbolic_cholesky,
};
use faer::{Conj, Par, Side};

use super::prefactored::try_memory;
use super::{SolveError, SparseMatrix};

/// A symmetric positive definite matrix (its lower triangle is read) with its pattern
/// analysed, and once [`SpdSystem::factor`] ran, factored.
pub struct SpdSystem {
    matrix: SparseMatrix,
    symbolic: SymbolicCholesky<u32>,
    /// The Cholesky factor's values, once factored.
    factor: Option<Vec<f64>>,
}

impl std::fmt::Debug for SpdSystem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("SpdSystem")
            .field("n", &self.matrix.nrows())
            .field("factored", &self.factor.is_some())
            .finish_non_exhaustive()
    }
}

impl SpdSystem {
    /// Analyses the pattern of `matrix`: the first step.
    ///
    /// Errors: [`SolveError::NonFiniteValue`], or [`SolveError::Factorization`] when faer
    /// runs out of memory.
    pub fn analyse(matrix: SparseMatrix) -> Result<SpdSystem, SolveError> {
        if matrix.values().iter().any(|x| !x.is_finite()) {
            return Err(SolveError::NonFiniteValue);
        }
        let symbolic = factorize_symbolic_cholesky(
            matrix.as_faer().symbolic(),
            Side::Lower,
            SymmetricOrdering::Amd,
            Default::default(),
        )
        .map_err(|err| SolveError::Factorization(format!("{err:?}")))?;
        Ok(SpdSystem {
            matrix,
            symbolic,
            factor: None,
        })
    }

    /// Whether [`SpdSystem::factor`] ran.
    pub fn is_factored(&self) -> bool {
        self.factor.is_some()
    }

    /// Factors the matrix: the second step (nothing when it is factored already).
    ///
    /// Errors: [`SolveError::NotPositiveDefinite`], or [`SolveError::Factorization`] when
    /// memory runs out.
    pub fn factor(&mut self) -> Result<(), SolveError> {
        if self.factor.is_some() {
            return Ok(());
        }
        let mut values = vec![0.0; self.symbolic.len_val()];
        let mut memory = try_memory(
            (self.symbolic).factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default()),
        )?;
        self.symbolic
            .factorize_numeric_llt::<f64>(
                &mut values,
                self.matrix.as_faer(),
                Side::Lower,
                LltRegularization::default(),
                Par::Seq,
                MemStack::new(&mut memory),
                Default::default(),
            )
            .map_err(|_| SolveError::NotPositiveDefinite)?;
        self.factor = Some(values);
        Ok(())
    }

    /// Solves the system for each column of `columns`, overwritten by its solution, factoring
    /// it first if [`SpdSystem::factor`] has not: the last step.
    ///
    /// Errors: those of [`SpdSystem::factor`], and [`SolveError::DimensionMismatch`].
    pub fn solve(&mut self, columns: &mut [Vec<f64>]) -> Result<(), SolveError> {
        let n = self.matrix.nrows();
        if let Some(bad) = columns.iter().find(|c| c.len() != n) {
            return Err(SolveError::DimensionMismatch {
                what: "right-hand side",
                expected: n,
                found: bad.len(),
            });
        }
        self.factor()?;
        let values = self.factor.as_deref().expect("factored above");
        let mut memory =
            try_memory((self.symbolic).solve_in_place_scratch::<f64>(columns.len(), Par::Seq))?;
        let mut rhs = faer::Mat::from_fn(n, columns.len(), |i, j| columns[j][i]);
        LltRef::new(&self.symbolic, values).solve_in_place_with_conj(
            Conj::No,
            rhs.as_mut(),
            Par::Seq,
            MemStack::new(&mut memory),
        );
        for (j, column) in columns.iter_mut().enumerate() {
            for (i, x) in column.iter_mut().enumerate() {
                *x = rhs[(i, j)];
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::super::Triplets;
    use super::super::test_support::dense_solve;
    use super::*;

    /// A path graph's Laplacian with its ends held (the diagonal 2 everywhere).
    fn path_system(n: usize) -> (SparseMatrix, Vec<Vec<f64>>) {
        let mut t = Triplets::new(n, n);
        let mut dense = vec![vec![0.0; n]; n];
        for i in 0..n {
            t.push(i, i, 2.0);
            dense[i][i] = 2.0;
            if i > 0 {
                t.push(i, i - 1, -1.0);
                dense[i][i - 1] = -1.0;
                dense[i - 1][i] = -1.0;
            }
        }
        (t.build(), dense)
    }

    #[test]
    fn the_three_steps_solve_like_dense_elimination() {
        let n = 9;
        let (a, dense) = path_system(n);
        let b: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
        let mut columns = vec![b.clone(), vec![1.0; n]];
        let mut system = SpdSystem::analyse(a).unwrap();
        assert!(!system.is_factored());
        system.factor().unwrap();
        assert!(system.is_factored());
        system.solve(&mut columns).unwrap();
        for (column, rhs) in columns.iter().zip([b, vec![1.0; n]]) {
            let expected = dense_solve(dense.clone(), rhs);
            for (x, e) in column.iter().zip(&expected) {
                assert!((x - e).abs() < 1e-12, "{x} against {e}");
            }
        }
    }

    #[test]
    fn an_indefinite_matrix_is_an_error_not_a_panic() {
        let mut t = Triplets::new(2, 2);
        t.push(0, 0, 1.0);
        t.push(1, 0, 3.0);
        t.push(1, 1, 1.0);
        let mut system = SpdSystem::analyse(t.build()).unwrap();
        assert!(matches!(
            system.factor(),
            Err(SolveError::NotPositiveDefinite)
        ));
        let result = system.solve(&mut [vec![1.0, 1.0]]);
        assert!(matches!(result, Err(SolveError::NotPositiveDefinite)));
    }

    #[test]
    fn non_finite_values_and_wrong_lengths_are_refused() {
        let mut t = Triplets::new(1, 1);
        t.push(0, 0, f64::NAN);
        assert!(matches!(
            SpdSystem::analyse(t.build()),
            Err(SolveError::NonFiniteValue)
        ));
        let (a, _) = path_system(3);
        let result = SpdSystem::analyse(a).unwrap().solve(&mut [vec![1.0; 2]]);
        assert!(matches!(result, Err(SolveError::DimensionMismatch { .. })));
    }
}
