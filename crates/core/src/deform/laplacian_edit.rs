//! The editing engine: factor once per ROI and handle set, then deform per drag frame.
//!
//! Unknowns are displacements `d = x - p` of the region's vertices (see `region.rs`), not
//! positions: an undisplaced handle set then gives exactly zero, and round-off scales with
//! the edit rather than with the model's distance from the origin. Row `i` of the system is
//! Eq. 4.4 in displacements, `d_i - Σ_j w_ij d_j = (R_i - I) δ_i`, with `δ_i` the rest
//! Laplacian coordinate and `R_i` the vertex's rotation: the identity in the linear edit,
//! fitted by the local step otherwise (see the [module docs](super)).

use glam::{DMat3, DQuat, DVec3};

use super::DeformError;
use super::exact_handles::ExactConstraints;
use super::handle::{HandlePoint, split_handles};
use super::params::{EditParams, HandleFit, Rotations};
use super::region::Region;
use super::rotation::{best_rotation, refine_rotation};
use crate::geometry::OneRingWeights;
use crate::mesh::{Mesh, VertexId};
use crate::solve::{Prefactored, SolveError, Triplets, check_len};

/// A Laplacian edit of one mesh with a fixed ROI and handle set, factored once; call
/// [`LaplacianEdit::deform`] with new handle targets every frame. See the
/// [module docs](super) for the method.
#[derive(Debug)]
pub struct LaplacianEdit {
    params: EditParams,
    n_handles: usize,
    /// Every mesh position at rest: vertices outside the ROI are copied from here.
    rest: Vec<DVec3>,
    /// Mesh vertex of each local index: ROI, ring 1, ring 2.
    region_vertices: Vec<VertexId>,
    n_roi: usize,
    rings: OneRingWeights,
    rest_local: Vec<DVec3>,
    /// Rest Laplacian coordinate `δ_i` of each row vertex.
    rest_delta: Vec<DVec3>,
    solver: Prefactored,
    /// Soft handle rows, in order after the Laplacian rows: handle index and rest value.
    soft_rows: Vec<(usize, DVec3)>,
    /// Exact vertex handles: local index and handle index.
    fixed_handles: Vec<(usize, usize)>,
    /// Exact handles inside edges or faces: handle index and rest value, one per row of
    /// `exact`.
    exact_handles: Vec<(usize, DVec3)>,
    exact: ExactConstraints,
    /// Rest position of every handle.
    handle_rest: Vec<DVec3>,
    /// How far each row vertex follows the handles in the linear edit: 0 at anchors, 1 at
    /// handles (empty for the linear edit). Spreads the handles' overall rotation as the
    /// starting guess of the rotation iterations.
    reach: Vec<f64>,
    rhs: Vec<DVec3>,
    fixed_values: Vec<DVec3>,
    displacement: Vec<DVec3>,
    /// Rotation of each row vertex.
    rotations: Vec<DMat3>,
}

