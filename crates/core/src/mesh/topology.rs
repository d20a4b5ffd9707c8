//! Global topology: boundary loops, connected components, Euler characteristic and genus.
//!
//! For an orientable surface with `c` components, `b` boundary loops and total genus `g`, the
//! Euler characteristic is `V - E + F = 2c - 2g - b`, so `g = (2c - chi - b) / 2`. Every
//! function here walks the half-edge arrays; nothing is cached, so nothing goes stale.

use rustc_hash::FxHashSet;

use super::{FaceId, HalfedgeId, Mesh, VertexId};

impl Mesh {
    /// Boundary loops as vertex cycles (first vertex not repeated).
    ///
    /// Each loop runs along its boundary half-edges, with the surface on the left: the outer
    /// rim of a counter-clockwise patch is counter-clockwise, holes run clockwise. Loops are
    /// ordered by their lowest boundary half-edge, so the result is deterministic.
    pub fn boundary_loops(&self) -> Vec<Vec<VertexId>> {
        let mut is_visited = vec![false; self.n_halfedges()];
        let mut loops = Vec::new();
        for start in (0..self.n_halfedges() as u32).map(HalfedgeId) {
            if is_visited[start.index()] || !self.is_boundary_halfedge(start) {
                continue;
            }
            let mut cycle = Vec::new();
            let mut h = start;
            // A manifold boundary vertex has exactly one outgoing boundary half-edge, its own
            // `vertex_halfedge`, so the loop's next half-edge is found in O(1).
            while !is_visited[h.index()] {
                is_visited[h.index()] = true;
                cycle.push(self.tail(h));
                h = self.vertex_halfedge(self.head(h));
            }
            debug_assert_eq!(h, start, "boundary walk did not close");
            loops.push(cycle);
        }
        loops
    }

    /// The closed loops around a set of faces (`inside`, one flag per face), as vertex
    /// cycles with the set on their left; a loop that runs into the mesh's own boundary is
    /// dropped.
    pub(crate) fn face_set_loops(&self, inside: &[bool]) -> Vec<Vec<VertexId>> {
        let is_cut = |h: HalfedgeId| {
            inside[self.face(h).index()]
                && self.twin(h).is_some_and(|t| !inside[self.face(t).index()])
        };
        let starts: Vec<HalfedgeId> = (0..self.n_halfedges() as u32)
            .map(HalfedgeId)
            .filter(|&h| is_cut(h))
            .collect();
        let mut visited = FxHashSet::default();
        let mut loops = Vec::new();
        for &first in &starts {
            if visited.contains(&first) {
                continue;
            }
            let mut curve = Vec::new();
            let mut h = first;
            let is_closed = loop {
                visited.insert(h);
                curve.push(self.tail(h));
                let Some(next) = self.next_cut(h, inside) else {
                    break false;
                };
                if next == first {
                    break true;
                }
                if visited.contains(&next) || curve.len() > starts.len() {
                    break false;
                }
                h = next;
            };
            if is_closed {
                loops.push(curve);
            }
        }
        loops
    }

    /// The cut half-edge that follows `h` around a face set: turning around its head through
    /// faces inside until the face across is outside. `None` at the mesh boundary.
    fn next_cut(&self, mut h: HalfedgeId, inside: &[bool]) -> Option<HalfedgeId> {
        // A vertex has fewer faces than there are faces in all.
        for _ in 0..self.n_faces() {
            let g = self.next(h);
            let across = self.twin(g)?;
            if !inside[self.face(across).index()] {
                return Some(g);
            }
            h = across;
        }
        None
    }

    /// Number of boundary loops (holes and rims).
    pub fn n_boundary_loops(&self) -> usize {
        self.boundary_loops().len()
    }

    /// Component label of every face (`0..n_components`, numbered by their lowest face) and the
    /// number of components. Two faces are connected when they share an edge.
    pub fn face_components(&self) -> (Vec<u32>, usize) {
        const UNLABELED: u32 = u32::MAX;
        let mut label = vec![UNLABELED; self.n_faces()];
        let mut n_components = 0u32;
        let mut stack = Vec::new();
        for seed in 0..self.n_faces() {
            if label[seed] != UNLABELED {
                continue;
            }
            label[seed] = n_components;
            stack.push(seed as u32);
            while let Some(f) = stack.pop() {
                for h in (3 * f..3 * f + 3).map(HalfedgeId) {
                    let Some(t) = self.twin(h) else { continue };
                    let g = self.face(t).index();
                    if label[g] == UNLABELED {
                        label[g] = n_components;
                        stack.push(g as u32);
                    }
                }
            }
            n_components += 1;
        }
        (label, n_components as usize)
    }

    /// Faces of each connected component, in increasing order of their lowest face.
    pub fn connected_components(&self) -> Vec<Vec<FaceId>> {
        let (label, n_components) = self.face_components();
        let mut components = vec![Vec::new(); n_components];
        for (f, &c) in label.iter().enumerate() {
            components[c as usize].push(FaceId(f as u32));
        }
        components
    }

