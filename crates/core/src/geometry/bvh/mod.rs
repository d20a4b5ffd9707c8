//! A bounding-volume hierarchy over a mesh's triangles, for the many rays a frame needs
//! (silhouette visibility), where [`raycast`](super::raycast) scans every triangle.
//!
//! Built as a linear BVH over a Morton curve ([`build`]). Nodes live in one flat
//! array in depth-first order with the two children of an inner node side by side, so a
//! child's index is always larger than its parent's; leaves refer to ranges of one permuted
//! face array. Queries take the mesh again: the hierarchy stores no positions, so it belongs
//! to one mesh and one set of positions, and [`Bvh::refit`] updates its boxes after the
//! vertices move (the tree gets looser the further they move; rebuild after large
//! deformations).

mod build;
mod inside;
mod nearest;
mod node;
mod overlap;
mod sphere;

use glam::DVec3;

use super::RayHit;
use super::raycast::intersect_triangle;
use crate::mesh::{FaceId, Mesh};
use node::{Aabb, Node, triangle_box};

/// A bounding-volume hierarchy over the triangles of one [`Mesh`]: a linear BVH (triangles
/// sorted along a Morton curve of their centroids, leaves of up to four), built in about 3 ms
/// for 80k triangles. It stores no positions: queries take the mesh, which must be the one it
/// was built for, with the positions of the last build or [`Bvh::refit`].
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    /// Face indices, permuted so that every leaf owns a contiguous range.
    faces: Vec<u32>,
}

impl Bvh {
    /// Builds the hierarchy over all triangles of `mesh`.
    pub fn new(mesh: &Mesh) -> Self {
        let (nodes, faces) = build::build(mesh);
        let mut bvh = Self { nodes, faces };
        bvh.refit(mesh);
        bvh
    }

    /// Recomputes every box from the mesh's current positions; the tree itself is kept.
    /// The mesh must have the connectivity the hierarchy was built for.
    pub fn refit(&mut self, mesh: &Mesh) {
        // Children follow their parents in the array, so a reverse sweep sees them first.
        for index in (0..self.nodes.len()).rev() {
            let Node { first, count, .. } = self.nodes[index];
            let mut bounds = Aabb::EMPTY;
            if count > 0 {
                for &f in &self.faces[first as usize..(first + count) as usize] {
                    bounds.grow(triangle_box(mesh, f));
                }
            } else {
                for child in [first, first + 1] {
                    let node = self.nodes[child as usize];
                    bounds.grow(node.bounds);
                }
            }
            self.nodes[index].bounds = bounds;
        }
    }

    /// The nearest hit of the ray `origin + t·dir` (`t > 0`) with any triangle, front or back;
    /// the same answer as the linear scan [`geometry::raycast`](super::raycast), ties going to
    /// the lower face id.
    pub fn raycast(&self, mesh: &Mesh, origin: DVec3, dir: DVec3) -> Option<RayHit> {
        debug_assert_eq!(
            mesh.n_faces(),
            self.faces.len(),
            "the BVH belongs to another mesh"
        );
        let inv_dir = dir.recip();
        let mut best: Option<RayHit> = None;
        let mut stack = Vec::with_capacity(64);
        if !self.nodes.is_empty() {
            stack.push(0u32);
        }
        while let Some(index) = stack.pop() {
            let node = self.nodes[index as usize];
            let limit = best.map_or(f64::INFINITY, |h| h.distance);
            if self.entry(index, origin, inv_dir, limit).is_none() {
                continue;
            }
            if node.count > 0 {
                for &f in &self.faces[node.first as usize..(node.first + node.count) as usize] {
                    let [a, b, c] = mesh.face_positions(FaceId(f));
                    let Some((t, u, v)) = intersect_triangle(origin, dir, a, b, c) else {
                        continue;
                    };
                    let is_better =
                        best.is_none_or(|h| t < h.distance || (t == h.distance && f < h.face.0));
                    if is_better {
                        best = Some(RayHit {
                            distance: t,
                            face: FaceId(f),
                            barycentric: DVec3::new(1.0 - u - v, u, v),
                        });
                    }
                }
                continue;
            }
            // Push the farther child first so the nearer one is searched first.
            let (left, right) = (node.first, node.first + 1);
            match (
                self.entry(left, origin, inv_dir, limit),
                self.entry(right, origin, inv_dir, limit),
            ) {
                (Some(l), Some(r)) if l < r => stack.extend([right, left]),
                (Some(_), Some(_)) => stack.extend([left, right]),
                (Some(_), None) => stack.push(left),
                (None, Some(_)) => stack.push(right),
                (None, None) => {}
            }
        }
        best
    }

