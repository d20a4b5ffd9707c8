//! The rows of Eq. 6.11 for one mesh and setting, with the scale `s` left open: every
//! weight that `s` changes is `s` times a weight computed once, so a new `s` changes the
//! values of the system but not its pattern (the factorization's analysis is kept).

use glam::DVec3;

use super::weights::{
    curvature_magnitudes, feature_laplacian_weights, gaussian_laplacian_weights,
    positional_weights, worst_radius_ratios,
};
use super::{FeatureFalloff, LaplacianKind, Mode, OptimizeParams, WeightScheme};
use crate::geometry::{
    cotan_laplacian, cotan_laplacian_coordinates, uniform_laplacian, vertex_areas, vertex_normals,
};
use crate::mesh::Mesh;
use crate::solve::{SparseMatrix, Triplets};

/// The weight of the two planes that keep a sliding vertex on its line, against 1 for the
/// Laplacian rows (their squares meet in the normal equations): after the curve ops of the
/// golden sessions the solve left the vertices 0.004–0.011 edge lengths off their lines
/// (against 0.09–0.18 with the planes weighted 1; a hundred held them no closer), and
/// [`Rows::keep_on_lines`] then puts them on.
const LINE_WEIGHT: f64 = 10.0;

/// `W_L L` and `W_L f` of Eq. 6.11, `W_p` at `s = 1`, and what the tangent-plane rows need.
pub(super) struct Rows {
    /// The Laplacian with each row scaled by its `W_L` (which does not depend on `s`).
    laplacian: SparseMatrix,
    /// `W_L f`, per vertex.
    target: Vec<DVec3>,
    /// `W_p` at `s = 1`, per vertex.
    positional: Vec<f64>,
    /// The input positions, which the positional rows hold.
    positions: Vec<DVec3>,
    /// The input's vertex normals, when the tangent-plane rows are on.
    normals: Option<Vec<DVec3>>,
    /// The sliding vertices of the coupled system.
    lines: Vec<Line>,
}

impl Rows {
    /// The rows for `mesh` and `params` (whose `scale` is ignored: see [`Rows::matrix`]);
    /// the vertices `tagged` marks are features that hold (see [`super::Selection`]).
    pub(super) fn new(
        mesh: &Mesh,
        params: &OptimizeParams,
        tagged: Option<&[bool]>,
        sliding: Option<&[Option<DVec3>]>,
    ) -> Rows {
        let kappa = curvature_magnitudes(mesh);
        let (mut positional, mut row_weights) = match (params.features, params.feature_falloff) {
            (false, _) => (
                positional_weights(&kappa, params.weights, 1.0),
                vec![1.0; mesh.n_vertices()],
            ),
            (true, FeatureFalloff::Linear | FeatureFalloff::Cdf) => {
                let scheme = match params.feature_falloff {
                    FeatureFalloff::Cdf => WeightScheme::Cdf,
                    _ => WeightScheme::Linear,
                };
                let weights = positional_weights(&kappa, scheme, 1.0);
                let rows = feature_laplacian_weights(&weights, 1.0);
                (weights, rows)
            }
            (true, FeatureFalloff::Gaussian) => (
                positional_weights(&kappa, params.weights, 1.0),
                gaussian_laplacian_weights(&kappa),
            ),
        };
        if params.quality {
            for (w, t) in positional.iter_mut().zip(worst_radius_ratios(mesh)) {
                *w *= t;
            }
        }
        let tagged = tagged.into_iter().flatten();
        for ((w, row), _) in (positional.iter_mut().zip(&mut row_weights))
            .zip(tagged)
            .filter(|(_, t)| **t)
        {
            (*w, *row) = (1.0, 0.0);
        }
        let (laplacian, target) = match params.mode {
            Mode::Shape => (uniform_laplacian(mesh), cotan_coordinates(mesh)),
            Mode::Smooth => (
                smoothing_laplacian(mesh, params.laplacian),
                vec![DVec3::ZERO; mesh.n_vertices()],
            ),
        };
        let normals = params.tangent_plane.then(|| vertex_normals(mesh));
        let lines = match (&normals, sliding) {
            (Some(normals), Some(sliding)) => sliding_planes(normals, sliding),
            _ => Vec::new(),
        };
        Rows {
            laplacian: laplacian.scale_rows(&row_weights),
            target: target
                .iter()
                .zip(&row_weights)
                .map(|(&f, &w)| f * w)
                .collect(),
            positional,
            positions: mesh.positions().to_vec(),
            normals,
            lines,
        }
    }

    /// The input positions.
    pub(super) fn positions(&self) -> &[DVec3] {
        &self.positions
    }

