//! The rows of Eq. 6.11 for one mesh and setting, and their solves: per coordinate (x, y
//! and z share one factorization), or coupled through the tangent-plane rows.

use glam::DVec3;

use super::weights::{
    curvature_magnitudes, feature_laplacian_weights, linear_weights, positional_weights,
    worst_radius_ratios,
};
use super::{LaplacianKind, Mode, OptimizeError, OptimizeParams};
use crate::geometry::{cotan_laplacian, uniform_laplacian, vertex_areas, vertex_normals};
use crate::mesh::Mesh;
use crate::solve::{Prefactored, SparseMatrix, Triplets, solve_least_squares};

/// `W_L L`, `W_L f` and `W_p` of Eq. 6.11, and the weight of the tangent-plane rows.
pub(super) struct Rows {
    /// The Laplacian with each row scaled by its `W_L`.
    laplacian: SparseMatrix,
    /// `W_L f`, per vertex.
    target: Vec<DVec3>,
    /// `W_p`, per vertex.
    positional: Vec<f64>,
    /// The weight of each tangent-plane row (the scale `s`, so it matches the positional rows).
    tangent_weight: f64,
}

impl Rows {
    pub(super) fn new(mesh: &Mesh, params: &OptimizeParams) -> Rows {
        let kappa = curvature_magnitudes(mesh);
        let (mut positional, row_weights) = if params.features {
            let linear = linear_weights(&kappa, params.scale);
            let rows = feature_laplacian_weights(&linear, params.scale);
            (linear, rows)
        } else {
            let weights = positional_weights(&kappa, params.weights, params.scale);
            (weights, vec![1.0; mesh.n_vertices()])
        };
        if params.quality {
            for (w, t) in positional.iter_mut().zip(worst_radius_ratios(mesh)) {
                *w *= t;
            }
        }
        let (laplacian, target) = match params.mode {
            Mode::Shape => (uniform_laplacian(mesh), cotan_coordinates(mesh)),
            Mode::Smooth => (
                smoothing_laplacian(mesh, params.laplacian),
                vec![DVec3::ZERO; mesh.n_vertices()],
            ),
        };
        Rows {
            laplacian: scale_rows(&laplacian, &row_weights),
            target: target
                .iter()
                .zip(&row_weights)
                .map(|(&f, &w)| f * w)
                .collect(),
            positional,
            tangent_weight: params.scale,
        }
    }

    /// Solves x, y and z apart: `[W_L L; W_p] V' = [W_L f; W_p V]`.
    pub(super) fn solve_separable(&self, mesh: &Mesh) -> Result<Vec<DVec3>, OptimizeError> {
        let n = mesh.n_vertices();
        let mut a = Triplets::with_capacity(2 * n, n, self.laplacian.nnz() + n);
        a.push_matrix(&self.laplacian, 0, 0, 1.0);
        for (i, &w) in self.positional.iter().enumerate() {
            a.push(n + i, i, w);
        }
        let rhs: Vec<DVec3> = self
            .target
            .iter()
            .copied()
            .chain(
                mesh.positions()
                    .iter()
                    .zip(&self.positional)
                    .map(|(&p, &w)| p * w),
            )
            .collect();
        let free = vec![false; n];
        Ok(solve_least_squares(
            &a.build(),
            &rhs,
            &free,
            &vec![DVec3::ZERO; n],
        )?)
    }

    /// Solves all coordinates at once with the tangent-plane rows `n_i · v'_i = n_i · v_i`
    /// (Eq. 6.15): a `7n × 3n` system, unknown `3 i + d` for coordinate `d` of vertex `i`.
    pub(super) fn solve_coupled(&self, mesh: &Mesh) -> Result<Vec<DVec3>, OptimizeError> {
        let n = mesh.n_vertices();
        let normals = vertex_normals(mesh);
        let mut a = Triplets::with_capacity(7 * n, 3 * n, 3 * self.laplacian.nnz() + 6 * n);
        let mut rhs = Vec::with_capacity(7 * n);
        for d in 0..3 {
            push_block(&mut a, &self.laplacian, d * n, d, 3);
            rhs.extend(self.target.iter().map(|f| f[d]));
        }
        for d in 0..3 {
            for (i, (&w, p)) in self.positional.iter().zip(mesh.positions()).enumerate() {
                a.push(3 * n + d * n + i, 3 * i + d, w);
                rhs.push(w * p[d]);
            }
        }
        for (i, (normal, p)) in normals.iter().zip(mesh.positions()).enumerate() {
            let w = self.tangent_weight;
            for d in 0..3 {
                a.push(6 * n + i, 3 * i + d, w * normal[d]);
            }
            rhs.push(w * normal.dot(*p));
        }
        let mut solver = Prefactored::new(&a.build(), &vec![false; 3 * n])?;
        let mut x = vec![0.0; 3 * n];
        solver.solve_scalar(&rhs, &vec![0.0; 3 * n], &mut x)?;
        Ok(x.chunks_exact(3)
            .map(|c| DVec3::new(c[0], c[1], c[2]))
            .collect())
    }
}

