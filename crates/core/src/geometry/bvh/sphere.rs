//! Sphere queries: the triangles that come within a radius of a point, as a brush needs.

use glam::DVec3;

use super::Bvh;
use super::nearest::box_distance_squared;
use crate::geometry::closest::closest_point_on_triangle;
use crate::mesh::{FaceId, Mesh};

impl Bvh {
    /// Calls `visit` with every face that comes within `radius` of `center`, each once, in
    /// no particular order. Costs in proportion to the faces near the sphere, not to the
    /// mesh: a brush's dab on a large scan visits the few boxes it overlaps.
    pub fn faces_within(
        &self,
        mesh: &Mesh,
        center: DVec3,
        radius: f64,
        mut visit: impl FnMut(FaceId),
    ) {
        let bound = radius * radius;
        let mut stack = Vec::with_capacity(64);
        if !self.nodes.is_empty() {
            stack.push(0u32);
        }
        while let Some(index) = stack.pop() {
            let node = self.nodes[index as usize];
            if box_distance_squared(&node.bounds, center) > bound {
                continue;
            }
            if node.count == 0 {
                stack.extend([node.first, node.first + 1]);
                continue;
            }
            for &f in &self.faces[node.first as usize..(node.first + node.count) as usize] {
                let closest = closest_point_on_triangle(center, mesh.face_positions(FaceId(f)));
                if closest.distance_squared(center) <= bound {
                    visit(FaceId(f));
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use crate::geometry::Bvh;
    use crate::geometry::closest::closest_point_on_triangle;
    use crate::mesh::primitives;

    #[test]
    fn faces_within_are_those_a_scan_finds() {
        let mesh = primitives::torus(2.0, 0.6, 32, 16);
        let bvh = Bvh::new(&mesh);
        for (center, radius) in [(DVec3::new(2.5, 0.0, 0.0), 0.4), (DVec3::ZERO, 1.5)] {
            let mut found = Vec::new();
            bvh.faces_within(&mesh, center, radius, |f| found.push(f));
            found.sort();
            let scanned: Vec<_> = mesh
                .faces()
                .filter(|&f| {
                    let q = closest_point_on_triangle(center, mesh.face_positions(f));
                    q.distance(center) <= radius
                })
                .collect();
            assert!(!scanned.is_empty());
            assert_eq!(found, scanned);
        }
    }
}
