//! Factor once, solve many: constrained least squares with a prefactored sparse Cholesky.
//!
//! Minimises `||A x - b||²` over the free unknowns with the fixed ones given (libigl's
//! `min_quad_with_fixed`, pmp's `cholesky_solve` with `is_constrained`). Splitting the columns
//! of `A` into free and fixed blocks, `A x = A_f x_f + A_c x_c`, the minimiser solves the normal
//! equations `(A_fᵀ A_f) x_f = A_fᵀ (b - A_c x_c)`. The normal matrix is factored once with
//! faer's sparse `LLᵀ` after AMD ordering; each solve is then two triangular solves, with x, y
//! and z as three columns of one right-hand side.
//!
//! faer's `SymbolicLlt`/`Llt` wrappers allocate their scratch on every call. To keep a drag
//! frame allocation-free we hold their building blocks instead: the
//! `SymbolicCholesky`, the numeric values, and `MemBuffer`s sized once for factoring and for
//! solving. `refactor_values` reuses the symbolic analysis, like `Llt::try_new_with_symbolic`.
//!
//! Limits: normal equations square the condition number, which is fine for the well-posed
//! Laplacian systems of FiberMesh (Nealen et al. 2007) but loses digits on badly scaled ones.
//! Rows with many entries (a dense row) make the normal matrix dense.

use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::sparse::linalg::cholesky::{LltRef, SymbolicCholesky, factorize_symbolic_cholesky};
use faer::{Conj, Mat, MatMut, Par, Side};
use glam::DVec3;

use super::SolveError;
use super::normal::NormalSystem;
use super::singular::is_numerically_singular;
use super::sparse::SparseMatrix;

/// A least-squares system `min ||A x - b||²` with fixed unknowns, factored once; see the
/// module docs.
pub struct Prefactored {
    /// `A` as last factored: its pattern checks `refactor_values`, its values build each
    /// right-hand side.
    a: SparseMatrix,
    fixed: Vec<bool>,
    system: NormalSystem,
    symbolic: SymbolicCholesky<u32>,
    l_values: Vec<f64>,
    /// Spare values buffer: a refactor fills it and swaps it in only on success.
    l_values_next: Vec<f64>,
    factor_memory: MemBuffer,
    solve_memory: MemBuffer,
    residual: Vec<DVec3>,
    residual_scalar: Vec<f64>,
    rhs: Mat<f64>,
}

impl std::fmt::Debug for Prefactored {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Prefactored")
            .field("n_rows", &self.a.nrows())
            .field("n_unknowns", &self.n_unknowns())
            .field("n_free", &self.n_free())
            .field("factor_nnz", &self.l_values.len())
            .finish_non_exhaustive()
    }
}

