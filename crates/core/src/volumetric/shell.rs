//! The inner and outer shells (Zhou et al. 2005, §3.2): the mesh offset inward and outward
//! by about one edge length, each vertex along its normal.
//!
//! The paper moves every vertex in small steps and undoes a step that makes the shell cross
//! itself or the mesh, a test of each moved vertex's triangles against the whole model. We
//! get the same guarantee for less: a vertex's offset is first capped at 40% of the free
//! distance along its normal (one ray through the BVH: the shell then stops short of the
//! opposite wall of a thin part, or of a neighbouring part outside), and then the
//! triangles of the shell that still cross each other (`Bvh::crossing_faces`) halve their
//! vertices' offsets, a few times. Thin features keep inner points (the paper's reason
//! for the shell): their shell sits in the middle instead of vanishing.

use glam::DVec3;

use crate::geometry::Bvh;
use crate::mesh::Mesh;

/// Of the free distance along the normal, the part a shell may take.
const CLEARANCE_SHARE: f64 = 0.4;
/// Rounds of halving the offsets of crossing triangles.
const UNCROSS_ROUNDS: usize = 6;

/// Which way a shell goes from the mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Side {
    Inner,
    Outer,
}

/// The shell of `mesh` on `side`, offset by at most `distance` along the unit `normals`: the
/// positions of the shell's vertices, one per mesh vertex, with the mesh's triangles.
pub(super) fn offset_shell(
    mesh: &Mesh,
    bvh: &Bvh,
    normals: &[DVec3],
    distance: f64,
    side: Side,
) -> Mesh {
    let sign = match side {
        Side::Inner => -1.0,
        Side::Outer => 1.0,
    };
    let directions: Vec<DVec3> = normals.iter().map(|&n| n * sign).collect();
    let mut offsets: Vec<f64> = mesh
        .positions()
        .iter()
        .zip(&directions)
        .map(|(&p, &dir)| distance.min(CLEARANCE_SHARE * clearance(mesh, bvh, p, dir)))
        .collect();
    let mut shell = mesh.clone();
    for round in 0..=UNCROSS_ROUNDS {
        place(&mut shell, mesh, &directions, &offsets);
        if round == UNCROSS_ROUNDS {
            break;
        }
        let crossing = Bvh::new(&shell).crossing_faces(&shell, |_| true);
        if crossing.is_empty() {
            break;
        }
        let mut halve = vec![false; offsets.len()];
        for (f, g) in crossing {
            for v in shell
                .face_vertices(f)
                .into_iter()
                .chain(shell.face_vertices(g))
            {
                halve[v.index()] = true;
            }
        }
        for (offset, _) in offsets.iter_mut().zip(&halve).filter(|(_, h)| **h) {
            *offset *= 0.5;
        }
    }
    shell
}

/// How far the ray from `p` along `dir` goes before it meets the mesh again; infinite when it
/// leaves (outward from a convex part) or the direction is degenerate.
fn clearance(mesh: &Mesh, bvh: &Bvh, p: DVec3, dir: DVec3) -> f64 {
    if dir.length_squared() == 0.0 {
        return 0.0;
    }
    // Start a hair off the surface, so the ray does not meet the faces around `p` at t ≈ 0.
    let start = 1e-7 * (1.0 + p.abs().max_element());
    bvh.raycast(mesh, p + dir * start, dir)
        .map_or(f64::INFINITY, |hit| hit.distance + start)
}

fn place(shell: &mut Mesh, mesh: &Mesh, directions: &[DVec3], offsets: &[f64]) {
    let rest = mesh.positions();
    for (v, p) in shell.positions_mut().iter_mut().enumerate() {
        *p = rest[v] + directions[v] * offsets[v];
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::vertex_normals;
    use crate::mesh::primitives;

    #[test]
    fn a_sphere_shell_is_a_smaller_and_a_larger_sphere() {
        let sphere = primitives::icosphere(1.0, 3);
        let normals = vertex_normals(&sphere);
        let bvh = Bvh::new(&sphere);
        let inner = offset_shell(&sphere, &bvh, &normals, 0.1, Side::Inner);
        let outer = offset_shell(&sphere, &bvh, &normals, 0.1, Side::Outer);
        for (i, o) in inner.positions().iter().zip(outer.positions()) {
            assert!(
                (i.length() - 0.9).abs() < 1e-3,
                "inner radius {}",
                i.length()
            );
            assert!(
                (o.length() - 1.1).abs() < 1e-3,
                "outer radius {}",
                o.length()
            );
        }
    }

    #[test]
    fn a_thin_part_keeps_its_inner_shell_inside() {
        // Offsetting a 0.2 thick capsule by 0.5 would turn it inside out.
        let capsule = primitives::capsule(0.1, 1.0, 16, 60);
        let normals = vertex_normals(&capsule);
        let bvh = Bvh::new(&capsule);
        let inner = offset_shell(&capsule, &bvh, &normals, 0.5, Side::Inner);
        for (p, rest) in inner.positions().iter().zip(capsule.positions()) {
            assert!(bvh.contains(&capsule, *p), "{p} left the capsule");
            if rest.x.abs() < 0.9 {
                // Across the cylinder the wall opposite is 0.2 away.
                assert!(
                    p.distance(*rest) <= CLEARANCE_SHARE * 0.2 + 1e-6,
                    "{p} moved too far"
                );
            }
        }
        let crossing = Bvh::new(&inner).crossing_faces(&inner, |_| true);
        assert!(crossing.is_empty(), "{} crossing pairs", crossing.len());
    }
}