    /// Whether some triangle crosses the segment from `from` to `to`, not counting hits within
    /// `margin` of `to` (so the surface that `to` lies on does not hide it).
    pub fn occluded(&self, mesh: &Mesh, from: DVec3, to: DVec3, margin: f64) -> bool {
        debug_assert_eq!(
            mesh.n_faces(),
            self.faces.len(),
            "the BVH belongs to another mesh"
        );
        let length = from.distance(to);
        let limit = length - margin;
        if self.nodes.is_empty() || limit.is_nan() || limit <= 0.0 {
            return false;
        }
        let dir = (to - from) / length;
        let mut hit = false;
        self.along_ray(from, dir, limit, |f| {
            let [a, b, c] = mesh.face_positions(FaceId(f));
            hit = intersect_triangle(from, dir, a, b, c).is_some_and(|(t, _, _)| t < limit);
            hit
        });
        hit
    }

    /// Calls `visit` with every face in the leaves whose boxes the ray `origin + t·dir`
    /// enters before `limit`, until it returns `true`.
    fn along_ray(&self, origin: DVec3, dir: DVec3, limit: f64, mut visit: impl FnMut(u32) -> bool) {
        let inv_dir = dir.recip();
        let mut stack = Vec::with_capacity(64);
        if !self.nodes.is_empty() {
            stack.push(0u32);
        }
        while let Some(index) = stack.pop() {
            if self.entry(index, origin, inv_dir, limit).is_none() {
                continue;
            }
            let node = self.nodes[index as usize];
            if node.count == 0 {
                stack.extend([node.first, node.first + 1]);
                continue;
            }
            for &f in &self.faces[node.first as usize..(node.first + node.count) as usize] {
                if visit(f) {
                    return;
                }
            }
        }
    }

    /// Where the ray enters a node's box (slab test), if it does before `limit`.
    fn entry(&self, index: u32, origin: DVec3, inv_dir: DVec3, limit: f64) -> Option<f64> {
        let node = &self.nodes[index as usize];
        let t0 = (node.bounds.lo - origin) * inv_dir;
        let t1 = (node.bounds.hi - origin) * inv_dir;
        // `f64::min`/`max` skip the NaN of a ray lying in a slab plane (0 · ∞).
        let t_enter = t0.min(t1).max_element().max(0.0);
        let t_exit = t0.max(t1).min_element();
        (t_enter <= t_exit && t_enter <= limit).then_some(t_enter)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::raycast;
    use crate::mesh::primitives::{icosphere, torus};

    /// A linear scan for `occluded`, the reference.
    fn occluded_by_scan(mesh: &Mesh, from: DVec3, to: DVec3, margin: f64) -> bool {
        let length = from.distance(to);
        let dir = (to - from) / length;
        raycast(mesh, from, dir).is_some_and(|hit| hit.distance < length - margin)
    }

    /// xorshift64*: a few reproducible random numbers without a dependency.
    struct Random(u64);

    impl Random {
        fn unit(&mut self) -> f64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
        }

        fn in_cube(&mut self, half: f64) -> DVec3 {
            DVec3::new(self.unit(), self.unit(), self.unit()) * 2.0 * half - half
        }
    }

