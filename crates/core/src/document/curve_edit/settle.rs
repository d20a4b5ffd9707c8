//! Settling a model after a curve op: re-optimize the fair surface through its curves
//! around what changed, and remesh where the topology may change.
//!
//! Only a region around the changed curves is re-optimized; the rest of the shape stays
//! exactly. Besides being faster, this keeps edits from drifting the whole shape: measuring
//! the magnitudes again and re-converging makes a shape about 1% thinner each time (see
//! [`FairSurface`]), which over a session of edits would deflate every part of a model
//! that no edit touched.

use glam::DVec3;

use super::super::CommandError;
use crate::fibermesh::{ControlCurve, FairSurface, region_around};
use crate::mesh::remesh::{Chain, RemeshParams, remesh_within};
use crate::mesh::{Mesh, VertexId};

/// Iteration cap when settling; FiberMesh converges in 5–10 iterations.
const MAX_ITERATIONS: usize = 15;

/// Convergence: no vertex moves more than this fraction of the bounding-box diagonal.
const TOLERANCE: f64 = 1e-3;

/// Iterations after a remesh: the shape is already settled, the new vertices only need to
/// find the fair surface again.
const ITERATIONS_AFTER_REMESH: usize = 4;

/// Where an op changed the surface: the vertices within `radius` (along the surface) of the
/// mesh vertices `around`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Change<'a> {
    /// Mesh vertices of the curve parts the op changed.
    pub around: &'a [u32],
    /// How far from them the surface may move.
    pub radius: f64,
}

impl Change<'_> {
    /// The region as a vertex mask of `mesh`.
    fn region(&self, mesh: &Mesh) -> Vec<bool> {
        region_around(mesh, self.around, self.radius)
    }
}

/// Re-optimizes `mesh` through `curves` (whose vertices already sit where they should) in
/// the region of `change`, aiming for the Laplacian magnitudes measured on `rest` (the
/// surface before the op moved any curve; the same as `mesh.positions()` when nothing
/// moved). With `relax`, the magnitudes in the region are not measured but interpolated
/// from around it, so that the shape a removed or changed constraint forced gives way.
pub(super) fn settle(
    mesh: &mut Mesh,
    curves: &[ControlCurve],
    rest: &[DVec3],
    change: Change<'_>,
    relax: bool,
) -> Result<(), CommandError> {
    let region = change.region(mesh);
    let relaxed = if relax { region.clone() } else { Vec::new() };
    let mut surface = FairSurface::new_regional(mesh, curves, &region, &relaxed)
        .map_err(CommandError::Surface)?;
    surface
        .measure_magnitudes(rest)
        .map_err(CommandError::Surface)?;
    surface
        .run(mesh.positions_mut(), MAX_ITERATIONS, TOLERANCE)
        .map_err(CommandError::Surface)?;
    Ok(())
}

/// Remeshes the region of `change` keeping every curve as an edge chain at the mesh's own
/// resolution, then lets the surface find its fair shape again there; the rest of the mesh
/// keeps its vertices exactly.
pub(super) fn remesh_and_settle(
    mesh: &Mesh,
    curves: &[ControlCurve],
    change: Change<'_>,
) -> Result<(Mesh, Vec<ControlCurve>), CommandError> {
    let chains: Vec<Chain> = curves
        .iter()
        .map(|c| Chain {
            vertices: c.vertices.iter().map(|v| v.0).collect(),
            closed: c.is_closed,
        })
        .collect();
    let params = RemeshParams::keep_resolution(mesh);
    let remeshed = remesh_within(mesh, &chains, &params, &change.region(mesh))?;
    let curves: Vec<ControlCurve> = curves
        .iter()
        .zip(remeshed.chains)
        .map(|(curve, chain)| ControlCurve {
            vertices: chain.vertices.into_iter().map(VertexId).collect(),
            is_closed: curve.is_closed,
            kind: curve.kind,
        })
        .collect();
    let mut mesh = remeshed.mesh;
    let mut surface = FairSurface::new_regional(&mesh, &curves, &remeshed.is_remeshed, &[])
        .map_err(CommandError::Surface)?;
    surface
        .run(mesh.positions_mut(), ITERATIONS_AFTER_REMESH, TOLERANCE)
        .map_err(CommandError::Surface)?;
    Ok((mesh, curves))
}