impl LaplacianEdit {
    /// Builds and factors the edit of `mesh`: the vertices with `roi[v]` move, all others stay,
    /// and `handles` will be moved to the targets given to [`LaplacianEdit::deform`].
    ///
    /// Errors: [`DeformError::RoiLength`], [`DeformError::InvalidHandle`],
    /// [`DeformError::HandleOutsideRoi`], [`DeformError::ConflictingHandles`],
    /// [`DeformError::DependentHandles`], and [`DeformError::Solve`] when the system cannot be
    /// factored (a ROI component with no anchor and no handle, for example a whole closed
    /// mesh, with soft handles only).
    pub fn new(
        mesh: &Mesh,
        roi: &[bool],
        handles: &[HandlePoint],
        params: EditParams,
    ) -> Result<LaplacianEdit, DeformError> {
        if roi.len() != mesh.n_vertices() {
            return Err(DeformError::RoiLength {
                expected: mesh.n_vertices(),
                found: roi.len(),
            });
        }
        if let HandleFit::Soft { weight } = params.fit
            && !(weight > 0.0 && weight.is_finite())
        {
            return Err(DeformError::InvalidWeight);
        }
        let region = Region::new(mesh, roi);
        let split = split_handles(mesh, &region, handles, params.fit)?;
        let n_rows = region.n_rows();
        let rings = OneRingWeights::new(mesh, &region.vertices()[..n_rows], |v| {
            region.local_unchecked(v)
        });
        let n_local = region.vertices().len();
        let soft_weight = match params.fit {
            HandleFit::Soft { weight } => weight,
            HandleFit::Exact => 0.0,
        };
        let mut triplets = Triplets::with_capacity(n_rows + split.soft.len(), n_local, 8 * n_rows);
        for i in 0..n_rows {
            triplets.push(i, i, 1.0);
            for (j, w) in rings.ring(i) {
                triplets.push(i, j, -w);
            }
        }
        for (s, (_, _, terms)) in split.soft.iter().enumerate() {
            for &(j, c) in terms {
                triplets.push(n_rows + s, j, soft_weight * c);
            }
        }
        let mut fixed: Vec<bool> = (0..n_local).map(|j| j >= region.n_roi()).collect();
        for &(local, _) in &split.fixed {
            fixed[local] = true;
        }
        let (exact_handles, exact_rows): (Vec<_>, Vec<_>) = split
            .exact
            .into_iter()
            .map(|(h, rest, terms)| ((h, rest), terms))
            .unzip();
        let constrained: Vec<usize> = exact_rows.iter().flatten().map(|&(j, _)| j).collect();
        let solver = Prefactored::with_last(&triplets.build(), &fixed, &constrained)?;
        let exact = ExactConstraints::new(&solver, exact_rows).map_err(|err| match err {
            SolveError::Singular => DeformError::DependentHandles,
            other => DeformError::Solve(other),
        })?;
        let rest_local: Vec<DVec3> = region
            .vertices()
            .iter()
            .map(|&v| mesh.position(v))
            .collect();
        let rest_delta = (0..n_rows)
            .map(|i| {
                let neighbours = rings.ring(i).map(|(j, w)| w * rest_local[j]);
                rest_local[i] - neighbours.sum::<DVec3>()
            })
            .collect();
        let mut edit = LaplacianEdit {
            params,
            n_handles: handles.len(),
            rest: mesh.positions().to_vec(),
            n_roi: region.n_roi(),
            rings,
            rest_local,
            rest_delta,
            solver,
            soft_rows: split
                .soft
                .into_iter()
                .map(|(h, rest, _)| (h, rest))
                .collect(),
            fixed_handles: split.fixed,
            exact_handles,
            exact,
            rhs: vec![DVec3::ZERO; n_rows + handles.len()],
            fixed_values: vec![DVec3::ZERO; n_local],
            displacement: vec![DVec3::ZERO; n_local],
            rotations: vec![DMat3::IDENTITY; n_rows],
            region_vertices: region.vertices().to_vec(),
            handle_rest: handles
                .iter()
                .map(|h| h.position(mesh.positions()))
                .collect(),
            reach: Vec::new(),
        };
        if let Rotations::Arap { .. } = params.rotations {
            edit.reach = edit.unit_reach()?;
        }
        Ok(edit)
    }

    /// The linear edit's displacement when every handle moves by one unit (per coordinate),
    /// with the same factorization.
    fn unit_reach(&mut self) -> Result<Vec<f64>, SolveError> {
        let n_rows = self.rings.n_rows();
        self.rhs.fill(DVec3::ZERO);
        if let HandleFit::Soft { weight } = self.params.fit {
            self.rhs[n_rows..n_rows + self.soft_rows.len()].fill(DVec3::splat(weight));
        }
        for &(local, _) in &self.fixed_handles {
            self.fixed_values[local] = DVec3::ONE;
        }
        let (exact, fixed_values) = (&mut self.exact, &self.fixed_values);
        self.solver.solve_with(
            &self.rhs[..n_rows + self.soft_rows.len()],
            fixed_values,
            &mut self.displacement,
            |u| exact.correct(u, fixed_values, |_| DVec3::ONE),
        )?;
        let reach = self.displacement[..n_rows]
            .iter()
            .map(|d| d.x.clamp(0.0, 1.0));
        Ok(reach.collect())
    }

    /// Starting rotations: the handles' best-fit rotation, spread by `reach`.
    fn initial_rotations(&mut self, targets: &[DVec3]) {
        let n = self.handle_rest.len().max(1) as f64;
        let rest_centre = self.handle_rest.iter().sum::<DVec3>() / n;
        let target_centre = targets.iter().sum::<DVec3>() / n;
        let mut covariance = self
            .handle_rest
            .iter()
            .zip(targets)
            .fold(DMat3::ZERO, |m, (&p, &t)| {
                m + outer(t - target_centre, p - rest_centre)
            });
        // A small pull towards the identity picks the least rotation about a line of
        // collinear handles, which the handles alone leave free.
        let size: f64 = (0..3).map(|k| covariance.col(k).length()).sum();
        covariance += DMat3::from_diagonal(DVec3::splat(1e-3 * size));
        let turn = DQuat::from_mat3(&best_rotation(covariance));
        for (rotation, &reach) in self.rotations.iter_mut().zip(&self.reach) {
            *rotation = DMat3::from_quat(DQuat::IDENTITY.slerp(turn, reach));
        }
    }