    fn meshes() -> Vec<Mesh> {
        vec![icosphere(1.0, 3), torus(1.0, 0.35, 48, 24)]
    }

    #[test]
    fn raycast_agrees_with_the_linear_scan() {
        let mut random = Random(0x9e37_79b9_7f4a_7c15);
        for mesh in meshes() {
            let bvh = Bvh::new(&mesh);
            let mut n_hits = 0;
            for _ in 0..500 {
                // Rays from outside and from inside towards points near the surface.
                let origin = random.in_cube(3.0);
                let dir = (random.in_cube(1.2) - origin).normalize();
                let fast = bvh.raycast(&mesh, origin, dir);
                assert_eq!(fast, raycast(&mesh, origin, dir), "{origin} {dir}");
                n_hits += usize::from(fast.is_some());
            }
            assert!(n_hits > 200, "too few hits to mean anything: {n_hits}");
        }
    }

    #[test]
    fn occluded_agrees_with_the_linear_scan() {
        let mut random = Random(42);
        for mesh in meshes() {
            let bvh = Bvh::new(&mesh);
            let (mut n_blocked, mut n_clear) = (0, 0);
            for _ in 0..500 {
                let from = random.in_cube(3.0);
                let to = random.in_cube(1.5);
                let expected = occluded_by_scan(&mesh, from, to, 0.05);
                assert_eq!(bvh.occluded(&mesh, from, to, 0.05), expected, "{from} {to}");
                if expected {
                    n_blocked += 1
                } else {
                    n_clear += 1
                }
            }
            assert!(n_blocked > 50 && n_clear > 50, "{n_blocked} {n_clear}");
        }
    }

    #[test]
    fn a_surface_point_is_visible_from_outside_but_not_through_the_mesh() {
        let sphere = icosphere(1.0, 3);
        let bvh = Bvh::new(&sphere);
        // A vertex of the sphere, seen from straight outside and from the far side.
        let p = sphere.positions()[7];
        assert!(!bvh.occluded(&sphere, 5.0 * p, p, 1e-6));
        assert!(bvh.occluded(&sphere, -5.0 * p, p, 1e-6));
        // A margin longer than the segment never occludes.
        assert!(!bvh.occluded(&sphere, -5.0 * p, p, 10.0));
    }

    #[test]
    fn refit_follows_moved_vertices() {
        let mut mesh = torus(1.0, 0.35, 32, 16);
        let mut bvh = Bvh::new(&mesh);
        for p in mesh.positions_mut() {
            *p = DVec3::new(2.0 * p.x + 0.3, p.y - 0.1 * p.x * p.x, 0.5 * p.z + p.y);
        }
        bvh.refit(&mesh);
        let mut random = Random(7);
        for _ in 0..300 {
            let origin = random.in_cube(4.0);
            let dir = (random.in_cube(1.5) - origin).normalize();
            assert_eq!(bvh.raycast(&mesh, origin, dir), raycast(&mesh, origin, dir));
        }
    }

    #[test]
    fn every_face_sits_in_exactly_one_leaf() {
        let mesh = icosphere(1.0, 4);
        let bvh = Bvh::new(&mesh);
        let mut seen = vec![0; mesh.n_faces()];
        for node in bvh.nodes.iter().filter(|n| n.count > 0) {
            assert!(node.count as usize <= build::MAX_LEAF);
            for &f in &bvh.faces[node.first as usize..(node.first + node.count) as usize] {
                seen[f as usize] += 1;
                let b = triangle_box(&mesh, f);
                assert!(b.lo.cmpge(node.bounds.lo).all() && b.hi.cmple(node.bounds.hi).all());
            }
        }
        assert!(seen.iter().all(|&k| k == 1));
        let empty = Bvh::new(&Mesh::default());
        assert_eq!(empty.raycast(&Mesh::default(), DVec3::ZERO, DVec3::Z), None);
        assert!(!empty.occluded(&Mesh::default(), DVec3::ZERO, DVec3::Z, 0.0));
    }
}
