//! The deformation energy and its solve (Zhou et al. 2005, Eq. 3 and §3.3 "Quadric Energy
//! Minimization"):
//!
//! `Σ_{i≤n} ‖L_M(p'_i) − ε'_i‖² + α Σ_{i∈soft} ‖p'_i − q_i‖² + β Σ_{i≤N} ‖L_G'(p'_i) − δ'_i‖²`,
//!
//! with `L_M` the mesh's normalised, clamped cotangent Laplacian (`deform`'s weights),
//! `L_G'` the graph Laplacian without mesh edges (QP weights, `weights.rs`), `ε' = T ε` and
//! `δ' = T δ` the rest coordinates turned by each point's propagated similarity `T`, and
//! `β = n β̃ / N`. The printed system of the paper has more rows than unknowns; we minimise
//! the energy itself, through the normal equations (as the digest reads it).
//!
//! **The volume term, edge by edge.** By default ([`GraphTerm::Edges`]) the third term keeps
//! each graph edge rather than each point's Laplacian coordinate:
//! `β Σ_i Σ_j w_ij ‖(p'_j − p'_i) − T_i (p_j − p_i)‖²`, the same weights, the same
//! propagated `T`, still one fixed matrix (the weighted graph Laplacian). Laplacian
//! coordinates are second differences: inside a regular lattice they vanish whatever its
//! spacing, so they say nothing about length. The paper's curves constrain positions all
//! along the deformed control curve, which fixes the length; the `deform` op's handles hold
//! only the ends, and with the printed term a capsule bent by half a turn shortens along
//! its middle and loses 14.4% of its volume (the surface editor: 14.8%), against 4.4% edge
//! by edge; a bar twisted by a quarter turn loses 7.0% against 2.6%
//! (`tests/suite/volumetric.rs` prints both). [`GraphTerm::Laplacian`] is the printed term.
//!
//! Hard constraints are fixed unknowns: handle points placed exactly and fixed points kept
//! (the `deform` op's spheres). Soft ones are the α rows (control curves). The matrix
//! depends only on the rest graph and on which points are constrained, so it is factored
//! once per handle set and every frame is one back-substitution for x, y and z.
//!
//! The unknowns are the displacements from rest: a frame in which no transform and no
//! target differs from rest has a zero right-hand side and leaves every point bit for bit.

use glam::DVec3;

use super::{Similarity, VolumetricError, VolumetricGraph};
use crate::geometry::OneRingWeights;
use crate::mesh::{Mesh, VertexId};
use crate::solve::{Prefactored, SparseMatrix, Triplets};

/// How the volume term keeps the graph's shape; see the module docs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GraphTerm {
    /// Each graph edge, turned by its point's similarity.
    #[default]
    Edges,
    /// Each point's Laplacian coordinate, turned (Eq. 3 as printed).
    Laplacian,
}

/// The energy's weights; the paper's defaults.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VolumetricParams {
    /// α: the weight of each soft positional row (the paper: 0.1 to 1, 0.2 by default).
    pub alpha: f64,
    /// β̃: the volumetric term's weight before scaling by `n / N` (the paper: 1).
    pub beta: f64,
    /// The form of the volume term.
    pub graph_term: GraphTerm,
}

impl Default for VolumetricParams {
    fn default() -> Self {
        VolumetricParams {
            alpha: 0.2,
            beta: 1.0,
            graph_term: GraphTerm::Edges,
        }
    }
}

/// What the edit holds still or pulls: per graph point.
#[derive(Clone, Debug, Default)]
pub struct Constraints {
    /// Graph points whose position is given every frame (handles and fixed parts).
    pub hard: Vec<bool>,
    /// Mesh vertices pulled toward targets by α rows, in the order targets are given.
    pub soft: Vec<VertexId>,
}

/// One factored volumetric edit of a mesh; see the module docs.
#[derive(Debug)]
pub struct VolumetricEdit {
    n_mesh: usize,
    rest: Vec<DVec3>,
    /// Rest cotangent Laplacian coordinate of each mesh vertex.
    rest_surface: Vec<DVec3>,
    /// Rest graph Laplacian coordinate of each point.
    rest_graph: Vec<DVec3>,
    /// The point whose transform turns each graph row.
    graph_owner: Vec<u32>,
    alpha_weight: f64,
    soft: Vec<VertexId>,
    solver: Prefactored,
    rhs: Vec<DVec3>,
    fixed_values: Vec<DVec3>,
    displacement: Vec<DVec3>,
}

