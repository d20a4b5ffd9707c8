//! A mesh's mirror image, vertex for vertex.

use glam::DVec3;

use super::{INVALID, Mesh};

impl Mesh {
    /// The mesh with every position mapped by `reflect` (a mirror) and every face turned over,
    /// so that its outside stays outside: the same vertex ids, and each face the same face.
    /// Tombstones stay tombstones.
    pub fn mirrored(&self, reflect: impl Fn(DVec3) -> DVec3) -> Mesh {
        // Face [a, b, c] becomes [a, c, b]: its half-edge at corner k is the old one at
        // corner 2 - k, reversed, so its twin is the old twin's image.
        let flip = |h: u32| match h {
            INVALID => INVALID,
            h => 3 * (h / 3) + 2 - h % 3,
        };
        let triangles: Vec<[u32; 3]> = self.triangles.iter().map(|&[a, b, c]| [a, c, b]).collect();
        let twin: Vec<u32> = (0..self.twin.len() as u32)
            .map(|h| flip(self.twin[flip(h) as usize]))
            .collect();
        // Each vertex starts at an outgoing half-edge, the boundary one where there is one.
        let mut vertex_halfedge = vec![INVALID; self.n_vertices()];
        for (h, &v) in triangles.as_flattened().iter().enumerate() {
            if v != INVALID && (vertex_halfedge[v as usize] == INVALID || twin[h] == INVALID) {
                vertex_halfedge[v as usize] = h as u32;
            }
        }
        let mesh = Mesh {
            positions: self.positions.iter().map(|&p| reflect(p)).collect(),
            triangles,
            twin,
            vertex_halfedge,
            n_dead_vertices: self.n_dead_vertices,
            n_dead_faces: self.n_dead_faces,
        };
        debug_assert_eq!(mesh.validate(), Ok(()));
        mesh
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{TriSoup, primitives};

    #[test]
    fn the_mirror_image_is_the_mesh_built_from_the_turned_soup() {
        let mut mesh = primitives::icosphere(1.0, 2);
        mesh.positions_mut()[0].x += 0.3;
        let reflect = |p: DVec3| DVec3::new(-p.x, p.y, p.z);
        let mirrored = mesh.mirrored(reflect);
        assert_eq!(mirrored.validate(), Ok(()));
        let soup = mesh.to_soup();
        let turned = Mesh::from_soup(&TriSoup {
            positions: soup.positions.iter().map(|&p| reflect(p)).collect(),
            triangles: soup.triangles.iter().map(|&[a, b, c]| [a, c, b]).collect(),
        })
        .unwrap();
        assert_eq!(mirrored.triangles(), turned.triangles());
        assert_eq!(mirrored.positions(), turned.positions());
        assert_eq!(mirrored.twin, turned.twin);
    }
}
