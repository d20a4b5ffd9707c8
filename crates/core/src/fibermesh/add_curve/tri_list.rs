//! A triangle list that can split edges and faces in place, for embedding a curve.
//!
//! [`Mesh`] has immutable topology, and a curve walk changes the mesh at every step, so the
//! walk works on this list (positions, triangles and a map from each directed edge to its
//! triangle) and builds one new [`Mesh`] at the end. Vertices are only appended, so every
//! input vertex keeps its index.

use glam::DVec3;
use rustc_hash::FxHashMap;

use crate::mesh::{Mesh, MeshError, TriSoup};

/// Triangles with directed-edge adjacency; splits are O(1) and recorded.
pub(super) struct TriList {
    /// Vertex positions: the input's, then the new vertices.
    pub positions: Vec<DVec3>,
    /// Counter-clockwise triangles.
    triangles: Vec<[u32; 3]>,
    /// The triangle holding each directed edge `a → b`.
    face_of_edge: FxHashMap<(u32, u32), u32>,
    /// One triangle of each vertex, where fans start.
    face_of_vertex: Vec<u32>,
    /// Every edge split as `(a, b, new)`, in order.
    pub splits: Vec<(u32, u32, u32)>,
}

/// A triangle's corners rotated so that `v` comes first.
pub(super) fn rotated(triangle: [u32; 3], v: u32) -> [u32; 3] {
    let [a, b, c] = triangle;
    if b == v {
        [b, c, a]
    } else if c == v {
        [c, a, b]
    } else {
        [a, b, c]
    }
}

impl TriList {
    /// The triangles of `mesh`, ready to split.
    pub fn new(mesh: &Mesh) -> Self {
        let triangles = mesh.triangles().to_vec();
        let mut face_of_edge = FxHashMap::default();
        face_of_edge.reserve(3 * triangles.len());
        let mut face_of_vertex = vec![0; mesh.n_vertices()];
        for (f, &[a, b, c]) in triangles.iter().enumerate() {
            let f = f as u32;
            face_of_edge.extend([((a, b), f), ((b, c), f), ((c, a), f)]);
            for v in [a, b, c] {
                face_of_vertex[v as usize] = f;
            }
        }
        Self {
            positions: mesh.positions().to_vec(),
            triangles,
            face_of_edge,
            face_of_vertex,
            splits: Vec::new(),
        }
    }

    /// The corners of triangle `f`.
    pub fn triangle(&self, f: u32) -> [u32; 3] {
        self.triangles[f as usize]
    }

    /// The corners' positions of triangle `f`.
    pub fn triangle_positions(&self, f: u32) -> [DVec3; 3] {
        self.triangle(f).map(|v| self.positions[v as usize])
    }

    /// All triangles, for scans over the whole surface.
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// The triangle holding the directed edge `a → b`, if any.
    pub fn face_of_edge(&self, a: u32, b: u32) -> Option<u32> {
        self.face_of_edge.get(&(a, b)).copied()
    }

    /// The triangles around `v`, each as `(face, corners rotated to start at v)`.
    pub fn fan(&self, v: u32) -> Vec<(u32, [u32; 3])> {
        let start = self.face_of_vertex[v as usize];
        let mut fan = vec![(start, rotated(self.triangle(start), v))];
        // Counter-clockwise: across the edge v–c of [v, b, c].
        let mut closed = false;
        while let Some(&(_, [_, _, c])) = fan.last() {
            let Some(f) = self.face_of_edge(v, c) else {
                break;
            };
            if f == start {
                closed = true;
                break;
            }
            fan.push((f, rotated(self.triangle(f), v)));
        }
        if !closed {
            // A boundary vertex: the rest of the fan lies clockwise from the start.
            let mut b = fan[0].1[1];
            while let Some(f) = self.face_of_edge(b, v) {
                let corners = rotated(self.triangle(f), v);
                b = corners[1];
                fan.push((f, corners));
            }
        }
        fan
    }