    /// Whether x, y and z are solved together (the tangent-plane rows couple them).
    pub(super) fn is_coupled(&self) -> bool {
        self.normals.is_some()
    }

    /// The system matrix at `scale`; its pattern is the same for every scale.
    ///
    /// Separable: `[W_L L; s W_p]`, `2n × n`, shared by x, y and z. Coupled: the `7n × 3n`
    /// system with unknown `3 i + d` for coordinate `d` of vertex `i`, whose rows `6n..7n`
    /// are the tangent-plane rows `s n_i · v'_i` (Eq. 6.15; weighted `s` to match the
    /// positional rows), then one row `s b_i · v'_i` per sliding vertex.
    pub(super) fn matrix(&self, scale: f64) -> SparseMatrix {
        let n = self.positions.len();
        let Some(normals) = &self.normals else {
            let mut a = Triplets::with_capacity(2 * n, n, self.laplacian.nnz() + n);
            a.push_matrix(&self.laplacian, 0, 0, 1.0);
            for (i, &w) in self.positional.iter().enumerate() {
                a.push(n + i, i, scale * w);
            }
            return a.build();
        };
        let rows = 7 * n + self.lines.len();
        let entries = 3 * self.laplacian.nnz() + 6 * n + 3 * self.lines.len();
        let mut a = Triplets::with_capacity(rows, 3 * n, entries);
        for d in 0..3 {
            push_block(&mut a, &self.laplacian, d * n, d, 3);
            for (i, &w) in self.positional.iter().enumerate() {
                a.push(3 * n + d * n + i, 3 * i + d, scale * w);
            }
        }
        let plane_weights = self.plane_weights();
        for (i, normal) in normals.iter().enumerate() {
            for d in 0..3 {
                a.push(6 * n + i, 3 * i + d, scale * plane_weights[i] * normal[d]);
            }
        }
        for (k, line) in self.lines.iter().enumerate() {
            for d in 0..3 {
                a.push(
                    7 * n + k,
                    3 * line.vertex + d,
                    scale * LINE_WEIGHT * line.plane[d],
                );
            }
        }
        a.build()
    }

    /// The weight of each vertex's tangent-plane row: [`LINE_WEIGHT`] for a sliding vertex,
    /// whose line is the crossing of that plane with its second one, else 1.
    fn plane_weights(&self) -> Vec<f64> {
        let mut weights = vec![1.0; self.positions.len()];
        for line in &self.lines {
            weights[line.vertex] = LINE_WEIGHT;
        }
        weights
    }

    /// Puts each sliding vertex of `positions` exactly on its line: the rows hold it there
    /// only in the least-squares sense, and a curve on a plane (a cut's rim) must stay on it.
    pub(super) fn keep_on_lines(&self, positions: &mut [DVec3]) {
        for line in &self.lines {
            let origin = self.positions[line.vertex];
            let offset = positions[line.vertex] - origin;
            positions[line.vertex] = origin + line.direction * offset.dot(line.direction);
        }
    }

    /// The right-hand side at `scale` of the separable system: `[W_L f; s W_p V]`.
    pub(super) fn rhs(&self, scale: f64) -> Vec<DVec3> {
        let held = self.positions.iter().zip(&self.positional);
        (self.target.iter().copied())
            .chain(held.map(|(&p, &w)| p * (scale * w)))
            .collect()
    }

    /// `N(scale) x` for the separable system, `N = (W_L L)ᵀ (W_L L) + s² W_p²`, with
    /// `rows` (one per vertex) as scratch.
    pub(super) fn normal_product(
        &self,
        scale: f64,
        x: &[DVec3],
        rows: &mut [DVec3],
        out: &mut [DVec3],
    ) {
        self.laplacian.mul_dvec3(x, rows);
        self.laplacian.mul_transpose_dvec3(rows, out);
        for ((out, &x), &w) in out.iter_mut().zip(x).zip(&self.positional) {
            *out += (scale * w) * (scale * w) * x;
        }
    }

    /// `Aᵀ b` at `scale` for the separable system: `(W_L L)ᵀ W_L f + s² W_p² V`.
    pub(super) fn normal_rhs(&self, scale: f64) -> Vec<DVec3> {
        let mut out = vec![DVec3::ZERO; self.positions.len()];
        self.laplacian.mul_transpose_dvec3(&self.target, &mut out);
        let held = self.positions.iter().zip(&self.positional);
        for (out, (&p, &w)) in out.iter_mut().zip(held) {
            *out += (scale * w) * (scale * w) * p;
        }
        out
    }

