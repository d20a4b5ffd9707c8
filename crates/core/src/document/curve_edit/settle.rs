//! Settling a model after a curve op: re-optimize the fair surface through its curves
//! around what changed, and remesh where the topology may change (then tidy the triangles
//! the remesh left poor, see [`super::tidy`]).
//!
//! Only a region around the changed curves is re-optimized; the rest of the shape stays
//! exactly. Besides being faster, this keeps edits from drifting the whole shape: measuring
//! the magnitudes again and re-converging makes a shape about 1% thinner each time (see
//! [`FairSurface`]), which over a session of edits would deflate every part of a model
//! that no edit touched.

use glam::DVec3;

use super::tidy::tidy_poor_triangles;
use crate::document::CommandError;
use crate::fibermesh::{FairSurface, region_around};
use crate::mesh::remesh::{Chain, RemeshParams, remesh_within};
use crate::mesh::{Mesh, VertexId};
use crate::model::ControlCurve;

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
    pub around: &'a [VertexId],
    /// How far from them the surface may move.
    pub radius: f64,
}

impl Change<'_> {
    /// The region as a vertex mask of `mesh`.
    pub(super) fn region(&self, mesh: &Mesh) -> Vec<bool> {
        region_around(mesh, self.around, self.radius)
    }
}

/// Re-optimizes `mesh` through `curves` (whose vertices already sit where they should) in
/// the region of `change`, aiming for the Laplacian magnitudes measured on `rest` (the
/// surface before the op moved any curve; the same as `mesh.positions()` when nothing
/// moved). With `relax`, the magnitudes in the region are not measured but interpolated
/// from around it, so that the shape a removed or changed constraint forced gives way.
///
/// Without `relax` (curves moved, the same curves), what is applied is the *difference*
/// the move makes: the optimization runs twice with the same factorization, from the
/// moved curves and from the curves at rest, and the rest surface gets the first result
/// minus the second. Re-converging a fair surface drifts it (about 1% thinner, see
/// [`FairSurface`]); inside a region whose rim is held, that drift was a visible step at
/// the rim, and the difference cancels it.
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
    let mut run = |positions: &mut [DVec3]| {
        surface.measure_magnitudes(rest)?;
        surface.run(positions, MAX_ITERATIONS, TOLERANCE)
    };
    if relax {
        run(mesh.positions_mut()).map_err(CommandError::Surface)?;
    } else {
        let mut still = rest.to_vec();
        run(&mut still).map_err(CommandError::Surface)?;
        run(mesh.positions_mut()).map_err(CommandError::Surface)?;
        for ((p, &r), &s) in mesh.positions_mut().iter_mut().zip(rest).zip(&still) {
            *p += r - s;
        }
    }
    tidy_poor_triangles(mesh, curves, &region);
    Ok(())
}

/// Remeshes the region of `change` keeping every curve as an edge chain at the mesh's own
/// resolution, then lets the vertices the remesh made find the fair surface between the
/// ones it kept; the rest of the mesh keeps its vertices exactly.
///
/// Only the new vertices move: the kept ones are on the settled surface already (the
/// remesher's moves are tangential), and re-converging them all, with magnitudes measured
/// on the remeshed surface, drifted the region away from its rim (up to a third of an edge
/// length at 40k vertices, a visible step). The new vertices aim for the typical magnitude
/// of the kept ones around them: measured where a split put them, on a chord, theirs is
/// meaningless (and after a pull that folded the surface, it made them run away).
pub(super) fn remesh_and_settle(
    mesh: &Mesh,
    curves: &[ControlCurve],
    change: Change<'_>,
) -> Result<(Mesh, Vec<ControlCurve>), CommandError> {
    remesh_and_settle_within(mesh, curves, &change.region(mesh))
}

