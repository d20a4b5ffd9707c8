//! Face and vertex normals.
//!
//! Vertex normals weight each incident face by its area: the sum of the faces' cross products
//! `(b - a) x (c - a)`, which are twice the area times the unit normal, normalised once. It is
//! cheap (one pass over faces, no trigonometry) and stable under subdivision; angle weights
//! would be less sensitive to irregular triangulations, at the cost of `acos` per corner.

use glam::DVec3;

use crate::mesh::{FaceId, Mesh};

/// `(b - a) x (c - a)`: twice the area times the unit normal.
pub(crate) fn face_cross(mesh: &Mesh, f: FaceId) -> DVec3 {
    let [a, b, c] = mesh.face_positions(f);
    (b - a).cross(c - a)
}

/// Unit normal of a face, by the right-hand rule over its corners; zero for a face with no
/// area.
pub fn face_normal(mesh: &Mesh, f: FaceId) -> DVec3 {
    face_cross(mesh, f).normalize_or_zero()
}

/// Unit normal of every face.
pub fn face_normals(mesh: &Mesh) -> Vec<DVec3> {
    mesh.faces().map(|f| face_normal(mesh, f)).collect()
}

/// Area-weighted unit vertex normals (zero where all incident faces have no area).
pub fn vertex_normals(mesh: &Mesh) -> Vec<DVec3> {
    let mut normals = Vec::new();
    vertex_normals_into(mesh, &mut normals);
    normals
}

/// [`vertex_normals`] into a reused buffer, resized to the vertex count: after the first
/// frame it allocates nothing.
pub fn vertex_normals_into(mesh: &Mesh, out: &mut Vec<DVec3>) {
    vertex_normals_of(mesh.triangles(), mesh.positions(), out);
}

/// [`vertex_normals_into`] for positions that are not (yet) a mesh's, such as a live
/// preview of a deformation: `triangles` index into `positions`.
pub fn vertex_normals_of(triangles: &[[u32; 3]], positions: &[DVec3], out: &mut Vec<DVec3>) {
    out.clear();
    out.resize(positions.len(), DVec3::ZERO);
    for &[a, b, c] in triangles {
        let [pa, pb, pc] = [a, b, c].map(|v| positions[v as usize]);
        let weighted = (pb - pa).cross(pc - pa);
        for v in [a, b, c] {
            out[v as usize] += weighted;
        }
    }
    for n in out.iter_mut() {
        *n = n.normalize_or_zero();
    }
}

/// How many of `triangles` face away from where they faced at `rest` once at `moved` (their
/// normals more than a right angle apart): the triangles a deformation folded over, which
/// a preview must not show (issue 49). Both slices index the same vertices.
pub fn flipped_faces(triangles: &[[u32; 3]], rest: &[DVec3], moved: &[DVec3]) -> usize {
    let normal = |p: &[DVec3], [a, b, c]: [u32; 3]| {
        let [pa, pb, pc] = [a, b, c].map(|v| p[v as usize]);
        (pb - pa).cross(pc - pa)
    };
    triangles
        .iter()
        .filter(|&&t| normal(rest, t).dot(normal(moved, t)) < 0.0)
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{fixtures, primitives};

    #[test]
    fn sphere_normals_point_outward() {
        for s in 0..4 {
            let mesh = primitives::icosphere(3.0, s);
            let normals = vertex_normals(&mesh);
            for (n, p) in normals.iter().zip(mesh.positions()) {
                assert!((n.length() - 1.0).abs() < 1e-12);
                assert!(n.dot(p.normalize()) > 0.99, "subdivision {s}: {n} at {p}");
            }
        }
    }

    #[test]
    fn closed_fixtures_have_outward_face_normals() {
        // Outward orientation means the faces' normals, weighted by area, point away from the
        // centroid on average; enclosed_volume checks the same more strictly.
        for fixture in fixtures::closed_meshes() {
            let mesh = &fixture.mesh;
            let centroid = mesh.positions().iter().sum::<DVec3>() / mesh.n_vertices() as f64;
            let outward: f64 = mesh
                .faces()
                .map(|f| {
                    let [a, b, c] = mesh.face_positions(f);
                    face_cross(mesh, f).dot((a + b + c) / 3.0 - centroid)
                })
                .sum();
            assert!(outward > 0.0, "{}", fixture.name);
        }
    }

    #[test]
    fn grid_normals_are_plus_z_and_buffer_is_reused() {
        let mesh = primitives::grid(3, 3, 1.0);
        let mut buffer = vec![DVec3::X; 100];
        vertex_normals_into(&mesh, &mut buffer);
        assert_eq!(buffer.len(), 16);
        assert!(buffer.iter().all(|&n| n == DVec3::Z));
        assert_eq!(face_normals(&mesh), vec![DVec3::Z; 18]);
    }

    #[test]
    fn cube_corner_normal_is_the_diagonal() {
        let mesh = primitives::cube(2.0);
        let normals = vertex_normals(&mesh);
        // Vertex 7 is (+1, +1, +1) and lies in both triangles of each of its three sides.
        assert!((normals[7] - DVec3::ONE.normalize()).length() < 1e-12);
    }
}
