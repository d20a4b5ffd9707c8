//! Which triangles of a mesh cross each other: pairs of boxes that overlap, found by
//! descending the hierarchy once per triangle, then an exact test of the candidates.
//!
//! Two triangles cross when an edge of one passes through the other (Möller–Trumbore on the
//! six edges, as segments). Triangles that share a vertex touch there by construction and
//! are skipped, as are exactly coplanar overlaps (no edge pierces the other triangle):
//! neither comes out of the operations that use this check (cut, tunnel), whose new
//! triangles meet the old ones only at shared vertices or cross them properly.

use glam::DVec3;

use super::Bvh;
use super::node::{Aabb, triangle_box};
use crate::geometry::segment_crosses_triangle;
use crate::mesh::{FaceId, Mesh};

impl Bvh {
    /// The pairs of triangles of `mesh` (the mesh it was built for) that cross each other,
    /// each pair once with the lower face first, among those for which `check` holds for at
    /// least one of the two; see the module docs for what counts as crossing.
    pub fn crossing_faces(
        &self,
        mesh: &Mesh,
        check: impl Fn(FaceId) -> bool,
    ) -> Vec<(FaceId, FaceId)> {
        let mut pairs = Vec::new();
        let mut stack = Vec::new();
        for f in mesh.faces().filter(|&f| check(f)) {
            let bounds = triangle_box(mesh, f.0);
            stack.clear();
            stack.push(0u32);
            while let Some(index) = stack.pop() {
                let Some(node) = self.nodes.get(index as usize) else {
                    continue;
                };
                if !overlaps(&node.bounds, &bounds) {
                    continue;
                }
                if node.count == 0 {
                    stack.extend([node.first, node.first + 1]);
                    continue;
                }
                for &g in &self.faces[node.first as usize..(node.first + node.count) as usize] {
                    let g = FaceId(g);
                    // A pair both of whose faces are checked is seen twice: keep one.
                    if g == f || (check(g) && g < f) {
                        continue;
                    }
                    if cross(mesh, f, g) {
                        pairs.push((f.min(g), f.max(g)));
                    }
                }
            }
        }
        pairs.sort_unstable();
        pairs
    }
}

fn overlaps(a: &Aabb, b: &Aabb) -> bool {
    a.lo.cmple(b.hi).all() && b.lo.cmple(a.hi).all()
}

/// Whether triangles `f` and `g`, which share no vertex, cross.
fn cross(mesh: &Mesh, f: FaceId, g: FaceId) -> bool {
    let (fv, gv) = (mesh.face_vertices(f), mesh.face_vertices(g));
    if fv.iter().any(|v| gv.contains(v)) {
        return false;
    }
    let (p, q) = (mesh.face_positions(f), mesh.face_positions(g));
    edge_pierces(&p, &q) || edge_pierces(&q, &p)
}

/// Whether an edge of triangle `edges` passes through triangle `target`.
fn edge_pierces(edges: &[DVec3; 3], &[a, b, c]: &[DVec3; 3]) -> bool {
    (0..3).any(|k| segment_crosses_triangle(edges[k], edges[(k + 1) % 3], a, b, c))
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::mesh::primitives::{icosphere, torus};

    #[test]
    fn closed_primitives_do_not_cross_themselves() {
        for mesh in [icosphere(1.0, 3), torus(1.0, 0.4, 32, 12)] {
            assert!(Bvh::new(&mesh).crossing_faces(&mesh, |_| true).is_empty());
        }
    }

    #[test]
    fn two_overlapping_spheres_cross_along_a_ring_of_faces() {
        let mut soup = icosphere(1.0, 2).to_soup();
        let mut other = icosphere(1.0, 2).to_soup();
        for p in &mut other.positions {
            p.x += 1.0;
        }
        soup.append(&other);
        let mesh = Mesh::from_soup(&soup).unwrap();
        let n = icosphere(1.0, 2).n_faces() as u32;
        let pairs = Bvh::new(&mesh).crossing_faces(&mesh, |_| true);
        assert!(pairs.len() > 20, "{} crossing pairs", pairs.len());
        assert!(
            pairs.iter().all(|&(f, g)| f.0 < n && g.0 >= n),
            "only across the spheres"
        );
        // Checking only the second sphere's faces finds the same pairs.
        let some = Bvh::new(&mesh).crossing_faces(&mesh, |f| f.0 >= n);
        assert_eq!(some, pairs);
    }
}
