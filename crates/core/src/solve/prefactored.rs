//! Factor once, solve many: constrained least squares with a prefactored sparse Cholesky.
//!
//! Minimises `||A x - b||²` over the free unknowns with the fixed ones given (libigl's
//! `min_quad_with_fixed`, pmp's `cholesky_solve` with `is_constrained`). Splitting the columns
//! of `A` into free and fixed blocks, `A x = A_f x_f + A_c x_c`, the minimiser solves the normal
//! equations `(A_fᵀ A_f) x_f = A_fᵀ (b - A_c x_c)`. The normal matrix is factored once with
//! faer's sparse `LLᵀ` (supernodal or simplicial, as faer picks) after AMD ordering; each
//! solve is then two triangular solves, with x, y and z as three columns of one right-hand
//! side.
//!
//! The two triangular solves are kept apart, with a hook between them
//! ([`Prefactored::solve_with`]), and some unknowns can be ordered last
//! ([`Prefactored::with_last`]): together they make hard equality constraints on those
//! unknowns cheap (see `deform`'s exact handles), because `L⁻¹` applied to a vector that is
//! zero outside the last rows is zero outside them too ([`Prefactored::forward_sparse_columns`]
//! only touches the trailing supernodes of a supernodal factor; a simplicial one, which faer
//! picks for small or very sparse systems, is solved whole).
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
use faer::linalg::matmul::matmul;
use faer::linalg::triangular_solve::solve_lower_triangular_in_place;
use faer::perm::PermRef;
use faer::sparse::SparseColMatRef;
use faer::sparse::linalg::cholesky::supernodal::SupernodalLltRef;
use faer::sparse::linalg::cholesky::{
    SymbolicCholesky, SymbolicCholeskyRaw, SymmetricOrdering, factorize_symbolic_cholesky,
};
use faer::sparse::linalg::triangular_solve::{
    solve_lower_triangular_in_place as sparse_lower_solve,
    solve_lower_triangular_transpose_in_place as sparse_lower_transpose_solve,
};
use faer::{Accum, Conj, Mat, MatMut, Par, Side};
use glam::DVec3;

