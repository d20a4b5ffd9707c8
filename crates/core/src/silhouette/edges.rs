//! Edge silhouettes: the mesh edges between a face turned towards the viewer and one turned
//! away (Nealen §4.3), with the hidden ones removed.
//!
//! On a closed mesh these are exactly the outline a renderer draws: the boundary of the
//! rasterized triangles' coverage is made of them (plus any boundary edges of an open mesh,
//! included here too). The smooth silhouettes of the module root lie within the faces and
//! are smoothed on screen, so they can sit a fraction of a pixel to a few pixels away from
//! the drawn outline on a bumpy surface; tests of "the rendered outline follows the stroke"
//! measure against these instead.
//!
//! Visibility: one occlusion ray per edge, at its midpoint moved outwards by
//! [`super::visibility::OFFSET_EDGES`] edge lengths along the mean of its faces' normals,
//! as for smooth silhouette points.

use std::collections::{BTreeMap, BTreeSet};

use glam::{DVec2, DVec3};

use super::visibility::{MARGIN_EDGES, OFFSET_EDGES, ray_origin};
use crate::camera::Camera;
use crate::geometry::{Bvh, face_normal};
use crate::mesh::{FaceId, HalfedgeId, Mesh, VertexId};

/// The visible edge silhouettes of `mesh` seen by `camera` in a viewport of `viewport` CSS
/// px, as screen segments (CSS px, y down), in no particular order; `bvh` must be built for
/// the mesh's current positions. Empty for an invalid camera.
pub fn edge_silhouettes(
    mesh: &Mesh,
    bvh: &Bvh,
    camera: &Camera,
    viewport: DVec2,
) -> Vec<[DVec2; 2]> {
    outline_edges(mesh, bvh, camera, viewport)
        .into_iter()
        .map(|edge| edge.screen)
        .collect()
}

/// A visible edge silhouette: a mesh edge on the outline as rendered.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutlineEdge {
    /// Its ends.
    pub vertices: [VertexId; 2],
    /// Its ends on screen (CSS px, y down).
    pub screen: [DVec2; 2],
}

/// [`edge_silhouettes`] with the mesh edge each segment is.
pub fn outline_edges(mesh: &Mesh, bvh: &Bvh, camera: &Camera, viewport: DVec2) -> Vec<OutlineEdge> {
    outline_edges_touching(mesh, bvh, camera, viewport, |_| true)
}

/// [`outline_edges`] with at least one end where `keep` says: the occlusion rays, most of
/// the cost, are cast only for those (an over-sketch looks at its region only).
pub fn outline_edges_touching(
    mesh: &Mesh,
    bvh: &Bvh,
    camera: &Camera,
    viewport: DVec2,
    keep: impl Fn(VertexId) -> bool,
) -> Vec<OutlineEdge> {
    if !camera.is_valid() {
        return Vec::new();
    }
    // Face normals and sides only where asked: a region's outline costs the region.
    let side = |f: FaceId| {
        let n = face_normal(mesh, f);
        (n, faces_viewer(mesh, camera, n, f))
    };
    let mut segments = Vec::new();
    for h in (0..mesh.n_halfedges() as u32).map(HalfedgeId) {
        let vertices = [mesh.tail(h), mesh.head(h)];
        if !vertices.into_iter().any(&keep) {
            continue;
        }
        let (n, is_front) = side(mesh.face(h));
        if !is_front {
            continue;
        }
        let outward = match mesh.twin(h) {
            // Each interior edge once, from its front-facing side.
            Some(twin) => match side(mesh.face(twin)) {
                (m, false) => n + m,
                _ => continue,
            },
            None => n,
        };
        let [a, b] = vertices.map(|v| mesh.position(v));
        if !is_seen(mesh, bvh, camera, a, b, outward.normalize_or_zero()) {
            continue;
        }
        if let (Some(pa), Some(pb)) = (
            camera.screen_from_world(a, viewport),
            camera.screen_from_world(b, viewport),
        ) {
            segments.push(OutlineEdge {
                vertices,
                screen: [pa.truncate(), pb.truncate()],
            });
        }
    }
    segments
}

/// A run of visible edge silhouettes joined end to end: the outline as rendered, as a
/// polyline of mesh vertices.
#[derive(Clone, Debug, PartialEq)]
pub struct OutlineChain {
    /// The vertices in order (a closed chain does not repeat its first).
    pub vertices: Vec<VertexId>,
    /// Where each is drawn (CSS px, y down).
    pub screen: Vec<DVec2>,
    /// Whether the last vertex joins the first.
    pub closed: bool,
}