    /// The right-hand side at `scale` of the coupled system, in the rows of [`Rows::matrix`].
    pub(super) fn coupled_rhs(&self, scale: f64) -> Vec<f64> {
        let n = self.positions.len();
        let mut rhs = Vec::with_capacity(7 * n);
        for d in 0..3 {
            rhs.extend(self.target.iter().map(|f| f[d]));
        }
        for d in 0..3 {
            let held = self.positions.iter().zip(&self.positional);
            rhs.extend(held.map(|(p, &w)| scale * w * p[d]));
        }
        let normals = self.normals.iter().flatten();
        let planes = normals.zip(&self.positions).zip(self.plane_weights());
        rhs.extend(planes.map(|((normal, p), w)| scale * w * normal.dot(*p)));
        let lines = self.lines.iter();
        rhs.extend(
            lines.map(|line| scale * LINE_WEIGHT * line.plane.dot(self.positions[line.vertex])),
        );
        rhs
    }
}

/// A vertex that may only slide along a line through its input position.
struct Line {
    vertex: usize,
    /// The unit direction of the line.
    direction: DVec3,
    /// The normal of the plane through the line that crosses the vertex's tangent plane
    /// (`normal × direction`): the two planes' rows leave the vertex the line.
    plane: DVec3,
}

/// The lines of the vertices with a sliding direction (and a normal across it).
fn sliding_planes(normals: &[DVec3], sliding: &[Option<DVec3>]) -> Vec<Line> {
    let lines = normals.iter().zip(sliding).enumerate();
    lines
        .filter_map(|(vertex, (normal, direction))| {
            let direction = (*direction)?.try_normalize()?;
            let plane = normal.cross(direction).try_normalize()?;
            Some(Line {
                vertex,
                direction,
                plane,
            })
        })
        .collect()
}

/// The input's normalized cotangent Laplacian coordinates `v_i − Σ_j w_ij v_j` with
/// `w_ij = ω_ij / Σ_k ω_ik` (Eq. 6.2, 6.4): the target of shape optimization. Where the
/// cotangents sum to nothing (degenerate fans) the uniform coordinate stands in, which
/// asks for no change.
fn cotan_coordinates(mesh: &Mesh) -> Vec<DVec3> {
    let (laplacian, diagonal) = cotan_laplacian_coordinates(mesh);
    let is_usable = usable_divisors(&diagonal);
    mesh.vertices()
        .map(|v| {
            let i = v.index();
            if is_usable[i] {
                laplacian[i] / diagonal[i]
            } else {
                let ring: DVec3 = mesh.vertex_neighbors(v).map(|u| mesh.position(u)).sum();
                mesh.position(v) - ring / mesh.valence(v) as f64
            }
        })
        .collect()
}

/// The Laplacian smoothing uses: uniform, normalized cotangent or `M⁻¹` times the cotangent
/// one (its rows are `κ̄ n`, Eq. 6.7, up to the factor 2).
fn smoothing_laplacian(mesh: &Mesh, kind: LaplacianKind) -> SparseMatrix {
    let divisors = match kind {
        LaplacianKind::Uniform => return uniform_laplacian(mesh),
        LaplacianKind::Cotan => cotan_laplacian_coordinates(mesh).1,
        LaplacianKind::CotanCurvature => vertex_areas(mesh),
    };
    normalized_rows(&cotan_laplacian(mesh), &divisors, mesh)
}

/// Whether each divisor is large enough to divide by: positive, and not vanishing next to
/// the largest one (no area, cotangents that cancel).
fn usable_divisors(divisors: &[f64]) -> Vec<bool> {
    let largest = divisors.iter().fold(0.0f64, |m, d| m.max(d.abs()));
    divisors.iter().map(|&d| d > 1e-12 * largest).collect()
}

/// `cotan` with row `i` divided by `divisors[i]`; rows whose divisor is not usable become
/// uniform Laplacian rows. Both Laplacians store every edge and the diagonal, so the result
/// keeps their common pattern.
fn normalized_rows(cotan: &SparseMatrix, divisors: &[f64], mesh: &Mesh) -> SparseMatrix {
    let uniform = uniform_laplacian(mesh);
    debug_assert!(uniform.has_same_pattern(cotan));
    let is_usable = usable_divisors(divisors);
    let mut out = cotan.clone();
    let entries = out.values_mut().iter_mut().zip(uniform.values());
    for ((value, &uniform), &row) in entries.zip(cotan.row_indices()) {
        let row = row as usize;
        *value = if is_usable[row] {
            *value / divisors[row]
        } else {
            uniform
        };
    }
    out
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