    /// Splits the edge `a`–`b` at `a + t (b − a)` in both its triangles and records it;
    /// returns the new vertex.
    pub fn split_edge(&mut self, a: u32, b: u32, t: f64) -> u32 {
        let (pa, pb) = (self.positions[a as usize], self.positions[b as usize]);
        let m = self.push_vertex(pa.lerp(pb, t));
        for (x, y) in [(a, b), (b, a)] {
            let Some(f) = self.face_of_edge.remove(&(x, y)) else {
                continue;
            };
            let [_, _, z] = rotated(self.triangle(f), x);
            let g = self.triangles.len() as u32;
            self.triangles[f as usize] = [x, m, z];
            self.triangles.push([m, y, z]);
            self.face_of_edge.extend([
                ((x, m), f),
                ((m, z), f),
                ((m, y), g),
                ((y, z), g),
                ((z, m), g),
            ]);
            self.face_of_vertex[y as usize] = g;
            self.face_of_vertex[m as usize] = f;
        }
        self.splits.push((a, b, m));
        m
    }

    /// Splits triangle `f` at the point with barycentric coordinates `bary` into three;
    /// returns the new vertex.
    pub fn split_face(&mut self, f: u32, bary: DVec3) -> u32 {
        let [a, b, c] = self.triangle(f);
        let [pa, pb, pc] = self.triangle_positions(f);
        let m = self.push_vertex(pa * bary.x + pb * bary.y + pc * bary.z);
        let g = self.triangles.len() as u32;
        let h = g + 1;
        self.triangles[f as usize] = [a, b, m];
        self.triangles.extend([[b, c, m], [c, a, m]]);
        self.face_of_edge.extend([
            ((b, m), f),
            ((m, a), f),
            ((b, c), g),
            ((c, m), g),
            ((m, b), g),
            ((c, a), h),
            ((a, m), h),
            ((m, c), h),
        ]);
        self.face_of_vertex[c as usize] = g;
        self.face_of_vertex[m as usize] = f;
        m
    }

    /// Puts a vertex at the point with barycentric coordinates `bary` in triangle `f`:
    /// a corner within `snap` (in barycentric units) of it, else a point on an edge within
    /// `snap` of it, else a new interior vertex. Snapping avoids slivers.
    pub fn insert_point(&mut self, f: u32, bary: DVec3, snap: f64) -> u32 {
        let corners = self.triangle(f);
        let bary = bary.max(DVec3::ZERO) / bary.max(DVec3::ZERO).element_sum();
        let nearest = bary.max_position();
        if bary[nearest] > 1.0 - snap {
            return corners[nearest];
        }
        let farthest = bary.min_position();
        if bary[farthest] < snap {
            let (i, j) = ((farthest + 1) % 3, (farthest + 2) % 3);
            let t = bary[j] / (bary[i] + bary[j]);
            return self.split_edge(corners[i], corners[j], t);
        }
        self.split_face(f, bary)
    }

    /// The embedded mesh.
    ///
    /// Errors: a [`MeshError`] if the splits broke the manifold (a bug).
    pub fn into_mesh(self) -> Result<Mesh, MeshError> {
        Mesh::from_soup(&TriSoup {
            positions: self.positions,
            triangles: self.triangles,
        })
    }

    fn push_vertex(&mut self, p: DVec3) -> u32 {
        self.positions.push(p);
        self.face_of_vertex.push(0);
        self.positions.len() as u32 - 1
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]

    use super::*;
    use crate::mesh::primitives::{grid, icosphere};

    #[test]
    fn splits_keep_a_valid_mesh_and_the_input_vertices() {
        let sphere = icosphere(1.0, 2);
        let mut list = TriList::new(&sphere);
        let [a, b, _] = list.triangle(5);
        let m = list.split_edge(a, b, 0.3);
        list.split_face(7, DVec3::new(0.2, 0.3, 0.5));
        list.insert_point(0, DVec3::new(0.95, 0.04, 0.01), 0.1);
        assert_eq!(list.splits, vec![(a, b, m)]);
        let fan: Vec<u32> = list.fan(m).iter().map(|&(_, [_, b, _])| b).collect();
        assert_eq!(fan.len(), 4);
        let mesh = list.into_mesh().unwrap();
        mesh.validate().unwrap();
        assert!(mesh.is_closed());
        assert_eq!(&mesh.positions()[..sphere.n_vertices()], sphere.positions());
        assert_eq!(mesh.n_vertices(), sphere.n_vertices() + 2);
    }

    #[test]
    fn fan_of_a_boundary_vertex_is_whole() {
        let plane = grid(2, 2, 1.0);
        let list = TriList::new(&plane);
        for v in 0..plane.n_vertices() as u32 {
            let faces = plane.vertex_faces(crate::mesh::VertexId(v)).count();
            assert_eq!(list.fan(v).len(), faces, "vertex {v}");
        }
    }
}
