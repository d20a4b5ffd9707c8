//! Opening a closed surface along a closed loop drawn on it, for the ops that attach
//! something there (the tunnel's tube, the extrusion's limb): the loop's stroke as seen,
//! the disk the loop bounds, and the rim left around the hole.

use glam::{DVec2, DVec3};
use rustc_hash::FxHashSet;

use crate::camera::Camera;
use crate::geometry::face_area;
use crate::mesh::{FaceId, HalfedgeId, Mesh, VertexId};

/// A stroke as seen through a camera: a loop on the surface, or an extrusion's silhouette.
#[derive(Clone, Copy, Debug)]
pub struct ViewedStroke<'a> {
    /// The camera it was drawn with.
    pub camera: &'a Camera,
    /// The viewport's size in CSS px.
    pub viewport: DVec2,
    /// The stroke in screen px.
    pub stroke: &'a [DVec2],
}

/// The faces on the side of the closed `chain` with less area.
pub(super) fn disk(mesh: &Mesh, chain: &[VertexId]) -> Vec<FaceId> {
    let n = chain.len();
    let on_chain: FxHashSet<(VertexId, VertexId)> = (0..n)
        .map(|k| (chain[k], chain[(k + 1) % n]))
        .flat_map(|(p, q)| [(p, q), (q, p)])
        .collect();
    let Some(h) = mesh.find_halfedge(chain[0], chain[1]) else {
        return Vec::new();
    };
    let sides = [Some(mesh.face(h)), mesh.twin(h).map(|t| mesh.face(t))];
    let fill = |seed: FaceId| {
        let mut seen = FxHashSet::default();
        let mut stack = vec![seed];
        seen.insert(seed);
        while let Some(f) = stack.pop() {
            for k in 0..3 {
                let h = HalfedgeId(3 * f.0 + k);
                if on_chain.contains(&(mesh.tail(h), mesh.head(h))) {
                    continue;
                }
                if let Some(t) = mesh.twin(h)
                    && seen.insert(mesh.face(t))
                {
                    stack.push(mesh.face(t));
                }
            }
        }
        seen.into_iter().collect::<Vec<FaceId>>()
    };
    let area = |faces: &[FaceId]| faces.iter().map(|&f| face_area(mesh, f)).sum::<f64>();
    sides
        .into_iter()
        .flatten()
        .map(fill)
        .min_by(|x, y| area(x).total_cmp(&area(y)))
        .unwrap_or_default()
}

/// The chain ordered so that the kept faces hold its edges `k → k + 1`.
pub(super) fn kept_forward(
    mesh: &Mesh,
    removed: &FxHashSet<FaceId>,
    chain: &[VertexId],
) -> Vec<VertexId> {
    let forward = mesh
        .find_halfedge(chain[0], chain[1])
        .is_some_and(|h| !removed.contains(&mesh.face(h)));
    if forward {
        chain.to_vec()
    } else {
        chain.iter().rev().copied().collect()
    }
}

/// The middle of a ring of points.
pub(super) fn middle(ring: &[DVec3]) -> DVec3 {
    ring.iter().sum::<DVec3>() / ring.len().max(1) as f64
}