impl Prefactored {
    /// Analyses and factors the system with `m x n` matrix `a`; `fixed[j]` says whether unknown
    /// `j` is given rather than solved for.
    ///
    /// Errors: [`SolveError::DimensionMismatch`] when `fixed.len() != n`,
    /// [`SolveError::NonFiniteValue`] for NaN or infinite entries, and
    /// [`SolveError::NotPositiveDefinite`] or [`SolveError::Singular`] when the free unknowns
    /// are not all determined (for example a Laplacian with nothing fixed).
    pub fn new(a: &SparseMatrix, fixed: &[bool]) -> Result<Prefactored, SolveError> {
        check_len("fixed", a.ncols(), fixed.len())?;
        check_finite(a)?;
        let system = NormalSystem::new(a, fixed);
        let symbolic = factorize_symbolic_cholesky(
            system.normal().symbolic(),
            Side::Lower,
            Default::default(),
            Default::default(),
        )
        .map_err(|err| SolveError::Factorization(format!("{err:?}")))?;
        let factor_req =
            symbolic.factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default());
        let solve_req = symbolic.solve_in_place_scratch::<f64>(3, Par::Seq);
        let n_free = system.n_free();
        let mut prefactored = Prefactored {
            a: a.clone(),
            fixed: fixed.to_vec(),
            l_values: vec![0.0; symbolic.len_val()],
            l_values_next: vec![0.0; symbolic.len_val()],
            symbolic,
            system,
            factor_memory: try_memory(factor_req)?,
            solve_memory: try_memory(solve_req)?,
            residual: vec![DVec3::ZERO; a.nrows()],
            residual_scalar: vec![0.0; a.nrows()],
            rhs: Mat::zeros(n_free, 3),
        };
        prefactored.factor_numeric()?;
        std::mem::swap(&mut prefactored.l_values, &mut prefactored.l_values_next);
        Ok(prefactored)
    }

    /// Refactors after the values of `A` changed but not its pattern (same shape, same stored
    /// entries), reusing the symbolic analysis. On error the previous factorization is kept.
    ///
    /// Errors: [`SolveError::PatternMismatch`] when the pattern differs (build a new
    /// `Prefactored`), and those of [`Prefactored::new`].
    pub fn refactor_values(&mut self, a: &SparseMatrix) -> Result<(), SolveError> {
        if !a.has_same_pattern(&self.a) || a.ncols() != self.a.ncols() {
            return Err(SolveError::PatternMismatch);
        }
        check_finite(a)?;
        self.system.fill_values(a);
        let result = self.factor_numeric();
        if result.is_ok() {
            std::mem::swap(&mut self.l_values, &mut self.l_values_next);
            self.a.values_mut().copy_from_slice(a.values());
        } else {
            // Keep the normal matrix consistent with the factorization still in use.
            self.system.fill_values(&self.a);
        }
        result
    }

    /// Number of unknowns `n` (columns of `A`), free and fixed.
    pub fn n_unknowns(&self) -> usize {
        self.a.ncols()
    }

    /// Number of free unknowns, the order of the factored matrix.
    pub fn n_free(&self) -> usize {
        self.system.n_free()
    }

    /// Number of equations `m` (rows of `A`).
    pub fn n_equations(&self) -> usize {
        self.a.nrows()
    }

    /// Which unknowns are fixed, as given to [`Prefactored::new`].
    pub fn fixed(&self) -> &[bool] {
        &self.fixed
    }

    /// Solves for x, y and z at once: `rhs` is `b` (length `m`), `fixed_values` holds the fixed
    /// unknowns (length `n`, free entries ignored), and `out` receives all `n` unknowns (fixed
    /// ones copied). Allocates nothing.
    ///
    /// Errors: [`SolveError::DimensionMismatch`] for wrong lengths.
    pub fn solve(
        &mut self,
        rhs: &[DVec3],
        fixed_values: &[DVec3],
        out: &mut [DVec3],
    ) -> Result<(), SolveError> {
        self.check_lengths(rhs.len(), fixed_values.len(), out.len())?;
        subtract_fixed(&self.a, &self.system, rhs, fixed_values, &mut self.residual);
        for col in 0..self.a.ncols() {
            let Some(f) = self.system.free_index(col) else {
                continue;
            };
            let projected = self.a.column(col).fold(DVec3::ZERO, |sum, (row, value)| {
                sum + value * self.residual[row]
            });
            for (k, value) in projected.to_array().into_iter().enumerate() {
                self.rhs[(f, k)] = value;
            }
        }
        self.triangular_solves(3);
        for (col, x) in out.iter_mut().enumerate() {
            *x = match self.system.free_index(col) {
                Some(f) => DVec3::new(self.rhs[(f, 0)], self.rhs[(f, 1)], self.rhs[(f, 2)]),
                None => fixed_values[col],
            };
        }
        Ok(())
    }

    /// [`Prefactored::solve`] for one scalar per unknown, as when diffusing curvature targets.
    ///
    /// Errors: [`SolveError::DimensionMismatch`] for wrong lengths.
    pub fn solve_scalar(
        &mut self,
        rhs: &[f64],
        fixed_values: &[f64],
        out: &mut [f64],
    ) -> Result<(), SolveError> {
        self.check_lengths(rhs.len(), fixed_values.len(), out.len())?;
        subtract_fixed(
            &self.a,
            &self.system,
            rhs,
            fixed_values,
            &mut self.residual_scalar,
        );
        for col in 0..self.a.ncols() {
            let Some(f) = self.system.free_index(col) else {
                continue;
            };
            self.rhs[(f, 0)] = self
                .a
                .column(col)
                .map(|(row, value)| value * self.residual_scalar[row])
                .sum();
        }
        self.triangular_solves(1);
        for (col, x) in out.iter_mut().enumerate() {
            *x = match self.system.free_index(col) {
                Some(f) => self.rhs[(f, 0)],
                None => fixed_values[col],
            };
        }
        Ok(())
    }

    /// Solves the normal equations themselves, `(A_fᵀ A_f) Y = R`, for several right-hand
    /// sides at once: `columns` has one row per unknown (`n`) and any number of columns. On
    /// input the rows of free unknowns hold `R`; on output they hold `Y`, and the rows of fixed
    /// unknowns are zero. These are the Green's functions a constrained solve needs (the
    /// Schur complement of extra equality constraints, as in `deform`'s exact handles).
    ///
    /// Unlike [`Prefactored::solve`] this allocates (scratch for all columns), so call it when
    /// setting up, not per frame.
    ///
    /// Errors: [`SolveError::DimensionMismatch`] when `columns` does not have `n` rows, and
    /// [`SolveError::Factorization`] when the scratch memory cannot be reserved.
    pub fn solve_normal_columns(&mut self, mut columns: MatMut<'_, f64>) -> Result<(), SolveError> {
        check_len("columns", self.a.ncols(), columns.nrows())?;
        let n_columns = columns.ncols();
        let mut free = Mat::<f64>::zeros(self.n_free(), n_columns);
        // Column by column: both matrices are column-major.
        for k in 0..n_columns {
            for col in 0..self.a.ncols() {
                if let Some(f) = self.system.free_index(col) {
                    free[(f, k)] = columns[(col, k)];
                }
            }
        }
        let mut memory = try_memory(
            self.symbolic
                .solve_in_place_scratch::<f64>(n_columns, Par::Seq),
        )?;
        LltRef::new(&self.symbolic, &self.l_values).solve_in_place_with_conj(
            Conj::No,
            free.as_mut(),
            Par::Seq,
            MemStack::new(&mut memory),
        );
        for k in 0..n_columns {
            for col in 0..self.a.ncols() {
                columns[(col, k)] = self.system.free_index(col).map_or(0.0, |f| free[(f, k)]);
            }
        }
        Ok(())
    }

    fn check_lengths(&self, n_rhs: usize, n_fixed: usize, n_out: usize) -> Result<(), SolveError> {
        check_len("rhs", self.a.nrows(), n_rhs)?;
        check_len("fixed_values", self.a.ncols(), n_fixed)?;
        check_len("out", self.a.ncols(), n_out)
    }

    /// Solves `N x = rhs` in place for the first `n_columns` columns of `self.rhs`.
    fn triangular_solves(&mut self, n_columns: usize) {
        let llt = LltRef::new(&self.symbolic, &self.l_values);
        let stack = MemStack::new(&mut self.solve_memory);
        llt.solve_in_place_with_conj(
            Conj::No,
            self.rhs.as_mut().subcols_mut(0, n_columns),
            Par::Seq,
            stack,
        );
    }

    /// Factors the current normal matrix into `l_values_next`.
    fn factor_numeric(&mut self) -> Result<(), SolveError> {
        let stack = MemStack::new(&mut self.factor_memory);
        self.symbolic
            .factorize_numeric_llt::<f64>(
                &mut self.l_values_next,
                self.system.normal().as_ref(),
                Side::Lower,
                LltRegularization::default(),
                Par::Seq,
                stack,
                Default::default(),
            )
            // Its only error is a non-positive pivot; the memory was reserved up front.
            .map_err(|_| SolveError::NotPositiveDefinite)?;
        let system = &self.system;
        if is_numerically_singular(&self.symbolic, &self.l_values_next, |k| system.diagonal(k)) {
            return Err(SolveError::Singular);
        }
        Ok(())
    }
}