    /// Number of connected components (0 for an empty mesh).
    pub fn n_components(&self) -> usize {
        self.face_components().1
    }

    /// `V - E + F`.
    pub fn euler_characteristic(&self) -> i64 {
        self.n_vertices() as i64 - self.n_edges() as i64 + self.n_faces() as i64
    }

    /// Total genus, summed over components, from `g = (2c - chi - b) / 2` (see module docs).
    ///
    /// A sphere and a disk have genus 0, a torus (with or without holes cut in it) 1; a sphere
    /// plus a torus, 1. `None` when the formula gives no whole non-negative number, which
    /// only a mesh breaking [`Mesh::validate`] can cause.
    pub fn genus(&self) -> Option<u32> {
        let c = self.n_components() as i64;
        let b = self.n_boundary_loops() as i64;
        let twice_genus = 2 * c - self.euler_characteristic() - b;
        if twice_genus < 0 || twice_genus % 2 != 0 {
            return None;
        }
        u32::try_from(twice_genus / 2).ok()
    }
}

#[cfg(test)]
mod tests {
    use crate::mesh::{Mesh, TriSoup, VertexId, fixtures, primitives};
    use glam::DVec3;

    #[test]
    fn icosphere_is_a_closed_sphere() {
        for subdivisions in 0..4 {
            let mesh = primitives::icosphere(1.0, subdivisions);
            assert!(mesh.is_closed());
            assert_eq!(mesh.euler_characteristic(), 2);
            assert_eq!(mesh.genus(), Some(0));
            assert_eq!(mesh.n_components(), 1);
            assert!(mesh.boundary_loops().is_empty());
        }
    }

    #[test]
    fn torus_has_genus_one() {
        let mesh = primitives::torus(3.0, 1.0, 16, 8);
        assert!(mesh.is_closed());
        assert_eq!(mesh.euler_characteristic(), 0);
        assert_eq!(mesh.genus(), Some(1));
    }

    #[test]
    fn grid_has_one_counter_clockwise_boundary_loop() {
        let (nx, ny) = (4, 3);
        let mesh = primitives::grid(nx, ny, 1.0);
        let loops = mesh.boundary_loops();
        assert_eq!(loops.len(), 1);
        assert_eq!(loops[0].len(), 2 * (nx + ny));
        assert_eq!(mesh.genus(), Some(0));
        assert_eq!(mesh.euler_characteristic(), 1);
        // Shoelace formula: positive signed area means counter-clockwise seen from +z.
        let p: Vec<DVec3> = loops[0].iter().map(|&v| mesh.position(v)).collect();
        let twice_area: f64 = (0..p.len())
            .map(|i| p[i].truncate().perp_dot(p[(i + 1) % p.len()].truncate()))
            .sum();
        assert!(
            (twice_area / 2.0 - 0.75).abs() < 1e-12,
            "area {}",
            twice_area / 2.0
        );
    }

    #[test]
    fn two_disjoint_spheres_are_two_components() {
        let mut soup = primitives::icosphere(1.0, 1).to_soup();
        let mut other = primitives::icosphere(0.5, 2).to_soup();
        other
            .positions
            .iter_mut()
            .for_each(|p| *p += DVec3::X * 5.0);
        soup.append(&other);
        let mesh = Mesh::from_soup(&soup).unwrap();
        assert_eq!(mesh.n_components(), 2);
        let components = mesh.connected_components();
        assert_eq!(components[0].len(), 80);
        assert_eq!(components[1].len(), 320);
        assert_eq!(mesh.euler_characteristic(), 4);
        assert_eq!(mesh.genus(), Some(0));
    }

    #[test]
    fn sphere_plus_torus_with_a_hole_has_genus_one() {
        let mut soup = primitives::icosphere(1.0, 1).to_soup();
        let mut torus = primitives::torus(3.0, 1.0, 12, 6).to_soup();
        torus.triangles.remove(7);
        soup.append(&torus);
        let mesh = Mesh::from_soup(&soup).unwrap();
        assert_eq!(mesh.n_boundary_loops(), 1);
        assert_eq!(mesh.boundary_loops()[0].len(), 3);
        assert_eq!(mesh.genus(), Some(1));
    }

    #[test]
    fn fixtures_report_their_tagged_topology() {
        for fixture in fixtures::all() {
            assert_eq!(
                fixture.mesh.is_closed(),
                fixture.is_closed,
                "{}",
                fixture.name
            );
            assert_eq!(
                fixture.mesh.genus(),
                Some(fixture.genus),
                "{}",
                fixture.name
            );
        }
    }

    #[test]
    fn single_triangle_loop_is_its_corners() {
        let soup = TriSoup {
            positions: vec![DVec3::ZERO, DVec3::X, DVec3::Y],
            triangles: vec![[0, 1, 2]],
        };
        let mesh = Mesh::from_soup(&soup).unwrap();
        assert_eq!(
            mesh.boundary_loops(),
            vec![vec![VertexId(0), VertexId(1), VertexId(2)]]
        );
    }
}
