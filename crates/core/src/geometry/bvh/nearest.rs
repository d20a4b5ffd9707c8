//! Nearest-point queries: the distance from a point to the surface.

use glam::DVec3;

use super::Bvh;
use super::node::Aabb;
use crate::geometry::closest::closest_point_on_triangle;
use crate::mesh::{FaceId, Mesh};

/// Squared distance from `p` to the box (0 inside).
pub(super) fn box_distance_squared(bounds: &Aabb, p: DVec3) -> f64 {
    let outside = (bounds.lo - p).max(p - bounds.hi).max(DVec3::ZERO);
    outside.length_squared()
}

impl Bvh {
    /// The point of the surface nearest to `p` and its face, or `None` for an empty mesh.
    /// Visits boxes nearest first and skips those farther than the best point so far.
    pub fn nearest(&self, mesh: &Mesh, p: DVec3) -> Option<(DVec3, FaceId)> {
        self.nearest_within(mesh, p, f64::INFINITY)
    }

    /// [`Bvh::nearest`] among the points within `radius` of `p`; `None` if there are none.
    /// Much cheaper for a point deep inside a closed surface, where many boxes lie at about
    /// the same distance and the unbounded search visits them all.
    pub fn nearest_within(&self, mesh: &Mesh, p: DVec3, radius: f64) -> Option<(DVec3, FaceId)> {
        let mut best: Option<(f64, DVec3, FaceId)> = None;
        let bound = radius * radius;
        let mut stack = Vec::with_capacity(64);
        if !self.nodes.is_empty() {
            stack.push(0u32);
        }
        while let Some(index) = stack.pop() {
            let node = self.nodes[index as usize];
            let limit = best.map_or(bound, |b| b.0);
            if box_distance_squared(&node.bounds, p) > limit {
                continue;
            }
            if node.count > 0 {
                for &f in &self.faces[node.first as usize..(node.first + node.count) as usize] {
                    let q = closest_point_on_triangle(p, mesh.face_positions(FaceId(f)));
                    let d = q.distance_squared(p);
                    if d <= bound && best.is_none_or(|b| d < b.0) {
                        best = Some((d, q, FaceId(f)));
                    }
                }
                continue;
            }
            let (left, right) = (node.first, node.first + 1);
            let distance = |child: u32| box_distance_squared(&self.nodes[child as usize].bounds, p);
            // The nearer child goes on top, to be searched first.
            if distance(left) < distance(right) {
                stack.extend([right, left]);
            } else {
                stack.extend([left, right]);
            }
        }
        best.map(|(_, q, f)| (q, f))
    }
}

#[cfg(test)]
mod tests {
    use glam::DVec3;

    use crate::geometry::Bvh;
    use crate::geometry::closest::closest_point_on_triangle;
    use crate::mesh::primitives;

    #[test]
    fn nearest_agrees_with_a_scan_of_every_face() {
        let mesh = primitives::torus(2.0, 0.6, 24, 12);
        let bvh = Bvh::new(&mesh);
        for k in 0..50 {
            let t = k as f64;
            let p = DVec3::new(
                (t * 0.7).sin() * 3.0,
                (t * 1.3).cos() * 3.0,
                (t * 0.4).sin(),
            );
            let (q, _) = bvh.nearest(&mesh, p).unwrap();
            let scan = mesh
                .faces()
                .map(|f| closest_point_on_triangle(p, mesh.face_positions(f)).distance(p))
                .fold(f64::INFINITY, f64::min);
            assert!((q.distance(p) - scan).abs() < 1e-12, "point {k}");
        }
    }
}