/// `residual = b - A_c x_c`, generic over scalars and vectors.
fn subtract_fixed<T>(
    a: &SparseMatrix,
    system: &NormalSystem,
    b: &[T],
    fixed_values: &[T],
    residual: &mut [T],
) where
    T: Copy + std::ops::SubAssign + std::ops::Mul<f64, Output = T>,
{
    residual.copy_from_slice(b);
    for (col, &x) in fixed_values.iter().enumerate() {
        if system.free_index(col).is_none() {
            for (row, value) in a.column(col) {
                residual[row] -= x * value;
            }
        }
    }
}

fn check_len(what: &'static str, expected: usize, found: usize) -> Result<(), SolveError> {
    if expected == found {
        Ok(())
    } else {
        Err(SolveError::DimensionMismatch {
            what,
            expected,
            found,
        })
    }
}

fn check_finite(a: &SparseMatrix) -> Result<(), SolveError> {
    if a.values().iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(SolveError::NonFiniteValue)
    }
}

fn try_memory(req: StackReq) -> Result<MemBuffer, SolveError> {
    MemBuffer::try_new(req).map_err(|_| SolveError::Factorization("out of memory".to_owned()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{cotan_laplacian, uniform_laplacian};
    use crate::mesh::{Mesh, primitives};
    use crate::solve::Triplets;
    use crate::solve::tests::random_system;

    fn boundary_mask(mesh: &Mesh) -> Vec<bool> {
        mesh.vertices()
            .map(|v| mesh.is_boundary_vertex(v))
            .collect()
    }

    fn linear(p: DVec3) -> DVec3 {
        DVec3::new(
            1.0 + 2.0 * p.x - p.y,
            0.5 * p.x + 3.0 * p.y,
            -p.x + 0.25 * p.y + 4.0,
        )
    }

    #[test]
    fn harmonic_interpolation_reproduces_a_linear_function() {
        let mesh = primitives::grid(12, 9, 3.0);
        let fixed = boundary_mask(&mesh);
        let expected: Vec<DVec3> = mesh.positions().iter().map(|&p| linear(p)).collect();
        // Only interior rows: boundary rows of a Laplacian are not zero on a linear function,
        // and least squares over them would pull the interior away from it.
        let interior_rows: Vec<usize> = (0..mesh.n_vertices()).filter(|&i| !fixed[i]).collect();
        for laplacian in [uniform_laplacian(&mesh), cotan_laplacian(&mesh)] {
            let laplacian = laplacian.select_rows(&interior_rows);
            let mut solver = Prefactored::new(&laplacian, &fixed).unwrap();
            assert_eq!(solver.n_unknowns(), 130);
            assert_eq!(solver.n_free(), 11 * 8);
            let mut x = vec![DVec3::ZERO; mesh.n_vertices()];
            solver
                .solve(&vec![DVec3::ZERO; interior_rows.len()], &expected, &mut x)
                .unwrap();
            for (got, want) in x.iter().zip(&expected) {
                assert!((*got - *want).length() < 1e-10, "{got} vs {want}");
            }
            let mut scalar = vec![0.0; mesh.n_vertices()];
            let fixed_x: Vec<f64> = expected.iter().map(|v| v.x).collect();
            solver
                .solve_scalar(&vec![0.0; interior_rows.len()], &fixed_x, &mut scalar)
                .unwrap();
            assert!(scalar.iter().zip(&x).all(|(s, v)| (s - v.x).abs() < 1e-12));
        }
    }

    #[test]
    fn refactor_values_matches_a_fresh_factorization() {
        let entries: Vec<(usize, usize, f64)> = (0..40)
            .map(|k| (k * 7 % 23, k * 5 % 17, ((k as f64) * 0.7).sin()))
            .collect();
        let a = random_system(23, 17, &entries);
        let mut fixed = vec![false; 17];
        fixed[4] = true;
        let mut solver = Prefactored::new(&a, &fixed).unwrap();
        let mut a2 = a.clone();
        a2.values_mut()
            .iter_mut()
            .enumerate()
            .for_each(|(i, v)| *v *= 1.0 + 0.1 * (i % 5) as f64);
        solver.refactor_values(&a2).unwrap();
        let mut fresh = Prefactored::new(&a2, &fixed).unwrap();
        let b: Vec<DVec3> = (0..23)
            .map(|i| DVec3::new(i as f64, 1.0, -(i as f64).sqrt()))
            .collect();
        let fixed_values = vec![DVec3::ONE; 17];
        let (mut x, mut y) = (vec![DVec3::ZERO; 17], vec![DVec3::ZERO; 17]);
        solver.solve(&b, &fixed_values, &mut x).unwrap();
        fresh.solve(&b, &fixed_values, &mut y).unwrap();
        assert_eq!(x, y);
    }

    #[test]
    fn failed_refactor_keeps_the_previous_factorization() {
        let mesh = primitives::grid(4, 4, 1.0);
        let laplacian = cotan_laplacian(&mesh);
        let fixed = boundary_mask(&mesh);
        let fixed_values: Vec<DVec3> = mesh.positions().iter().map(|&p| linear(p)).collect();
        let mut solver = Prefactored::new(&laplacian, &fixed).unwrap();
        let rhs = vec![DVec3::ZERO; mesh.n_vertices()];
        let mut before = vec![DVec3::ZERO; mesh.n_vertices()];
        solver.solve(&rhs, &fixed_values, &mut before).unwrap();

        let mut zero = laplacian.clone();
        zero.values_mut().fill(0.0);
        assert_eq!(
            solver.refactor_values(&zero),
            Err(SolveError::NotPositiveDefinite)
        );
        let mut nan = laplacian.clone();
        nan.values_mut()[3] = f64::NAN;
        assert_eq!(
            solver.refactor_values(&nan),
            Err(SolveError::NonFiniteValue)
        );
        assert_eq!(
            solver.refactor_values(&SparseMatrix::identity(25)),
            Err(SolveError::PatternMismatch)
        );

        let mut after = vec![DVec3::ZERO; mesh.n_vertices()];
        solver.solve(&rhs, &fixed_values, &mut after).unwrap();
        assert_eq!(before, after);
    }

    #[test]
    fn undetermined_unknowns_are_errors_not_panics() {
        // Column 2 appears in no equation: an exactly zero pivot.
        let mut t = Triplets::new(3, 3);
        t.push(0, 0, 1.0);
        t.push(1, 1, 1.0);
        t.push(2, 0, 1.0);
        assert_eq!(
            Prefactored::new(&t.build(), &[false; 3]).unwrap_err(),
            SolveError::NotPositiveDefinite
        );
        // Two identical columns: rank deficient without a zero column.
        let mut t = Triplets::new(2, 2);
        for (r, c) in [(0, 0), (0, 1), (1, 0), (1, 1)] {
            t.push(r, c, 1.0);
        }
        assert!(Prefactored::new(&t.build(), &[false; 2]).is_err());
        // A Laplacian with nothing fixed leaves translations free.
        for mesh in [
            primitives::grid(10, 10, 1.0),
            primitives::icosphere(1.0, 3),
            primitives::grid(80, 80, 1.0),
        ] {
            let err = Prefactored::new(&cotan_laplacian(&mesh), &vec![false; mesh.n_vertices()])
                .unwrap_err();
            assert!(err.is_underdetermined(), "{err:?}");
        }
    }

    #[test]
    fn normal_columns_invert_the_normal_matrix() {
        let entries: Vec<(usize, usize, f64)> = (0..30)
            .map(|k| (k * 5 % 19, k * 3 % 11, ((k as f64) * 1.3).cos()))
            .collect();
        let a = random_system(19, 11, &entries);
        let mut fixed = vec![false; 11];
        fixed[2] = true;
        fixed[7] = true;
        let mut solver = Prefactored::new(&a, &fixed).unwrap();
        let free: Vec<usize> = (0..11).filter(|&j| !fixed[j]).collect();
        let dense = a.to_dense();
        let normal = |p: usize, q: usize| dense.iter().map(|r| r[p] * r[q]).sum::<f64>();
        // Each column is a unit vector on a free unknown, plus junk on fixed rows.
        let mut columns = Mat::<f64>::zeros(11, free.len());
        for (k, &j) in free.iter().enumerate() {
            columns[(j, k)] = 1.0;
            columns[(2, k)] = 5.0;
        }
        solver.solve_normal_columns(columns.as_mut()).unwrap();
        for (k, &j) in free.iter().enumerate() {
            assert_eq!(columns[(2, k)], 0.0);
            assert_eq!(columns[(7, k)], 0.0);
            for &p in &free {
                let nz: f64 = free.iter().map(|&q| normal(p, q) * columns[(q, k)]).sum();
                let expected = if p == j { 1.0 } else { 0.0 };
                assert!((nz - expected).abs() < 1e-12, "(N Y)[{p}, {k}] = {nz}");
            }
        }
        assert!(matches!(
            solver.solve_normal_columns(Mat::<f64>::zeros(10, 2).as_mut()),
            Err(SolveError::DimensionMismatch { .. })
        ));
    }

    #[test]
    fn everything_fixed_copies_the_fixed_values() {
        let a = SparseMatrix::identity(3);
        let mut solver = Prefactored::new(&a, &[true; 3]).unwrap();
        assert_eq!(solver.n_free(), 0);
        let fixed_values = [DVec3::X, DVec3::Y, DVec3::Z];
        let mut out = [DVec3::ZERO; 3];
        solver
            .solve(&[DVec3::ONE; 3], &fixed_values, &mut out)
            .unwrap();
        assert_eq!(out, fixed_values);
    }
}