    /// Moves the handles to `targets` (one per handle, in the order given to
    /// [`LaplacianEdit::new`]) and writes every vertex position to `out` (one per mesh
    /// vertex). Vertices outside the ROI are copied from the rest positions, bit for bit.
    /// Allocates nothing.
    ///
    /// Errors: [`SolveError::DimensionMismatch`] when `targets` or `out` has the wrong length.
    pub fn deform(&mut self, targets: &[DVec3], out: &mut [DVec3]) -> Result<(), SolveError> {
        check_len("targets", self.n_handles, targets.len())?;
        check_len("out", self.rest.len(), out.len())?;
        for &(local, h) in &self.fixed_handles {
            self.fixed_values[local] = targets[h] - self.rest_local[local];
        }
        self.rotations.fill(DMat3::IDENTITY);
        if let Rotations::Arap { .. } = self.params.rotations {
            self.initial_rotations(targets);
        }
        self.global_step(targets)?;
        if let Rotations::Arap { iterations } = self.params.rotations {
            for _ in 0..iterations {
                self.local_step();
                self.global_step(targets)?;
            }
        }
        out.copy_from_slice(&self.rest);
        for (local, &v) in self.region_vertices[..self.n_roi].iter().enumerate() {
            out[v.index()] = self.rest_local[local] + self.displacement[local];
        }
        Ok(())
    }

    /// The vertices whose Laplacian coordinates the system holds (the ROI, then its first
    /// anchor ring), each with its rest coordinate `δ_i` (normalised cotangent weights).
    pub fn laplacian_rows(&self) -> impl ExactSizeIterator<Item = (VertexId, DVec3)> + '_ {
        let rows = &self.region_vertices[..self.rings.n_rows()];
        rows.iter().copied().zip(self.rest_delta.iter().copied())
    }

    /// The ROI's vertices, in the order of [`LaplacianEdit::prescribed_displacement`]'s
    /// result.
    pub fn roi_vertices(&self) -> &[VertexId] {
        &self.region_vertices[..self.n_roi]
    }

    /// How far each ROI vertex moves when the Laplacian coordinate of each row vertex
    /// changes by `change` (in the order of [`LaplacianEdit::laplacian_rows`]) and the
    /// handles and anchors stay: Nealen's prescribed Laplacians (Eq. 4.4, §4.4), the
    /// least-squares solution of `L d = Δδ`. Linear in `change`, so a caller whose targets
    /// vary along a line solves once and scales.
    ///
    /// Errors: [`SolveError::DimensionMismatch`] when `change` has the wrong length.
    pub fn prescribed_displacement(&mut self, change: &[DVec3]) -> Result<Vec<DVec3>, SolveError> {
        let n_rows = self.rings.n_rows();
        check_len("change", n_rows, change.len())?;
        self.rhs[..n_rows].copy_from_slice(change);
        self.rhs[n_rows..].fill(DVec3::ZERO);
        self.fixed_values.fill(DVec3::ZERO);
        let n_equations = n_rows + self.soft_rows.len();
        let (exact, fixed_values) = (&mut self.exact, &self.fixed_values);
        self.solver.solve_with(
            &self.rhs[..n_equations],
            fixed_values,
            &mut self.displacement,
            |u| exact.correct(u, fixed_values, |_| DVec3::ZERO),
        )?;
        Ok(self.displacement[..self.n_roi].to_vec())
    }

    /// Number of ROI vertices (free unknowns, counting vertex handles).
    pub fn n_roi(&self) -> usize {
        self.n_roi
    }

    /// Number of handles.
    pub fn n_handles(&self) -> usize {
        self.n_handles
    }

    /// The parameters the edit was built with.
    pub fn params(&self) -> EditParams {
        self.params
    }

    /// Solves for the displacements with the current rotations.
    fn global_step(&mut self, targets: &[DVec3]) -> Result<(), SolveError> {
        let n_rows = self.rings.n_rows();
        for i in 0..n_rows {
            self.rhs[i] = (self.rotations[i] - DMat3::IDENTITY) * self.rest_delta[i];
        }
        if let HandleFit::Soft { weight } = self.params.fit {
            for (s, &(h, rest)) in self.soft_rows.iter().enumerate() {
                self.rhs[n_rows + s] = weight * (targets[h] - rest);
            }
        }
        let n_equations = n_rows + self.soft_rows.len();
        let (exact, exact_handles) = (&mut self.exact, &self.exact_handles);
        let fixed_values = &self.fixed_values;
        self.solver.solve_with(
            &self.rhs[..n_equations],
            fixed_values,
            &mut self.displacement,
            |u| {
                exact.correct(u, fixed_values, |m| {
                    let (h, rest) = exact_handles[m];
                    targets[h] - rest
                })
            },
        )?;
        debug_assert_eq!(self.exact.len(), self.exact_handles.len());
        Ok(())
    }

    /// Fits a rotation per row vertex to its deformed one-ring (cotangent-weighted spokes).
    fn local_step(&mut self) {
        for i in 0..self.rings.n_rows() {
            let p = self.rest_local[i];
            let x = p + self.displacement[i];
            let covariance = self.rings.ring(i).fold(DMat3::ZERO, |m, (j, w)| {
                let rest_edge = p - self.rest_local[j];
                let edge = x - self.rest_local[j] - self.displacement[j];
                m + outer(edge * w, rest_edge)
            });
            self.rotations[i] = refine_rotation(covariance, self.rotations[i]);
        }
    }
}

fn outer(a: DVec3, b: DVec3) -> DMat3 {
    DMat3::from_cols(a * b.x, a * b.y, a * b.z)
}