/// The visible edge silhouettes ([`outline_edges`]) joined into chains: each runs between
/// two vertices where the outline ends or branches (or round a loop), in vertex order of
/// its start, so the same mesh and view give the same chains.
pub fn outline_chains(
    mesh: &Mesh,
    bvh: &Bvh,
    camera: &Camera,
    viewport: DVec2,
) -> Vec<OutlineChain> {
    let edges = outline_edges(mesh, bvh, camera, viewport);
    let mut neighbours: BTreeMap<VertexId, Vec<VertexId>> = BTreeMap::new();
    let mut screen: BTreeMap<VertexId, DVec2> = BTreeMap::new();
    for edge in &edges {
        let [a, b] = edge.vertices;
        neighbours.entry(a).or_default().push(b);
        neighbours.entry(b).or_default().push(a);
        screen.insert(a, edge.screen[0]);
        screen.insert(b, edge.screen[1]);
    }
    let key = |a: VertexId, b: VertexId| if a < b { (a, b) } else { (b, a) };
    let mut walked: BTreeSet<(VertexId, VertexId)> = BTreeSet::new();
    let walk = |start: VertexId, next: VertexId, walked: &mut BTreeSet<_>| {
        let mut vertices = vec![start];
        let (mut previous, mut current) = (start, next);
        walked.insert(key(start, next));
        loop {
            if current == start {
                return (vertices, true);
            }
            vertices.push(current);
            let around = &neighbours[&current];
            let onward = (around.len() == 2)
                .then(|| around.iter().copied().find(|&w| w != previous))
                .flatten()
                .filter(|&w| !walked.contains(&key(current, w)));
            let Some(w) = onward else {
                return (vertices, false);
            };
            walked.insert(key(current, w));
            (previous, current) = (current, w);
        }
    };
    let mut chains = Vec::new();
    // Open runs first, from every end or branch; then the loops left over.
    let ends: Vec<VertexId> = neighbours
        .iter()
        .filter(|(_, around)| around.len() != 2)
        .map(|(&v, _)| v)
        .collect();
    let starts = ends
        .into_iter()
        .chain(neighbours.keys().copied().collect::<Vec<_>>());
    for start in starts {
        for next in neighbours[&start].clone() {
            if !walked.contains(&key(start, next)) {
                let (vertices, closed) = walk(start, next, &mut walked);
                let screen = vertices.iter().map(|v| screen[v]).collect();
                chains.push(OutlineChain {
                    vertices,
                    screen,
                    closed,
                });
            }
        }
    }
    chains
}

/// Whether face `f` (unit normal `normal`) turns its front towards the eye.
fn faces_viewer(mesh: &Mesh, camera: &Camera, normal: DVec3, f: FaceId) -> bool {
    match camera.ortho_height {
        Some(_) => normal.dot(camera.forward()) < 0.0,
        None => {
            let [a, b, c] = mesh.face_positions(f);
            normal.dot((a + b + c) / 3.0 - camera.eye) < 0.0
        }
    }
}

/// Whether the middle of the edge `a`–`b` is in sight, aiming slightly outside the surface.
fn is_seen(mesh: &Mesh, bvh: &Bvh, camera: &Camera, a: DVec3, b: DVec3, outward: DVec3) -> bool {
    let length = a.distance(b);
    let target = 0.5 * (a + b) + OFFSET_EDGES * length * outward;
    !bvh.occluded(
        mesh,
        ray_origin(camera, target),
        target,
        MARGIN_EDGES * length,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives;

    /// The outline of a sphere of radius r seen from distance d lies at the angle
    /// asin(r / d) from the view axis: every segment end is that far from the centre on
    /// screen (to within the polygon's chord error), none is hidden behind it.
    #[test]
    fn a_sphere_outline_is_a_circle_of_the_known_radius() {
        let mesh = primitives::icosphere(1.0, 5);
        let bvh = Bvh::new(&mesh);
        let camera = Camera::default();
        let viewport = DVec2::new(1000.0, 1000.0);
        let segments = edge_silhouettes(&mesh, &bvh, &camera, viewport);
        let centre = camera
            .screen_from_world(DVec3::ZERO, viewport)
            .unwrap()
            .truncate();
        // The tangent point above the centre: at angle acos(1 / d) from the eye direction.
        let d = camera.eye.length();
        let tangent = camera.eye / (d * d) + DVec3::Y * (1.0 - 1.0 / (d * d)).sqrt();
        let radius = camera
            .screen_from_world(tangent, viewport)
            .unwrap()
            .truncate()
            .distance(centre);
        assert!(segments.len() > 100, "{} segments", segments.len());
        for [a, b] in &segments {
            for p in [a, b] {
                let r = p.distance(centre);
                assert!((r - radius).abs() < 0.02 * radius, "{r} vs {radius}");
            }
        }
        // The far side's edges facing away are not outline; the loop closes: every end is
        // shared by two segments.
        let mut ends: Vec<DVec2> = segments.iter().flatten().copied().collect();
        ends.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
        assert!(ends.chunks(2).all(|pair| pair[0] == pair[1]));
        // Joined, they are one loop through every segment.
        let chains = outline_chains(&mesh, &bvh, &camera, viewport);
        assert_eq!(chains.len(), 1);
        assert!(chains[0].closed);
        assert_eq!(chains[0].vertices.len(), segments.len());
        let n = chains[0].screen.len();
        for k in 0..n {
            let (a, b) = (chains[0].screen[k], chains[0].screen[(k + 1) % n]);
            assert!(
                segments
                    .iter()
                    .any(|s| (s[0] == a && s[1] == b) || (s[0] == b && s[1] == a))
            );
        }
    }
}
