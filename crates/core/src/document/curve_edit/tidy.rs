//! Evening out the poor triangles a remesh leaves next to control curves, by Laplacian mesh
//! optimization (Nealen's thesis ch. 6: §6.5 shape optimization with tangent-plane rows and
//! quality modulation), the tidy-up the thesis runs after sketch operations.
//!
//! The remesher keeps every curve as an edge chain and never moves a curve vertex off its
//! curve, so where curves meet or bend sharply it can leave slivers whose vertices all lie on
//! curves, or two of them on a curve edge much shorter than its neighbours. With the curve
//! vertices held, an optimization cannot reach those (tried on the golden sessions: the worst
//! radius ratio went from 0.213 to 0.185 in one). Here a curve vertex slides along its curve
//! instead: besides its tangent plane, one more row holds it on the line of the curve's
//! tangent there, and the uniform Laplacian evens out its spacing. Where curves meet, and at
//! the ends of open curves, vertices hold.
//!
//! It runs only when a triangle of the region is below [`POOR`], moves only the vertices
//! within [`RINGS`] rings of the poor triangles (an optimization of the whole region cost
//! 0.65 s after a pull at 40k vertices, for one triangle at 0.29), and its result is kept
//! only when the worst radius ratio there rises, so it never leaves the mesh worse than the
//! remesh did.

use glam::DVec3;

use crate::mesh::{Mesh, VertexId};
use crate::model::ControlCurve;
use crate::optimize::quality::radius_ratio;
use crate::optimize::{Mode, OptimizeParams, Optimizer, Selection, WeightScheme};

/// A triangle with a radius ratio below this is poor enough to tidy around it.
const POOR: f64 = 0.3;

/// How many rings of vertices around the poor triangles move: enough room to even out a
/// sliver and its neighbours, little enough that the solve stays small. Where two curve
/// vertices crowd, their curve's spacing evens out over several edges on each side: with
/// 3–6 rings a golden session's sliver stayed at 0.034, 7 raised it to 0.338.
const RINGS: usize = 8;

/// Moves the vertices of `region` (a vertex mask) near its poor triangles to better
/// triangles, curve vertices along their curves; does nothing when that does not raise the
/// worst radius ratio there.
pub(super) fn tidy_poor_triangles(mesh: &mut Mesh, curves: &[ControlCurve], region: &[bool]) {
    let Some(near) = near_poor_triangles(mesh, region) else {
        return;
    };
    let before = worst_ratio(mesh, mesh.positions(), &near);
    let Some(positions) = optimized(mesh, curves, &near) else {
        return;
    };
    if worst_ratio(mesh, &positions, &near) > before {
        mesh.positions_mut().copy_from_slice(&positions);
    }
}

/// The vertices of `region` within [`RINGS`] rings of its triangles below [`POOR`] (a
/// vertex mask), or `None` when it has none.
fn near_poor_triangles(mesh: &Mesh, region: &[bool]) -> Option<Vec<bool>> {
    let mut near = vec![false; mesh.n_vertices()];
    let mut front: Vec<VertexId> = mesh
        .faces()
        .map(|f| mesh.face_vertices(f))
        .filter(|vertices| vertices.iter().any(|v| region[v.index()]))
        .filter(|vertices| radius_ratio(vertices.map(|v| mesh.position(v))) < POOR)
        .flatten()
        .filter(|v| region[v.index()] && !std::mem::replace(&mut near[v.index()], true))
        .collect();
    if front.is_empty() {
        return None;
    }
    for _ in 0..RINGS {
        front = front
            .iter()
            .flat_map(|&v| mesh.vertex_neighbors(v))
            .filter(|w| region[w.index()] && !std::mem::replace(&mut near[w.index()], true))
            .collect();
    }
    Some(near)
}

/// One shape optimization of `region` with the curve vertices sliding, or `None` when the
/// solve fails (the remesh's result is a valid mesh: it stays).
fn optimized(mesh: &Mesh, curves: &[ControlCurve], region: &[bool]) -> Option<Vec<DVec3>> {
    let (movable, sliding) = curve_constraints(mesh, curves, region);
    let params = OptimizeParams {
        mode: Mode::Shape,
        weights: WeightScheme::Cdf,
        tangent_plane: true,
        quality: true,
        ..OptimizeParams::default()
    };
    let selection = Selection {
        movable: Some(movable),
        features: None,
        sliding: Some(sliding),
    };
    let mut optimizer = Optimizer::new(mesh, &params, &selection).ok()?;
    optimizer.solve(params.scale).ok()
}

/// Which vertices may move (those of `region` except where curves meet or end), and the
/// direction each curve vertex slides along (its curve's chord through its neighbours).
fn curve_constraints(
    mesh: &Mesh,
    curves: &[ControlCurve],
    region: &[bool],
) -> (Vec<bool>, Vec<Option<DVec3>>) {
    let mut movable = region.to_vec();
    let mut sliding: Vec<Option<DVec3>> = vec![None; mesh.n_vertices()];
    let mut on_curves = vec![0u8; mesh.n_vertices()];
    for curve in curves {
        let chain = &curve.vertices;
        for (k, &v) in chain.iter().enumerate() {
            let i = v.index();
            on_curves[i] = on_curves[i].saturating_add(1);
            let neighbours = match (curve.is_closed, k) {
                (true, _) => Some((
                    chain[(k + chain.len() - 1) % chain.len()],
                    chain[(k + 1) % chain.len()],
                )),
                (false, 0) => None,
                (false, _) if k + 1 == chain.len() => None,
                (false, _) => Some((chain[k - 1], chain[k + 1])),
            };
            sliding[i] =
                neighbours.and_then(|(a, b)| (mesh.position(b) - mesh.position(a)).try_normalize());
            if sliding[i].is_none() {
                movable[i] = false;
            }
        }
    }
    for (i, &count) in on_curves.iter().enumerate() {
        if count > 1 {
            movable[i] = false;
            sliding[i] = None;
        }
    }
    (movable, sliding)
}

/// The worst radius ratio of the triangles with a vertex in `region`, at `positions`.
fn worst_ratio(mesh: &Mesh, positions: &[DVec3], region: &[bool]) -> f64 {
    mesh.faces()
        .map(|f| mesh.face_vertices(f))
        .filter(|vertices| vertices.iter().any(|v| region[v.index()]))
        .map(|vertices| radius_ratio(vertices.map(|v| positions[v.index()])))
        .fold(1.0, f64::min)
}
