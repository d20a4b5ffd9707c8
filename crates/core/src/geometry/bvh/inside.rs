//! Inside tests: whether a point lies inside a closed mesh, by the parity of a ray's
//! crossings.

use glam::DVec3;

use super::Bvh;
use crate::geometry::raycast::intersect_triangle;
use crate::mesh::{FaceId, Mesh};

/// The direction of the parity ray: skewed off the axes, so that it meets no edge or vertex
/// of a generated mesh (lattices, spheres, boxes) head on.
const PARITY_DIR: DVec3 = DVec3::new(0.577_3, 0.577_4, 0.577_5);

impl Bvh {
    /// Whether `p` lies inside the closed `mesh`: the ray from it crosses the surface an odd
    /// number of times. For a mesh with holes the answer is that of one ray, not a winding
    /// number.
    pub fn contains(&self, mesh: &Mesh, p: DVec3) -> bool {
        let dir = PARITY_DIR.normalize();
        let mut crossings = 0usize;
        self.along_ray(p, dir, f64::INFINITY, |f| {
            let [a, b, c] = mesh.face_positions(FaceId(f));
            crossings += usize::from(intersect_triangle(p, dir, a, b, c).is_some());
            false
        });
        crossings % 2 == 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::primitives::{icosphere, torus};

    #[test]
    fn points_inside_a_sphere_and_a_torus_are_told_from_points_outside() {
        let sphere = icosphere(1.0, 3);
        let bvh = Bvh::new(&sphere);
        assert!(bvh.contains(&sphere, DVec3::ZERO));
        assert!(bvh.contains(&sphere, DVec3::new(0.5, -0.3, 0.6)));
        assert!(!bvh.contains(&sphere, DVec3::new(1.2, 0.0, 0.0)));
        let ring = torus(1.0, 0.35, 48, 24);
        let bvh = Bvh::new(&ring);
        assert!(!bvh.contains(&ring, DVec3::ZERO), "the hole is outside");
        assert!(bvh.contains(&ring, DVec3::new(1.0, 0.0, 0.0)));
        assert!(!bvh.contains(&ring, DVec3::new(1.0, 0.0, 0.5)));
    }
}