impl VolumetricEdit {
    /// Builds and factors the edit of `mesh` through its `graph`.
    ///
    /// Errors: [`VolumetricError::Solve`] when the system cannot be factored (nothing
    /// constrained: the whole model could float), [`VolumetricError::BadParams`].
    pub fn new(
        mesh: &Mesh,
        graph: &VolumetricGraph,
        constraints: &Constraints,
        params: VolumetricParams,
    ) -> Result<VolumetricEdit, VolumetricError> {
        let usable = |x: f64| x.is_finite() && x > 0.0;
        if !usable(params.alpha) || !usable(params.beta) {
            return Err(VolumetricError::BadParams);
        }
        let (n, big_n) = (graph.n_mesh(), graph.n_points());
        let edges = params.graph_term == GraphTerm::Edges;
        let n_graph_rows = if edges {
            (0..big_n).map(|i| graph.row(i).len()).sum()
        } else {
            big_n
        };
        let vertices: Vec<VertexId> = mesh.vertices().collect();
        let rings = OneRingWeights::new(mesh, &vertices, |v| v.0);
        let graph_weight = (params.beta * n as f64 / big_n as f64).sqrt();
        let alpha_weight = params.alpha.sqrt();
        let n_rows = n + n_graph_rows + constraints.soft.len();
        let mut triplets = Triplets::with_capacity(n_rows, big_n, 8 * n + 24 * big_n);
        let points = graph.points();
        let mut rest_surface = Vec::with_capacity(n);
        for i in 0..n {
            triplets.push(i, i, 1.0);
            let mut delta = points[i];
            for (j, w) in rings.ring(i) {
                triplets.push(i, j, -w);
                delta -= w * points[j];
            }
            rest_surface.push(delta);
        }
        let mut rest_graph = Vec::with_capacity(n_graph_rows);
        let mut graph_owner = Vec::with_capacity(n_graph_rows);
        let mut row = n;
        for i in 0..big_n {
            if edges {
                // Row `√(β w_ij) (p'_j − p'_i) = √(β w_ij) T_i (p_j − p_i)`.
                for (j, w) in graph.row(i) {
                    let s = w.sqrt() * graph_weight;
                    triplets.push(row, i, -s);
                    triplets.push(row, j, s);
                    rest_graph.push(s * (points[j] - points[i]));
                    graph_owner.push(i as u32);
                    row += 1;
                }
                continue;
            }
            triplets.push(row, i, graph_weight);
            let mut delta = points[i];
            for (j, w) in graph.row(i) {
                triplets.push(row, j, -graph_weight * w);
                delta -= w * points[j];
            }
            rest_graph.push(graph_weight * delta);
            graph_owner.push(i as u32);
            row += 1;
        }
        for (k, v) in constraints.soft.iter().enumerate() {
            triplets.push(row + k, v.index(), alpha_weight);
        }
        let mut hard = constraints.hard.clone();
        hard.resize(big_n, false);
        let solver = Prefactored::new(&triplets.build(), &hard)?;
        Ok(VolumetricEdit {
            n_mesh: n,
            rest: points.to_vec(),
            rest_surface,
            rest_graph,
            graph_owner,
            alpha_weight,
            soft: constraints.soft.clone(),
            solver,
            rhs: vec![DVec3::ZERO; n_rows],
            fixed_values: vec![DVec3::ZERO; big_n],
            displacement: vec![DVec3::ZERO; big_n],
        })
    }

    /// The last frame's least-squares problem over the displacements from rest, for checking
    /// against other solvers: `A`, `b`, which unknowns are fixed and their values (the
    /// solution is what [`VolumetricEdit::deform`] added to the rest positions).
    pub fn last_system(&self) -> (&SparseMatrix, &[DVec3], &[bool], &[DVec3]) {
        let solver = &self.solver;
        (
            solver.matrix(),
            &self.rhs,
            solver.fixed(),
            &self.fixed_values,
        )
    }

    /// How many of the points are the mesh's vertices (the first ones).
    pub fn n_mesh(&self) -> usize {
        self.n_mesh
    }

    /// Solves one frame: `transforms[i]` turns point `i`'s rest Laplacian coordinates,
    /// `hard(i, rest)` gives the position of each hard-constrained point from its index and
    /// rest position (called for those only),
    /// `soft_targets` one target per soft vertex; writes every graph point's new position
    /// to `out` (the first `n` are the mesh's vertices). Allocates nothing.
    ///
    /// Errors: [`VolumetricError::Solve`] for wrong lengths.
    pub fn deform(
        &mut self,
        transforms: &[Similarity],
        hard: impl Fn(usize, DVec3) -> DVec3,
        soft_targets: &[DVec3],
        out: &mut [DVec3],
    ) -> Result<(), VolumetricError> {
        let (n, big_n) = (self.n_mesh, self.rest.len());
        crate::solve::check_len("transforms", big_n, transforms.len())?;
        crate::solve::check_len("soft targets", self.soft.len(), soft_targets.len())?;
        let (surface_rows, rest) = self.rhs.split_at_mut(n);
        for ((row, &t), &delta) in surface_rows
            .iter_mut()
            .zip(transforms)
            .zip(&self.rest_surface)
        {
            *row = turned(t, delta);
        }
        let rows = rest.iter_mut().zip(&self.graph_owner).zip(&self.rest_graph);
        for ((row, &owner), &delta) in rows {
            *row = turned(transforms[owner as usize], delta);
        }
        let soft_rows = n + self.rest_graph.len();
        for (k, (v, &target)) in self.soft.iter().zip(soft_targets).enumerate() {
            self.rhs[soft_rows + k] = self.alpha_weight * (target - self.rest[v.index()]);
        }
        for (i, value) in self.fixed_values.iter_mut().enumerate() {
            *value = if self.solver.fixed()[i] {
                hard(i, self.rest[i]) - self.rest[i]
            } else {
                DVec3::ZERO
            };
        }
        self.solver
            .solve(&self.rhs, &self.fixed_values, &mut self.displacement)?;
        for ((out, &rest), &d) in out.iter_mut().zip(&self.rest).zip(&self.displacement) {
            *out = rest + d;
        }
        Ok(())
    }
}

/// `T δ − δ`: how much a rest coordinate changes; exactly zero for the identity.
fn turned(t: Similarity, delta: DVec3) -> DVec3 {
    if t == Similarity::IDENTITY {
        DVec3::ZERO
    } else {
        t.apply(delta) - delta
    }
}