/// [`remesh_and_settle`] in the region `region` (a vertex mask) rather than a change's.
pub(super) fn remesh_and_settle_within(
    mesh: &Mesh,
    curves: &[ControlCurve],
    region: &[bool],
) -> Result<(Mesh, Vec<ControlCurve>), CommandError> {
    let Remeshed {
        mut mesh,
        curves,
        is_new,
        is_remeshed,
    } = remesh(mesh, curves, region)?;
    let mut surface = FairSurface::new_regional(&mesh, &curves, &is_new, &is_new)
        .map_err(CommandError::Surface)?;
    surface
        .run(mesh.positions_mut(), ITERATIONS_AFTER_REMESH, TOLERANCE)
        .map_err(CommandError::Surface)?;
    tidy_poor_triangles(&mut mesh, &curves, &is_remeshed);
    Ok((mesh, curves))
}

/// The Laplacian magnitudes [`remesh_and_fair_within`] aims for in its region.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Aim {
    /// Those of the surface as it is, except at the remesh's new vertices, which lie on
    /// chords and take the typical magnitude of the rest: for a first guess of the right
    /// girth (an extrusion's sweep of round rings is as curved as a limb that thick).
    Measured,
    /// The typical magnitude of the surface around the region everywhere in it: for a seam
    /// whose crease should give way to a blend (a merge's).
    Typical,
}

/// Remeshes `region` (a vertex mask) and re-optimizes all of it, not only the vertices the
/// remesh made: for a new part whose shape is a first guess, which must become the fair
/// surface through its curves.
pub(super) fn remesh_and_fair_within(
    mesh: &Mesh,
    curves: &[ControlCurve],
    region: &[bool],
    aim: Aim,
) -> Result<(Mesh, Vec<ControlCurve>), CommandError> {
    let Remeshed {
        mut mesh,
        curves,
        is_new,
        is_remeshed,
    } = remesh(mesh, curves, region)?;
    let relax = match aim {
        Aim::Measured => &is_new,
        Aim::Typical => &is_remeshed,
    };
    let mut surface = FairSurface::new_regional(&mesh, &curves, &is_remeshed, relax)
        .map_err(CommandError::Surface)?;
    surface
        .run(mesh.positions_mut(), MAX_ITERATIONS, TOLERANCE)
        .map_err(CommandError::Surface)?;
    tidy_poor_triangles(&mut mesh, &curves, &is_remeshed);
    Ok((mesh, curves))
}

/// Remeshes `region` (a vertex mask) as [`remesh_and_settle`] does, without settling: for
/// a model whose surface no curves define, or an edit that moved the surface itself (the
/// `curves` are kept as edge chains, and come back over the new vertices).
pub(in crate::document) fn remesh_only(
    mesh: &Mesh,
    curves: &[ControlCurve],
    region: &[bool],
) -> Result<(Mesh, Vec<ControlCurve>), CommandError> {
    let remeshed = remesh(mesh, curves, region)?;
    Ok((remeshed.mesh, remeshed.curves))
}

/// A model's mesh and curves after a remesh of a region.
struct Remeshed {
    mesh: Mesh,
    /// The curves, as edge chains of `mesh`.
    curves: Vec<ControlCurve>,
    /// Which vertices the remesh made.
    is_new: Vec<bool>,
    /// Which vertices lie in the remeshed region.
    is_remeshed: Vec<bool>,
}

/// `region` (a vertex mask) remeshed with every curve kept as an edge chain.
fn remesh(mesh: &Mesh, curves: &[ControlCurve], region: &[bool]) -> Result<Remeshed, CommandError> {
    let chains: Vec<Chain> = curves
        .iter()
        .map(|c| Chain {
            vertices: c.vertices.clone(),
            closed: c.is_closed,
        })
        .collect();
    let params = RemeshParams::keep_resolution(mesh);
    let remeshed = remesh_within(mesh, &chains, &params, region)?;
    let curves: Vec<ControlCurve> = curves
        .iter()
        .zip(remeshed.chains)
        .map(|(curve, chain)| ControlCurve {
            vertices: chain.vertices,
            is_closed: curve.is_closed,
            kind: curve.kind,
        })
        .collect();
    Ok(Remeshed {
        mesh: remeshed.mesh,
        curves,
        is_new: remeshed.is_new,
        is_remeshed: remeshed.is_remeshed,
    })
}
