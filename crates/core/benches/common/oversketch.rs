//! The over-sketch-sized edit shared by `benches/deform.rs` and `examples/deform_export.rs`:
//! a cap ROI of about 5k vertices on a 40,962-vertex icosphere and about 100 handles where
//! edges cross a curve through the cap, as silhouette points do.

use glam::{DMat3, DVec3};
use sketchmesh_core::deform::HandlePoint;
use sketchmesh_core::mesh::{HalfedgeId, Mesh, primitives};

/// The icosphere the edit runs on (6 subdivisions, 40,962 vertices).
pub fn sphere() -> Mesh {
    primitives::icosphere(1.0, 6)
}

/// The pole of the cap.
const POLE: DVec3 = DVec3::Z;
/// Chord radius of the cap ROI: `(1 - cos θ) / 2` of the sphere, about 12% or 5k vertices.
const ROI_RADIUS: f64 = 0.7;
/// Chord radius of the handle curve's extent around the pole.
const HANDLE_RADIUS: f64 = 0.45;
/// The handle curve lies in the plane `y = PLANE_Y`, off the icosphere's symmetry planes so
/// that no vertex lies on it.
const PLANE_Y: f64 = 0.0123;

/// The cap ROI and handles at the edge crossings of the plane `y = PLANE_Y` near the pole.
pub fn oversketch_edit(mesh: &Mesh) -> (Vec<bool>, Vec<HandlePoint>) {
    let p = mesh.positions();
    let roi = p
        .iter()
        .map(|&q| (q - POLE).length() < ROI_RADIUS)
        .collect();
    let handles = (0..mesh.n_halfedges() as u32)
        .map(HalfedgeId)
        .filter_map(|h| {
            let (a, b) = (mesh.tail(h), mesh.head(h));
            let (pa, pb) = (p[a.index()], p[b.index()]);
            // Each edge once: from its lower end to its upper end.
            let crosses = pa.y < PLANE_Y && pb.y > PLANE_Y;
            let is_near = (0.5 * (pa + pb) - POLE).length() < HANDLE_RADIUS;
            (crosses && is_near)
                .then(|| HandlePoint::on_edge(a, b, (PLANE_Y - pa.y) / (pb.y - pa.y)))
        })
        .collect();
    (roi, handles)
}

/// Targets: the handle curve pushed outward and turned a little, like a redrawn silhouette.
pub fn targets(mesh: &Mesh, handles: &[HandlePoint]) -> Vec<DVec3> {
    let turn = DMat3::from_rotation_y(0.2);
    handles
        .iter()
        .map(|h| {
            let q = h.position(mesh.positions());
            let bulge = 0.15 * (1.0 - ((q - POLE).length() / HANDLE_RADIUS).powi(2));
            turn * q + q.normalize() * bulge
        })
        .collect()
}
