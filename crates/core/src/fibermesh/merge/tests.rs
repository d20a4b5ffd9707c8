#![allow(clippy::unwrap_used)]

use glam::DVec3;

use super::*;
use crate::geometry::enclosed_volume;
use crate::mesh::primitives::{icosphere, torus};

fn moved(mut mesh: Mesh, by: DVec3) -> Mesh {
    for p in mesh.positions_mut() {
        *p += by;
    }
    mesh
}

#[test]
fn two_overlapping_spheres_merge_into_one_closed_surface() {
    let a = icosphere(1.0, 4);
    let b = moved(icosphere(0.8, 4), DVec3::new(1.3, 0.2, 0.1));
    let merged = merge(&a, &b).unwrap();
    let mesh = &merged.mesh;
    mesh.validate().unwrap();
    assert!(mesh.is_closed());
    assert_eq!(mesh.genus(), Some(0));
    assert!(Bvh::new(mesh).crossing_faces(mesh, |_| true).is_empty());
    assert_eq!(merged.seams.len(), 1);
    let seam = &merged.seams[0];
    for k in 0..seam.len() {
        assert!(
            mesh.find_edge(seam[k], seam[(k + 1) % seam.len()])
                .is_some()
        );
    }
    // The seam lies on the first sphere, the gap outside the second.
    let gap = SEAM_GAPS[0] * a.mean_edge_length().min(b.mean_edge_length());
    for &v in seam {
        let p = mesh.position(v);
        assert!((p.length() - 1.0).abs() < 0.005, "{p} off the first sphere");
        let q = p - DVec3::new(1.3, 0.2, 0.1);
        assert!(
            (q.length() - 0.8 - gap).abs() < 0.005,
            "{p} off the second sphere"
        );
    }
    // The union's volume (within 2%) is checked on created shapes in the topology suite;
    // here, it holds more than either sphere and less than both.
    let (va, vb, volume) = (
        enclosed_volume(&a),
        enclosed_volume(&b),
        enclosed_volume(mesh),
    );
    assert!(
        volume > va.max(vb) && volume < va + vb,
        "{volume} from {va} and {vb}"
    );
}

#[test]
fn a_sphere_through_a_torus_s_tube_makes_a_genus_one_shape_with_two_seams() {
    let ring = torus(1.0, 0.35, 64, 24);
    let ball = moved(icosphere(0.5, 4), DVec3::new(1.0, 0.0, 0.0));
    let merged = merge(&ring, &ball).unwrap();
    assert_eq!(merged.seams.len(), 2);
    assert_eq!(merged.mesh.genus(), Some(1));
    assert!(merged.mesh.is_closed());
}

#[test]
fn shapes_apart_or_one_inside_the_other_are_refused() {
    let a = icosphere(1.0, 3);
    let far = moved(icosphere(1.0, 3), DVec3::new(3.0, 0.0, 0.0));
    assert_eq!(merge(&a, &far).unwrap_err(), MergeError::NotTouching);
    let small = icosphere(0.3, 3);
    assert_eq!(merge(&a, &small).unwrap_err(), MergeError::NotTouching);
    assert_eq!(merge(&small, &a).unwrap_err(), MergeError::Inside);
}