/// The input's normalized cotangent Laplacian coordinates `v_i − Σ_j w_ij v_j` with
/// `w_ij = ω_ij / Σ_k ω_ik` (Eq. 6.2, 6.4): the target of shape optimization. Where the
/// cotangents sum to nothing (degenerate fans) the uniform coordinate stands in, which
/// asks for no change.
fn cotan_coordinates(mesh: &Mesh) -> Vec<DVec3> {
    let cotan = normalized_rows(&cotan_laplacian(mesh), |_, diagonal| diagonal, mesh);
    let mut out = vec![DVec3::ZERO; mesh.n_vertices()];
    cotan.mul_dvec3(mesh.positions(), &mut out);
    out
}

/// The Laplacian smoothing uses: uniform, normalized cotangent or `M⁻¹` times the cotangent
/// one (its rows are `κ̄ n`, Eq. 6.7, up to the factor 2).
fn smoothing_laplacian(mesh: &Mesh, kind: LaplacianKind) -> SparseMatrix {
    match kind {
        LaplacianKind::Uniform => uniform_laplacian(mesh),
        LaplacianKind::Cotan => {
            normalized_rows(&cotan_laplacian(mesh), |_, diagonal| diagonal, mesh)
        }
        LaplacianKind::CotanCurvature => {
            let areas = vertex_areas(mesh);
            normalized_rows(&cotan_laplacian(mesh), |i, _| areas[i], mesh)
        }
    }
}

/// `cotan` with row `i` divided by `divisor(i, L_ii)`; rows whose divisor is not positive
/// (no area, cotangents that cancel) become uniform Laplacian rows.
fn normalized_rows(
    cotan: &SparseMatrix,
    divisor: impl Fn(usize, f64) -> f64,
    mesh: &Mesh,
) -> SparseMatrix {
    let n = cotan.nrows();
    let divisors: Vec<f64> = (0..n).map(|i| divisor(i, cotan.get(i, i))).collect();
    let largest = divisors.iter().fold(0.0f64, |m, d| m.max(d.abs()));
    let is_usable = |i: usize| divisors[i] > 1e-12 * largest;
    let uniform = uniform_laplacian(mesh);
    let mut out = Triplets::with_capacity(n, n, cotan.nnz());
    for col in 0..n {
        for (row, value) in cotan.column(col) {
            if is_usable(row) {
                out.push(row, col, value / divisors[row]);
            }
        }
        for (row, value) in uniform.column(col) {
            if !is_usable(row) {
                out.push(row, col, value);
            }
        }
    }
    out.build()
}

/// `matrix` with row `i` multiplied by `weights[i]`.
fn scale_rows(matrix: &SparseMatrix, weights: &[f64]) -> SparseMatrix {
    let mut out = Triplets::with_capacity(matrix.nrows(), matrix.ncols(), matrix.nnz());
    for col in 0..matrix.ncols() {
        for (row, value) in matrix.column(col) {
            out.push(row, col, weights[row] * value);
        }
    }
    out.build()
}

/// Copies `block` into `a` at row offset `row0`, its column `j` going to column
/// `stride * j + col0`.
fn push_block(a: &mut Triplets, block: &SparseMatrix, row0: usize, col0: usize, stride: usize) {
    for col in 0..block.ncols() {
        for (row, value) in block.column(col) {
            a.push(row0 + row, stride * col + col0, value);
        }
    }
}