use super::SolveError;
use super::normal::NormalSystem;
use super::ordering::amd_with_last;
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
    /// Position of each free unknown in the factor's (permuted) order.
    position: Vec<u32>,
    factor_memory: MemBuffer,
    solve_memory: MemBuffer,
    residual: Vec<DVec3>,
    residual_scalar: Vec<f64>,
    /// Right-hand sides, then solutions, in the factor's order.
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
        Prefactored::with_last(a, fixed, &[])
    }

    /// [`Prefactored::new`], with the free unknowns in `last` eliminated after all others
    /// (the rest in AMD order), so that [`Prefactored::forward_sparse_columns`] is cheap for
    /// columns on them. Fixed unknowns in `last` are ignored.
    ///
    /// Errors: those of [`Prefactored::new`].
    pub(crate) fn with_last(
        a: &SparseMatrix,
        fixed: &[bool],
        last: &[usize],
    ) -> Result<Prefactored, SolveError> {
        check_len("fixed", a.ncols(), fixed.len())?;
        check_finite(a)?;
        let system = NormalSystem::new(a, fixed);
        let last_free: Vec<usize> = last.iter().filter_map(|&j| system.free_index(j)).collect();
        let custom = if last_free.is_empty() {
            None
        } else {
            Some(amd_with_last(system.normal().symbolic(), &last_free)?)
        };
        let ordering = match &custom {
            Some((fwd, inv)) => {
                SymmetricOrdering::Custom(PermRef::new_checked(fwd, inv, system.n_free()))
            }
            None => SymmetricOrdering::Amd,
        };
        let symbolic = factorize_symbolic_cholesky(
            system.normal().symbolic(),
            Side::Lower,
            ordering,
            Default::default(),
        )
        .map_err(|err| SolveError::Factorization(format!("{err:?}")))?;
        let position = match symbolic.perm() {
            Some(perm) => perm.arrays().1.to_vec(),
            None => (0..system.n_free() as u32).collect(),
        };
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
            position,
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

    /// The matrix `A` it was built for (its values as last refactored).
    pub fn matrix(&self) -> &SparseMatrix {
        &self.a
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
        self.solve_with(rhs, fixed_values, out, |_| {})
    }

    /// [`Prefactored::solve`] with `between` applied to the intermediate `u = L⁻¹ P r`
    /// (`n_free × 3`, in the factor's order) before the second triangular solve. With `N =
    /// Pᵀ L Lᵀ P` the solution is `Pᵀ L⁻ᵀ u`, so changing `u` by `-Y λ`, where `Y = L⁻¹ P Cᵀ`,
    /// subtracts `N⁻¹ Cᵀ λ`: a correction for constraints `C x = t` without a third solve.
    ///
    /// Errors: [`SolveError::DimensionMismatch`] for wrong lengths.
    pub(crate) fn solve_with(
        &mut self,
        rhs: &[DVec3],
        fixed_values: &[DVec3],
        out: &mut [DVec3],
        between: impl FnOnce(MatMut<'_, f64>),
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
            self.set_rhs_row(self.position[f] as usize, projected);
        }
        self.triangular_solves(3, between);
        for (col, x) in out.iter_mut().enumerate() {
            *x = match self.free_position(col) {
                Some(p) => self.rhs_row(p),
                None => fixed_values[col],
            };
        }
        Ok(())
    }

    /// `out = N⁻¹ r` for x, y and z at once, where `N` is the normal matrix of the free
    /// unknowns and `r` holds one vector per unknown (entries of fixed unknowns are ignored,
    /// their outputs zero): the preconditioner of an iterative solve whose matrix is close to
    /// `N` (the same system with other weights). Allocates nothing.
    ///
    /// Errors: [`SolveError::DimensionMismatch`] for wrong lengths.
    pub fn solve_normal(&mut self, r: &[DVec3], out: &mut [DVec3]) -> Result<(), SolveError> {
        check_len("r", self.a.ncols(), r.len())?;
        check_len("out", self.a.ncols(), out.len())?;
        for (col, &r) in r.iter().enumerate() {
            if let Some(p) = self.free_position(col) {
                self.set_rhs_row(p, r);
            }
        }
        self.triangular_solves(3, |_| {});
        for (col, x) in out.iter_mut().enumerate() {
            *x = self
                .free_position(col)
                .map_or(DVec3::ZERO, |p| self.rhs_row(p));
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
            self.rhs[(self.position[f] as usize, 0)] = self
                .a
                .column(col)
                .map(|(row, value)| value * self.residual_scalar[row])
                .sum();
        }
        self.triangular_solves(1, |_| {});
        for (col, x) in out.iter_mut().enumerate() {
            *x = match self.system.free_index(col) {
                Some(f) => self.rhs[(self.position[f] as usize, 0)],
                None => fixed_values[col],
            };
        }
        Ok(())
    }

    /// `Y = L⁻¹ P Cᵀ` for sparse columns of `Cᵀ` (each a list of `(unknown, coefficient)`,
    /// terms on fixed unknowns skipped), with `N = Pᵀ L Lᵀ P`: then `C_f N⁻¹ C_fᵀ = Yᵀ Y` and
    /// [`Prefactored::solve_with`] can apply `N⁻¹ C_fᵀ` for free. Returns the first row `r0`
    /// (in the factor's order) where `Y` can be nonzero and rows `r0..` of `Y`: the
    /// substitution starts at the supernode holding the columns' first unknown, so it costs
    /// little when they are ordered last ([`Prefactored::with_last`]). Allocates; call it when
    /// setting up, not per frame.
    pub(crate) fn forward_sparse_columns(
        &self,
        columns: &[Vec<(usize, f64)>],
    ) -> (usize, Mat<f64>) {
        let n = self.n_free();
        let free_position = |j: usize| self.system.free_index(j).map(|f| self.position[f] as usize);
        let first = columns
            .iter()
            .flatten()
            .filter_map(|&(j, _)| free_position(j))
            .min()
            .unwrap_or(n);
        if first == n {
            return (n, Mat::zeros(0, columns.len()));
        }
        let supernodal = match self.symbolic.raw() {
            SymbolicCholeskyRaw::Supernodal(supernodal) => supernodal,
            SymbolicCholeskyRaw::Simplicial(simplicial) => {
                let mut y = self.scatter_columns(columns, 0);
                let l = SparseColMatRef::new(simplicial.factor(), &self.l_values[..]);
                sparse_lower_solve(l, Conj::No, y.as_mut(), Par::Seq);
                return (0, y);
            }
        };
        let begins = supernodal.supernode_begin();
        let s0 = begins.partition_point(|&b| b as usize <= first) - 1;
        let r0 = begins[s0] as usize;
        let mut y = self.scatter_columns(columns, r0);
        let llt = SupernodalLltRef::new(supernodal, &self.l_values);
        let mut update = Mat::<f64>::zeros(0, columns.len());
        for s in s0..supernodal.n_supernodes() {
            let node = llt.supernode(s);
            let block = node.val();
            let size = block.ncols();
            let (top, bottom) = block.split_at_row(size);
            let mut y_top = y.as_mut().subrows_mut(node.start() - r0, size);
            solve_lower_triangular_in_place(top, y_top.as_mut(), Par::Seq);
            update.resize_with(bottom.nrows(), columns.len(), |_, _| 0.0);
            matmul(
                update.as_mut(),
                Accum::Replace,
                bottom,
                y_top.as_ref(),
                1.0,
                Par::Seq,
            );
            for m in 0..columns.len() {
                for (idx, &i) in node.pattern().iter().enumerate() {
                    y[(i as usize - r0, m)] -= update[(idx, m)];
                }
            }
        }
        (r0, y)
    }

    fn check_lengths(&self, n_rhs: usize, n_fixed: usize, n_out: usize) -> Result<(), SolveError> {
        check_len("rhs", self.a.nrows(), n_rhs)?;
        check_len("fixed_values", self.a.ncols(), n_fixed)?;
        check_len("out", self.a.ncols(), n_out)
    }

    /// Row `p` (in the factor's order) of the x, y and z right-hand sides.
    fn rhs_row(&self, p: usize) -> DVec3 {
        DVec3::new(self.rhs[(p, 0)], self.rhs[(p, 1)], self.rhs[(p, 2)])
    }

    fn set_rhs_row(&mut self, p: usize, value: DVec3) {
        for (k, value) in value.to_array().into_iter().enumerate() {
            self.rhs[(p, k)] = value;
        }
    }

    /// Position in the factor's order of unknown `j`, or `None` when it is fixed.
    fn free_position(&self, j: usize) -> Option<usize> {
        self.system.free_index(j).map(|f| self.position[f] as usize)
    }

    /// Sparse columns (terms on fixed unknowns skipped) as a dense matrix in the factor's
    /// order, from row `r0` on.
    fn scatter_columns(&self, columns: &[Vec<(usize, f64)>], r0: usize) -> Mat<f64> {
        let mut y = Mat::<f64>::zeros(self.n_free() - r0, columns.len());
        for (m, column) in columns.iter().enumerate() {
            for &(j, c) in column {
                if let Some(p) = self.free_position(j) {
                    y[(p - r0, m)] += c;
                }
            }
        }
        y
    }

    /// Solves `N x = rhs` in place for the first `n_columns` columns of `self.rhs` (in the
    /// factor's order), calling `between` after the forward substitution.
    fn triangular_solves(&mut self, n_columns: usize, between: impl FnOnce(MatMut<'_, f64>)) {
        if self.n_free() == 0 {
            return;
        }
        let stack = MemStack::new(&mut self.solve_memory);
        let mut x = self.rhs.as_mut().subcols_mut(0, n_columns);
        match self.symbolic.raw() {
            SymbolicCholeskyRaw::Supernodal(supernodal) => {
                let llt = SupernodalLltRef::new(supernodal, &self.l_values);
                llt.l_solve_with_conj(Conj::No, x.as_mut(), Par::Seq, stack);
                between(x.as_mut());
                llt.l_transpose_solve_with_conj(Conj::No, x, Par::Seq, stack);
            }
            SymbolicCholeskyRaw::Simplicial(simplicial) => {
                let l = SparseColMatRef::new(simplicial.factor(), &self.l_values[..]);
                sparse_lower_solve(l, Conj::No, x.as_mut(), Par::Seq);
                between(x.as_mut());
                sparse_lower_transpose_solve(l, Conj::No, x, Par::Seq);
            }
        }
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

/// `Ok` when a buffer named `what` has the `expected` length, else
/// [`SolveError::DimensionMismatch`].
pub(crate) fn check_len(
    what: &'static str,
    expected: usize,
    found: usize,
) -> Result<(), SolveError> {
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

pub(super) fn try_memory(req: StackReq) -> Result<MemBuffer, SolveError> {
    MemBuffer::try_new(req).map_err(|_| SolveError::Factorization("out of memory".to_owned()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::{cotan_laplacian, uniform_laplacian};
    use crate::mesh::{Mesh, primitives};
    use crate::solve::Triplets;
    use crate::solve::test_support::random_system;

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
    fn forward_columns_give_the_inverse_normal_matrix() {
        let entries: Vec<(usize, usize, f64)> = (0..30)
            .map(|k| (k * 5 % 19, k * 3 % 11, ((k as f64) * 1.3).cos()))
            .collect();
        let a = random_system(19, 11, &entries);
        let mut fixed = vec![false; 11];
        fixed[2] = true;
        fixed[7] = true;
        let free: Vec<usize> = (0..11).filter(|&j| !fixed[j]).collect();
        let dense = a.to_dense();
        let normal = |p: usize, q: usize| dense.iter().map(|r| r[p] * r[q]).sum::<f64>();
        // Each column is a unit vector on a free unknown, plus a term on a fixed one.
        let columns: Vec<Vec<(usize, f64)>> =
            free.iter().map(|&j| vec![(j, 1.0), (2, 5.0)]).collect();
        for last in [&[][..], &[9, 0, 2]] {
            let solver = Prefactored::with_last(&a, &fixed, last).unwrap();
            let (first, y) = solver.forward_sparse_columns(&columns);
            assert_eq!(first + y.nrows(), free.len());
            let mut inverse = Mat::<f64>::zeros(free.len(), free.len());
            matmul(
                inverse.as_mut(),
                Accum::Replace,
                y.transpose(),
                y.as_ref(),
                1.0,
                Par::Seq,
            );
            // (Yᵀ Y) = N⁻¹ on the free unknowns: N (Yᵀ Y) = I.
            for (k, &j) in free.iter().enumerate() {
                for (pi, &p) in free.iter().enumerate() {
                    let nz: f64 = free
                        .iter()
                        .enumerate()
                        .map(|(qi, &q)| normal(p, q) * inverse[(qi, k)])
                        .sum();
                    let expected = if p == j { 1.0 } else { 0.0 };
                    assert!((nz - expected).abs() < 1e-12, "(N Yᵀ Y)[{pi}, {k}] = {nz}");
                }
            }
        }
    }

    #[test]
    fn columns_on_the_last_unknowns_skip_the_leading_rows() {
        // Large enough for faer to choose a supernodal factor.
        let mesh = primitives::grid(60, 60, 1.0);
        let fixed = boundary_mask(&mesh);
        let last = [1830, 1831, 1832, 1833];
        let columns: Vec<Vec<(usize, f64)>> = last.iter().map(|&j| vec![(j, 1.0)]).collect();
        let rows = |last: &[usize]| {
            let solver = Prefactored::with_last(&cotan_laplacian(&mesh), &fixed, last).unwrap();
            let (first, y) = solver.forward_sparse_columns(&columns);
            assert_eq!(first + y.nrows(), solver.n_free());
            y.nrows()
        };
        // Four unknowns last: only the trailing supernode (a few dozen rows after faer's
        // relaxed amalgamation) is touched, against most rows in AMD's order.
        let (ordered_last, scattered) = (rows(&last), rows(&[]));
        assert!(
            3 * ordered_last < scattered,
            "{ordered_last} vs {scattered} rows"
        );
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
