#![allow(clippy::unwrap_used)]

use glam::{DVec2, DVec3};

use super::*;
use crate::camera::Camera;
use crate::mesh::primitives::{icosphere, torus};

const VIEWPORT: DVec2 = DVec2::new(800.0, 600.0);

fn behind() -> Camera {
    Camera {
        eye: DVec3::new(0.0, 0.0, -5.0),
        ..Camera::default()
    }
}

/// A loop of `radius` world units around `centre`, drawn as seen through `camera`.
fn ring(camera: &Camera, centre: DVec3, radius: f64) -> Vec<DVec2> {
    let (right, up) = (DVec3::X, DVec3::Y);
    (0..48)
        .map(|k| {
            let a = std::f64::consts::TAU * k as f64 / 48.0;
            let p = centre + radius * (a.cos() * right + a.sin() * up);
            camera.screen_from_world(p, VIEWPORT).unwrap().truncate()
        })
        .collect()
}

fn stroke<'a>(camera: &'a Camera, points: &'a [DVec2]) -> ViewedStroke<'a> {
    ViewedStroke {
        camera,
        viewport: VIEWPORT,
        stroke: points,
    }
}

#[test]
fn loops_on_the_front_and_the_back_of_a_sphere_drill_a_hole_through_it() {
    let sphere = icosphere(1.0, 3);
    let (front, back) = (Camera::default(), behind());
    let a = ring(&front, DVec3::Z, 0.35);
    let b = ring(&back, -DVec3::Z, 0.35);
    let t = tunnel(&sphere, stroke(&front, &a), stroke(&back, &b)).unwrap();
    let mesh = &t.mesh;
    mesh.validate().unwrap();
    assert!(mesh.is_closed());
    assert_eq!(mesh.genus(), Some(1));
    assert!(Bvh::new(mesh).crossing_faces(mesh, |_| true).is_empty());
    for chain in &t.loops {
        for k in 0..chain.len() {
            assert!(
                mesh.find_edge(chain[k], chain[(k + 1) % chain.len()])
                    .is_some()
            );
        }
    }
    let tube = t.is_tube.iter().filter(|&&x| x).count();
    assert!(tube > 50, "{tube} tube vertices");
    // The tube runs straight through the middle: its vertices lie near the z axis.
    for (v, _) in t.is_tube.iter().enumerate().filter(|(_, x)| **x) {
        let p = mesh.positions()[v];
        assert!(p.truncate().length() < 0.45, "tube vertex {p} off the axis");
    }
}

#[test]
fn loops_that_do_not_face_each_other_through_the_shape_are_refused() {
    let ring_shape = torus(1.0, 0.4, 96, 32);
    let top = Camera::default();
    let a = ring(&top, DVec3::new(0.0, 1.0, 0.4), 0.15);
    let b = ring(&top, DVec3::new(0.0, -1.0, 0.4), 0.15);
    let result = tunnel(&ring_shape, stroke(&top, &a), stroke(&top, &b));
    assert_eq!(result.unwrap_err(), TunnelError::NotFacing);
}

#[test]
fn the_same_loop_twice_is_refused() {
    let sphere = icosphere(1.0, 3);
    let front = Camera::default();
    let a = ring(&front, DVec3::Z, 0.35);
    let result = tunnel(&sphere, stroke(&front, &a), stroke(&front, &a));
    assert_eq!(result.unwrap_err(), TunnelError::LoopsTouch);
}

#[test]
fn a_loop_off_the_shape_says_so() {
    let sphere = icosphere(1.0, 3);
    let front = Camera::default();
    let a = ring(&front, DVec3::Z, 0.35);
    let off = ring(&front, DVec3::new(2.0, 0.0, 0.0), 0.3);
    let result = tunnel(&sphere, stroke(&front, &a), stroke(&front, &off));
    assert!(matches!(result.unwrap_err(), TunnelError::Loop(_)));
}
