//! An optimization held open while its scale changes (the app's slider): the system is
//! analysed and factored once; a new scale changes only the values of the positional and
//! tangent-plane rows, so it costs a numeric refactorization on the kept analysis (AMD
//! ordering, elimination tree, normal-matrix pattern) and a back-substitution, and gives
//! bit for bit what a fresh [`optimize`](super::optimize) at that scale gives. For a preview
//! that must not stall a frame, [`Optimizer::refine`] approaches a new scale by
//! preconditioned conjugate gradients instead ([`super::refine`]), one iteration per call.

use glam::DVec3;

use super::refine::Refinement;
use super::system::Rows;
use super::{OptimizeError, OptimizeParams, Selection};
use crate::mesh::Mesh;
use crate::solve::{Prefactored, SparseMatrix};

/// One mesh's optimization with its factorization, ready to solve at any scale.
pub struct Optimizer {
    /// The settings; `scale` is the one the factorization is for.
    params: OptimizeParams,
    rows: Rows,
    solver: Prefactored,
    /// Per vertex: whether it keeps its place (outside the region).
    fixed: Vec<bool>,
    /// The preview's approach to another scale, if one is under way.
    refinement: Option<Refinement>,
}

/// Conjugate-gradient iterations after which a refinement gives up and refactors (a scale
/// far from the factored one).
const MAX_ITERATIONS: usize = 40;

/// The optimized positions of `mesh` (one per vertex, same order; the triangles stay).
///
/// Errors: [`OptimizeError::InvalidScale`] for a scale that is not positive and finite,
/// [`OptimizeError::Empty`] for a mesh without faces, [`OptimizeError::Solve`] when the
/// factorization fails.
pub fn optimize(mesh: &Mesh, params: &OptimizeParams) -> Result<Vec<DVec3>, OptimizeError> {
    Optimizer::new(mesh, params, &Selection::default())?.solve(params.scale)
}

impl std::fmt::Debug for Optimizer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Optimizer")
            .field("params", &self.params)
            .finish_non_exhaustive()
    }
}

impl Optimizer {
    /// Builds and factors the system of `mesh` with `params`; only the vertices `selection`
    /// leaves movable move, and the features it tags hold.
    ///
    /// Errors: [`OptimizeError::InvalidScale`], [`OptimizeError::Empty`],
    /// [`OptimizeError::EmptyRegion`], or the solver's.
    pub fn new(
        mesh: &Mesh,
        params: &OptimizeParams,
        selection: &Selection,
    ) -> Result<Optimizer, OptimizeError> {
        check_scale(params.scale)?;
        if mesh.n_faces() == 0 {
            return Err(OptimizeError::Empty);
        }
        let fixed: Vec<bool> = match &selection.movable {
            Some(movable) => movable.iter().map(|&m| !m).collect(),
            None => vec![false; mesh.n_vertices()],
        };
        if fixed.len() != mesh.n_vertices() || fixed.iter().all(|&f| f) {
            return Err(OptimizeError::EmptyRegion);
        }
        let rows = Rows::new(
            mesh,
            params,
            selection.features.as_deref(),
            selection.sliding.as_deref(),
        );
        let a = rows.matrix(params.scale);
        let unknowns_fixed: Vec<bool> = match rows.is_coupled() {
            true => fixed.iter().flat_map(|&f| [f; 3]).collect(),
            false => fixed.clone(),
        };
        let solver = Prefactored::new(&a, &unknowns_fixed)?;
        Ok(Optimizer {
            params: *params,
            rows,
            solver,
            fixed,
            refinement: None,
        })
    }

    /// The settings, with the scale last solved at.
    pub fn params(&self) -> &OptimizeParams {
        &self.params
    }

    /// The separable least-squares system `A x = b` at the current scale (`A` is `2n × n`, `b`
    /// one vector per row), for checking against other solvers; `None` when the
    /// tangent-plane rows couple the coordinates.
    pub fn least_squares_system(&self) -> Option<(SparseMatrix, Vec<DVec3>)> {
        let scale = self.params.scale;
        (!self.rows.is_coupled()).then(|| (self.rows.matrix(scale), self.rows.rhs(scale)))
    }

    /// Whether `params` differ from this optimizer's at most in the scale, so that
    /// [`Optimizer::solve`] serves them.
    pub fn serves(&self, params: &OptimizeParams) -> bool {
        OptimizeParams {
            scale: self.params.scale,
            ..*params
        } == self.params
    }

    /// The optimized positions at `scale`, refactoring first when the scale changed (on a
    /// failed refactorization the previous one is kept).
    ///
    /// Errors: [`OptimizeError::InvalidScale`], the solver's, or
    /// [`OptimizeError::NotFinite`].
    pub fn solve(&mut self, scale: f64) -> Result<Vec<DVec3>, OptimizeError> {
        check_scale(scale)?;
        if scale != self.params.scale {
            self.solver.refactor_values(&self.rows.matrix(scale))?;
            self.params.scale = scale;
        }
        let n = self.solver.n_unknowns();
        let held = self.rows.positions();
        let positions = if self.rows.is_coupled() {
            let mut x = vec![0.0; n];
            let rhs = self.rows.coupled_rhs(scale);
            let held: Vec<f64> = held.iter().flat_map(|p| p.to_array()).collect();
            self.solver.solve_scalar(&rhs, &held, &mut x)?;
            let mut positions: Vec<DVec3> = x
                .chunks_exact(3)
                .map(|c| DVec3::new(c[0], c[1], c[2]))
                .collect();
            self.rows.keep_on_lines(&mut positions);
            positions
        } else {
            let mut x = vec![DVec3::ZERO; n];
            let rhs = self.rows.rhs(scale);
            self.solver.solve(&rhs, held, &mut x)?;
            x
        };
        if positions.iter().all(|p| p.is_finite()) {
            Ok(positions)
        } else {
            Err(OptimizeError::NotFinite)
        }
    }

    /// One step of the preview toward `scale`: `shown` (the positions on screen) moves
    /// closer to the solution. Returns whether it is there: exactly when `scale` is the
    /// factored one or the system is coupled (which has no iterative path and refactors),
    /// else to a relative residual of 1e-5 by conjugate gradients preconditioned with the
    /// kept factorization, one iteration per call (after [`MAX_ITERATIONS`] it refactors).
    /// [`Optimizer::solve`] gives the exact result to commit.
    ///
    /// Errors: those of [`Optimizer::solve`].
    pub fn refine(&mut self, scale: f64, shown: &mut Vec<DVec3>) -> Result<bool, OptimizeError> {
        check_scale(scale)?;
        if scale == self.params.scale || self.rows.is_coupled() {
            self.refinement = None;
            *shown = self.solve(scale)?;
            return Ok(true);
        }
        let refinement = match &mut self.refinement {
            Some(r) if r.scale() == scale => r,
            slot => slot.insert(Refinement::new(
                &self.rows,
                &mut self.solver,
                &self.fixed,
                scale,
                shown,
            )?),
        };
        refinement.iterate(&self.rows, &mut self.solver, &self.fixed)?;
        shown.copy_from_slice(refinement.estimate());
        if refinement.has_converged() {
            return Ok(true);
        }
        if refinement.iterations() >= MAX_ITERATIONS {
            self.refinement = None;
            *shown = self.solve(scale)?;
            return Ok(true);
        }
        Ok(false)
    }
}

fn check_scale(scale: f64) -> Result<(), OptimizeError> {
    if scale.is_finite() && scale > 0.0 {
        Ok(())
    } else {
        Err(OptimizeError::InvalidScale(scale))
    }
}
