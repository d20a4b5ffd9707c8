//! The shape diameter function (SDF) of Shapira et al. 2008, as SEED uses it to find the part
//! of a model an over-sketch belongs to (Bao & Howard, §4.1).
//!
//! At a vertex, rays go into the volume inside a cone around the inward normal and the SDF is
//! a robust mean of their lengths: the local thickness. SEED casts 32 rays in a 60° cone on
//! the GPU; we cast [`SDF_RAYS`] on the CPU through the BVH, in a fixed pattern (a centre ray
//! and two rings), so results are deterministic. As in Shapira et al., lengths more than one
//! standard deviation from the median are dropped before averaging (SEED does not say how it
//! aggregates); their weighting by angle is left out.

use glam::DVec3;

use super::Bvh;
use crate::mesh::{Mesh, VertexId};

/// Rays per vertex: one along the inward normal, then rings of 5 and 10.
pub const SDF_RAYS: usize = 16;

/// Half the cone's opening angle: SEED's and Shapira's cone is 60° wide.
const CONE_HALF_ANGLE: f64 = std::f64::consts::FRAC_PI_6;

/// The ray directions around `-normal`: unit vectors within [`CONE_HALF_ANGLE`] of it.
fn cone_directions(normal: DVec3) -> [DVec3; SDF_RAYS] {
    let axis = -normal.normalize_or(DVec3::Z);
    let (u, v) = axis.any_orthonormal_pair();
    let mut directions = [axis; SDF_RAYS];
    let rings = [(1, 5, 0.5 * CONE_HALF_ANGLE), (6, 10, CONE_HALF_ANGLE)];
    for (start, count, angle) in rings {
        for k in 0..count {
            let turn =
                std::f64::consts::TAU * (k as f64 + 0.5 * (start as f64 - 1.0)) / count as f64;
            let side = u * turn.cos() + v * turn.sin();
            directions[start + k] = axis * angle.cos() + side * angle.sin();
        }
    }
    directions
}

/// The SDF at vertex `v` with (outward) vertex normal `normal`, or `None` when no ray meets
/// the surface again (an open mesh seen from outside, or a degenerate normal).
pub fn shape_diameter(mesh: &Mesh, bvh: &Bvh, v: VertexId, normal: DVec3) -> Option<f64> {
    if normal.length_squared() == 0.0 {
        return None;
    }
    let p = mesh.position(v);
    // Start a hair inside, so the ray does not meet the faces around `v` at t ≈ 0.
    let offset = 1e-7 * (1.0 + p.abs().max_element());
    let mut lengths: Vec<f64> = cone_directions(normal)
        .iter()
        .filter_map(|&dir| {
            bvh.raycast(mesh, p + dir * offset, dir)
                .map(|hit| hit.distance + offset)
        })
        .collect();
    if lengths.is_empty() {
        return None;
    }
    lengths.sort_by(f64::total_cmp);
    let median = lengths[lengths.len() / 2];
    let n = lengths.len() as f64;
    let mean = lengths.iter().sum::<f64>() / n;
    let deviation = (lengths.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / n).sqrt();
    let kept: Vec<f64> = lengths
        .into_iter()
        .filter(|l| (l - median).abs() <= deviation)
        .collect();
    Some(kept.iter().sum::<f64>() / kept.len() as f64)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::vertex_normals;
    use crate::mesh::primitives;

    #[test]
    fn cone_directions_are_unit_and_within_the_cone() {
        let normal = DVec3::new(0.3, -0.5, 0.8).normalize();
        for dir in cone_directions(normal) {
            assert!((dir.length() - 1.0).abs() < 1e-12);
            let angle = dir.angle_between(-normal);
            assert!(angle <= CONE_HALF_ANGLE + 1e-12, "{angle}");
        }
    }

    #[test]
    fn a_sphere_is_about_as_thick_as_its_chords_in_the_cone() {
        // A chord at angle a from the diameter is 2 r cos a: the mean over the pattern lies
        // between 2 r cos 30° and 2 r.
        let mesh = primitives::icosphere(1.5, 3);
        let bvh = Bvh::new(&mesh);
        let normals = vertex_normals(&mesh);
        for v in mesh.vertices().step_by(37) {
            let sdf = shape_diameter(&mesh, &bvh, v, normals[v.index()]).unwrap();
            assert!((2.6 - 0.02..=3.0 + 1e-9).contains(&sdf), "{sdf}");
        }
    }

    #[test]
    fn a_thin_capsule_is_thin_and_an_open_grid_has_none() {
        let mesh = primitives::capsule(0.2, 2.0, 24, 40);
        let bvh = Bvh::new(&mesh);
        let normals = vertex_normals(&mesh);
        let side = mesh
            .vertices()
            .find(|&v| mesh.position(v).x.abs() < 0.3)
            .unwrap();
        let sdf = shape_diameter(&mesh, &bvh, side, normals[side.index()]).unwrap();
        assert!((0.3..0.45).contains(&sdf), "{sdf}");
        let grid = primitives::grid(4, 4, 1.0);
        let bvh = Bvh::new(&grid);
        assert_eq!(shape_diameter(&grid, &bvh, VertexId(5), DVec3::Z), None);
    }
}
